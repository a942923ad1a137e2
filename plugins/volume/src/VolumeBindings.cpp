// SPDX-License-Identifier: MIT
#include "VolumeBindings.hpp"

#include <volpost/core/optics/ThickPsi.hpp>

#include <cstdio>
#include <utility>

namespace volpost::volume::binding {

std::string glslDefines() {
  const std::pair<const char*, GLuint> all[] = {
      {"BINDING_NODES", kNodes},         {"BINDING_TETS", kTets},
      {"BINDING_NEIGHBORS", kNeighbors}, {"BINDING_CELL_VALUES", kCellValues},
      {"BINDING_BVH", kBvh},             {"BINDING_BOUNDARY_FACES", kBoundaryFaces},
      {"BINDING_TF_COLOR_TAU", kTfColorTau}, {"BINDING_TF_VALUES", kTfValues},
      {"BINDING_ORDER", kOrder},         {"BINDING_RAY_STATE", kRayState},
      {"BINDING_RAY_COUNTERS", kRayCounters}, {"UNIT_PSI", kPsiTable},
      {"UNIT_ISO", kIsoTable},           {"UNIT_PRE", kPreTable},
      {"UNIT_SCENE_DEPTH", kSceneDepth}, {"UNIT_IMAGE", kImage},
      {"UNIT_GRID", kGrid},              {"UNIT_TF2D", kTf2d},
      {"BINDING_TF_KNOTS", kTfKnots},    {"BINDING_VISIBLE_TETS", kVisibleTets},
      {"BINDING_FOUND_FACES", kFoundFaces}, {"UNIT_NEAREST_ENTRY", kNearestEntry},
      {"UNIT_FARTHEST_ENTRY", kFarthestEntry}, {"UNIT_THICK_PSI", kThickPsi}};
  std::string out;
  for (const auto& [name, value] : all) out += "#define " + std::string(name) + " " + std::to_string(value) + "\n";
  const auto floatDefine = [&](const char* name, double value) {
    char text[64];
    std::snprintf(text, sizeof text, "#define %s %.17g\n", name, value);
    out += text;
  };
  floatDefine("THICK_PSI_MIN_DEPTH", optics::ThickPsiTable::kMinDepth);
  floatDefine("THICK_PSI_TABLE_END", optics::ThickPsiTable::kTableEnd);
  return out;
}

}  // namespace volpost::volume::binding

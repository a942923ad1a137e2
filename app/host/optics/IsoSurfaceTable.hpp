// SPDX-License-Identifier: MIT
// The iso-surface table of Roettger et al. 2000, over (s_front, s_back) texels spanning
// [sMin, sMax]: the renderers intersect iso-surfaces exactly instead; this table is kept
// as the yardstick of that choice (tests and the optics bench compare with it).
#pragma once

#include <volpost/core/optics/IsoTables.hpp>

#include <glm/vec4.hpp>

#include <vector>

namespace volpost::optics {

/// Roettger et al. 2000: for a segment from s_front to s_back, the color (premultiplied)
/// and opacity of the first iso-surface crossed, transparent where none is. RGBA floats,
/// index [sBack * N + sFront].
struct IsoSurfaceTable {
  IsoSurfaceTable(const std::vector<IsoSurface>& surfaces, double sMin, double sMax, int resolution);
  int resolution;
  double sMin, sMax;
  std::vector<float> values;
  glm::dvec4 at(double sFront, double sBack) const;
};

}  // namespace volpost::optics

// SPDX-License-Identifier: MIT
#include "SurfaceRepresentation.hpp"

#include <array>
#include <utility>

namespace volpost::app {
namespace {

constexpr std::array<std::pair<SurfaceRepresentation, const char*>, 5> kNames{{
    {SurfaceRepresentation::Surface, "surface"},
    {SurfaceRepresentation::Wireframe, "wireframe"},
    {SurfaceRepresentation::Points, "points"},
    {SurfaceRepresentation::FeatureEdges, "feature-edges"},
    {SurfaceRepresentation::Outline, "outline"},
}};

}  // namespace

std::string toString(SurfaceRepresentation r) {
  for (const auto& [value, name] : kNames)
    if (value == r) return name;
  return "surface";
}

std::optional<SurfaceRepresentation> surfaceRepresentationFromString(const std::string& text) {
  for (const auto& [value, name] : kNames)
    if (text == name) return value;
  return std::nullopt;
}

std::string surfaceRepresentationChoices() {
  std::string out;
  for (const auto& [value, name] : kNames) out += (out.empty() ? "" : ", ") + std::string(name);
  return out;
}

}  // namespace volpost::app

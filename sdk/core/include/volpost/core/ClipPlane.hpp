// SPDX-License-Identifier: MIT
#pragma once

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace volpost {

/// Keeps the half-space the normal points into: points x with dot(x - point, normal) >= 0.
struct ClipPlane {
  glm::dvec3 point{0.0};
  glm::dvec3 normal{0.0, 0.0, 1.0};
  bool keeps(const glm::dvec3& x) const { return glm::dot(x - point, normal) >= 0.0; }
  bool operator==(const ClipPlane&) const = default;
};

}  // namespace volpost

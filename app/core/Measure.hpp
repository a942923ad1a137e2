// SPDX-License-Identifier: MIT
// Measuring between probed points: the distance between two, the angle at the middle one
// of three. The Probe panel shows them for its selected points.
#pragma once

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <cmath>
#include <numbers>
#include <optional>

namespace volpost::app {

inline double distanceBetween(const glm::dvec3& a, const glm::dvec3& b) { return glm::length(b - a); }

/// The angle ABC at b in degrees (0..180); nullopt when a or c coincides with b.
inline std::optional<double> angleAt(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  const glm::dvec3 u = a - b, v = c - b;
  const double lu = glm::length(u), lv = glm::length(v);
  if (!(lu > 0.0) || !(lv > 0.0)) return std::nullopt;
  // atan2 of the cross and dot products: accurate for angles near 0 and 180 too.
  return std::atan2(glm::length(glm::cross(u, v)), glm::dot(u, v)) * 180.0 / std::numbers::pi;
}

}  // namespace volpost::app

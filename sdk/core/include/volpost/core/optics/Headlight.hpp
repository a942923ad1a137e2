// SPDX-License-Identifier: MIT
// Shading of a volume's emission by its gradient, with the light at the eye (a headlight):
// the emitted color C becomes C (0.3 + 0.7 |cos|) + 0.3 |cos|^20 (white), cos the angle
// between the gradient and the ray. Two-sided (the gradient's sign says nothing about which
// side faces the light); unlit where the gradient is zero. The same numbers in every
// renderer's shaders and in the references.
#pragma once

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cmath>

namespace volpost::optics {

/// (multiplier of the color, white added) for a gradient seen along the unit direction.
inline glm::dvec2 headlight(const glm::dvec3& gradient, const glm::dvec3& direction) {
  const double g = glm::length(gradient);
  if (!(g > 0.0) || !std::isfinite(g)) return {1.0, 0.0};
  const double c = std::abs(glm::dot(gradient / g, direction));
  return {0.3 + 0.7 * c, 0.3 * std::pow(c, 20.0)};
}

/// The shading factor of an iso-surface with this gradient seen along the unit direction
/// (0.3 + 0.7 |cos|; 1 where the gradient is zero).
inline double isoShade(const glm::dvec3& gradient, const glm::dvec3& direction) {
  const double g = glm::length(gradient);
  return g > 0.0 && std::isfinite(g) ? 0.3 + 0.7 * std::abs(glm::dot(gradient / g, direction)) : 1.0;
}

}  // namespace volpost::optics

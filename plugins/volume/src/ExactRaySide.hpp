// SPDX-License-Identifier: MIT
// On which side of an edge a ray passes, decided where float cannot: in double where its
// rounding bound allows, else in exact arithmetic, and where the exact answer is "on the
// edge's line" (rays through vertices, along edges, in faces) by a symbolic perturbation of
// the ray that is the same for every edge - so all the signs are those of one real ray in
// general position, and every decision of a walk agrees with every other.
#pragma once

#include <glm/vec3.hpp>

namespace volpost::volume {

/// Sign of d . ((a - o) x (b - o)) for the ray o + t d, perturbed as above: true when
/// positive. `value` gets the double product (0 where only the perturbation decides).
bool rayEdgeSidePositive(const glm::dvec3& o, const glm::dvec3& d, const glm::dvec3& a, const glm::dvec3& b,
                         double& value);

}  // namespace volpost::volume

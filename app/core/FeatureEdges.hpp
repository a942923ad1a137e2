// SPDX-License-Identifier: MIT
// The edges that outline a surface: where its faces meet at a sharp angle (more than
// `angleDegrees` between their normals) and where it has a border. A box's twelve edges,
// not the triangles' diagonals on its flat faces: the undeformed outline under a deformed
// shape, drawn without caging the picture in element edges.
#pragma once

#include "host/BoundarySurface.hpp"

#include <glm/vec3.hpp>

#include <vector>

namespace volpost::app {

/// Segment endpoints, two per edge, in model coordinates.
std::vector<glm::dvec3> featureEdges(const BoundarySurface& surface, double angleDegrees = 30.0);

}  // namespace volpost::app

// SPDX-License-Identifier: MIT
// Where a plane cuts a cell: the points where it crosses the edges between the cell's
// corners, in order around the section (a convex polygon for a convex cell), each with the
// two corner nodes and how far along from the first. Picking draws the cut faces from
// these, glyphs sit at their centres with values interpolated along the edges.
#pragma once

#include <volpost/core/ClipPlane.hpp>
#include <volpost/core/Model.hpp>

#include <glm/vec3.hpp>

#include <cstddef>
#include <vector>

namespace volpost::app {

struct SectionPoint {
  glm::dvec3 at{0.0};
  NodeIndex a = 0, b = 0;  ///< the edge's corner nodes
  double t = 0.0;          ///< at = a + t (b - a)
};

/// The section of `cell` of `model` by `plane` (normal of any length), its points in order
/// around it; fewer than three when the plane does not cross the cell.
std::vector<SectionPoint> cellSection(const Model& model, std::size_t cell, const ClipPlane& plane);

}  // namespace volpost::app

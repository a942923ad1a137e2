// SPDX-License-Identifier: MIT
// The cross-section of a tetrahedral mesh by a plane: the polygons where the plane cuts
// each tet (marching tetrahedra on the signed distances), with the result interpolated
// linearly along the cut edges. What a section cut shows, colored by the result.
#pragma once

#include <volpost/core/ClipPlane.hpp>
#include <volpost/core/RegularGrid.hpp>
#include <volpost/core/SampleView.hpp>
#include <volpost/core/Tetrahedralize.hpp>
#include <volpost/core/optics/ElementField.hpp>

#include "host/ElementRefinement.hpp"

#include <glm/vec3.hpp>

#include <span>
#include <vector>

namespace volpost {

struct SectionTriangles {
  std::vector<glm::dvec3> positions;  ///< three per triangle, model coordinates
  std::vector<double> values;         ///< one per position (NaN where the result has none)
  std::size_t cutTets = 0;            ///< tets the plane passes through
  /// From the cells' own shapes and field: subdivisions of the split's tetrahedra along
  /// each edge (0: the split as it is) and whether the tolerance was reached.
  int refinement = 0;
  bool toleranceReached = true;
};

/// `values`: one per node of tets.mesh (`perNode`) or one per tet (element results), or
/// empty (geometry only). Triangles face along the plane's normal, the side it keeps.
SectionTriangles cutTetrahedra(const TetMesh& tets, std::span<const double> values, bool perNode, const ClipPlane& plane);

/// The section of the cells' own shapes (curved where a quadratic cell's midside nodes
/// leave the straight edge), colored by the cells' own field: the split's tetrahedra in
/// cells the plane may cross are refined to `limits` (ElementRefinement) and cut.
/// `cellValues`: empty for `field`'s values, or one per cell of field.mesh() (element
/// results, constant in a cell).
SectionTriangles cutCells(const optics::ElementField& field, std::span<const double> cellValues, const ClipPlane& plane,
                          const RefinementLimits& limits = {});

/// The same for a regular grid's cells without building them: `values` one per grid point
/// (`perNode`) or per cell, or empty. Each crossed cell is cut as six tets, so the section
/// is linear in each of them; on a plane through grid points it shows the samples exactly.
/// `cutTets` counts those tets.
SectionTriangles cutGrid(const RegularGrid& grid, SampleView values, bool perNode, const ClipPlane& plane);

}  // namespace volpost

// SPDX-License-Identifier: MIT
// Iso-surfaces as triangle meshes (marching tetrahedra over the conforming tetrahedra of
// the model), for export and for drawing as opaque geometry.
#pragma once

#include <volpost/core/Progress.hpp>
#include <volpost/core/SampleView.hpp>
#include <volpost/core/Tetrahedralize.hpp>

#include "host/BoundarySurface.hpp"
#include "host/ElementRefinement.hpp"

#include <span>

namespace volpost {

struct ExtractedSurface {
  /// Positions are float model coordinates minus `origin`, like BoundarySurface.
  SurfaceMesh mesh;
  glm::dvec3 origin{0.0};
  /// Triangles kept with vertices of their own where sheets touch at one vertex (a node
  /// exactly at the iso-value between two of them), which a manifold mesh cannot share.
  std::size_t separatedFaces = 0;
  /// From the cells' own field: the subdivisions of the split's tetrahedra along each edge
  /// (0: the split's field as it is), the deviation estimated to be left (relative, see
  /// RefinedTetrahedra) and whether it is within the tolerance asked for.
  int refinement = 0;
  double deviation = 0.0;
  bool toleranceReached = true;
};

/// The surface value == iso of a nodal field given on `tets.mesh`'s nodes (see
/// TetMesh::nodeValues). Vertices on a tet edge are shared by every tet around the edge, so
/// the surface is connected and watertight inside the mesh; triangles face increasing
/// values. Tets with a NaN value are left out. Throws std::invalid_argument on a value
/// count that is not one per node.
ExtractedSurface extractIsoSurface(const TetMesh& tets, std::span<const double> nodeValues, double iso,
                                   const Progress& progress = {});

/// The level set of the cells' own field (`field`: their shape functions, trilinear in a
/// hex8, quadratic in a tet10), not of its split's linear field: the split's tetrahedra in
/// cells whose field can reach `iso` (ElementField::valueBound) are refined to `limits`
/// (ElementRefinement) and the pieces contoured. Closed and oriented like the split's.
ExtractedSurface extractIsoSurface(const optics::ElementField& field, double iso, const RefinementLimits& limits = {},
                                   const Progress& progress = {});

/// The same for a regular grid's point values without building its cells or tetrahedra:
/// each cell the value crosses is split into six tets on the fly (one split in every cell,
/// so the surface is watertight). Throws std::invalid_argument on a value count that is
/// not one per point.
ExtractedSurface extractIsoSurface(const RegularGrid& grid, SampleView pointValues, double iso,
                                   const Progress& progress = {});

}  // namespace volpost

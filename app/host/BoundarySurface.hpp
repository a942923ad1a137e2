// SPDX-License-Identifier: MIT
// The outer boundary of a volume mesh as a triangle surface (OpenMesh), extracted once.
#pragma once

#include <volpost/core/Mesh.hpp>
#include <volpost/core/Progress.hpp>
#include <volpost/core/RegularGrid.hpp>

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <array>
#include <cstdint>
#include <vector>

namespace volpost {

using SurfaceMesh = OpenMesh::TriMesh_ArrayKernelT<>;

/// Boundary faces are the cell faces that no other cell shares. Quadrilaterals and the
/// faces of quadratic cells are split into triangles through their midside nodes, so
/// nodal results are drawn with every node the solver computed.
struct BoundarySurface {
  /// Positions are float model coordinates minus `origin` (keeps float precision on
  /// models far from the origin).
  SurfaceMesh mesh;
  glm::dvec3 origin{0.0};
  OpenMesh::VPropHandleT<NodeIndex> nodeOfVertex;      ///< mesh node of each surface vertex
  OpenMesh::FPropHandleT<std::uint32_t> cellOfFace;    ///< cell each triangle comes from
  /// Element edges on the boundary (pairs of mesh node indices, through midside nodes).
  std::vector<std::array<NodeIndex, 2>> edges;
  /// Where element edges are drawn in pieces (a curved cell's), how far apart the edges
  /// are near each piece: the shortest element edge at either end of the edge it is a piece
  /// of, so dense edges fade as the cells crowd, not as the pieces do. Empty: found from
  /// the edges themselves.
  std::vector<float> edgeSpacing;
  std::size_t boundaryFaceCount = 0;      ///< cell faces (tri or quad) on the boundary
  std::size_t nonManifoldFaceCount = 0;   ///< faces OpenMesh could not attach, split off
};

BoundarySurface extractBoundary(const Mesh& mesh, const Progress& progress = {});
/// The boundary of a regular grid's hexahedra without building them: the same faces, nodes,
/// cells and edges as extractBoundary(hexahedraOfGrid(grid)), in another order.
BoundarySurface extractBoundary(const RegularGrid& grid, const Progress& progress = {});

}  // namespace volpost

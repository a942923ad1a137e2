// SPDX-License-Identifier: MIT
// Finds the cell holding a point and the interpolation weights there: probing results at a
// point, picking. Works on the conforming tetrahedra of the model (tetrahedralize), so
// every cell type is handled the same way: linear inside each tet (tet10 through its 8
// sub-tets, hexahedra, wedges and pyramids through their Steiner-point split).
#pragma once

#include <volpost/core/Tetrahedralize.hpp>

#include <glm/vec3.hpp>

#include <array>
#include <optional>
#include <vector>

namespace volpost {

struct PointLocation {
  std::size_t tet = 0;                 ///< tet of TetMesh::mesh
  std::size_t cell = 0;                ///< the source cell (TetMesh::cellOfTet)
  std::array<NodeIndex, 4> nodes{};    ///< the tet's nodes (TetMesh::mesh numbering)
  std::array<double, 4> weights{};     ///< barycentric weights, sum 1
};

class PointLocator {
 public:
  explicit PointLocator(const TetMesh& tets);
  /// The tet containing p (on a shared face: either one), or nullopt outside the mesh.
  /// `tolerance` is relative to the tet size: points that far outside still count.
  std::optional<PointLocation> locate(const glm::dvec3& p, double tolerance = 1e-9) const;
  /// Interpolates values given per TetMesh node (TetMesh::nodeValues) or per source cell.
  static double interpolateNodal(const PointLocation& at, const std::vector<double>& tetNodeValues);

 private:
  const TetMesh& tets_;
  glm::dvec3 min_{0.0}, cellSize_{1.0};
  glm::ivec3 resolution_{1};
  std::vector<std::uint32_t> start_;   // CSR: tets overlapping each grid cell
  std::vector<std::uint32_t> items_;
  std::size_t gridIndex(const glm::ivec3& c) const;
  glm::ivec3 gridCell(const glm::dvec3& p) const;
};

}  // namespace volpost

// SPDX-License-Identifier: MIT
// Finds the cell holding a point and the interpolation weights there: probing results at a
// point, picking. Works on the conforming tetrahedra of the model (tetrahedralize), so
// every cell type is handled the same way: linear inside each tet (tet10 through its 8
// sub-tets, hexahedra, wedges and pyramids through their Steiner-point split).
#pragma once

#include <volpost/core/Tetrahedralize.hpp>

#include <glm/vec3.hpp>

#include <algorithm>
#include <array>
#include <optional>
#include <vector>

namespace volpost {

struct PointLocation {
  std::size_t tet = 0;                 ///< tet of TetMesh::mesh
  std::size_t cell = 0;                ///< the source cell (TetMesh::sourceCell)
  std::array<NodeIndex, 4> nodes{};    ///< the tet's nodes (TetMesh::mesh numbering)
  std::array<double, 4> weights{};     ///< barycentric weights, sum 1
};

/// How far outside the cells a point may lie and still count as in the mesh, as a fraction
/// of the model's size (its diagonal): 1e-5 covers coordinates copied from files that keep
/// six significant digits (CalculiX .frd) on a model near the origin, and refuses a point
/// one ten-thousandth of the model outside.
inline constexpr double kOnMeshTolerance = 1e-5;

class PointLocator {
 public:
  explicit PointLocator(const TetMesh& tets);
  /// The tet containing p (on a shared face: either one), or nullopt outside the mesh.
  /// `tolerance`: how far outside a tet p may lie, as a fraction of the model's size.
  std::optional<PointLocation> locate(const glm::dvec3& p, double tolerance = kOnMeshTolerance) const;
  /// Tets whose bounding boxes come within `radius` of p (model units), each once.
  std::vector<std::uint32_t> tetsNear(const glm::dvec3& p, double radius) const;
  /// Interpolates values given per TetMesh node (TetMesh::nodeValues) or per source cell.
  static double interpolateNodal(const PointLocation& at, const std::vector<double>& tetNodeValues);
  /// The model's diagonal (what the tolerances are relative to).
  double modelSize() const { return modelSize_; }
  /// The search grid's largest spacing (about the size of a couple of tets).
  double gridSpacing() const { return std::max({cellSize_.x, cellSize_.y, cellSize_.z}); }

 private:
  const TetMesh& tets_;
  double modelSize_ = 1.0;
  glm::dvec3 min_{0.0}, cellSize_{1.0};
  glm::ivec3 resolution_{1};
  std::vector<std::uint32_t> start_;   // CSR: tets overlapping each grid cell
  std::vector<std::uint32_t> items_;
  std::size_t gridIndex(const glm::ivec3& c) const;
  glm::ivec3 gridCell(const glm::dvec3& p) const;
  /// Barycentric weights of p in tet t and how far outside it p lies (0 inside), model units.
  double distanceOutside(std::size_t t, const glm::dvec3& p, std::array<double, 4>& weights) const;
};

}  // namespace volpost

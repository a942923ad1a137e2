// SPDX-License-Identifier: MIT
// One cell of the model as a refinement sees it: a tetrahedron of the cell's split, the
// cell's isoparametric map and field on it (a point named by its barycentric weights in
// that tetrahedron), or, for a cell drawn linearly, the split tetrahedron's own corners.
#pragma once

#include "host/ElementRefinement.hpp"

#include <volpost/core/CellShape.hpp>
#include <volpost/core/Mesh.hpp>
#include <volpost/core/Tetrahedralize.hpp>
#include <volpost/core/optics/ElementField.hpp>

#include <glm/geometric.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <span>

namespace volpost {

class CellMap {
 public:
  CellMap(const Mesh& cells, const optics::ElementField& field, const TetMesh& split,
          std::span<const double> splitValues)
      : cells_(cells), field_(field), split_(split), splitValues_(splitValues) {}

  /// Prepares for split tetrahedron `tet`; false when its cell is drawn linearly.
  bool select(std::size_t tet) {
    const auto tetNodes = split_.mesh.cellNodes(tet);
    return select(split_.sourceCell(tet), {tetNodes[0], tetNodes[1], tetNodes[2], tetNodes[3]});
  }

  /// Prepares for the simplex of these nodes of `cell` (the split's: the cell's own nodes
  /// and the points its split added); a triangle repeats its last corner, with no weight.
  bool select(std::uint32_t cell, const std::array<NodeIndex, 4>& corners) {
    cell_ = cell;
    corners_ = corners;
    linear_ = field_.linearIn(cell_);
    if (linear_) return false;
    type_ = cells_.cellType(cell_);
    const auto ids = cells_.cellNodes(cell_);
    count_ = int(ids.size());
    const std::span<const double> values = field_.values();
    for (int i = 0; i < count_; ++i) {
      nodes_[std::size_t(i)] = cells_.nodes[ids[std::size_t(i)]];
      values_[std::size_t(i)] = values[ids[std::size_t(i)]];
    }
    for (int k = 0; k < 4; ++k)
      xi_[std::size_t(k)] = naturalCoordinatesOfSplitNode(cells_, cell_, corners_[std::size_t(k)]);
    flatFaced_ = type_ == CellType::Pyramid5 || flatFacedCell(type_, {nodes_.data(), std::size_t(count_)});
    return true;
  }

  /// Whether the cell's map bends none of its faces (a linear cell whose faces are flat):
  /// it then only moves points within the cell, and straight pieces placed by it fill the
  /// cell as they should.
  bool flatFaced() const { return linear_ || flatFaced_; }

  /// The field's gradient in space at barycentric weights `w` (zero where the pieces are
  /// placed in space: their points do not move).
  glm::dvec3 gradient(const std::array<double, 4>& w) const {
    if (linear_ || type_ == CellType::Pyramid5) return glm::dvec3(0.0);
    glm::dvec3 xi(0.0);
    for (int k = 0; k < 4; ++k) xi += w[std::size_t(k)] * xi_[std::size_t(k)];
    return field_.gradient(cell_, xi);
  }

  const std::array<NodeIndex, 4>& corners() const { return corners_; }
  std::uint32_t cell() const { return cell_; }

  /// The point at barycentric weights `w` (summing to 1) of the split tetrahedron.
  void at(const std::array<double, 4>& w, glm::dvec3& position, double& value) const {
    if (linear_) {
      position = glm::dvec3(0.0);
      value = 0.0;
      for (int k = 0; k < 4; ++k) {
        position += w[std::size_t(k)] * split_.mesh.nodes[corners_[std::size_t(k)]];
        value += w[std::size_t(k)] * splitValues_[corners_[std::size_t(k)]];
      }
      return;
    }
    glm::dvec3 xi(0.0);
    for (int k = 0; k < 4; ++k) xi += w[std::size_t(k)] * xi_[std::size_t(k)];
    const std::span<const glm::dvec3> nodes(nodes_.data(), std::size_t(count_));
    if (type_ == CellType::Pyramid5) {
      // A pyramid's natural coordinates span a cube whose top face is the apex: straight
      // pieces there would not tile it. Its edges are straight, so the pieces are placed
      // in space and the point's coordinates found by the inverse map.
      position = glm::dvec3(0.0);
      double linear = 0.0;
      for (int k = 0; k < 4; ++k) {
        position += w[std::size_t(k)] * split_.mesh.nodes[corners_[std::size_t(k)]];
        linear += w[std::size_t(k)] * splitValues_[corners_[std::size_t(k)]];
      }
      const auto found = naturalCoordinates(type_, nodes, position, xi);
      value = found ? field_.valueAt(cell_, clampToReference(type_, *found)) : linear;  // the apex: its own value
      return;
    }
    // The shape functions once for both (they were half of the refinement's time): the
    // same sums as positionAt and ElementField::valueAt, so the same numbers.
    const ShapeValues n = shapeFunctions(type_, xi);
    const glm::dvec3 origin = nodes_[0];
    glm::dvec3 x(0.0);
    value = 0.0;
    for (std::size_t i = 0; i < std::size_t(count_); ++i) {
      x += n[i] * (nodes_[i] - origin);
      value += n[i] * values_[i];
    }
    position = origin + x;
  }

 private:
  const Mesh& cells_;
  const optics::ElementField& field_;
  const TetMesh& split_;
  std::span<const double> splitValues_;
  std::uint32_t cell_ = 0;
  std::array<NodeIndex, 4> corners_{};
  bool linear_ = true;
  CellType type_ = CellType::Tet4;
  int count_ = 0;
  std::array<glm::dvec3, kMaxCellNodes> nodes_{};
  std::array<double, kMaxCellNodes> values_{};  ///< the field at the cell's nodes
  std::array<glm::dvec3, 4> xi_{};
  bool flatFaced_ = false;

  static bool flatFacedCell(CellType type, std::span<const glm::dvec3> nodes) {
    const CellTopology& topo = topology(type);
    if (topo.quadratic) return false;
    for (const CellFace& f : topo.faces) {
      if (f.size != 4) continue;
      const glm::dvec3 a = nodes[f.corners[0]], b = nodes[f.corners[1]], c = nodes[f.corners[2]],
                       d = nodes[f.corners[3]];
      const double size = glm::length(c - a) + glm::length(d - b);
      if (std::abs(glm::dot(b - a, glm::cross(c - a, d - a))) > 1e-9 * size * size * size) return false;
    }
    return true;
  }
};

}  // namespace volpost

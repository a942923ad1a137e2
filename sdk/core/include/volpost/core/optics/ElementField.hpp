// SPDX-License-Identifier: MIT
// The field as the finite-element program defines it: in each cell, the node values
// through the cell's own shape functions (trilinear in a hex8, quadratic in a tet10,
// serendipity in a hex20 and a wedge15), found at a point through the inverse of the
// cell's isoparametric map. The reference integrates it, instead of the field linear on the
// tetrahedra the cells are split into, when asked for the element interpolation. The split
// still gives the geometry: exact for cells with straight edges and plane faces; a warped
// face or a curved edge is drawn as its split's facets (docs/methods/element_field.md).
#pragma once

#include <volpost/core/Mesh.hpp>
#include <volpost/core/Tetrahedralize.hpp>
#include <volpost/core/optics/PolynomialSegment.hpp>

#include <glm/vec3.hpp>

#include <atomic>
#include <cstdint>
#include <optional>
#include <span>
#include <utility>
#include <vector>

namespace volpost::optics {

class ElementField {
 public:
  /// `mesh`: the cells as the file has them, `values` one per node; `tets`: their split.
  /// Points given to the methods are relative to `origin`. The mesh and the split are
  /// referenced, not copied: they must outlive this.
  ElementField(const Mesh& mesh, std::span<const double> values, const TetMesh& tets, glm::dvec3 origin);

  std::uint32_t cellOfTet(std::size_t tet) const { return tets_.sourceCell(tet); }
  const Mesh& mesh() const { return mesh_; }
  const TetMesh& split() const { return tets_; }
  /// The node values, one per node of mesh().
  std::span<const double> values() const { return values_; }
  /// Where the split's linear field is the whole story: a tet4, or a cell whose map cannot
  /// be inverted (folded, inverted, collapsed: drawn by its split and listed).
  bool linearIn(std::uint32_t cell) const { return !elementCells_[cell]; }
  /// How far a cell drawn by its own field bends away from its split's flat facets (the
  /// largest midside node's distance from its edge's middle, a quadrilateral's corner's from
  /// its face's plane); 0 where that is within 1e-4 of the cell's size (six printed digits
  /// leave straight cells 1e-5 off) or the cell is drawn by its split.
  double bend(std::uint32_t cell) const { return bends_.empty() ? 0.0 : double(bends_[cell]); }
  /// The cells whose map cannot be inverted, ascending.
  const std::vector<std::uint32_t>& uninvertibleCells() const { return uninvertible_; }
  /// The values' range (what tolerances are relative to; 1 when they are all equal).
  double valueScale() const { return scale_; }
  /// The diagonal of the nodes' bounding box: no straight ray is longer inside the mesh.
  double diagonal() const { return diagonal_; }
  /// Where points given to the methods are measured from.
  const glm::dvec3& origin() const { return origin_; }
  /// Bounds of the field anywhere in `cell` (lo, hi): for a hex8, wedge6 or pyramid5 the
  /// node values' range (shape functions >= 0); for a tet10 the range of its Bernstein
  /// coefficients; for a hex20 (triquadratic) and a wedge15 (quadratic on the triangle times
  /// quadratic along the axis) the range of the tensor Bernstein coefficients of the space
  /// its serendipity field lies in. The field is a convex combination of them.
  std::optional<std::pair<double, double>> valueBound(std::uint32_t cell) const;

  /// The value at `p` in `cell`; `xi` is where the inverse map starts and gets the natural
  /// coordinates found. nullopt where the map's iteration does not converge.
  std::optional<double> value(std::uint32_t cell, const glm::dvec3& p, glm::dvec3& xi) const;
  /// Whether `cell`'s isoparametric map is affine (a parallelepiped hex8, a straight-sided
  /// quadratic cell with its midside nodes halfway): then the natural coordinates move
  /// linearly along a straight ray and valueAt needs no inverse map.
  bool affine(std::uint32_t cell) const { return elementCells_[cell] == kAffine; }
  /// For an affine cell: the natural coordinates of the `count` points `p` without Newton
  /// steps (one Jacobian, inverted). False where the Jacobian is singular.
  bool affineCoordinates(std::uint32_t cell, const glm::dvec3* p, glm::dvec3* xi, int count) const;
  /// For an affine cell: the degree of its field as a polynomial along any straight line
  /// (the coordinates move linearly: 2 for a tet10 or wedge6, 3 for a hex8 or wedge15, 4
  /// for a hex20); -1 where it is not a polynomial of known degree.
  int degreeAlongLine(std::uint32_t cell) const;
  /// For an affine cell (degreeAlongLine >= 0): its field along the natural coordinates
  /// front + (u + 1) / 2 (back - front), u in [-1, 1], as the polynomial it is (a hex8's
  /// cubic multiplied out, the others interpolated at degree + 1 points). nullopt where the
  /// degree is unknown or a value is not finite.
  std::optional<ScalarPolynomial> polynomialAlong(std::uint32_t cell, const glm::dvec3& front,
                                                  const glm::dvec3& back) const;
  /// The value at natural coordinates `xi` of `cell`.
  double valueAt(std::uint32_t cell, const glm::dvec3& xi) const;
  /// The gradient per length unit at natural coordinates `xi` of `cell`.
  glm::dvec3 gradient(std::uint32_t cell, const glm::dvec3& xi) const;
  /// Where the inverse map starts in this cell.
  glm::dvec3 start(std::uint32_t cell) const;

  /// Ray stretches where the inverse map did not converge and the split's field was drawn.
  void countFallback() const { ++fallbacks_; }
  std::size_t fallbacks() const { return fallbacks_; }

 private:
  int gather(std::uint32_t cell, glm::dvec3* nodes, double* values) const;

  const Mesh& mesh_;
  std::vector<double> values_;
  const TetMesh& tets_;
  glm::dvec3 origin_;
  static constexpr char kAffine = 2;  ///< in elementCells_: drawn by its own field, map affine
  std::vector<char> elementCells_;    ///< per cell: 0 the split's field, 1 its own, kAffine its own (affine map)
  std::vector<std::uint32_t> uninvertible_;
  std::vector<float> bends_;  ///< per cell (empty when no cell bends)
  double scale_ = 1.0;
  double diagonal_ = 0.0;
  mutable std::atomic<std::size_t> fallbacks_{0};
};

}  // namespace volpost::optics

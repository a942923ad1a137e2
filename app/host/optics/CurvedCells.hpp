// SPDX-License-Identifier: MIT
// The cells whose shape the split's flat facets do not follow: a tet10, hex20 or wedge15
// with a midside node off the middle of its edge, or a cell with a quadrilateral face whose
// corners are not in one plane (its face is then the bilinear or quadratic surface the map
// gives). For those the reference finds where a ray runs inside the cell on the cell's own
// shape: the points of the ray whose natural coordinates (Newton's method on the map) lie
// in the reference cell, the ends found by bisection to rounding.
#pragma once

#include "host/optics/BoxTree.hpp"

#include <volpost/core/Mesh.hpp>
#include <volpost/core/optics/ElementField.hpp>

#include <glm/vec3.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace volpost::optics {

/// A ray's stretch [t0, t1] inside one cell.
struct CellStretch {
  double t0, t1;
  std::uint32_t cell;
};

class CurvedCells {
 public:
  /// The field's cells drawn through their own shape functions that bend away from their
  /// split's facets (ElementField::bend). Positions relative to the field's origin, as its rays.
  explicit CurvedCells(const ElementField& field);  ///< referenced: it must outlive this

  bool empty() const { return cells_.empty(); }
  std::size_t count() const { return cells_.size(); }
  bool curved(std::uint32_t cell) const { return field_.bend(cell) > 0.0; }

  /// The stretches of the ray o + t d (unit d) with t in [tMin, tMax] inside curved cells,
  /// appended to `out` (unsorted). `seeds`: parameters sampled besides the even ones (where
  /// the ray meets the split's tets of curved cells: short stretches near a cell's edges).
  void stretches(const glm::dvec3& o, const glm::dvec3& d, double tMin, double tMax, std::span<const double> seeds,
                 std::vector<CellStretch>& out) const;

  /// Even samples along a cell's part of a ray between which the ends are searched (with
  /// the seeds): a stretch between two of them that no seed falls in (a ray grazing a bulge
  /// beyond the split) can be missed.
  static constexpr int kSamples = 32;

 private:
  struct Cell {
    std::uint32_t id;
    CellType type;
    std::uint32_t firstNode;  ///< into nodes_
    int nodeCount;
  };
  void stretchesIn(const Cell& cell, const glm::dvec3& o, const glm::dvec3& d, const std::vector<double>& samples,
                   std::vector<CellStretch>& out) const;

  const ElementField& field_;  ///< referenced: it must outlive this
  std::vector<Cell> cells_;
  std::vector<glm::dvec3> nodes_;        ///< the curved cells' nodes, relative to the field's origin
  std::vector<BoxTree::Box> cellBoxes_;  ///< per curved cell, holding its whole shape
  BoxTree boxes_;
};

}  // namespace volpost::optics

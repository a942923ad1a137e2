// SPDX-License-Identifier: MIT
// Where a table over the scalar puts its texels. Spread evenly over the value range, a
// narrow peak of the transfer function falls between two texels and a pre-integrated
// table interpolated across it misses it (the "netting" of tet faces over a sharp peak).
// The warp gives half the texels to the values, in proportion to their span, and the other
// half equally to the function's pieces between control points, however narrow: a peak of
// three points gets as many texels as a wide ramp. It is piecewise linear (knots at the
// control points), so the renderers map a value to its table coordinate exactly. Given
// the table's texel count, the knots are moved onto texels (where the pieces are fewer
// than the texels), so that between two neighbouring texels the function is linear and a
// table interpolated there is smooth.
#pragma once

#include <volpost/core/TransferFunction.hpp>

#include <vector>

namespace volpost::optics {

class TableWarp {
 public:
  /// The identity over [sMin, sMax] when the function has no piece inside it. With
  /// `texels` >= 2, each knot lies on a texel (coordinate k / (texels - 1)) when the
  /// pieces are no more than texels - 1.
  TableWarp(const TransferFunction& tf, double sMin, double sMax, int texels = 0);

  /// The table coordinate (0..1) of a value, clamped to the range; and back.
  double toTable(double s) const;
  double fromTable(double u) const;
  /// The knots: values and their table coordinates, increasing from (sMin, 0) to (sMax, 1).
  const std::vector<double>& values() const { return s_; }
  const std::vector<double>& coordinates() const { return u_; }

 private:
  void snapToTexels(int texels);

  std::vector<double> s_, u_;
};

}  // namespace volpost::optics

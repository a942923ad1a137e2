// SPDX-License-Identifier: MIT
// The pre-integrated transfer function (Roettger 2000, Engel 2001), split so that a table
// cannot net a sharp function. A segment's opacity is exact: 1 - exp(-D), its optical depth
// D from OpticalDepth (any length, no table). Only the color of an optically thin segment
// (D <= kMaxDepth) comes from a 3D table over (s_front, s_back, D): the mean color the
// segment shows, C / alpha, which for given ends depends on the depth alone and stays
// within the colors crossed. A thicker segment is integrated exactly (cut at every control
// point crossed): its color has structure finer than any table (where the light comes
// from shifts with the depth), and a ray meets only a few of them before it is opaque.
// The value texels lie where TableWarp puts them, knots on texels, so between two texels
// the function is linear. Built exactly (to 1e-11: a series in the depth whose moments
// are polynomial integrals over the pieces), multithreaded.
#pragma once

#include <volpost/core/TransferFunction.hpp>
#include <volpost/core/optics/OpticalDepth.hpp>
#include <volpost/core/optics/TableWarp.hpp>

#include <glm/vec4.hpp>

#include <vector>

namespace volpost::optics {

class PreintegrationTable {
 public:
  /// Scalars span [sMin, sMax] in `scalarResolution` texels placed by the function's
  /// TableWarp (texel i at warp().fromTable(i / (N - 1))); depths [0, kMaxDepth] in
  /// `depthResolution` texels, evenly. A function with more than 2 control
  /// points per scalar texel is first resampled at 2 per texel for the colors (detail the
  /// table cannot show), so the cost stays bounded whatever the point count; the opacity
  /// still comes from every point.
  PreintegrationTable(const TransferFunction& tf, double sMin, double sMax, int scalarResolution, int depthResolution,
                      int threads = 0);

  int scalarResolution() const { return ns_; }
  int depthResolution() const { return nd_; }
  /// Mean color (rgb) as floats, index [(d * Ns + sBack) * Ns + sFront] * 3.
  const std::vector<float>& values() const { return values_; }
  /// Where the scalar texels lie: a lookup maps each value through it first.
  const TableWarp& warp() const { return warp_; }
  /// Segments up to this optical depth take their color from the table (transmittance
  /// 0.61: a ray crosses at most ~12 thicker ones before it is opaque to 1/1000).
  static constexpr double kMaxDepth = 0.5;
  /// What a renderer composites for a segment (premultiplied color, alpha): the exact
  /// opacity with the table's trilinear color (as the GPU sampler) where the segment is
  /// thin, the exact integral where it is thick; for error studies.
  glm::dvec4 lookup(double sFront, double sBack, double length) const;

 private:
  int ns_, nd_;
  TransferFunction tf_;
  TableWarp warp_;
  OpticalDepth depth_;
  std::vector<float> values_;
};

}  // namespace volpost::optics

// SPDX-License-Identifier: MIT
// The pre-integrated transfer function (Roettger 2000, Engel 2001): a 3D table over
// (s_front, s_back, length) of the associated color and alpha of a segment, built here
// with the exact segment integration (every control point cut), multithreaded.
#pragma once

#include <volpost/core/TransferFunction.hpp>
#include <volpost/core/optics/TableWarp.hpp>

#include <glm/vec4.hpp>

#include <vector>

namespace volpost::optics {

class PreintegrationTable {
 public:
  /// Scalars span [sMin, sMax] in `scalarResolution` texels placed by the function's
  /// TableWarp (texel i at warp().fromTable(i / (N - 1))), lengths [0, maxLength] in
  /// `lengthResolution` texels (texel i at i / (N - 1) of the span). A function with more
  /// than 8 control points per scalar texel is first resampled at 8 per texel (detail the
  /// table cannot show), so the cost stays bounded whatever the point count.
  PreintegrationTable(const TransferFunction& tf, double sMin, double sMax, int scalarResolution, double maxLength,
                      int lengthResolution, int threads = 0);

  int scalarResolution() const { return ns_; }
  int lengthResolution() const { return nl_; }
  /// RGBA (premultiplied color, alpha) as floats, index [(l * Ns + sBack) * Ns + sFront].
  const std::vector<float>& values() const { return values_; }
  /// Where the scalar texels lie: a lookup maps each value through it first.
  const TableWarp& warp() const { return warp_; }
  /// Trilinear lookup (as the GPU sampler), for error studies.
  glm::dvec4 lookup(double sFront, double sBack, double length) const;

 private:
  int ns_, nl_;
  double sMin_, sMax_, maxLength_;
  TableWarp warp_;
  std::vector<float> values_;
};

}  // namespace volpost::optics

// SPDX-License-Identifier: MIT
// The optical depth of a ray segment over which the scalar goes linearly from s_front to
// s_back: length x the mean extinction over [s_front, s_back]. The extinction is piecewise
// linear in the scalar, so the mean is exact from the integrals of whole pieces between
// the control points crossed (running sums, kept as two floats on the GPU) and the two
// partial pieces at the ends; no difference of nearly equal values divides by a small one.
// The pre-integrated mode takes its opacity from it (exact, whatever the segment's
// length) and only the color from its table.
#pragma once

#include <volpost/core/TransferFunction.hpp>

#include <vector>

namespace volpost::optics {

class OpticalDepth {
 public:
  /// Control points as values (ascending, equal ones allowed) and their extinctions.
  OpticalDepth(std::vector<double> values, std::vector<double> extinctions);
  explicit OpticalDepth(const TransferFunction& tf);

  /// Optical depth of a segment of `length` over which the scalar goes linearly from
  /// sFront to sBack (either order); the extinction is clamped beyond the end points.
  double depth(double sFront, double sBack, double length) const;
  /// Extinction at s.
  double extinction(double s) const;
  /// Integral of the extinction over the scalar from the first control point to each one.
  const std::vector<double>& runningIntegrals() const { return integral_; }

 private:
  /// Extinction at s, given the index of the first control point above s.
  double extinctionAt(double s, std::size_t firstAbove) const;

  std::vector<double> value_, tau_, integral_;
};

}  // namespace volpost::optics

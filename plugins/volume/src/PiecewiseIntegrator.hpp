// SPDX-License-Identifier: MIT
// Exact integration of ray segments through a piecewise-linear transfer function, made for
// the inner loop of a renderer: the control points in flat arrays (no allocation per
// segment), and a test that answers "is the extinction zero over this whole value range?"
// in one lookup, so segments in the transparent part of the range cost nothing.
#pragma once

#include <volpost/core/TransferFunction.hpp>
#include <volpost/core/optics/SegmentIntegral.hpp>

#include <glm/vec2.hpp>

#include <vector>

namespace volpost::volume {

/// Shading of the emission at the two ends of a segment (multiplier of the color, white
/// added: volpost/core/optics/Headlight.hpp), interpolated linearly along it.
struct EmissionShade {
  glm::dvec2 front{1.0, 0.0}, back{1.0, 0.0};
};

/// Where the extinction is zero, for an empty-space test: for control points at `values`
/// (ascending) with extinctions `taus`, n + 1 entries: [0] for values below the first point,
/// [j + 1] for the piece from point j on (above the last for j = n - 1). Each is the value up
/// to which the extinction stays zero from anywhere in that piece, -inf where it is not zero
/// over the piece, +inf where it stays zero for ever.
std::vector<double> zeroExtinctionRuns(const std::vector<double>& values, const std::vector<double>& taus);

class PiecewiseIntegrator {
 public:
  explicit PiecewiseIntegrator(const TransferFunction& tf);

  /// True when the extinction is zero for every value between a and b: such a segment
  /// neither emits nor absorbs.
  bool transparent(double a, double b) const;

  /// The segment over which the scalar goes linearly from sFront to sBack: cut at every
  /// control point crossed, each piece integrated exactly (as integrateSegment).
  optics::SegmentLight integrate(double sFront, double sBack, double length, const EmissionShade* shade = nullptr) const;

 private:
  int pieceOf(double s) const;  ///< j with value[j] <= s < value[j + 1]; -1 below, n - 1 above
  void at(int piece, double s, glm::dvec3& color, double& tau) const;

  std::vector<double> values_, tau_;
  std::vector<double> inverseWidth_;  ///< per piece (0 for a step: two points at one value)
  std::vector<glm::dvec3> colors_;
  std::vector<double> zeroUntil_;  ///< per piece + 1: extinction is zero from there up to this value
};

}  // namespace volpost::volume

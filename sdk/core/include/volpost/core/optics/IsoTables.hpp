// SPDX-License-Identifier: MIT
// The 2D table of the GPU linear-segment integration (cut points), over
// (s_front, s_back) texels spanning [sMin, sMax] (texel i at i / (N - 1) of the span).
#pragma once

#include <volpost/core/TransferFunction.hpp>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <optional>
#include <vector>

namespace volpost::optics {

/// The scalar value of texel i of n spanning [sMin, sMax], and the texel nearest to s.
double texelValue(double sMin, double sMax, int n, int i);
int nearestTexel(double sMin, double sMax, int n, double s);
/// Values of `sorted` (ascending) met going from a toward b: beyond a (strictly), up to b
/// (inclusive), in the order met; at most `limit` of them (found by binary search).
std::vector<double> crossed(const std::vector<double>& sorted, double a, double b,
                            std::size_t limit = std::size_t(-1));
/// Throws std::invalid_argument unless n >= 2 and sMax > sMin.
void checkTableResolution(int n, double sMin, double sMax);

/// Espinha 2005, 4.2: for a segment from s_front to s_back, the first control point crossed
/// and the one after it, -1 where there is none (the seed cut the ray there and looked the
/// table up again from the cut; volpost's GPU modes take "none" from it, a segment that is
/// one exact piece, and walk the control points of the others). Looked up at the nearest texels
/// of s_front and s_back, an entry computed at the texel centres alone misses a point
/// that lies between a value and its texel's centre, and the piece is integrated across it
/// (a peak narrower than a few texels was lost: max error 0.68). So each entry covers its
/// texels' whole cells (half a texel each side, and 1/64 more for the sampler's rounding):
/// going up (front texel below back texel), the first two points above the front cell's
/// lower edge and below the back cell's upper edge; going down, the mirror image; on the
/// diagonal (one texel, either direction), the first two points in the cell going up.
/// Stored as two floats per texel, index [sBack * N + sFront], as positions in the range
/// ((s - sMin) / (sMax - sMin), in [0, 1]) so that -1 can only mean "none".
struct IsoDetectionTable {
  IsoDetectionTable(const TransferFunction& tf, double sMin, double sMax, int resolution);
  int resolution;
  double sMin, sMax;
  std::vector<float> values;
  /// The entry (as scalar values, -1 for none) at the texel nearest to (sFront, sBack).
  std::pair<double, double> at(double sFront, double sBack) const;
  /// Where a piece from s toward sBack is cut, from the entry alone: the first control
  /// point strictly between them, or sBack when there is none; nullopt where the entry
  /// cannot tell (several points in the front's cell, or one texel holding both ends with
  /// a point in it) and the control points must be searched.
  std::optional<double> cut(double s, double sBack) const;
};

/// An iso-surface: a value, its color and opacity (opaque = 1).
struct IsoSurface {
  double value;
  glm::dvec3 color;
  double opacity = 1.0;
};

}  // namespace volpost::optics

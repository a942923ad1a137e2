// SPDX-License-Identifier: MIT
// The 2D table of the GPU linear-segment integration (cut points), over
// (s_front, s_back) texels spanning [sMin, sMax] (texel i at i / (N - 1) of the span).
#pragma once

#include <volpost/core/TransferFunction.hpp>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

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
/// (s_iso) and the one after it (next_s_iso), -1 where there is none. The GPU cuts the ray
/// at s_iso, integrates the piece exactly, and looks the table up again from s_iso. A
/// point is "crossed" when it lies strictly beyond s_front and not beyond s_back.
/// Stored as two floats per texel, index [sBack * N + sFront], as positions in the range
/// ((s - sMin) / (sMax - sMin), in [0, 1]) so that -1 can only mean "none".
struct IsoDetectionTable {
  IsoDetectionTable(const TransferFunction& tf, double sMin, double sMax, int resolution);
  int resolution;
  double sMin, sMax;
  std::vector<float> values;
  /// The entry (as scalar values, -1 for none) at the texel nearest to (sFront, sBack).
  std::pair<double, double> at(double sFront, double sBack) const;
};

/// An iso-surface: a value, its color and opacity (opaque = 1).
struct IsoSurface {
  double value;
  glm::dvec3 color;
  double opacity = 1.0;
};

}  // namespace volpost::optics

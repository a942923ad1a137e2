// SPDX-License-Identifier: MIT
// The 2D tables of the GPU linear-segment integration and GPU iso-surfaces, over
// (s_front, s_back) texels spanning [sMin, sMax] (texel i at i / (N - 1) of the span).
#pragma once

#include <volpost/core/TransferFunction.hpp>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <vector>

namespace volpost::optics {

/// Seed 004, 4.2: for a segment from s_front to s_back, the first control point crossed
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

/// Roettger et al. 2000: for a segment from s_front to s_back, the color (premultiplied)
/// and opacity of the first iso-surface crossed, transparent where none is. RGBA floats,
/// index [sBack * N + sFront].
struct IsoSurfaceTable {
  IsoSurfaceTable(const std::vector<IsoSurface>& surfaces, double sMin, double sMax, int resolution);
  int resolution;
  double sMin, sMax;
  std::vector<float> values;
  glm::dvec4 at(double sFront, double sBack) const;
};

}  // namespace volpost::optics

// SPDX-License-Identifier: MIT
// The transfer function of the emission-absorption model: piecewise linear in the scalar.
//
// Convention: each control point carries a color C (linear RGB, 0..1) and an extinction
// coefficient tau >= 0 in 1 / model length unit. Along a ray, light is absorbed at rate tau
// and emitted as C * tau (so C is the color of a thick region). Between control points both
// C and tau are linear in the scalar. Every control point is an iso-value: the exact
// integration cuts rays where they cross one.
//
// Users often think in opacity: alpha = 1 - exp(-tau * L) is the opacity of a slab of
// thickness L of constant tau. opacityToExtinction / extinctionToOpacity convert both ways
// for a stated reference length L.
#pragma once

#include <glm/vec3.hpp>

#include <optional>
#include <string>
#include <vector>

namespace volpost {

/// Where extinctions go through float (the GPU's arithmetic, the 2D function's table), they
/// are capped here: opaque over any length a picture resolves (1e-10 units: an optical
/// depth of 1e10), while its products with lengths and running integrals stay finite
/// (float ends at 3.4e38; an extinction of 1e300 gave NaN pixels).
inline constexpr double kMaxFloatExtinction = 1e20;

struct ControlPoint {
  double value = 0.0;          ///< scalar value (the iso-value), in field units
  glm::dvec3 color{1.0};       ///< emitted color, linear RGB 0..1
  double extinction = 0.0;     ///< tau, 1 / model length unit, >= 0
  bool operator==(const ControlPoint&) const = default;
};

double opacityToExtinction(double opacity, double referenceLength);
double extinctionToOpacity(double extinction, double referenceLength);

class TransferFunction {
 public:
  /// More control points than anyone can edit; the bound keeps every per-point cost small.
  static constexpr std::size_t kMaxPoints = 65536;

  TransferFunction() = default;
  /// Points are sorted by value. Throws std::invalid_argument on negative extinction,
  /// non-finite numbers, colors outside 0..1 or more than kMaxPoints points.
  explicit TransferFunction(std::vector<ControlPoint> points);

  const std::vector<ControlPoint>& points() const { return points_; }
  bool empty() const { return points_.empty(); }
  double minValue() const { return points_.empty() ? 0.0 : points_.front().value; }
  double maxValue() const { return points_.empty() ? 0.0 : points_.back().value; }

  /// Below the first point and above the last, the end points hold (clamped).
  glm::dvec3 color(double s) const;
  double extinction(double s) const;

  /// True when the extinction is zero at every value from lo to hi (lo <= hi): a segment
  /// whose values stay there neither emits nor absorbs.
  bool transparentOver(double lo, double hi) const;

  /// The control-point values strictly between a and b, ordered from a toward b (a > b
  /// too). These are the places where exact integration cuts a segment.
  std::vector<double> crossings(double a, double b) const;

  /// A default for a field's range: a ramp of the named color map with extinction rising
  /// from 0 to `maxExtinction` (1 / length unit).
  static TransferFunction ramp(double min, double max, const std::string& colorMap, double maxExtinction,
                               int points = 9);

  /// volpost's own JSON: {"format":"volpost-tf","version":1,"lengthUnit":"mm",
  /// "points":[{"value":..,"color":[r,g,b],"extinction":..}, ...]}. Throws
  /// std::runtime_error naming the offending entry.
  static TransferFunction fromJson(const std::string& text);
  std::string toJson(const std::string& lengthUnit = "") const;

  /// A ParaView color-map preset (a JSON array of presets, or one preset object with
  /// "RGBPoints": [x, r, g, b, ...]). Colors come from the preset, mapped onto
  /// [min, max] if given; extinction is interpolated from this function's current points
  /// (or 0 if it has none). `presetName` picks one preset from an array (first if empty).
  TransferFunction withParaViewColors(const std::string& presetJson, const std::string& presetName = "",
                                      std::optional<std::pair<double, double>> range = std::nullopt) const;

  bool operator==(const TransferFunction&) const = default;

 private:
  std::vector<ControlPoint> points_;
};

}  // namespace volpost

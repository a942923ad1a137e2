// SPDX-License-Identifier: MIT
#include "VolumeDefaults.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace volpost::app {

TransferFunction defaultTransferFunction(const ScalarView& view, double modelDiagonal, const std::string& colorMap,
                                         std::optional<DisplayRange> range) {
  double lo = view.range.valid() ? view.range.min : 0.0;
  double hi = view.range.valid() && view.range.max > lo ? view.range.max : lo + 1.0;
  if (range) {
    lo = range->min;
    hi = range->max;
  }
  // Clear at the lowest value and dense where the result peaks: no fog over the whole model
  // (a floor of 10 % gave the lowest values a quarter of the opacity and veiled everything).
  // A signed result (a stress component, a pressure) peaks at both ends: dense at both,
  // clear at zero, so no shell of high values hides the lowest ones.
  const double tauMax = 24.0 / std::max(modelDiagonal, 1e-300);
  std::vector<ControlPoint> points = TransferFunction::ramp(lo, hi, colorMap, tauMax).points();
  const bool signedResult = lo < 0.0 && hi > 0.0;
  const double largest = std::max(-lo, hi);
  for (auto& p : points) {
    const double weight = signedResult ? std::abs(p.value) / largest : (p.value - lo) / (hi - lo);
    p.extinction = tauMax * weight;
  }
  if (signedResult) {  // a point at zero, so the clear middle is where the sign changes
    const glm::dvec3 zeroColor = ColorMap::named(colorMap).at(-lo / (hi - lo));
    points.push_back({0.0, zeroColor, 0.0});
    std::sort(points.begin(), points.end(), [](const ControlPoint& a, const ControlPoint& b) { return a.value < b.value; });
    points.erase(std::unique(points.begin(), points.end(),
                             [](const ControlPoint& a, const ControlPoint& b) { return a.value == b.value; }),
                 points.end());
  }
  return TransferFunction(std::move(points));
}

std::optional<std::string> transferFunctionRangeNote(const TransferFunction& tf, const ScalarView& view) {
  if (!view.range.valid() || tf.points().empty()) return std::nullopt;
  const double lo = view.range.min, hi = view.range.max;
  const double overlap = std::min(hi, tf.maxValue()) - std::max(lo, tf.minValue());
  const bool covered = hi > lo ? overlap >= 0.5 * (hi - lo) : (lo >= tf.minValue() && lo <= tf.maxValue());
  if (covered) return std::nullopt;
  const auto number = [](double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", v);
    return std::string(text);
  };
  const std::string what = overlap > 0.0 ? "covers less than half of it" : "misses it";
  return "the transfer function spans " + number(tf.minValue()) + " to " + number(tf.maxValue()) + " but " +
         view.quantity.displayName() + " spans " + number(lo) + " to " + number(hi) + ": it " + what +
         " (made for another result?)";
}

ColorMap colorMapOf(const TransferFunction& tf) {
  std::vector<ColorMap::Point> points;
  const double lo = tf.minValue(), span = tf.maxValue() > lo ? tf.maxValue() - lo : 1.0;
  for (const ControlPoint& p : tf.points()) points.push_back({(p.value - lo) / span, p.color});
  if (points.size() < 2) points = {{0.0, glm::dvec3(0.5)}, {1.0, glm::dvec3(0.5)}};
  return ColorMap("transfer function", points);
}

}  // namespace volpost::app

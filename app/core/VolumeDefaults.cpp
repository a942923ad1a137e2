// SPDX-License-Identifier: MIT
#include "VolumeDefaults.hpp"

#include <algorithm>

namespace volpost::app {

TransferFunction defaultTransferFunction(const ScalarView& view, double modelDiagonal, const std::string& colorMap,
                                         std::optional<DisplayRange> range) {
  double lo = view.range.valid() ? view.range.min : 0.0;
  double hi = view.range.valid() && view.range.max > lo ? view.range.max : lo + 1.0;
  if (range) {
    lo = range->min;
    hi = range->max;
  }
  // A thin fog everywhere (10%) so the part's shape shows, dense where the result peaks.
  const double tauMax = 24.0 / std::max(modelDiagonal, 1e-300);
  std::vector<ControlPoint> points = TransferFunction::ramp(lo, hi, colorMap, tauMax).points();
  for (auto& p : points) p.extinction = tauMax * (0.1 + 0.9 * (p.value - lo) / (hi - lo));
  return TransferFunction(std::move(points));
}

ColorMap colorMapOf(const TransferFunction& tf) {
  std::vector<ColorMap::Point> points;
  const double lo = tf.minValue(), span = tf.maxValue() > lo ? tf.maxValue() - lo : 1.0;
  for (const ControlPoint& p : tf.points()) points.push_back({(p.value - lo) / span, p.color});
  if (points.size() < 2) points = {{0.0, glm::dvec3(0.5)}, {1.0, glm::dvec3(0.5)}};
  return ColorMap("transfer function", points);
}

}  // namespace volpost::app

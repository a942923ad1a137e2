// SPDX-License-Identifier: MIT
#include "PiecewiseIntegrator.hpp"

#include <volpost/core/optics/QuickSegment.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace volpost::volume {

std::vector<double> zeroExtinctionRuns(const std::vector<double>& values, const std::vector<double>& taus) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  const std::size_t n = values.size();
  std::vector<double> until(n + 1, -inf);  // built from the top down
  if (n == 0) return until;
  until[n] = taus[n - 1] == 0.0 ? inf : -inf;  // above the last point
  for (std::size_t j = n - 1; j-- > 0;)
    if (taus[j] == 0.0 && taus[j + 1] == 0.0) until[j + 1] = std::max(values[j + 1], until[j + 2]);
  if (taus[0] == 0.0) until[0] = std::max(values[0], until[1]);  // below the first point
  return until;
}

PiecewiseIntegrator::PiecewiseIntegrator(const TransferFunction& tf) {
  for (const ControlPoint& p : tf.points()) {
    values_.push_back(p.value);
    colors_.push_back(p.color);
    tau_.push_back(p.extinction);
  }
  const int n = int(values_.size());
  for (int i = 0; i + 1 < n; ++i) {
    const double width = values_[std::size_t(i) + 1] - values_[std::size_t(i)];
    inverseWidth_.push_back(width > 0.0 ? 1.0 / width : 0.0);
  }
  zeroUntil_ = zeroExtinctionRuns(values_, tau_);
}

int PiecewiseIntegrator::pieceOf(double s) const {
  return int(std::upper_bound(values_.begin(), values_.end(), s) - values_.begin()) - 1;
}

bool PiecewiseIntegrator::transparent(double a, double b) const {
  if (values_.empty() || !std::isfinite(a) || !std::isfinite(b)) return true;
  const double lo = std::min(a, b), hi = std::max(a, b);
  return hi <= zeroUntil_[std::size_t(pieceOf(lo) + 1)];
}

void PiecewiseIntegrator::at(int piece, double s, glm::dvec3& color, double& tau) const {
  const int n = int(values_.size());
  if (piece < 0 || piece >= n - 1) {  // clamped outside the points
    const std::size_t i = piece < 0 ? 0 : std::size_t(n) - 1;
    color = colors_[i];
    tau = tau_[i];
    return;
  }
  const std::size_t i = std::size_t(piece);
  const double w = std::clamp((s - values_[i]) * inverseWidth_[i], 0.0, 1.0);
  color = colors_[i] + (colors_[i + 1] - colors_[i]) * w;
  tau = tau_[i] + (tau_[i + 1] - tau_[i]) * w;
}

optics::SegmentLight PiecewiseIntegrator::integrate(double sFront, double sBack, double length,
                                                   const EmissionShade* shade) const {
  optics::SegmentLight total;
  // The color at value x, shaded as interpolated along the segment.
  const auto lit = [&](glm::dvec3& c, double x) {
    if (!shade) return;
    const double w = sBack != sFront ? std::clamp((x - sFront) / (sBack - sFront), 0.0, 1.0) : 0.5;
    const glm::dvec2 k = shade->front + w * (shade->back - shade->front);
    c = c * k.x + glm::dvec3(k.y);
  };
  if (values_.empty() || !(length > 0.0)) return total;
  // A value that is no number (a sample beyond the renderer's float range) shows nothing;
  // it must not walk the control points for ever.
  if (!std::isfinite(sFront) || !std::isfinite(sBack)) return total;
  glm::dvec3 c0, c1;
  double t0, t1;
  const double lo = std::min(sFront, sBack), hi = std::max(sFront, sBack);
  const int low = pieceOf(lo);
  // Transparent over the whole range (zero extinction): nothing emitted, nothing absorbed.
  if (hi <= zeroUntil_[std::size_t(low + 1)]) return total;
  if (sFront == sBack) {
    at(low, sFront, c0, t0);
    lit(c0, sFront);
    return t0 > 0.0 ? optics::constantSegment(c0, t0, length) : total;
  }
  // No control point within the segment (most segments of a fine mesh): one linear piece.
  if (low + 1 < int(values_.size()) && hi < values_[std::size_t(low) + 1]) {
    at(low, sFront, c0, t0);
    at(low, sBack, c1, t1);
    lit(c0, sFront);
    lit(c1, sBack);
    return t0 > 0.0 || t1 > 0.0 ? optics::quickLinearSegment(c0, t0, c1, t1, length) : total;
  }
  int piece = sFront == lo ? low : pieceOf(sFront);
  const bool rising = sBack > sFront;
  const double perValue = length / std::abs(sBack - sFront);
  double x0 = sFront;
  // With a falling value, a point exactly at x0 belongs to the piece below.
  if (!rising && piece >= 0 && values_[std::size_t(piece)] == x0) --piece;
  at(piece, x0, c0, t0);
  lit(c0, x0);
  while (true) {
    // The next control point toward sBack, or sBack itself.
    double x1 = sBack;
    if (rising && piece + 1 < int(values_.size()) && values_[std::size_t(piece) + 1] < sBack) x1 = values_[std::size_t(piece) + 1];
    if (!rising && piece >= 0 && values_[std::size_t(piece)] > sBack) x1 = values_[std::size_t(piece)];
    at(piece, x1, c1, t1);
    lit(c1, x1);
    if (t0 > 0.0 || t1 > 0.0)
      optics::compositeBehind(total, optics::quickLinearSegment(c0, t0, c1, t1, std::abs(x1 - x0) * perValue));
    if (x1 == sBack) break;
    piece += rising ? 1 : -1;
    x0 = x1;
    at(piece, x0, c0, t0);
    lit(c0, x0);
  }
  return total;
}

}  // namespace volpost::volume

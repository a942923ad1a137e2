// SPDX-License-Identifier: MIT
#include <volpost/core/optics/TableWarp.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace volpost::optics {

TableWarp::TableWarp(const TransferFunction& tf, double sMin, double sMax, int texels) {
  if (!(sMax > sMin)) throw std::invalid_argument("a table's value range must not be empty");
  s_.push_back(sMin);
  for (const ControlPoint& p : tf.points())
    if (p.value > s_.back() && p.value < sMax) s_.push_back(p.value);
  s_.push_back(sMax);
  // A piece between two control points (not the constant ends outside the function).
  const double first = tf.empty() ? sMax : tf.minValue(), last = tf.empty() ? sMin : tf.maxValue();
  std::vector<bool> inner(s_.size() - 1);
  std::size_t innerCount = 0;
  for (std::size_t i = 0; i + 1 < s_.size(); ++i) innerCount += inner[i] = s_[i] >= first && s_[i + 1] <= last;
  u_.assign(s_.size(), 0.0);
  const double span = sMax - sMin;
  for (std::size_t i = 0; i + 1 < s_.size(); ++i) {
    const double byValue = (s_[i + 1] - s_[i]) / span;
    const double weight = innerCount ? 0.5 * byValue + (inner[i] ? 0.5 / double(innerCount) : 0.0) : byValue;
    u_[i + 1] = u_[i] + weight;
  }
  for (double& u : u_) u /= u_.back();
  u_.back() = 1.0;
  if (texels >= 2) snapToTexels(texels);
}

// Each inner knot to its nearest texel, at least one texel after the one before it and
// leaving one for each knot after it; the ends stay at 0 and 1.
void TableWarp::snapToTexels(int texels) {
  const long intervals = texels - 1, knots = long(u_.size());
  if (knots - 1 > intervals) return;  // more pieces than texels: left where they are
  long previous = 0;
  for (long k = 1; k + 1 < knots; ++k) {
    const long nearest = std::lround(u_[std::size_t(k)] * double(intervals));
    const long texel = std::clamp(nearest, previous + 1, intervals - (knots - 1 - k));
    u_[std::size_t(k)] = double(texel) / double(intervals);
    previous = texel;
  }
}

double TableWarp::toTable(double s) const {
  if (!(s > s_.front())) return 0.0;
  if (!(s < s_.back())) return 1.0;
  const std::size_t i = std::size_t(std::upper_bound(s_.begin(), s_.end(), s) - s_.begin()) - 1;
  return u_[i] + (u_[i + 1] - u_[i]) * (s - s_[i]) / (s_[i + 1] - s_[i]);
}

double TableWarp::fromTable(double u) const {
  if (!(u > 0.0)) return s_.front();
  if (!(u < 1.0)) return s_.back();
  const std::size_t i = std::size_t(std::upper_bound(u_.begin(), u_.end(), u) - u_.begin()) - 1;
  if (!(u_[i + 1] > u_[i])) return s_[i];
  return s_[i] + (s_[i + 1] - s_[i]) * (u - u_[i]) / (u_[i + 1] - u_[i]);
}

}  // namespace volpost::optics

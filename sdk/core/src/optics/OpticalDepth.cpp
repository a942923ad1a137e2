// SPDX-License-Identifier: MIT
#include <volpost/core/optics/OpticalDepth.hpp>

#include <algorithm>
#include <stdexcept>

namespace volpost::optics {

OpticalDepth::OpticalDepth(std::vector<double> values, std::vector<double> extinctions)
    : value_(std::move(values)), tau_(std::move(extinctions)) {
  if (value_.size() != tau_.size()) throw std::invalid_argument("optical depth: one extinction per value");
  if (!std::is_sorted(value_.begin(), value_.end()))
    throw std::invalid_argument("optical depth: control-point values must be ascending");
  integral_.assign(value_.size(), 0.0);
  for (std::size_t i = 1; i < value_.size(); ++i)
    integral_[i] = integral_[i - 1] + (value_[i] - value_[i - 1]) * 0.5 * (tau_[i - 1] + tau_[i]);
}

namespace {
std::vector<double> valuesOf(const TransferFunction& tf) {
  std::vector<double> v;
  for (const ControlPoint& p : tf.points()) v.push_back(p.value);
  return v;
}
std::vector<double> extinctionsOf(const TransferFunction& tf) {
  std::vector<double> v;
  for (const ControlPoint& p : tf.points()) v.push_back(p.extinction);
  return v;
}
}  // namespace

OpticalDepth::OpticalDepth(const TransferFunction& tf) : OpticalDepth(valuesOf(tf), extinctionsOf(tf)) {}

double OpticalDepth::extinctionAt(double s, std::size_t firstAbove) const {
  if (value_.empty()) return 0.0;
  if (firstAbove == 0) return tau_.front();
  if (firstAbove >= value_.size()) return tau_.back();
  const std::size_t i = firstAbove;
  const double w = (s - value_[i - 1]) / (value_[i] - value_[i - 1]);  // value_[i-1] <= s < value_[i]
  return tau_[i - 1] + w * (tau_[i] - tau_[i - 1]);
}

double OpticalDepth::extinction(double s) const {
  return extinctionAt(s, std::size_t(std::upper_bound(value_.begin(), value_.end(), s) - value_.begin()));
}

double OpticalDepth::depth(double sFront, double sBack, double length) const {
  const double a = std::min(sFront, sBack), b = std::max(sFront, sBack);
  const std::size_t above = std::size_t(std::upper_bound(value_.begin(), value_.end(), a) - value_.begin());
  const double tauA = extinctionAt(a, above);
  if (!(b > a)) return length * tauA;
  // Control points strictly inside (a, b): indices above .. notBelow - 1.
  const std::size_t notBelow = std::size_t(std::lower_bound(value_.begin(), value_.end(), b) - value_.begin());
  const double tauB = notBelow >= value_.size() ? (value_.empty() ? 0.0 : tau_.back()) : extinctionAt(b, notBelow);
  if (above >= notBelow) return length * 0.5 * (tauA + tauB);  // one linear piece: its middle
  const std::size_t first = above, last = notBelow - 1;
  const double span = b - a;
  const double head = (value_[first] - a) / span * 0.5 * (tauA + tau_[first]);
  const double whole = (integral_[last] - integral_[first]) / span;
  const double tail = (b - value_[last]) / span * 0.5 * (tau_[last] + tauB);
  return length * (head + whole + tail);
}

}  // namespace volpost::optics

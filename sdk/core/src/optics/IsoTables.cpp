// SPDX-License-Identifier: MIT
#include <volpost/core/optics/IsoTables.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace volpost::optics {

double texelValue(double sMin, double sMax, int n, int i) { return sMin + (sMax - sMin) * i / (n - 1); }

int nearestTexel(double sMin, double sMax, int n, double s) {
  return std::clamp(int(std::lround((s - sMin) / (sMax - sMin) * (n - 1))), 0, n - 1);
}

std::vector<double> crossed(const std::vector<double>& sorted, double a, double b, std::size_t limit) {
  std::vector<double> out;
  if (a < b) {
    for (auto it = std::upper_bound(sorted.begin(), sorted.end(), a); it != sorted.end() && *it <= b && out.size() < limit; ++it)
      out.push_back(*it);
  } else if (a > b) {
    auto it = std::lower_bound(sorted.begin(), sorted.end(), a);  // first >= a: the ones before are < a
    while (it != sorted.begin() && out.size() < limit) {
      --it;
      if (*it < b) break;
      out.push_back(*it);
    }
  }
  return out;
}

void checkTableResolution(int n, double sMin, double sMax) {
  if (n < 2 || !(sMax > sMin)) throw std::invalid_argument("iso table: resolution must be >= 2 and sMax > sMin");
}

IsoDetectionTable::IsoDetectionTable(const TransferFunction& tf, double lo, double hi, int n)
    : resolution(n), sMin(lo), sMax(hi), values(std::size_t(n) * std::size_t(n) * 2) {
  checkTableResolution(n, lo, hi);
  std::vector<double> points;
  for (const auto& p : tf.points())
    if (points.empty() || points.back() != p.value) points.push_back(p.value);
  const double reach = (0.5 + 1.0 / 64.0) * (hi - lo) / (n - 1);  // a texel's cell, and the sampler's rounding
  for (int b = 0; b < n; ++b)
    for (int f = 0; f < n; ++f) {
      const double cf = texelValue(lo, hi, n, f), cb = texelValue(lo, hi, n, b);
      // Points strictly inside the cells' span, in the order a segment meets them.
      std::vector<double> c = f <= b ? crossed(points, cf - reach, cb + reach, 3) : crossed(points, cf + reach, cb - reach, 3);
      if (!c.empty() && c.back() == (f <= b ? cb + reach : cb - reach)) c.pop_back();  // the far edge itself
      float* out = &values[(std::size_t(b) * std::size_t(n) + std::size_t(f)) * 2];
      out[0] = c.size() > 0 ? float((c[0] - lo) / (hi - lo)) : -1.0f;
      out[1] = c.size() > 1 ? float((c[1] - lo) / (hi - lo)) : -1.0f;
    }
}

std::pair<double, double> IsoDetectionTable::at(double sFront, double sBack) const {
  const int f = nearestTexel(sMin, sMax, resolution, sFront), b = nearestTexel(sMin, sMax, resolution, sBack);
  const float* v = &values[(std::size_t(b) * std::size_t(resolution) + std::size_t(f)) * 2];
  const auto toValue = [&](float t) { return t < 0.0f ? -1.0 : sMin + double(t) * (sMax - sMin); };
  return {toValue(v[0]), toValue(v[1])};
}

std::optional<double> IsoDetectionTable::cut(double s, double sBack) const {
  const int f = nearestTexel(sMin, sMax, resolution, s), b = nearestTexel(sMin, sMax, resolution, sBack);
  const auto [first, next] = at(s, sBack);
  if (first < 0.0 || s == sBack) return sBack;  // no point in the cells' span
  if (f == b) return std::nullopt;
  const bool up = sBack > s;
  const auto ahead = [&](double v) { return up ? v > s : v < s; };
  double v = first;
  if (!ahead(v)) {
    if (next < 0.0) return sBack;
    v = next;
    if (!ahead(v)) return std::nullopt;
  }
  return (up ? v < sBack : v > sBack) ? v : sBack;
}

}  // namespace volpost::optics

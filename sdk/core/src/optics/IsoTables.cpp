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
  for (int b = 0; b < n; ++b)
    for (int f = 0; f < n; ++f) {
      const auto c = crossed(points, texelValue(lo, hi, n, f), texelValue(lo, hi, n, b), 2);
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

}  // namespace volpost::optics

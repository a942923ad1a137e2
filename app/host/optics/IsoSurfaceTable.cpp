// SPDX-License-Identifier: MIT
#include "host/optics/IsoSurfaceTable.hpp"

#include <algorithm>

namespace volpost::optics {

IsoSurfaceTable::IsoSurfaceTable(const std::vector<IsoSurface>& surfaces, double lo, double hi, int n)
    : resolution(n), sMin(lo), sMax(hi), values(std::size_t(n) * std::size_t(n) * 4) {
  checkTableResolution(n, lo, hi);
  std::vector<IsoSurface> sorted = surfaces;
  std::sort(sorted.begin(), sorted.end(), [](const auto& a, const auto& b) { return a.value < b.value; });
  std::vector<double> isoValues;
  for (const auto& s : sorted) isoValues.push_back(s.value);
  for (int b = 0; b < n; ++b)
    for (int f = 0; f < n; ++f) {
      const auto c = crossed(isoValues, texelValue(lo, hi, n, f), texelValue(lo, hi, n, b), 1);
      float* out = &values[(std::size_t(b) * std::size_t(n) + std::size_t(f)) * 4];
      if (c.empty()) {
        std::fill(out, out + 4, 0.0f);
        continue;
      }
      const auto& s = *std::find_if(sorted.begin(), sorted.end(), [&](const IsoSurface& x) { return x.value == c[0]; });
      for (int k = 0; k < 3; ++k) out[k] = float(s.color[k] * s.opacity);
      out[3] = float(s.opacity);
    }
}

glm::dvec4 IsoSurfaceTable::at(double sFront, double sBack) const {
  const int f = nearestTexel(sMin, sMax, resolution, sFront), b = nearestTexel(sMin, sMax, resolution, sBack);
  const float* v = &values[(std::size_t(b) * std::size_t(resolution) + std::size_t(f)) * 4];
  return {v[0], v[1], v[2], v[3]};
}

}  // namespace volpost::optics

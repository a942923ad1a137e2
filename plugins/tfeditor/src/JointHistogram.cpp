// SPDX-License-Identifier: MIT
#include "JointHistogram.hpp"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>

namespace volpost::tfeditor {

std::uint32_t JointHistogram::largest() const {
  return counts.empty() ? 0 : *std::max_element(counts.begin(), counts.end());
}

JointHistogram JointHistogram::ofGrid(const RegularGrid& grid, SampleView values, int valueBins,
                                      int gradientBins) {
  JointHistogram h;
  h.valueBins = valueBins;
  h.gradientBins = gradientBins;
  h.counts.assign(std::size_t(valueBins) * std::size_t(gradientBins), 0);
  if (values.size() != grid.pointCount() || values.empty()) return h;
  const auto [nx, ny, nz] = grid.dims;
  const std::size_t stride =
      std::max<std::size_t>(1, std::size_t(std::ceil(std::cbrt(double(grid.pointCount()) / 8e6))));
  const glm::dmat3 gradientToWorld = glm::transpose(glm::inverse(grid.indexToWorld()));
  const auto at = [&](std::size_t i, std::size_t j, std::size_t k) { return values[grid.pointIndex(i, j, k)]; };
  // d value / d index along one axis: central inside, one-sided on the faces.
  const auto derivative = [&](std::size_t i, std::size_t j, std::size_t k, int axis) {
    std::size_t n = grid.dims[std::size_t(axis)], x = axis == 0 ? i : axis == 1 ? j : k;
    if (n < 2) return 0.0;
    const std::size_t lo = x > 0 ? x - 1 : x, hi = x + 1 < n ? x + 1 : x;
    const auto shifted = [&](std::size_t to) {
      return axis == 0 ? at(to, j, k) : axis == 1 ? at(i, to, k) : at(i, j, to);
    };
    return (shifted(hi) - shifted(lo)) / double(hi - lo);
  };
  std::vector<float> sampleValue, sampleGradient;
  for (std::size_t k = 0; k < nz; k += stride)
    for (std::size_t j = 0; j < ny; j += stride)
      for (std::size_t i = 0; i < nx; i += stride) {
        const double v = at(i, j, k);
        const double g = glm::length(gradientToWorld * glm::dvec3(derivative(i, j, k, 0), derivative(i, j, k, 1),
                                                                  derivative(i, j, k, 2)));
        if (!std::isfinite(v) || !std::isfinite(g)) continue;
        sampleValue.push_back(float(v));
        sampleGradient.push_back(float(g));
      }
  if (sampleValue.empty()) return h;
  const auto [lo, hi] = std::minmax_element(sampleValue.begin(), sampleValue.end());
  h.valueLow = *lo;
  h.valueHigh = *hi > *lo ? double(*hi) : double(*lo) + 1.0;
  std::vector<float> sorted = sampleGradient;
  const std::size_t q = std::min(sorted.size() - 1, std::size_t(0.995 * double(sorted.size())));
  std::nth_element(sorted.begin(), sorted.begin() + std::ptrdiff_t(q), sorted.end());
  h.gradientHigh = sorted[q] > 0.0f ? double(sorted[q]) : 1.0;
  for (std::size_t s = 0; s < sampleValue.size(); ++s) {
    const int v = std::clamp(int((sampleValue[s] - h.valueLow) / (h.valueHigh - h.valueLow) * valueBins), 0, valueBins - 1);
    const double gx = sampleGradient[s] / h.gradientHigh * gradientBins;
    if (gx > double(gradientBins)) continue;  // above the shown range
    ++h.counts[std::size_t(std::min(int(gx), gradientBins - 1)) * std::size_t(valueBins) + std::size_t(v)];
  }
  return h;
}

}  // namespace volpost::tfeditor

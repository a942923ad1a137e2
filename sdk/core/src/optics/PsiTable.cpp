// SPDX-License-Identifier: MIT
#include <volpost/core/optics/PsiTable.hpp>

#include <volpost/core/optics/SegmentIntegral.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace volpost::optics {

PsiTable::PsiTable(int resolution) : n_(resolution), values_(std::size_t(resolution) * std::size_t(resolution)) {
  if (resolution < 2) throw std::invalid_argument("psi table resolution must be >= 2");
  for (int b = 0; b < n_; ++b)
    for (int f = 0; f < n_; ++f)
      values_[std::size_t(b) * std::size_t(n_) + std::size_t(f)] =
          float(psi(depthOf(gammaOfTexel(f)), depthOf(gammaOfTexel(b))));
}

double PsiTable::gammaOfTexel(int i) const {
  return std::min(double(i) / (n_ - 1), 1.0 - 0.25 / n_);
}

double PsiTable::lookup(double tf, double tb) const {
  const auto coord = [&](double t, int& i0, double& w) {
    const double x = std::clamp(gammaOf(t), 0.0, 1.0) * (n_ - 1);
    i0 = std::min(int(x), n_ - 2);
    w = x - i0;
  };
  int f0, b0;
  double wf, wb;
  coord(tf, f0, wf);
  coord(tb, b0, wb);
  const auto at = [&](int f, int b) { return double(values_[std::size_t(b) * std::size_t(n_) + std::size_t(f)]); };
  return (1 - wb) * ((1 - wf) * at(f0, b0) + wf * at(f0 + 1, b0)) + wb * ((1 - wf) * at(f0, b0 + 1) + wf * at(f0 + 1, b0 + 1));
}

}  // namespace volpost::optics

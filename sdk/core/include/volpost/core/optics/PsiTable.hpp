// SPDX-License-Identifier: MIT
// psi tabulated for the GPU: an N x N float table over gamma = t / (t + 1) in [0, 1) for
// the front and back optical depths (Moreland & Angel). Independent of the transfer
// function: built once.
#pragma once

#include <vector>

namespace volpost::optics {

class PsiTable {
 public:
  explicit PsiTable(int resolution);
  int resolution() const { return n_; }
  /// Row-major, index [gammaBack * N + gammaFront]; texel i holds gamma = i / (N - 1),
  /// clamped below 1 (the last texel is at gamma = 1 - 1/(4N), t = 4N - 1).
  const std::vector<float>& values() const { return values_; }
  /// Bilinear lookup as a GPU sampler would do it (texel-centre mapping), for error studies.
  double lookup(double tf, double tb) const;

  static double gammaOf(double t) { return t / (t + 1.0); }
  static double depthOf(double gamma) { return gamma / (1.0 - gamma); }

 private:
  double gammaOfTexel(int i) const;
  int n_;
  std::vector<float> values_;
};

}  // namespace volpost::optics

// SPDX-License-Identifier: MIT
// psi of optically thick pieces (depth E = (tf + tb) / 2 > kMinDepth) from two functions of
// one variable, for the GPU. With d = (tb - tf) / 2 and r = sqrt(|d|), completing the square
// in psi = int_0^1 exp(-(tf x + d x^2)) dx gives
//   psi = F(tf / 2r) / r - exp(-E) F(tb / 2r) / r,
// F = sqrt(pi)/2 erfcx where the back is thicker (d > 0), Dawson's integral where the front
// is (d < 0). Where E > 1 the second term is below 0.37 of the first: no cancellation. F
// is tabulated over y = u / (u + 1), u <= kTableEnd, as F(u) (1 + u) (bounded and smooth);
// beyond, its asymptotic series (error ~ 2 / u^8 relative). A 2D table over (tf, tb)
// cannot follow psi where one end is transparent and the other opaque (the 512^2 table
// was 4e-4 off at E = 30-100 and 0.02 beyond); this is 1e-6 off at any E > 1.
#pragma once

#include <vector>

namespace volpost::optics {

class ThickPsiTable {
 public:
  static constexpr double kMinDepth = 1.0;  ///< used where (tf + tb) / 2 exceeds this
  static constexpr double kTableEnd = 50.0;  ///< largest u tabulated; the series beyond

  explicit ThickPsiTable(int resolution = 1024);
  int resolution() const { return n_; }
  /// Interleaved pairs (erfcx, Dawson) x (1 + u): texel i at y = i / (N - 1) * yEnd().
  const std::vector<float>& values() const { return values_; }
  static double yEnd() { return kTableEnd / (kTableEnd + 1.0); }

  /// psi as the shader computes it (the float table, interpolated linearly), for tests.
  double psi(double tf, double tb) const;

  /// The two functions, in double (the table's source).
  static double halfSqrtPiErfcx(double u);
  static double dawson(double u);

 private:
  double f(bool frontThicker, double t, double r) const;  // F(t / 2r) / r
  int n_;
  std::vector<float> values_;
};

}  // namespace volpost::optics

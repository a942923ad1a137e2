// SPDX-License-Identifier: MIT
// The exact integral of a segment with linear color and extinction (SegmentIntegral.hpp),
// made cheap for a renderer's inner loop: most pieces of a fine mesh are optically thin,
// and for them psi and the transmittance come from short series instead of quadrature and
// the library's exp. Inline, because a ray caster calls it once per tet it crosses: a call
// into the library and a returned struct cost as much as the series.
#pragma once

#include <volpost/core/optics/SegmentIntegral.hpp>

#include <algorithm>
#include <cmath>

namespace volpost::optics {

namespace quick_segment_detail {

// psi for optically thin pieces (E = (tf + tb) / 2 <= kThinDepth), from the series
//   psi = sum_k (-1)^k / k! integral_0^1 (a x + d x^2)^k dx,  a = tf, d = (tb - tf) / 2,
// cut after k = 8: since 0 <= a x + d x^2 <= E, the rest is below E^9 / 9! = 5.4e-9 at
// E = 0.5. Most pieces of a fine mesh are this thin; thicker ones (at most ~20 per ray
// before it stops) take the exact quadrature of psi. (Series up to E = 1, order 12, were
// no faster than that quadrature on the wheel, where thick pieces are common.)
inline constexpr int kOrder = 8;
inline constexpr double kThinDepth = 0.5;

struct SeriesCoefficients {
  double c[kOrder + 1][kOrder + 1] = {};  // c[k][j] multiplies a^(k-j) d^j
  constexpr SeriesCoefficients() {
    double factorial = 1.0;
    for (int k = 0; k <= kOrder; ++k) {
      if (k > 0) factorial *= k;
      double binomial = 1.0;
      for (int j = 0; j <= k; ++j) {
        c[k][j] = (k % 2 ? -1.0 : 1.0) / factorial * binomial / (k + j + 1);
        binomial = binomial * (k - j) / (j + 1);
      }
    }
  }
};
inline constexpr SeriesCoefficients kSeries;

// sum_j d^j sum_{k >= j} c[k][j] a^(k - j), each inner sum by Horner, up to `order`.
template <int order>
inline double series(double a, double d) {
  double sum = 0.0;
  // Unrolled: the coefficients become constants in the code (the loops as loops cost
  // twice the arithmetic).
#pragma GCC unroll 16
  for (int j = order; j >= 0; --j) {
    double inner = 0.0;
#pragma GCC unroll 16
    for (int k = order; k >= j; --k) inner = inner * a + kSeries.c[k][j];
    sum = sum * d + inner;
  }
  return sum;
}

// exp(-x) by its Taylor polynomial of degree `degree`, by Horner: the rest is below
// x^(degree + 1) / (degree + 1)!.
// (multiplied by 1/k from a table: a division per term would cost more than exp itself)
inline constexpr double kInverse[] = {0.0,       1.0,       1.0 / 2.0, 1.0 / 3.0, 1.0 / 4.0, 1.0 / 5.0,
                                      1.0 / 6.0, 1.0 / 7.0, 1.0 / 8.0, 1.0 / 9.0, 1.0 / 10.0};
template <int degree>
inline double expSeries(double x) {
  static_assert(degree < int(sizeof kInverse / sizeof kInverse[0]));
  double sum = 1.0;
#pragma GCC unroll 16
  for (int k = degree; k >= 1; --k) sum = 1.0 - x * sum * kInverse[k];
  return sum;
}

// psi and the transmittance exp(-E) of a thin piece, the orders following the depth E:
// psi's rest below E^(K+1) / (K+1)! <= 5.6e-9, the transmittance's two orders further
// (below 1.2e-11: it multiplies everything behind the piece).
inline void thinPiece(double a, double d, double& psiValue, double& transmittance) {
  const double depth = a + d;
  if (depth <= 0.01) psiValue = series<3>(a, d), transmittance = expSeries<5>(depth);       // 4e-10
  else if (depth <= 0.1) psiValue = series<5>(a, d), transmittance = expSeries<7>(depth);   // 1.4e-9
  else if (depth <= 0.2) psiValue = series<6>(a, d), transmittance = expSeries<8>(depth);   // 2.5e-9
  else if (depth <= 0.35) psiValue = series<7>(a, d), transmittance = expSeries<9>(depth);  // 5.6e-9
  else psiValue = series<kOrder>(a, d), transmittance = expSeries<kOrder + 2>(depth);       // 5.4e-9 at 0.5
}

}  // namespace quick_segment_detail

/// psi(tf, tb) for a thin piece, (tf + tb) / 2 <= 0.5, from its series (order 3 to 8 as the
/// depth needs), within 6e-9 of psi.
inline double thinPsi(double tf, double tb) {
  double p, z;
  quick_segment_detail::thinPiece(tf, 0.5 * (tb - tf), p, z);
  return p;
}

/// As linearSegment, with psi from thinPsi and the transmittance from its series where the
/// piece is thin (optical depth <= 0.5), psi from quadrature otherwise: within 6e-9 of it.
inline SegmentLight quickLinearSegment(const glm::dvec3& colorFront, double tauFront, const glm::dvec3& colorBack,
                                       double tauBack, double length) {
  const double tf = tauFront * length, tb = tauBack * length;
  const double depth = 0.5 * (tf + tb);
  double p, z;
  if (depth <= quick_segment_detail::kThinDepth) {
    quick_segment_detail::thinPiece(tf, 0.5 * (tb - tf), p, z);
  } else {
    z = std::exp(-depth);
    p = psi(tf, tb);
  }
  const double wBack = std::max(p - z, 0.0), wFront = std::max(1.0 - p, 0.0);
  return {colorBack * wBack + colorFront * wFront, z};
}

}  // namespace volpost::optics

// SPDX-License-Identifier: MIT
// An independent high-precision reference: adaptive Gauss-Legendre quadrature in 113-bit
// __float128 (libquadmath), nodes computed by Newton iteration at that precision.
#pragma once

#include <quadmath.h>

#include <array>
#include <cmath>
#include <functional>

namespace volpost::test {

using quad = __float128;

template <int N>
struct QuadGaussLegendre {
  std::array<quad, N> x{}, w{};
  QuadGaussLegendre() {
    for (int i = 0; i < N; ++i) {
      quad z = cosq(acosq(quad(-1)) * (i + quad(0.75)) / (N + quad(0.5)));
      for (int it = 0; it < 100; ++it) {
        quad p0 = 1, p1 = z;
        for (int k = 2; k <= N; ++k) {
          const quad p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
          p0 = p1;
          p1 = p2;
        }
        const quad dp = N * (z * p1 - p0) / (z * z - 1);
        const quad dz = p1 / dp;
        z -= dz;
        if (fabsq(dz) < quad(1e-33)) {
          x[std::size_t(i)] = z;
          w[std::size_t(i)] = 2 / ((1 - z * z) * dp * dp);
          break;
        }
      }
    }
  }
  quad integrate(const std::function<quad(quad)>& f, quad a, quad b) const {
    const quad h = (b - a) / 2, m = (a + b) / 2;
    quad s = 0;
    for (int i = 0; i < N; ++i) s += w[std::size_t(i)] * f(m + h * x[std::size_t(i)]);
    return s * h;
  }
};

/// Adaptive: bisects until a 20-point and a 30-point rule agree to `tolerance` relative to
/// the running total.
inline quad adaptiveIntegral(const std::function<quad(quad)>& f, quad a, quad b, quad tolerance = quad(1e-22),
                             int depth = 0) {
  static const QuadGaussLegendre<20> g20;
  static const QuadGaussLegendre<30> g30;
  const quad coarse = g20.integrate(f, a, b), fine = g30.integrate(f, a, b);
  if (fabsq(fine - coarse) <= tolerance * fabsq(fine) || depth > 60) return fine;
  const quad m = (a + b) / 2;
  return adaptiveIntegral(f, a, m, tolerance, depth + 1) + adaptiveIntegral(f, m, b, tolerance, depth + 1);
}

/// psi(tf, tb) in quad precision.
inline quad psiReference(double tf, double tb) {
  const quad a = tf, d = (quad(tb) - quad(tf)) / 2;
  return adaptiveIntegral([&](quad x) { return expq(-(a * x + d * x * x)); }, 0, 1);
}

}  // namespace volpost::test

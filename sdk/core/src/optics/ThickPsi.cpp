// SPDX-License-Identifier: MIT
#include <volpost/core/optics/ThickPsi.hpp>

#include <volpost/core/optics/SegmentIntegral.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace volpost::optics {
namespace {

// 1/(2u) (1 -+ q + 3 q^2 -+ 15 q^3 + 105 q^4), q = 1 / (2 u^2): both functions' asymptotic
// series (erfcx alternating, Dawson's all positive); at u = 25 the next term is 1e-13.
double asymptotic(double u, double sign) {
  const double q = 1.0 / (2.0 * u * u);
  return (1.0 + sign * q + 3.0 * q * q + sign * 15.0 * q * q * q + 105.0 * q * q * q * q) / (2.0 * u);
}

}  // namespace

double ThickPsiTable::halfSqrtPiErfcx(double u) {
  // exp(u^2) erfc(u) holds in double up to u = 25 (exp(625) = 1e271); the series beyond.
  return u <= 25.0 ? 0.5 * std::sqrt(M_PI) * std::exp(u * u) * std::erfc(u) : asymptotic(u, -1.0);
}

// D(u) = exp(-u^2) int_0^u exp(t^2) dt = u psi(2 u^2, 0), psi by its exact quadrature.
double ThickPsiTable::dawson(double u) { return u == 0.0 ? 0.0 : u * optics::psi(2.0 * u * u, 0.0); }

ThickPsiTable::ThickPsiTable(int resolution) : n_(resolution), values_(2 * std::size_t(std::max(resolution, 0))) {
  if (resolution < 2) throw std::invalid_argument("thick-piece psi table resolution must be >= 2");
  for (int i = 0; i < n_; ++i) {
    const double y = yEnd() * double(i) / double(n_ - 1), u = y / (1.0 - y);
    values_[2 * std::size_t(i)] = float(halfSqrtPiErfcx(u) * (1.0 + u));
    values_[2 * std::size_t(i) + 1] = float(dawson(u) * (1.0 + u));
  }
}

double ThickPsiTable::f(bool frontThicker, double t, double r) const {
  const double u = t / (2.0 * r);
  if (u > kTableEnd) {  // 1/(2u r) = 1/t: no division by a vanishing r
    const double q = r * r / (t * t) * 2.0;  // 1 / (2 u^2)
    return (1.0 + (frontThicker ? q : -q) + 3.0 * q * q) / t;
  }
  const double x = u / (1.0 + u) / yEnd() * double(n_ - 1);
  const int i = std::min(int(x), n_ - 2);
  const double w = x - double(i);
  const std::size_t channel = frontThicker ? 1 : 0;
  const double g = double(values_[2 * std::size_t(i) + channel]) * (1.0 - w) + double(values_[2 * std::size_t(i + 1) + channel]) * w;
  return g / (1.0 + u) / r;
}

double ThickPsiTable::psi(double tf, double tb) const {
  const double d = 0.5 * (tb - tf);
  if (d == 0.0) return -std::expm1(-tf) / tf;
  const double r = std::sqrt(std::abs(d));
  return f(d < 0.0, tf, r) - std::exp(-0.5 * (tf + tb)) * f(d < 0.0, tb, r);
}

}  // namespace volpost::optics

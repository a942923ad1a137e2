// SPDX-License-Identifier: MIT
#include <volpost/core/optics/QuickSegment.hpp>
#include <volpost/core/optics/SegmentIntegral.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace volpost::optics {
namespace {

// 10-point Gauss-Legendre on [-1, 1] (nodes and weights to 17 digits).
constexpr std::array<double, 5> kNodes = {0.1488743389816312108848260, 0.4333953941292471907992659,
                                          0.6794095682990244062343274, 0.8650633666889845107320967,
                                          0.9739065285171717200779640};
constexpr std::array<double, 5> kWeights = {0.2955242247147528701738930, 0.2692667193099963550912269,
                                            0.2190863625159820439955349, 0.1494513491505805931457763,
                                            0.0666713443086881375935688};

// A panel spans at most this optical depth, and its steepest rate times its width stays
// below it too: 10-point Gauss-Legendre then integrates exp(-E) to ~1e-16.
constexpr double kPanelDepth = 4.0;
constexpr double kCutDepth = 40.0;   // exp(-40) = 4e-18: the rest of the integral is below 1 ulp

// x in [0, 1] where the optical depth E(x) = tf x + d x^2 reaches e (E is increasing).
double depthToX(double tf, double d, double e) {
  const double disc = tf * tf + 4.0 * d * e;
  return 2.0 * e / (tf + std::sqrt(std::max(disc, 0.0)));
}

double glPanel(double tf, double d, double a, double b) {
  const double half = 0.5 * (b - a), mid = 0.5 * (a + b);
  double sum = 0.0;
  for (std::size_t i = 0; i < kNodes.size(); ++i)
    for (double x : {mid - half * kNodes[i], mid + half * kNodes[i]}) sum += kWeights[i] * std::exp(-(tf + d * x) * x);
  return sum * half;
}

}  // namespace

double zeta(double tf, double tb) { return std::exp(-0.5 * (tf + tb)); }

double psi(double tf, double tb) {
  tf = std::max(tf, 0.0);
  tb = std::max(tb, 0.0);
  if (tf == tb) return tf == 0.0 ? 1.0 : -std::expm1(-tf) / tf;
  const double d = 0.5 * (tb - tf);
  const double total = 0.5 * (tf + tb);  // E(1)
  // Thin segments: the series QuickSegment.hpp also uses, cut after k = 8, whose rest is
  // below 0.1^9 / 9! = 3e-15 here.
  if (total <= 0.1) return quick_segment_detail::series<quick_segment_detail::kOrder>(tf, d);
  const double depth = std::min(total, kCutDepth);
  const double end = total <= kCutDepth ? 1.0 : depthToX(tf, d, kCutDepth);
  const int panels = std::max(1, int(std::ceil(depth / kPanelDepth)));
  double sum = 0.0, a = 0.0;
  for (int k = 1; k <= panels; ++k) {
    const double b = k == panels ? end : depthToX(tf, d, depth * k / panels);
    // Where tau falls toward the back, the front of a panel is steeper than its depth says.
    const double rate = std::max(tf + 2.0 * d * a, tf + 2.0 * d * b) * (b - a);
    const int parts = std::max(1, int(std::ceil(rate / kPanelDepth)));
    for (int j = 0; j < parts; ++j) sum += glPanel(tf, d, a + (b - a) * j / parts, a + (b - a) * (j + 1) / parts);
    a = b;
  }
  return sum;
}

SegmentLight linearSegment(const glm::dvec3& colorFront, double tauFront, const glm::dvec3& colorBack, double tauBack,
                           double length) {
  const double tf = tauFront * length, tb = tauBack * length;
  const double z = zeta(tf, tb), p = psi(tf, tb);
  // psi >= zeta and psi <= 1 hold mathematically; clamp the last ulp of rounding.
  const double wBack = std::max(p - z, 0.0), wFront = std::max(1.0 - p, 0.0);
  return {colorBack * wBack + colorFront * wFront, z};
}

SegmentLight constantSegment(const glm::dvec3& color, double tau, double length) {
  const double alpha = -std::expm1(-tau * length);
  return {color * alpha, 1.0 - alpha};
}

TransferSample sampleSide(const TransferFunction& tf, double s, bool fromBelow) {
  const auto& p = tf.points();
  if (p.empty()) return {};
  // The pair of points around s on that side: lo.value < s <= hi.value from below,
  // lo.value <= s < hi.value from above.
  const auto hi = fromBelow ? std::lower_bound(p.begin(), p.end(), s, [](const ControlPoint& q, double v) { return q.value < v; })
                            : std::upper_bound(p.begin(), p.end(), s, [](double v, const ControlPoint& q) { return v < q.value; });
  if (hi == p.begin()) return {p.front().color, p.front().extinction};
  if (hi == p.end()) return {p.back().color, p.back().extinction};
  const auto lo = hi - 1;
  const double w = (s - lo->value) / (hi->value - lo->value);
  return {lo->color + w * (hi->color - lo->color), lo->extinction + w * (hi->extinction - lo->extinction)};
}

SegmentLight integrateSegment(const TransferFunction& tf, double sFront, double sBack, double length) {
  SegmentLight total;
  if (!(length > 0.0) || tf.empty()) return total;
  if (sFront == sBack) return constantSegment(tf.color(sFront), tf.extinction(sFront), length);
  const bool rising = sBack > sFront;
  double s0 = sFront, x0 = 0.0;
  const auto pieceTo = [&](double s1, double x1) {
    const double len = (x1 - x0) * length;
    if (len > 0.0) {
      const TransferSample a = sampleSide(tf, s0, !rising), b = sampleSide(tf, s1, rising);
      compositeBehind(total, linearSegment(a.color, a.extinction, b.color, b.extinction, len));
    }
    s0 = s1;
    x0 = x1;
  };
  for (double cut : tf.crossings(sFront, sBack)) pieceTo(cut, (cut - sFront) / (sBack - sFront));
  pieceTo(sBack, 1.0);
  return total;
}

}  // namespace volpost::optics

// SPDX-License-Identifier: MIT
#include <volpost/core/optics/PolynomialSegment.hpp>

#include <volpost/core/optics/Headlight.hpp>
#include <volpost/core/optics/QuickSegment.hpp>
#include <volpost/core/optics/SegmentIntegral.hpp>

#include <glm/common.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

namespace volpost::optics {
namespace {

constexpr int kGaussPoints = 16;
constexpr double kPanelDepth = 0.1;  // optical depth per quadrature panel
constexpr double kDark = 1e-20;      // transmittance below which nothing behind is seen

struct GaussLegendre {
  std::array<double, kGaussPoints> x{}, w{};
};

// Nodes and weights on [-1, 1] by Newton's method on the Legendre polynomial, once.
const GaussLegendre& gaussLegendre() {
  static const GaussLegendre rule = [] {
    GaussLegendre g;
    const int n = kGaussPoints;
    for (int i = 0; i < n; ++i) {
      double x = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5)), dp = 1.0;
      for (int iteration = 0; iteration < 100; ++iteration) {
        double p0 = 1.0, p1 = x;
        for (int k = 2; k <= n; ++k) {
          const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
          p0 = p1;
          p1 = p2;
        }
        dp = n * (x * p1 - p0) / (x * x - 1.0);
        const double step = p1 / dp;
        x -= step;
        if (std::abs(step) < 1e-16) break;
      }
      g.x[std::size_t(i)] = x;
      g.w[std::size_t(i)] = 2.0 / ((1.0 - x * x) * dp * dp);
    }
    return g;
  }();
  return rule;
}

// The value where a monotone p reaches `target` in [a, b] (p(a) and p(b) on either side):
// Newton steps kept inside a shrinking bracket, bisection where a step leaves it.
double solveMonotone(const ScalarPolynomial& p, const ScalarPolynomial& dp, double target, double a, double b) {
  double fa = p.at(a) - target;
  double x = 0.5 * (a + b);
  for (int iteration = 0; iteration < 200 && b - a > 1e-16 * (1.0 + std::abs(a) + std::abs(b)); ++iteration) {
    const double f = p.at(x) - target;
    if (f == 0.0) return x;
    if ((f < 0.0) == (fa < 0.0)) a = x, fa = f;
    else b = x;
    const double slope = dp.at(x);
    double next = slope != 0.0 ? x - f / slope : 0.5 * (a + b);
    if (!(next > a && next < b)) next = 0.5 * (a + b);
    if (next == x) break;
    x = next;
  }
  return x;
}

// The largest |p| on [ua, ub] (exact for degree <= 1, else bounded by its coefficients).
double largestOn(const ScalarPolynomial& p, double ua, double ub) {
  if (p.degree <= 1) return std::max(std::abs(p.at(ua)), std::abs(p.at(ub)));
  const double m = std::max(std::abs(ua), std::abs(ub));
  double bound = 0.0, power = 1.0;
  for (int k = 0; k <= p.degree; ++k, power *= m) bound += std::abs(p.c[std::size_t(k)]) * power;
  return bound;
}

// The monotone piece cut into linear pieces, each within delta of s (chords of a function
// with |s''| <= M2 over width h stray by at most M2 h^2 / 8), each lit in closed form.
SegmentLight chordPieces(const ScalarPolynomial& s, const ScalarPolynomial& curvature, double ua, double ub,
                         const TransferSample& a, const TransferSample& b, double s0, double s1, double delta,
                         double halfLength) {
  constexpr int kMostChords = 4096;
  const double bend = largestOn(curvature, ua, ub);
  const double wanted = (ub - ua) * std::sqrt(bend / (8.0 * delta));
  const int n = std::clamp(int(std::ceil(std::min(wanted, double(kMostChords)))), 1, kMostChords);
  const double step = (ub - ua) / n, inverseRange = 1.0 / (s1 - s0);
  const auto sample = [&](double value) {
    const double w = std::clamp((value - s0) * inverseRange, 0.0, 1.0);
    return TransferSample{a.color + w * (b.color - a.color), a.extinction + w * (b.extinction - a.extinction)};
  };
  SegmentLight light;
  TransferSample front = a;
  for (int i = 1; i <= n && light.transmittance >= kDark; ++i) {
    const TransferSample back = i == n ? b : sample(s.at(ua + i * step));
    compositeBehind(light,
                    quickLinearSegment(front.color, front.extinction, back.color, back.extinction, step * halfLength));
    front = back;
  }
  return light;
}

// A stretch where the scalar goes monotonically from s0 to s1 and no control point lies
// strictly between them: extinction and color are linear in the scalar. To rounding, or in
// chords within the accuracy's tolerance.
SegmentLight monotonePiece(const TransferFunction& tf, const ScalarPolynomial& s, const ScalarPolynomial& integral,
                           const ScalarPolynomial& curvature, double ua, double ub, double s0, double s1,
                           double halfLength, const EmissionAccuracy& accuracy) {
  if (!(ub > ua)) return {};
  const double length = (ub - ua) * halfLength;
  if (s0 == s1) return constantSegment(tf.color(s0), tf.extinction(s0), length);
  const bool rising = s1 > s0;
  const TransferSample a = sampleSide(tf, s0, !rising), b = sampleSide(tf, s1, rising);
  if (a.extinction == 0.0 && b.extinction == 0.0) return {glm::dvec3(0.0), 1.0};  // transparent: nothing emitted
  const double slope = (b.extinction - a.extinction) / (s1 - s0);                 // extinction per unit scalar
  const double integralAtA = integral.at(ua);
  // Optical depth from ua: halfLength * integral of (a.extinction + slope (s(v) - s0)) dv.
  const auto depth = [&](double u) {
    return halfLength * (a.extinction * (u - ua) + slope * (integral.at(u) - integralAtA - s0 * (u - ua)));
  };
  const double total = std::max(0.0, depth(ub));
  SegmentLight light{glm::dvec3(0.0), std::exp(-total)};
  if (a.color == b.color) {  // the emission integrates to color * (1 - transmittance)
    light.color = a.color * (1.0 - light.transmittance);
    return light;
  }
  if (accuracy.tolerance > 0.0) {
    const double weight = pixelSensitivity(a, b, s1 - s0, accuracy.brightest);
    if (weight > 0.0) {
      const double share = 1.0 - light.transmittance + length / accuracy.rayLength;
      const double delta = 0.5 * accuracy.tolerance * share / (length * weight);
      return chordPieces(s, curvature, ua, ub, a, b, s0, s1, delta, halfLength);
    }
  }
  const GaussLegendre& g = gaussLegendre();
  const auto emitted = [&](double u) {
    const double w = std::clamp((s.at(u) - s0) / (s1 - s0), 0.0, 1.0);
    const glm::dvec3 color = a.color + w * (b.color - a.color);
    const double extinction = a.extinction + w * (b.extinction - a.extinction);
    return color * (extinction * std::exp(-std::max(0.0, depth(u))) * halfLength);
  };
  // Panels of optical depth <= kPanelDepth, split in half until they are.
  struct Panel {
    double u0, u1;
    int level;
  };
  // Depth first: at most one pending panel per level (48 levels), no allocation.
  std::array<Panel, 64> stack;
  std::size_t pending = 0;
  stack[pending++] = {ua, ub, 0};
  while (pending > 0) {
    const Panel p = stack[--pending];
    const double d0 = depth(p.u0);
    if (std::exp(-d0) < kDark) continue;  // nothing of it is seen
    if (depth(p.u1) - d0 > kPanelDepth && p.level < 48) {
      const double mid = 0.5 * (p.u0 + p.u1);
      stack[pending++] = {mid, p.u1, p.level + 1};
      stack[pending++] = {p.u0, mid, p.level + 1};
      continue;
    }
    const double centre = 0.5 * (p.u0 + p.u1), half = 0.5 * (p.u1 - p.u0);
    for (int i = 0; i < kGaussPoints; ++i)
      light.color += (g.w[std::size_t(i)] * half) * emitted(centre + half * g.x[std::size_t(i)]);
  }
  return light;
}

struct Cut {
  double u, s;
  const IsoSurface* surface;  ///< the iso-surface composited here, or none
};

}  // namespace

double pixelSensitivity(const TransferSample& a, const TransferSample& b, double valueSpan, double brightest) {
  const glm::dvec3 dColor = (b.color - a.color) / valueSpan;
  const double dTau = (b.extinction - a.extinction) / valueSpan;
  const glm::dvec3 atA = glm::abs(dTau * a.color + a.extinction * dColor);
  const glm::dvec3 atB = glm::abs(dTau * b.color + b.extinction * dColor);
  return std::max({atA.x, atA.y, atA.z, atB.x, atB.y, atB.z}) + brightest * std::abs(dTau);
}

double ScalarPolynomial::at(double u) const {
  double v = c[std::size_t(degree)];
  for (int k = degree - 1; k >= 0; --k) v = v * u + c[std::size_t(k)];
  return v;
}

ScalarPolynomial ScalarPolynomial::derivative() const {
  ScalarPolynomial d;
  d.degree = std::max(0, degree - 1);
  for (int k = 1; k <= degree; ++k) d.c[std::size_t(k - 1)] = k * c[std::size_t(k)];
  return d;
}

ScalarPolynomial ScalarPolynomial::antiderivative() const {
  ScalarPolynomial a;
  a.degree = std::min(degree + 1, int(a.c.size()) - 1);
  for (int k = 0; k < a.degree; ++k) a.c[std::size_t(k + 1)] = c[std::size_t(k)] / (k + 1);
  return a;
}

std::vector<double> zerosIn(const ScalarPolynomial& p, double a, double b) {
  std::vector<double> zeros;
  if (p.degree <= 0) return zeros;
  if (p.degree == 1) {
    if (p.c[1] != 0.0) {
      const double x = -p.c[0] / p.c[1];
      if (x > a && x < b) zeros.push_back(x);
    }
    return zeros;
  }
  // Between consecutive turning points p is monotone: at most one zero there.
  const ScalarPolynomial dp = p.derivative();
  // At most kMaxDegree + 1 turning points, and the two ends.
  std::array<double, ScalarPolynomial::kMaxDegree + 4> ends{};
  std::size_t count = 0;
  ends[count++] = a;
  for (double x : zerosIn(dp, a, b))
    if (count + 1 < ends.size()) ends[count++] = x;
  ends[count++] = b;
  // A value within rounding of zero at a turning point is a zero that touches (a double
  // root): taken there, not found again on either side.
  double size = 0.0;
  for (int k = 0; k <= p.degree; ++k) size += std::abs(p.c[std::size_t(k)]);
  const auto zeroish = [&](double f) { return std::abs(f) <= 8.0 * std::numeric_limits<double>::epsilon() * size; };
  for (std::size_t i = 0; i + 1 < count; ++i) {
    const double x0 = ends[i], x1 = ends[i + 1];
    const double f0 = p.at(x0), f1 = p.at(x1);
    const bool touches0 = i > 0 && zeroish(f0), touches1 = i + 2 < count && zeroish(f1);
    if (touches1) zeros.push_back(x1);
    else if (!touches0 && ((f0 < 0.0 && f1 > 0.0) || (f0 > 0.0 && f1 < 0.0)))
      zeros.push_back(solveMonotone(p, dp, 0.0, x0, x1));
  }
  zeros.erase(std::unique(zeros.begin(), zeros.end()), zeros.end());
  return zeros;
}

namespace {

// What interpolating at n Chebyshev points needs, for each n up to kMaxDegree + 1: the
// points (ascending u), the points halfway between them, the transform's cosines, and the
// monomial coefficients of the Chebyshev polynomials (T_k+1 = 2u T_k - T_k-1).
constexpr int kMostPoints = ScalarPolynomial::kMaxDegree + 1;
struct ChebyshevTables {
  std::array<double, kMostPoints> points{}, between{};
  std::array<std::array<double, kMostPoints>, kMostPoints> transform{};
};
using ChebyshevMonomials = std::array<std::array<double, kMostPoints>, kMostPoints>;

const ChebyshevMonomials& chebyshevMonomials() {
  static const ChebyshevMonomials t = [] {
    ChebyshevMonomials m{};
    m[0][0] = 1.0;
    m[1][1] = 1.0;
    for (std::size_t k = 1; k + 1 < kMostPoints; ++k)
      for (std::size_t j = 0; j < kMostPoints; ++j) m[k + 1][j] = (j > 0 ? 2.0 * m[k][j - 1] : 0.0) - m[k - 1][j];
    return m;
  }();
  return t;
}

const ChebyshevTables& chebyshevTables(int n) {
  static const std::array<ChebyshevTables, kMostPoints + 1> all = [] {
    std::array<ChebyshevTables, kMostPoints + 1> tables{};
    for (int count = 1; count <= kMostPoints; ++count) {
      ChebyshevTables& c = tables[std::size_t(count)];
      for (int i = 0; i < count; ++i) {
        c.points[std::size_t(i)] = -std::cos(std::numbers::pi * (i + 0.5) / count);
        c.between[std::size_t(i)] = -std::cos(std::numbers::pi * (i + 1.0) / count);
        for (int k = 0; k < count; ++k)
          c.transform[std::size_t(k)][std::size_t(i)] = std::cos(std::numbers::pi * k * (i + 0.5) / count);
      }
    }
    return tables;
  }();
  return all[std::size_t(n)];
}

}  // namespace

std::span<const double> chebyshevPoints(int n) {
  n = std::clamp(n, 1, kMostPoints);
  return std::span<const double>(chebyshevTables(n).points.data(), std::size_t(n));
}

ScalarPolynomial interpolateChebyshev(std::span<const double> values) {
  const int n = std::clamp(int(values.size()), 1, kMostPoints);
  const ChebyshevTables& cosines = chebyshevTables(n);
  // Coefficients of T_k by the discrete cosine transform; the sign (-1)^k because the
  // points run from u = -1 up while the cosines run down.
  std::array<double, kMostPoints> coefficients{};
  double magnitude = 0.0;
  for (int k = 0; k < n; ++k) {
    double sum = 0.0;
    for (int i = 0; i < n; ++i) sum += values[std::size_t(i)] * cosines.transform[std::size_t(k)][std::size_t(i)];
    coefficients[std::size_t(k)] = sum * (k % 2 ? -1.0 : 1.0) * (k == 0 ? 1.0 : 2.0) / n;
    magnitude += std::abs(coefficients[std::size_t(k)]);
  }
  // The degree the values need: trailing coefficients at rounding level dropped (a cubic
  // stays a cubic, which keeps its zeros cheap to find).
  int needed = n - 1;
  while (needed > 0 && std::abs(coefficients[std::size_t(needed)]) <= 1e-14 * magnitude) --needed;
  const ChebyshevMonomials& chebyshev = chebyshevMonomials();
  ScalarPolynomial p;
  p.degree = needed;
  for (int k = 0; k <= needed; ++k)
    for (int j = 0; j <= k; ++j)
      p.c[std::size_t(j)] += coefficients[std::size_t(k)] * chebyshev[std::size_t(k)][std::size_t(j)];
  return p;
}

std::optional<ScalarPolynomial> fitChebyshev(const std::function<std::optional<double>(double u)>& f, double& error,
                                             int degree) {
  const int n = std::clamp(degree, 0, ScalarPolynomial::kMaxDegree) + 1;
  const ChebyshevTables& cosines = chebyshevTables(n);
  std::array<double, kMostPoints> values{};
  for (int i = 0; i < n; ++i) {
    const auto v = f(cosines.points[std::size_t(i)]);
    if (!v || !std::isfinite(*v)) return std::nullopt;
    values[std::size_t(i)] = *v;
  }
  const ScalarPolynomial p = interpolateChebyshev(std::span<const double>(values.data(), std::size_t(n)));
  error = 0.0;
  if (degree < ScalarPolynomial::kMaxDegree) return p;  // f is a polynomial of that degree: exact
  for (int i = 0; i + 1 < n; ++i) {
    const double u = cosines.between[std::size_t(i)];
    const auto v = f(u);
    if (!v || !std::isfinite(*v)) return std::nullopt;
    error = std::max(error, std::abs(*v - p.at(u)));
  }
  return p;
}

SegmentLight integratePolynomialSegment(const TransferFunction& tf, const std::vector<IsoSurface>& isoSurfaces,
                                        const ScalarPolynomial& s, double length, const GradientAlong& gradientAt,
                                        const glm::dvec3& direction, const EmissionAccuracy& accuracy) {
  SegmentLight total;
  if (!(length > 0.0) || tf.empty()) return total;
  const ScalarPolynomial ds = s.derivative(), integral = s.antiderivative(), curvature = ds.derivative();
  // Scratch lists kept per thread: a renderer calls this for every stretch of every ray.
  thread_local std::vector<double> turns;
  thread_local std::vector<Cut> cuts, stretch;
  turns.assign(1, -1.0);
  for (double u : zerosIn(ds, -1.0, 1.0)) turns.push_back(u);
  turns.push_back(1.0);
  // The values it takes lie between those at its ends and turns: where the transfer function
  // is transparent over them and no surface's value is among them, nothing is seen.
  double lo = INFINITY, hi = -INFINITY;
  for (double u : turns) lo = std::min(lo, s.at(u)), hi = std::max(hi, s.at(u));
  const bool surfaceInside = std::any_of(isoSurfaces.begin(), isoSurfaces.end(),
                                         [&](const IsoSurface& iso) { return iso.value >= lo && iso.value <= hi; });
  if (!surfaceInside && tf.transparentOver(lo, hi)) return total;
  // Every cut in order: control points and iso-values crossed on each monotone stretch.
  cuts.assign(1, {-1.0, s.at(-1.0), nullptr});
  for (std::size_t i = 0; i + 1 < turns.size(); ++i) {
    const double ua = turns[i], ub = turns[i + 1], sa = s.at(ua), sb = s.at(ub);
    stretch.clear();
    // The control-point values strictly between sa and sb (as TransferFunction::crossings,
    // without a list per stretch; sorted with the iso-values below).
    const double low = std::min(sa, sb), high = std::max(sa, sb);
    for (const ControlPoint& point : tf.points())
      if (point.value > low && point.value < high && (stretch.empty() || stretch.back().s != point.value))
        stretch.push_back({solveMonotone(s, ds, point.value, ua, ub), point.value, nullptr});
    for (const IsoSurface& iso : isoSurfaces) {
      const bool crossed = sb > sa ? (iso.value > sa && iso.value <= sb) : (iso.value < sa && iso.value >= sb);
      if (!crossed) continue;
      stretch.push_back({iso.value == sb ? ub : solveMonotone(s, ds, iso.value, ua, ub), iso.value, &iso});
    }
    std::sort(stretch.begin(), stretch.end(), [&](const Cut& x, const Cut& y) {
      return sb > sa ? x.s < y.s || (x.s == y.s && !x.surface) : x.s > y.s || (x.s == y.s && !x.surface);
    });
    double previous = std::max(ua, cuts.back().u);  // rounding must not reorder them
    for (Cut& c : stretch) previous = c.u = std::clamp(c.u, previous, ub);
    cuts.insert(cuts.end(), stretch.begin(), stretch.end());
    if (stretch.empty() || stretch.back().u < ub || stretch.back().surface) cuts.push_back({ub, sb, nullptr});
  }
  const double halfLength = 0.5 * length;
  for (std::size_t i = 1; i < cuts.size() && total.transmittance >= kDark; ++i) {
    const Cut& from = cuts[i - 1];
    const Cut& to = cuts[i];
    compositeBehind(total, monotonePiece(tf, s, integral, curvature, from.u, to.u, from.s, to.s, halfLength, accuracy));
    if (to.surface) {
      const double shade = isoShade(gradientAt(to.u), direction);
      compositeBehind(total, {to.surface->color * shade * to.surface->opacity, 1.0 - to.surface->opacity});
    }
  }
  return total;
}

}  // namespace volpost::optics

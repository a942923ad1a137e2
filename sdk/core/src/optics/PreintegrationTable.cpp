// SPDX-License-Identifier: MIT
#include <volpost/core/optics/PreintegrationTable.hpp>

#include <volpost/core/optics/SegmentIntegral.hpp>

#include <volpost/core/WorkerThreads.hpp>

#include <glm/common.hpp>

#include <boost/math/quadrature/gauss.hpp>

#include <algorithm>
#include <optional>

#include <atomic>
#include <cmath>
#include <stdexcept>
#include <thread>

namespace volpost::optics {

namespace {

// The table resolves the function at its value texels only: control points finer than
// kSamplesPerTexel per texel cannot show in it, but they cost a cut in every texel's
// integral (a 10,000-point function took minutes; 255 points take 0.4 s at 256^2 x 9).
// Such a function is resampled at that many points per texel, evenly over its range,
// before the table's colors are built (its opacity comes from every point).
constexpr int kSamplesPerTexel = 2;

TransferFunction forTable(const TransferFunction& tf, double sMin, double sMax, int texels) {
  const std::size_t limit = std::size_t(kSamplesPerTexel) * std::size_t(texels);
  if (tf.points().size() <= limit) return tf;
  const double lo = std::min(sMin, tf.minValue()), hi = std::max(sMax, tf.maxValue());
  std::vector<ControlPoint> points;
  for (std::size_t i = 0; i <= limit; ++i) {
    const double s = lo + (hi - lo) * double(i) / double(limit);
    points.push_back({s, glm::clamp(tf.color(s), 0.0, 1.0), tf.extinction(s)});
  }
  return TransferFunction(std::move(points));
}

struct Piece {
  glm::dvec3 c0, c1;
  double tau0, tau1, fraction;  // fraction of the segment's length
};

// A segment with no extinction shows nothing, but its texel is a corner of cells whose
// other corners do: their mean color tends to the color where the extinction starts next
// to it, so the texel holds that one (the nearer edge, by value), not an arbitrary color.
glm::dvec3 colorAtNearestExtinction(const TransferFunction& tf, double a, double b) {
  const auto& p = tf.points();
  if (p.empty()) return glm::dvec3(0.0);
  const auto positiveAbove = [&](double c) {  // extinction > 0 just above c
    const auto k = std::upper_bound(p.begin(), p.end(), c, [](double v, const ControlPoint& q) { return v < q.value; });
    return k == p.end() ? p.back().extinction > 0.0 : tf.extinction(c) > 0.0 || k->extinction > 0.0;
  };
  const auto positiveBelow = [&](double c) {  // extinction > 0 just below c
    const auto k = std::lower_bound(p.begin(), p.end(), c, [](const ControlPoint& q, double v) { return q.value < v; });
    return k == p.begin() ? p.front().extinction > 0.0 : tf.extinction(c) > 0.0 || std::prev(k)->extinction > 0.0;
  };
  std::optional<double> above, below;
  if (positiveAbove(b)) above = b;
  for (std::size_t k = 0; !above && k < p.size(); ++k)
    if (p[k].value > b && positiveAbove(p[k].value)) above = p[k].value;
  if (positiveBelow(a)) below = a;
  for (std::size_t k = p.size(); !below && k-- > 0;)
    if (p[k].value < a && positiveBelow(p[k].value)) below = p[k].value;
  if (above && (!below || *above - b <= a - *below)) return tf.color(*above);
  if (below) return tf.color(*below);
  return tf.color(0.5 * (a + b));
}

// The mean color C / alpha of a segment at every optical depth of the table, from moments
// computed once. Along a segment of optical depth D, let w in [0, 1] be the fraction of D
// accumulated so far: it depends on the values alone, not on D, and the color emitted per
// unit of depth is c(w). So C = D int_0^1 c(w) e^(-D w) dw and alpha = 1 - e^(-D). Around
// w = 1/2, e^(-D w) = e^(-D/2) sum_k (-D)^k (w - 1/2)^k / k!, whose terms beyond k = 8 are
// below (D/2)^9 / 9! < 1.1e-11 for D <= kMaxDepth: the mean color is
//   (D/2) / sinh(D/2) * sum_k (-D)^k / k! * mu_k,   mu_k = int_0^1 c(w) (w - 1/2)^k dw,
// each moment a polynomial integral over every piece (c linear, w quadratic in the piece's
// parameter: degree 2k + 2 <= 18, exact with ten Gauss-Legendre nodes). Nine depths cost one
// pass over the pieces instead of nine exact integrations (a 255-point function built 11x
// slower that way).
class MeanColorSeries {
 public:
  static constexpr int kTerms = 9;  // moments mu_0 .. mu_8

  /// `pieces` with some extinction > 0.
  explicit MeanColorSeries(const std::vector<Piece>& pieces) {
    using Gauss = boost::math::quadrature::gauss<double, 10>;
    // w depends on the extinctions' ratios only: scaled to a peak of 1, extinctions near
    // the double's limits (1e-320, 1e308) neither vanish nor overflow.
    double peak = 0.0, meanTau = 0.0;
    for (const Piece& q : pieces) peak = std::max({peak, q.tau0, q.tau1});
    for (const Piece& q : pieces) meanTau += q.fraction * 0.5 * (q.tau0 / peak + q.tau1 / peak);
    double w0 = 0.0;  // depth fraction at the piece's front
    for (const Piece& q : pieces) {
      const double tau0 = q.tau0 / peak, slope = q.tau1 / peak - tau0, scale = q.fraction / meanTau;
      for (std::size_t i = 0; i < Gauss::abscissa().size(); ++i)
        for (double sign : {-1.0, 1.0}) {
          const double t = 0.5 * (1.0 + sign * Gauss::abscissa()[i]);
          const double v = w0 + scale * t * (tau0 + 0.5 * slope * t) - 0.5;
          glm::dvec3 term = (0.5 * Gauss::weights()[i] * scale * (tau0 + slope * t)) * (q.c0 + (q.c1 - q.c0) * t);
          for (int k = 0; k < kTerms; ++k, term *= v) moments_[k] += term;
        }
      w0 += scale * 0.5 * (tau0 + tau0 + slope);
    }
  }

  glm::dvec3 meanColor(double depth) const {
    glm::dvec3 sum(0.0);
    double coefficient = 1.0;  // (-D)^k / k!
    for (int k = 0; k < kTerms; ++k, coefficient *= -depth / k) sum += coefficient * moments_[k];
    const double half = 0.5 * depth;
    return half > 0.0 ? sum * (half / std::sinh(half)) : sum;
  }

 private:
  glm::dvec3 moments_[kTerms] = {};
};

}  // namespace

PreintegrationTable::PreintegrationTable(const TransferFunction& original, double sMin, double sMax,
                                         int scalarResolution, int depthResolution, int threads)
    : ns_(scalarResolution), nd_(depthResolution), tf_(original),
      warp_(original, sMin, sMax > sMin ? sMax : sMin + 1.0, scalarResolution), depth_(original),
      values_(std::size_t(scalarResolution) * std::size_t(scalarResolution) * std::size_t(depthResolution) * 3) {
  if (ns_ < 2 || nd_ < 2 || !(sMax > sMin))
    throw std::invalid_argument("pre-integration table: resolutions must be >= 2 and the range non-empty");
  if (threads <= 0) threads = int(usableCores());
  const TransferFunction tf = forTable(original, sMin, sMax, scalarResolution);
  // One (sFront, sBack) pair per task: its pieces are found once and reused for every depth.
  std::atomic<int> next{0};
  const auto work = [&] {
    std::vector<Piece> pieces;
    for (int pair; (pair = next++) < ns_ * ns_;) {
      const int f = pair % ns_, b = pair / ns_;
      const double sf = warp_.fromTable(double(f) / (ns_ - 1)), sb = warp_.fromTable(double(b) / (ns_ - 1));
      pieces.clear();
      double s0 = sf, x0 = 0.0;
      const bool rising = sb >= sf;  // a constant segment takes the value above a step, as everywhere
      const auto addPiece = [&](double s1, double x1) {
        if (x1 > x0) {  // each side of a step (two points at one value) with its own limit
          const TransferSample a = sampleSide(tf, s0, !rising), e = sampleSide(tf, s1, rising);
          pieces.push_back({a.color, e.color, a.extinction, e.extinction, x1 - x0});
        }
        s0 = s1;
        x0 = x1;
      };
      if (sf != sb)
        for (double cut : tf.crossings(sf, sb)) addPiece(cut, (cut - sf) / (sb - sf));
      addPiece(sb, 1.0);
      double meanTau = 0.0;
      for (const Piece& q : pieces) meanTau += q.fraction * 0.5 * (q.tau0 + q.tau1);
      const glm::dvec3 clear = meanTau > 0.0 ? glm::dvec3(0.0) : colorAtNearestExtinction(tf, std::min(sf, sb), std::max(sf, sb));
      // A constant segment shows its one color at any depth (the value above a step, as
      // constantSegment composites it).
      const std::optional<MeanColorSeries> series =
          meanTau > 0.0 && sf != sb ? std::optional(MeanColorSeries(pieces)) : std::nullopt;
      const glm::dvec3 constant = pieces.front().c0;
      for (int d = 0; d < nd_; ++d) {
        const double depth = kMaxDepth * double(d) / (nd_ - 1);
        const glm::dvec3 c = series ? series->meanColor(depth) : meanTau > 0.0 ? constant : clear;
        float* out = &values_[((std::size_t(d) * std::size_t(ns_) + std::size_t(b)) * std::size_t(ns_) + std::size_t(f)) * 3];
        for (int k = 0; k < 3; ++k) out[k] = float(c[k]);
      }
    }
  };
  runOnThreads(unsigned(threads), [&](unsigned) { work(); });
}

glm::dvec4 PreintegrationTable::lookup(double sFront, double sBack, double length) const {
  const auto coord = [](double x, int n, int& i0, double& w) {
    x = std::clamp(x, 0.0, 1.0) * (n - 1);
    i0 = std::min(int(x), n - 2);
    w = x - i0;
  };
  const double depth = depth_.depth(sFront, sBack, length);
  if (depth > kMaxDepth) {
    const SegmentLight exact = integrateSegment(tf_, sFront, sBack, length);
    return glm::dvec4(exact.color, 1.0 - exact.transmittance);
  }
  int f0, b0, d0;
  double wf, wb, wd;
  coord(warp_.toTable(sFront), ns_, f0, wf);
  coord(warp_.toTable(sBack), ns_, b0, wb);
  coord(depth / kMaxDepth, nd_, d0, wd);
  glm::dvec3 color(0.0);
  for (int dd = 0; dd < 2; ++dd)
    for (int db = 0; db < 2; ++db)
      for (int df = 0; df < 2; ++df) {
        const double w = (df ? wf : 1 - wf) * (db ? wb : 1 - wb) * (dd ? wd : 1 - wd);
        const float* v = &values_[((std::size_t(d0 + dd) * std::size_t(ns_) + std::size_t(b0 + db)) * std::size_t(ns_) +
                                   std::size_t(f0 + df)) * 3];
        color += w * glm::dvec3(v[0], v[1], v[2]);
      }
  const double alpha = -std::expm1(-depth);
  return glm::dvec4(color * alpha, alpha);
}

}  // namespace volpost::optics

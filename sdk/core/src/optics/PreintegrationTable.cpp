// SPDX-License-Identifier: MIT
#include <volpost/core/optics/PreintegrationTable.hpp>

#include <volpost/core/optics/SegmentIntegral.hpp>

#include <volpost/core/WorkerThreads.hpp>

#include <glm/common.hpp>

#include <algorithm>

#include <atomic>
#include <cmath>
#include <stdexcept>
#include <thread>

namespace volpost::optics {

namespace {

// The table resolves the function at its value texels only: control points finer than
// kSamplesPerTexel per texel cannot show in it, but they cost a cut in every texel's
// integral (a 10,000-point function took minutes). Such a function is resampled at that
// many points per texel over its range, exactly at the texels, before the table is built.
constexpr int kSamplesPerTexel = 8;

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

}  // namespace

PreintegrationTable::PreintegrationTable(const TransferFunction& original, double sMin, double sMax,
                                         int scalarResolution, double maxLength, int lengthResolution, int threads)
    : ns_(scalarResolution), nl_(lengthResolution), sMin_(sMin), sMax_(sMax), maxLength_(maxLength),
      warp_(original, sMin, sMax > sMin ? sMax : sMin + 1.0),
      values_(std::size_t(scalarResolution) * std::size_t(scalarResolution) * std::size_t(lengthResolution) * 4) {
  if (ns_ < 2 || nl_ < 2 || !(sMax > sMin) || !(maxLength > 0.0))
    throw std::invalid_argument("pre-integration table: resolutions must be >= 2 and ranges non-empty");
  if (threads <= 0) threads = int(std::max(1u, std::thread::hardware_concurrency()));
  const TransferFunction tf = forTable(original, sMin, sMax, scalarResolution);
  // One (sFront, sBack) pair per task: its cut points are found once and reused for
  // every length.
  struct Piece {
    glm::dvec3 c0, c1;
    double tau0, tau1, fraction;
  };
  std::atomic<int> next{0};
  const auto work = [&] {
    std::vector<Piece> pieces;
    for (int pair; (pair = next++) < ns_ * ns_;) {
      const int f = pair % ns_, b = pair / ns_;
      const double sf = warp_.fromTable(double(f) / (ns_ - 1)), sb = warp_.fromTable(double(b) / (ns_ - 1));
      pieces.clear();
      double s0 = sf, x0 = 0.0;
      const auto addPiece = [&](double s1, double x1) {
        if (x1 > x0) pieces.push_back({tf.color(s0), tf.color(s1), tf.extinction(s0), tf.extinction(s1), x1 - x0});
        s0 = s1;
        x0 = x1;
      };
      if (sf != sb)
        for (double cut : tf.crossings(sf, sb)) addPiece(cut, (cut - sf) / (sb - sf));
      addPiece(sb, 1.0);
      for (int l = 0; l < nl_; ++l) {
        const double length = maxLength_ * l / (nl_ - 1);
        SegmentLight light;
        for (const Piece& p : pieces) {
          compositeBehind(light, sf == sb ? constantSegment(p.c0, p.tau0, length)
                                          : linearSegment(p.c0, p.tau0, p.c1, p.tau1, p.fraction * length));
          if (light.transmittance < 1e-8) break;  // the rest is below float precision
        }
        float* out = &values_[((std::size_t(l) * std::size_t(ns_) + std::size_t(b)) * std::size_t(ns_) + std::size_t(f)) * 4];
        out[0] = float(light.color.r);
        out[1] = float(light.color.g);
        out[2] = float(light.color.b);
        out[3] = float(1.0 - light.transmittance);
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
  int f0, b0, l0;
  double wf, wb, wl;
  coord(warp_.toTable(sFront), ns_, f0, wf);
  coord(warp_.toTable(sBack), ns_, b0, wb);
  coord(length / maxLength_, nl_, l0, wl);
  glm::dvec4 sum(0.0);
  for (int dl = 0; dl < 2; ++dl)
    for (int db = 0; db < 2; ++db)
      for (int df = 0; df < 2; ++df) {
        const double w = (df ? wf : 1 - wf) * (db ? wb : 1 - wb) * (dl ? wl : 1 - wl);
        const float* v = &values_[((std::size_t(l0 + dl) * std::size_t(ns_) + std::size_t(b0 + db)) * std::size_t(ns_) +
                                   std::size_t(f0 + df)) * 4];
        sum += w * glm::dvec4(v[0], v[1], v[2], v[3]);
      }
  return sum;
}

}  // namespace volpost::optics

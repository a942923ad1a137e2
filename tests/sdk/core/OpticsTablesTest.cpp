// SPDX-License-Identifier: MIT
// The GPU tables against the exact integration they approximate, with stated bounds.
#include <volpost/core/optics/IsoTables.hpp>
#include <volpost/core/optics/PreintegrationTable.hpp>
#include <volpost/core/optics/PsiTable.hpp>
#include <volpost/core/optics/SegmentIntegral.hpp>

#include <gtest/gtest.h>

#include <algorithm>

#include <cmath>
#include <random>

using namespace volpost;
using namespace volpost::optics;

namespace {

TransferFunction segments(int n) {  // n linear segments with alternating peaks
  std::vector<ControlPoint> p;
  for (int i = 0; i <= n; ++i) {
    const double t = double(i) / n;
    p.push_back({t, {t, 1.0 - t, 0.5 + 0.5 * (i % 2)}, (i % 3) * 2.0});
  }
  return TransferFunction(p);
}

}  // namespace

TEST(PsiTable, TexelsHoldExactPsiAndInterpolationErrorIsBounded) {
  const PsiTable table(256);
  EXPECT_FLOAT_EQ(table.values()[0], 1.0f);
  const double onTexel = PsiTable::depthOf(100.0 / 255.0);
  EXPECT_NEAR(table.lookup(onTexel, onTexel), psi(onTexel, onTexel), 1e-7);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> e(-4.0, 3.0);
  double worst = 0.0;
  for (int i = 0; i < 20000; ++i) {
    const double tf = std::pow(10.0, e(rng)), tb = std::pow(10.0, e(rng));
    worst = std::max(worst, std::abs(table.lookup(tf, tb) - psi(tf, tb)));
  }
  std::printf("psi table 256^2: worst absolute error %.3g over depths 1e-4..1e3\n", worst);
  EXPECT_LE(worst, 0.012);  // measured 0.0096; 1024^2 is in bench/ and docs/optics.md
}

TEST(PreintegrationTable, TexelsAreExactAndInterpolationErrorIsMeasured) {
  const TransferFunction tf = segments(8);
  const PreintegrationTable table(tf, 0.0, 1.0, 33, 2.0, 17);
  // At texel centres the table is the exact integral (to float).
  for (int f : {0, 7, 32})
    for (int b : {0, 20, 32})
      for (int l : {0, 5, 16}) {
        const double sf = table.warp().fromTable(f / 32.0), sb = table.warp().fromTable(b / 32.0), len = 2.0 * l / 16;
        const SegmentLight exact = integrateSegment(tf, sf, sb, len);
        const glm::dvec4 t = table.lookup(sf, sb, len);
        EXPECT_NEAR(t.a, 1.0 - exact.transmittance, 1e-6);
        EXPECT_NEAR(t.r, exact.color.r, 1e-6);
      }
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  double worst = 0.0;
  for (int i = 0; i < 5000; ++i) {
    const double sf = u(rng), sb = u(rng), len = 2.0 * u(rng);
    const SegmentLight exact = integrateSegment(tf, sf, sb, len);
    worst = std::max(worst, std::abs(table.lookup(sf, sb, len).a - (1.0 - exact.transmittance)));
  }
  std::printf("pre-integration table 33x33x17, 8 segments: worst alpha error %.3g\n", worst);
  EXPECT_LE(worst, 0.1);  // measured 0.085 with evenly spread texels: the coarse table's known weakness
}

TEST(TableWarp, PiecewiseLinearBothWaysAndFairToNarrowPieces) {
  // A peak 0.01 wide at 0.5 in [0, 1]: its two pieces get a quarter of the table each.
  const TransferFunction peak({{0.495, {1, 1, 1}, 0.0}, {0.5, {1, 0, 0}, 400.0}, {0.505, {1, 1, 1}, 0.0}});
  const TableWarp warp(peak, 0.0, 1.0);
  EXPECT_EQ(warp.toTable(0.0), 0.0);
  EXPECT_EQ(warp.toTable(1.0), 1.0);
  EXPECT_NEAR(warp.toTable(0.5), 0.5, 1e-12);
  EXPECT_NEAR(warp.toTable(0.505) - warp.toTable(0.495), 0.5 + 0.5 * 0.01, 1e-12);
  for (double s = -0.1; s <= 1.1; s += 0.0137) {
    const double u = warp.toTable(s);
    EXPECT_TRUE(u >= 0.0 && u <= 1.0);
    EXPECT_NEAR(warp.fromTable(u), std::clamp(s, 0.0, 1.0), 1e-12);
  }
  // No piece inside the range: the identity.
  const TableWarp plain(TransferFunction({{2.0, {1, 1, 1}, 1.0}}), 0.0, 1.0);
  EXPECT_NEAR(plain.toTable(0.3), 0.3, 1e-15);
}

// The netting of a sharp peak: with texels spread evenly (the same function padded with
// points that change nothing, so every piece is as wide), segments across the peak lose it
// between texels; the warp puts texels on it.
TEST(PreintegrationTable, ASharpPeakIsResolvedWhereTexelsWereEven) {
  const TransferFunction peak({{0.0, {0.2, 0.2, 1.0}, 0.0},
                               {0.495, {1, 1, 1}, 0.0},
                               {0.5, {1, 0, 0}, 60.0},
                               {0.505, {1, 1, 1}, 0.0},
                               {1.0, {0.2, 0.2, 1.0}, 0.0}});
  std::vector<ControlPoint> even;
  for (int i = 0; i <= 200; ++i) {
    const double s = i / 200.0;
    if (std::abs(s - 0.5) > 0.006) even.push_back({s, peak.color(s), peak.extinction(s)});
  }
  for (const ControlPoint& p : peak.points()) even.push_back(p);
  const TransferFunction padded(even);
  const PreintegrationTable warped(peak, 0.0, 1.0, 64, 1.0, 16), flat(padded, 0.0, 1.0, 64, 1.0, 16);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  double worstWarped = 0.0, worstFlat = 0.0, sumWarped = 0.0, sumFlat = 0.0;
  for (int i = 0; i < 4000; ++i) {
    // Segments that cross or end near the peak, as tets over it do.
    const double sf = 0.5 + 0.1 * (u(rng) - 0.5), sb = 0.5 + 0.1 * (u(rng) - 0.5), len = u(rng);
    const double exact = 1.0 - integrateSegment(peak, sf, sb, len).transmittance;
    const double w = std::abs(warped.lookup(sf, sb, len).a - exact), f = std::abs(flat.lookup(sf, sb, len).a - exact);
    worstWarped = std::max(worstWarped, w);
    worstFlat = std::max(worstFlat, f);
    sumWarped += w * w;
    sumFlat += f * f;
  }
  const double rmsWarped = std::sqrt(sumWarped / 4000), rmsFlat = std::sqrt(sumFlat / 4000);
  std::printf("pre-integration 64^2x16 over a peak 1/100 of the range wide: alpha error RMS %.3g worst %.3g warped, "
              "RMS %.3g worst %.3g with texels spread evenly\n",
              rmsWarped, worstWarped, rmsFlat, worstFlat);
  EXPECT_LE(worstWarped, worstFlat / 2.0);
  EXPECT_LE(rmsWarped, rmsFlat / 4.0);
}

TEST(IsoDetectionTable, FirstAndNextControlPointCrossed) {
  const TransferFunction tf({{0.2, {1, 0, 0}, 1.0}, {0.5, {0, 1, 0}, 1.0}, {0.8, {0, 0, 1}, 1.0}});
  const IsoDetectionTable t(tf, 0.0, 1.0, 11);
  const auto near = [](std::pair<double, double> a, double x, double y) {
    return std::abs(a.first - x) < 1e-6 && std::abs(a.second - y) < 1e-6;
  };
  EXPECT_TRUE(near(t.at(0.0, 1.0), 0.2, 0.5));
  EXPECT_TRUE(near(t.at(1.0, 0.0), 0.8, 0.5));
  EXPECT_TRUE(near(t.at(0.3, 0.4), -1, -1));
  EXPECT_TRUE(near(t.at(0.5, 0.5), -1, -1));  // s_f == s_b: nothing crossed, nothing divided
  EXPECT_TRUE(near(t.at(0.2, 0.6), 0.5, -1));  // starting on a point does not cross it
  EXPECT_TRUE(near(t.at(0.1, 0.2), 0.2, -1));  // ending on one does
}


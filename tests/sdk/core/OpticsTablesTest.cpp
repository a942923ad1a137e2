// SPDX-License-Identifier: MIT
// The GPU tables against the exact integration they approximate, with stated bounds.
#include <volpost/core/optics/IsoTables.hpp>
#include <volpost/core/optics/OpticalDepth.hpp>
#include <volpost/core/optics/PreintegrationTable.hpp>
#include <volpost/core/optics/PsiTable.hpp>
#include <volpost/core/optics/SegmentIntegral.hpp>
#include <volpost/core/optics/ThickPsi.hpp>

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
  EXPECT_LE(worst, 0.012);  // measured 0.0096; 1024^2 is in bench/ and docs/methods/optics.md
}

TEST(ThickPsi, FunctionsHoldKnownValuesAndPsiHoldsOverEveryThickDepth) {
  EXPECT_NEAR(ThickPsiTable::halfSqrtPiErfcx(1.0), 0.5 * std::sqrt(M_PI) * 0.42758357615580705, 1e-15);
  EXPECT_NEAR(ThickPsiTable::halfSqrtPiErfcx(30.0), 0.5 * std::sqrt(M_PI) * 0.018795888861416754, 1e-14);  // its series
  EXPECT_NEAR(ThickPsiTable::dawson(1.0), 0.53807950691276841, 1e-15);
  EXPECT_NEAR(ThickPsiTable::dawson(10.0), 0.05025384718759854, 1e-15);
  const ThickPsiTable table;
  const PsiTable square(512);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  double worst = 0.0, worstSquare = 0.0;
  for (int i = 0; i < 200000; ++i) {
    // Depths 1 to 1e6; either end thicker; some with one end nearly clear, some nearly equal.
    const double depth = ThickPsiTable::kMinDepth * std::pow(1e6, u(rng));
    const double f = i % 4 == 0 ? 0.5 + 1e-4 * (u(rng) - 0.5) : i % 4 == 1 ? 1e-3 * u(rng) : i % 4 == 2 ? 1.0 - 1e-3 * u(rng) : u(rng);
    const double tf = 2.0 * depth * f, tb = 2.0 * depth * (1.0 - f);
    const double exact = psi(tf, tb);
    worst = std::max(worst, std::abs(table.psi(tf, tb) - exact));
    worstSquare = std::max(worstSquare, std::abs(square.lookup(tf, tb) - exact));
  }
  std::printf("psi of thick pieces: worst error %.3g (the 512^2 table: %.3g)\n", worst, worstSquare);
  EXPECT_LE(worst, 5e-6);  // measured 3.8e-6 (the front thicker, depth ~1); 2e-8 beyond 10
}

TEST(OpticalDepth, MatchesTheCutIntegralAndIsStableAcrossNearbyPoints) {
  const TransferFunction tf = segments(8);
  const OpticalDepth depth(tf);
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(-0.2, 1.2);
  for (int i = 0; i < 2000; ++i) {
    const double sf = u(rng), sb = u(rng), len = 3.0 * std::abs(u(rng));
    const double exact = -std::log(integrateSegment(tf, sf, sb, len).transmittance);
    EXPECT_NEAR(depth.depth(sf, sb, len), exact, 1e-12 * std::max(1.0, exact)) << sf << " " << sb << " " << len;
  }
  // A tiny step across a control point where the extinction kinks: the mean of the two
  // sides, with no difference of running sums divided by the tiny step.
  // The point at 3/8 has extinction 0; it rises with slope 32 below it and 16 above it.
  const double k = 3.0 / 8.0, a = k - 1e-12, b = k + 3e-12, below = k - a, above = b - k;
  const double mean = (16.0 * below * below + 8.0 * above * above) / (b - a);
  EXPECT_NEAR(depth.depth(a, b, 1.0), mean, 1e-12 * mean);
  EXPECT_NEAR(depth.depth(b, a, 1.0), mean, 1e-12 * mean);
  EXPECT_EQ(depth.depth(0.5, 0.5, 2.0), 2.0 * tf.extinction(0.5));
  EXPECT_THROW(OpticalDepth({1.0, 0.0}, {1.0, 1.0}), std::invalid_argument);
  // A step (two points at one value), a single point, no point.
  const TransferFunction step({{0.0, {1, 1, 1}, 0.0}, {0.5, {1, 1, 1}, 0.0}, {0.5, {1, 0, 0}, 4.0}, {1.0, {1, 0, 0}, 4.0}});
  const OpticalDepth stepDepth(step);
  EXPECT_NEAR(stepDepth.depth(0.25, 0.75, 2.0), 2.0 * 0.5 * 4.0, 1e-12);
  EXPECT_NEAR(stepDepth.depth(0.75, 0.25, 2.0), 4.0, 1e-12);
  EXPECT_NEAR(stepDepth.depth(0.1, 0.4, 2.0), 0.0, 1e-15);
  EXPECT_NEAR(stepDepth.depth(0.6, 0.9, 2.0), 8.0, 1e-12);
  EXPECT_EQ(OpticalDepth(TransferFunction({{0.3, {1, 1, 1}, 2.0}})).depth(-5.0, 5.0, 3.0), 6.0);
  EXPECT_EQ(OpticalDepth(TransferFunction()).depth(0.0, 1.0, 1.0), 0.0);
}

TEST(PreintegrationTable, OpacityIsExactAndColorsHoldAtTexels) {
  const TransferFunction tf = segments(8);
  const PreintegrationTable table(tf, 0.0, 1.0, 33, 9);
  // At texel centres the color is the exact integral's (to float).
  for (int f : {0, 7, 32})
    for (int b : {0, 20, 32})
      for (int d : {1, 4, 8}) {
        const double sf = table.warp().fromTable(f / 32.0), sb = table.warp().fromTable(b / 32.0);
        const double depth = PreintegrationTable::kMaxDepth * d / 8.0, meanTau = OpticalDepth(tf).depth(sf, sb, 1.0);
        if (meanTau == 0.0) continue;
        const SegmentLight exact = integrateSegment(tf, sf, sb, depth / meanTau);
        const glm::dvec4 t = table.lookup(sf, sb, depth / meanTau);
        EXPECT_NEAR(t.a, 1.0 - exact.transmittance, 1e-12);
        EXPECT_NEAR(t.r, exact.color.r, 1e-6);
        EXPECT_NEAR(t.b, exact.color.b, 1e-6);
      }
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  double worstAlpha = 0.0, worstColor = 0.0;
  for (int i = 0; i < 5000; ++i) {
    const double sf = u(rng), sb = u(rng), len = std::pow(10.0, 4.0 * u(rng) - 2.0);
    const SegmentLight exact = integrateSegment(tf, sf, sb, len);
    const glm::dvec4 t = table.lookup(sf, sb, len);
    worstAlpha = std::max(worstAlpha, std::abs(t.a - (1.0 - exact.transmittance)));
    for (int c = 0; c < 3; ++c) worstColor = std::max(worstColor, std::abs(t[c] - exact.color[c]));
  }
  std::printf("pre-integration table 33x33x9, 8 segments, lengths 0.01..100: worst alpha error %.3g, color %.3g\n",
              worstAlpha, worstColor);
  EXPECT_LE(worstAlpha, 1e-12);
  EXPECT_LE(worstColor, 0.01);  // measured 0.0058: the color between texels; the opacity is exact
}

// Every texel holds the exact mean color C / alpha of its segment, to float: the table's
// series in the optical depth against the cut integration, over a function with a step
// (two points at one value), a run of zero extinction and a piece thick enough that the
// table's deepest texels hold segments of very uneven light.
TEST(PreintegrationTable, EveryTexelHoldsTheExactMeanColor) {
  const TransferFunction tf({{0.0, {0.1, 0.2, 0.9}, 0.0},
                             {0.2, {0.9, 0.1, 0.1}, 0.0},
                             {0.3, {1.0, 1.0, 0.0}, 40.0},
                             {0.3, {0.0, 1.0, 1.0}, 2.0},
                             {0.6, {0.5, 0.0, 1.0}, 0.5},
                             {1.0, {1.0, 1.0, 1.0}, 9.0}});
  const int n = 21, depths = 9;
  const PreintegrationTable table(tf, 0.0, 1.0, n, depths);
  const OpticalDepth depthOf(tf);
  double worst = 0.0;
  int checked = 0;
  for (int d = 1; d < depths; ++d)
    for (int b = 0; b < n; ++b)
      for (int f = 0; f < n; ++f) {
        const double sf = table.warp().fromTable(f / double(n - 1)), sb = table.warp().fromTable(b / double(n - 1));
        const double meanTau = depthOf.depth(sf, sb, 1.0);
        if (meanTau == 0.0 || sf == sb) continue;
        const double depth = PreintegrationTable::kMaxDepth * d / double(depths - 1);
        const SegmentLight exact = integrateSegment(tf, sf, sb, depth / meanTau);
        const float* texel = &table.values()[((std::size_t(d) * n + b) * n + f) * 3];
        for (int c = 0; c < 3; ++c)
          worst = std::max(worst, std::abs(texel[c] - exact.color[c] / (1.0 - exact.transmittance)));
        ++checked;
      }
  std::printf("pre-integration texels against the exact mean color: worst %.3g over %d texels\n", worst, checked);
  EXPECT_GT(checked, 2000);
  EXPECT_LE(worst, 3e-7);  // float rounding of colors <= 1
}

// The mean color at a given optical depth depends on the extinctions' ratios only: a
// function scaled by 1e-300 or 1e300 has the same table, and extinctions at the double's
// limits (a denormal, 1e308 whose sums overflow) give colors, never NaN or black.
TEST(PreintegrationTable, TheTableDependsOnTheExtinctionsRatiosOnly) {
  const auto scaled = [](double factor) {
    std::vector<ControlPoint> p = segments(6).points();
    for (ControlPoint& q : p) q.extinction *= factor;
    return TransferFunction(p);
  };
  const PreintegrationTable plain(scaled(1.0), 0.0, 1.0, 17, 9);
  for (double factor : {1e-300, 1e300, 1e-320 / 4.0, 1e308 / 4.0}) {
    const PreintegrationTable table(scaled(factor), 0.0, 1.0, 17, 9);
    const bool exactRatios = factor == 1e-300 || factor == 1e300;  // a denormal keeps few bits
    for (std::size_t i = 0; i < plain.values().size(); ++i) {
      ASSERT_TRUE(std::isfinite(table.values()[i])) << factor << " texel " << i;
      if (exactRatios) ASSERT_NEAR(table.values()[i], plain.values()[i], 1e-6) << factor << " texel " << i;
    }
  }
  const TransferFunction huge({{0.0, {1, 0, 0}, 1e308}, {1.0, {0, 1, 0}, 1e308}});
  const PreintegrationTable table(huge, 0.0, 1.0, 9, 3);
  const float* whole = &table.values()[((2 * 9 + 8) * 9 + 0) * 3];  // deepest, from 0 to 1
  EXPECT_GT(whole[0], 0.5f);  // seen from the red end
  EXPECT_GT(whole[1], 0.1f);
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

// The netting of a sharp peak: a table interpolated over a peak 1/100 of the range wide
// loses it where segments cross it between texels. The opacity no longer comes from the
// table; the color does, from texels on the peak's control points.
TEST(PreintegrationTable, ASharpPeakIsNotNetted) {
  const TransferFunction peak({{0.0, {0.2, 0.2, 1.0}, 0.0},
                               {0.495, {1, 1, 1}, 0.0},
                               {0.5, {1, 0, 0}, 60.0},
                               {0.505, {1, 1, 1}, 0.0},
                               {1.0, {0.2, 0.2, 1.0}, 0.0}});
  const PreintegrationTable table(peak, 0.0, 1.0, 64, 9);
  EXPECT_EQ(table.warp().toTable(0.495) * 63.0, std::round(table.warp().toTable(0.495) * 63.0));  // on a texel
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  double worstAlpha = 0.0, worstColor = 0.0, sum = 0.0;
  const int n = 20000;
  for (int i = 0; i < n; ++i) {
    // Segments that cross or end near the peak, as tets over it do, 0.001 to 10 long.
    const double sf = 0.5 + 0.1 * (u(rng) - 0.5), sb = 0.5 + 0.1 * (u(rng) - 0.5), len = std::pow(10.0, 4.0 * u(rng) - 3.0);
    const SegmentLight exact = integrateSegment(peak, sf, sb, len);
    const glm::dvec4 t = table.lookup(sf, sb, len);
    worstAlpha = std::max(worstAlpha, std::abs(t.a - (1.0 - exact.transmittance)));
    for (int c = 0; c < 3; ++c) {
      const double e = std::abs(t[c] - exact.color[c]);
      worstColor = std::max(worstColor, e);
      sum += e * e;
    }
  }
  std::printf("pre-integration 64x64x9 over a peak 1/100 of the range wide: alpha error %.3g, color error RMS %.3g worst %.3g\n",
              worstAlpha, std::sqrt(sum / (3.0 * n)), worstColor);
  EXPECT_LE(worstAlpha, 1e-12);
  EXPECT_LE(worstColor, 0.004);  // measured 0.0024 at 64 texels (6.5e-4 at the renderers' 128)
}

TEST(IsoDetectionTable, EntriesCoverTheirTexelsCells) {
  // Texels 1/8 apart, cells +-1/16 (and 1/64 of a texel); values exact in float.
  const TransferFunction tf({{0.25, {1, 0, 0}, 1.0}, {0.46875, {0, 1, 0}, 1.0}, {0.53125, {0, 1, 0}, 1.0},
                             {0.75, {0, 0, 1}, 1.0}});
  const IsoDetectionTable t(tf, 0.0, 1.0, 9);
  const auto near = [](std::pair<double, double> a, double x, double y) {
    return std::abs(a.first - x) < 1e-9 && std::abs(a.second - y) < 1e-9;
  };
  EXPECT_TRUE(near(t.at(0.0, 1.0), 0.25, 0.46875));
  EXPECT_TRUE(near(t.at(1.0, 0.0), 0.75, 0.53125));
  EXPECT_TRUE(near(t.at(0.3, 0.4), 0.25, -1));  // 0.25 lies in the front texel's cell
  EXPECT_TRUE(near(t.at(0.32, 0.38), -1, -1));  // one texel, no point in its cell
  // The cut as the GPU makes it.
  const auto cutAt = [&](double a, double b) { return t.cut(a, b).value_or(-2.0); };
  EXPECT_EQ(cutAt(0.3, 0.4), 0.4);       // 0.25 is behind: no cut
  EXPECT_EQ(cutAt(0.25, 0.6), 0.46875);  // starting on a point does not cross it
  EXPECT_EQ(cutAt(0.1, 0.25), 0.25);     // ending on one: the piece ends there anyway
  // Points between a value and its texel's centre (0.5), which entries computed at the
  // centres missed, going up and going down.
  EXPECT_EQ(cutAt(0.45, 0.6), 0.46875);
  EXPECT_EQ(cutAt(0.55, 0.3), 0.53125);
  EXPECT_FALSE(t.cut(0.49, 0.51).has_value());  // one texel holding both ends and points: search
  EXPECT_EQ(cutAt(0.32, 0.38), 0.38);
}

// Against the exact next crossing, for every pair of a dense set of values: the table says
// where to cut or that it cannot tell, and is never wrong. A point between a value and its
// texel's centre was missed when entries were computed at the centres alone.
TEST(IsoDetectionTable, NeverMissesAPointBetweenTexelCentres) {
  std::vector<ControlPoint> p;
  for (double v : {0.0, 0.3, 0.597, 0.6, 0.603, 0.61, 0.95, 1.0}) p.push_back({v, {1, 1, 1}, 1.0});
  const TransferFunction tf(p);
  const IsoDetectionTable t(tf, 0.0, 1.0, 64);
  int told = 0, pairs = 0;
  for (int i = 0; i <= 400; ++i)
    for (int j = 0; j <= 400; ++j) {
      const double a = i / 400.0, b = j / 400.0;
      const auto exact = tf.crossings(a, b);
      const double expected = exact.empty() ? b : exact.front();
      const std::optional<double> c = t.cut(a, b);
      ++pairs;
      if (!c) continue;
      ++told;
      // A point stored in float may lie just ahead of a start on it: a piece of no length.
      ASSERT_TRUE(std::abs(*c - expected) < 1e-6 || std::abs(*c - a) < 1e-6) << "from " << a << " to " << b << ": " << *c;
    }
  std::printf("iso-detection table 64^2: %d of %d pieces cut from the table, the rest searched\n", told, pairs);
  EXPECT_GT(told, pairs * 9 / 10);
}


// SPDX-License-Identifier: MIT
// The GPU tables against the exact integration they approximate, with stated bounds.
#include <volpost/core/optics/IsoTables.hpp>
#include <volpost/core/optics/PreintegrationTable.hpp>
#include <volpost/core/optics/PsiTable.hpp>
#include <volpost/core/optics/SegmentIntegral.hpp>

#include <gtest/gtest.h>

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
        const double sf = f / 32.0, sb = b / 32.0, len = 2.0 * l / 16;
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
  EXPECT_LE(worst, 0.1);  // measured 0.085: the coarse table's known weakness (seed 5.3)
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


// SPDX-License-Identifier: MIT
// A segment whose scalar is a polynomial along it, against independent evaluation: the
// linear case against the closed form, higher degrees against a fine midpoint sum of the
// transfer function itself; zeros, fits and iso-surfaces met twice on a turning scalar.
#include <volpost/core/optics/PolynomialSegment.hpp>

#include <gtest/gtest.h>

#include <cmath>

using namespace volpost;
using namespace volpost::optics;

namespace {

// A sharp peak between smooth ramps, colors that change across it.
TransferFunction peakTf() {
  return TransferFunction({{-1.0, {0.1, 0.2, 0.9}, 0.4},
                           {0.1, {0.9, 0.1, 0.1}, 0.6},
                           {0.15, {1.0, 0.9, 0.2}, 9.0},
                           {0.2, {0.2, 0.8, 0.3}, 0.6},
                           {1.5, {1.0, 1.0, 1.0}, 2.0}});
}

ScalarPolynomial polynomial(std::initializer_list<double> c) {
  ScalarPolynomial p;
  p.degree = int(c.size()) - 1;
  std::size_t k = 0;
  for (double v : c) p.c[k++] = v;
  return p;
}

// The emission-absorption integral by the midpoint rule on n steps, each step's light
// exact for its constant color and extinction; Richardson-extrapolated from n and 2n.
SegmentLight midpoint(const TransferFunction& tf, const ScalarPolynomial& s, double length, int n) {
  const auto sum = [&](int steps) {
    SegmentLight total;
    const double h = 2.0 / steps;
    for (int i = 0; i < steps; ++i) {
      const double v = s.at(-1.0 + (i + 0.5) * h);
      compositeBehind(total, constantSegment(tf.color(v), tf.extinction(v), 0.5 * length * h));
    }
    return total;
  };
  const SegmentLight a = sum(n), b = sum(2 * n);
  return {(4.0 * b.color - a.color) / 3.0, (4.0 * b.transmittance - a.transmittance) / 3.0};
}

double difference(const SegmentLight& a, const SegmentLight& b) {
  return std::max({std::abs(a.color.r - b.color.r), std::abs(a.color.g - b.color.g), std::abs(a.color.b - b.color.b),
                   std::abs(a.transmittance - b.transmittance)});
}

const GradientAlong kAlongRay = [](double) { return glm::dvec3(0.0, 0.0, 1.0); };

}  // namespace

TEST(PolynomialSegment, ZerosOfACubicAndOfATouchingSquare) {
  // (u - 0.3)(u + 0.5)(u - 0.9) = u^3 - 0.7u^2 - 0.33u + 0.135
  const auto zeros = zerosIn(polynomial({0.135, -0.33, -0.7, 1.0}), -1.0, 1.0);
  ASSERT_EQ(zeros.size(), 3u);
  EXPECT_NEAR(zeros[0], -0.5, 1e-14);
  EXPECT_NEAR(zeros[1], 0.3, 1e-14);
  EXPECT_NEAR(zeros[2], 0.9, 1e-14);
  EXPECT_TRUE(zerosIn(polynomial({1.0, 0.0, 1.0}), -1.0, 1.0).empty());  // 1 + u^2 > 0
  const auto touch = zerosIn(polynomial({0.04, -0.4, 1.0}), -1.0, 1.0);  // (u - 0.2)^2
  ASSERT_EQ(touch.size(), 1u);
  EXPECT_NEAR(touch[0], 0.2, 1e-12);
}

TEST(PolynomialSegment, AChebyshevFitRecoversACubicExactlyAndSaysWhenItDoesNotFit) {
  double error = 1.0;
  const auto cubic = fitChebyshev([](double u) { return std::optional<double>(2.0 - u + 0.5 * u * u * u); }, error);
  ASSERT_TRUE(cubic);
  EXPECT_EQ(cubic->degree, 3);
  EXPECT_LT(error, 1e-14);
  EXPECT_NEAR(cubic->c[0], 2.0, 1e-14);
  EXPECT_NEAR(cubic->c[1], -1.0, 1e-14);
  EXPECT_NEAR(cubic->c[3], 0.5, 1e-13);
  fitChebyshev([](double u) { return std::optional<double>(std::abs(u)); }, error);  // a kink: no degree-8 fit
  EXPECT_GT(error, 1e-3);
  EXPECT_FALSE(fitChebyshev([](double u) { return u > 0.5 ? std::nullopt : std::optional<double>(u); }, error));
}

TEST(PolynomialSegment, ALinearScalarGivesTheLinearSegmentsExactIntegral) {
  const TransferFunction tf = peakTf();
  for (auto [a, b] : {std::pair{-0.8, 1.4}, std::pair{1.2, 0.05}, std::pair{0.12, 0.13}}) {
    const SegmentLight exact = integrateSegment(tf, a, b, 0.7);
    const SegmentLight got =
        integratePolynomialSegment(tf, {}, polynomial({0.5 * (a + b), 0.5 * (b - a)}), 0.7, kAlongRay, {0, 0, 1});
    EXPECT_LT(difference(exact, got), 1e-13) << a << " " << b;
  }
}

TEST(PolynomialSegment, TurningScalarsAcrossASharpPeakMatchAFineMidpointSum) {
  const TransferFunction tf = peakTf();
  // A quartic that turns three times, crossing the peak six times; a cubic; a flat square.
  for (const ScalarPolynomial& s :
       {polynomial({0.15, 0.1, -1.2, -0.1, 1.1}), polynomial({0.4, -0.9, 0.2, 0.5}), polynomial({0.12, 0.0, 0.05})}) {
    for (double length : {0.3, 2.5}) {
      const SegmentLight got = integratePolynomialSegment(tf, {}, s, length, kAlongRay, {0, 0, 1});
      const SegmentLight reference = midpoint(tf, s, length, 200000);
      EXPECT_LT(difference(got, reference), 2e-9) << s.degree << " " << length;
      EXPECT_GT(got.transmittance, 0.0);
    }
  }
}

TEST(PolynomialSegment, AnIsoSurfaceIsMetWhereverATurningScalarCrossesIt) {
  // s = u^2 from 1 down to 0 and back: the value 0.25 is met at u = -0.5 and u = 0.5.
  const TransferFunction clear({{0.0, glm::dvec3(0.0), 0.0}, {1.0, glm::dvec3(0.0), 0.0}});
  const std::vector<IsoSurface> iso{{0.25, glm::dvec3(1.0), 0.5}};
  std::vector<double> metAt;
  const GradientAlong gradient = [&](double u) {
    metAt.push_back(u);
    return glm::dvec3(0.0, 0.0, 1.0);  // facing the ray: full shade
  };
  const SegmentLight got =
      integratePolynomialSegment(clear, iso, polynomial({0.0, 0.0, 1.0}), 1.0, gradient, {0, 0, 1});
  ASSERT_EQ(metAt.size(), 2u);
  EXPECT_NEAR(metAt[0], -0.5, 1e-14);
  EXPECT_NEAR(metAt[1], 0.5, 1e-14);
  EXPECT_NEAR(got.transmittance, 0.25, 1e-15);
  EXPECT_NEAR(got.color.r, 0.5 + 0.5 * 0.5, 1e-15);
  // A surface at the front value is the cell in front's (not met); at the back value it is met.
  metAt.clear();
  integratePolynomialSegment(clear, {{1.0, glm::dvec3(1.0), 0.5}}, polynomial({0.0, 0.0, 1.0}), 1.0, gradient,
                             {0, 0, 1});
  ASSERT_EQ(metAt.size(), 1u);
  EXPECT_EQ(metAt[0], 1.0);
}

TEST(PolynomialSegment, AKnownDegreeIsInterpolatedAtThatManyPointsExactly) {
  int calls = 0;
  double error = 1.0;
  const auto cubic = fitChebyshev(
      [&](double u) {
        ++calls;
        return std::optional<double>(2.0 - u + 0.5 * u * u * u);
      },
      error, 3);
  ASSERT_TRUE(cubic);
  EXPECT_EQ(calls, 4);
  EXPECT_EQ(error, 0.0);
  EXPECT_NEAR(cubic->c[1], -1.0, 1e-14);
  EXPECT_NEAR(cubic->c[3], 0.5, 1e-14);
}

// Chords within a tolerance: every channel and the transmittance within it of the exact
// integral (the pieces a segment takes add up to at most its length and their opacities
// to at most one, so the segment is also the whole ray here), on steep and gentle peaks.
TEST(PolynomialSegment, ChordsStayWithinTheToleranceOfTheExactIntegral) {
  const TransferFunction steep({{0.0, {0.2, 0.3, 0.9}, 0.0},
                                {0.30, {0.2, 0.6, 0.9}, 0.0},
                                {0.40, {1.0, 0.7, 0.2}, 40.0},
                                {0.50, {0.9, 0.2, 0.1}, 0.0},
                                {1.0, {0.9, 0.2, 0.1}, 0.0}});
  const std::vector<ScalarPolynomial> scalars{polynomial({0.15, 0.1, -1.2, -0.1, 1.1}),
                                              polynomial({0.4, -0.9, 0.2, 0.5}), polynomial({0.38, 0.3, -0.25})};
  for (const TransferFunction& tf : {peakTf(), steep})
    for (const ScalarPolynomial& s : scalars)
      for (double length : {0.05, 0.4, 3.0}) {
        const SegmentLight exact = integratePolynomialSegment(tf, {}, s, length, kAlongRay, {0, 0, 1});
        for (double tolerance : {1e-2, 1e-3, 1e-4}) {
          const EmissionAccuracy accuracy{tolerance, length, 1.0};
          const SegmentLight got = integratePolynomialSegment(tf, {}, s, length, kAlongRay, {0, 0, 1}, accuracy);
          EXPECT_LE(difference(got, exact), tolerance) << s.degree << " " << length;
        }
      }
  // The chords are what is drawn (not the exact quadrature under another name).
  const ScalarPolynomial& cubic = scalars[1];
  const SegmentLight exact = integratePolynomialSegment(steep, {}, cubic, 3.0, kAlongRay, {0, 0, 1});
  const SegmentLight chords =
      integratePolynomialSegment(steep, {}, cubic, 3.0, kAlongRay, {0, 0, 1}, EmissionAccuracy{1e-2, 3.0, 1.0});
  EXPECT_GT(difference(chords, exact), 1e-9);
}

TEST(PolynomialSegment, AStretchWhoseValuesStayTransparentIsSkippedWhole) {
  const TransferFunction tf({{0.0, {1, 1, 1}, 0.0}, {0.5, {1, 1, 1}, 0.0}, {0.6, {1, 0, 0}, 5.0}});
  EXPECT_TRUE(tf.transparentOver(-3.0, 0.5));
  EXPECT_FALSE(tf.transparentOver(0.2, 0.51));
  EXPECT_FALSE(tf.transparentOver(0.7, 0.9)) << "clamped above the last point";
  // Rises to 0.45 and falls again: transparent throughout; a surface at 0.4 is still met twice.
  const ScalarPolynomial s = polynomial({0.45, 0.0, -0.4});
  const SegmentLight clear = integratePolynomialSegment(tf, {}, s, 1.0, kAlongRay, {0, 0, 1});
  EXPECT_EQ(clear.transmittance, 1.0);
  EXPECT_EQ(clear.color, glm::dvec3(0.0));
  const std::vector<IsoSurface> surface{{0.4, {1.0, 1.0, 1.0}, 0.5}};
  const SegmentLight met = integratePolynomialSegment(tf, surface, s, 1.0, kAlongRay, {0, 0, 1});
  EXPECT_NEAR(met.transmittance, 0.25, 1e-12);
}

// SPDX-License-Identifier: MIT
// psi against a 113-bit adaptive quadrature on a dense grid of optical depths from 1e-8 to
// 1e4 and on nearly equal pairs; the worst relative error is printed and must be <= 1e-12
// (the goal is 1e-9).
#include "support/QuadPrecision.hpp"

#include <volpost/core/optics/SegmentIntegral.hpp>

#include <gtest/gtest.h>

#include <cstdio>
#include <vector>

using namespace volpost;
using volpost::test::quad;

namespace {

std::vector<double> depths() {
  std::vector<double> v = {0.0};
  for (int e = -8; e <= 4; ++e)
    for (double m : {1.0, 2.0, 5.0}) v.push_back(m * std::pow(10.0, e));
  return v;
}

struct Worst {
  double error = 0.0, tf = 0.0, tb = 0.0;
  void update(double e, double f, double b) {
    if (e > error) *this = {e, f, b};
  }
};

double relativeError(double tf, double tb) {
  const quad ref = volpost::test::psiReference(tf, tb);
  return double(fabsq((quad(optics::psi(tf, tb)) - ref) / ref));
}

}  // namespace

TEST(Psi, MatchesQuadPrecisionOnADenseGrid) {
  Worst worst;
  const auto grid = depths();
  for (double tf : grid)
    for (double tb : grid) worst.update(relativeError(tf, tb), tf, tb);
  std::printf("psi grid (%zu x %zu, 1e-8..1e4): worst relative error %.3g at tf=%g tb=%g\n", grid.size(), grid.size(),
              worst.error, worst.tf, worst.tb);
  EXPECT_LE(worst.error, 1e-12);
}

TEST(Psi, MatchesQuadPrecisionForNearlyEqualArguments) {
  Worst worst;
  for (double t : depths())
    for (double eps : {1e-15, 1e-13, 1e-11, 1e-9, 1e-7, 1e-5, 1e-3, 1e-1})
      for (double sign : {-1.0, 1.0}) {
        const double tb = t * (1.0 + sign * eps) + (t == 0.0 ? eps : 0.0);
        worst.update(relativeError(t, tb), t, tb);
        worst.update(relativeError(tb, t), tb, t);
      }
  std::printf("psi nearly equal: worst relative error %.3g at tf=%.17g tb=%.17g\n", worst.error, worst.tf, worst.tb);
  EXPECT_LE(worst.error, 1e-12);
}

TEST(Psi, KnownValuesAndBounds) {
  EXPECT_DOUBLE_EQ(optics::psi(0.0, 0.0), 1.0);
  EXPECT_NEAR(optics::psi(1.0, 1.0), 1.0 - std::exp(-1.0), 1e-16);
  EXPECT_NEAR(optics::psi(1e-8, 1e-8), 1.0 - 0.5e-8, 1e-16);
  for (double tf : depths())
    for (double tb : depths()) {
      const double p = optics::psi(tf, tb), z = optics::zeta(tf, tb);
      EXPECT_LE(p, 1.0);
      EXPECT_GE(p, z * (1.0 - 1e-15));
    }
  // Small thickness: psi ~ 1 - (2 tf + tb) / 6.
  EXPECT_NEAR(optics::psi(2e-6, 8e-6), 1.0 - (2 * 2e-6 + 8e-6) / 6.0, 1e-11);
}

TEST(SegmentIntegral, LinearSegmentEqualsTheEmissionIntegral) {
  // Emission seen from the front: integral of C(x) tau(x) D T(x), T(x) = exp(-int_0^x tau D).
  const double cases[][3] = {{0.3, 2.0, 1.5}, {5.0, 0.01, 0.7}, {1e-6, 3e-6, 2.0}, {40.0, 40.0001, 1.0}, {0.0, 9.0, 0.1}};
  const glm::dvec3 cf(0.9, 0.2, 0.1), cb(0.1, 0.4, 1.0);
  for (const auto& c : cases) {
    const double tauF = c[0], tauB = c[1], D = c[2];
    const auto light = optics::linearSegment(cf, tauF, cb, tauB, D);
    for (int k = 0; k < 3; ++k) {
      const quad emission = volpost::test::adaptiveIntegral(
          [&](quad x) {
            const quad tau = tauF + (quad(tauB) - tauF) * x, color = cf[k] + (quad(cb[k]) - cf[k]) * x;
            const quad depth = D * (tauF * x + (quad(tauB) - tauF) * x * x / 2);
            return color * tau * D * expq(-depth);
          },
          0, 1);
      EXPECT_NEAR(light.color[k], double(emission), 1e-13 * (1.0 + double(emission))) << tauF << " " << tauB;
    }
    EXPECT_NEAR(light.transmittance, std::exp(-0.5 * (tauF + tauB) * D), 1e-16);
  }
}

TEST(SegmentIntegral, CutsAtEveryControlPointCrossed) {
  // A TF with a sharp peak: a segment across it must equal the pieces composited.
  const TransferFunction tf({{0.0, {0, 0, 1}, 0.0}, {0.5, {1, 1, 1}, 50.0}, {0.5001, {1, 0, 0}, 0.0}, {1.0, {1, 0, 0}, 1.0}});
  EXPECT_EQ(tf.crossings(0.0, 1.0), (std::vector<double>{0.5, 0.5001}));
  EXPECT_EQ(tf.crossings(1.0, 0.0), (std::vector<double>{0.5001, 0.5}));
  const auto whole = optics::integrateSegment(tf, 0.2, 0.9, 2.0);
  optics::SegmentLight pieces;
  const double len = 2.0 / 0.7;  // length per unit of s
  optics::compositeBehind(pieces, optics::linearSegment(tf.color(0.2), tf.extinction(0.2), tf.color(0.5), 50.0, 0.3 * len));
  optics::compositeBehind(pieces, optics::linearSegment(tf.color(0.5), 50.0, tf.color(0.5001), 0.0, 0.0001 * len));
  optics::compositeBehind(pieces, optics::linearSegment(tf.color(0.5001), 0.0, tf.color(0.9), tf.extinction(0.9), 0.3999 * len));
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(whole.color[k], pieces.color[k], 1e-13);
  EXPECT_NEAR(whole.transmittance, pieces.transmittance, 1e-13);
}

TEST(SegmentIntegral, EqualEndsIsAConstantSegment) {
  const TransferFunction tf({{0.0, {0.2, 0.4, 0.6}, 1.0}, {1.0, {1, 1, 1}, 3.0}});
  const auto s = optics::integrateSegment(tf, 0.5, 0.5, 0.25);
  const double alpha = 1.0 - std::exp(-2.0 * 0.25);
  EXPECT_NEAR(s.transmittance, 1.0 - alpha, 1e-16);
  EXPECT_NEAR(s.color.r, 0.6 * alpha, 1e-16);
}

// A step (two points at one value): each side of it integrates its own limit, in both
// directions; the value at the step itself belonged to the piece above, so a segment
// rising to it took the higher extinction for the whole piece below.
TEST(IntegrateSegment, EachSideOfAStepTakesItsOwnLimit) {
  const TransferFunction step({{0.0, {1, 1, 1}, 1.0}, {0.5, {1, 0, 0}, 1.0}, {0.5, {0, 0, 1}, 3.0}, {1.0, {0, 0, 1}, 3.0}});
  for (const auto& [front, back] : {std::pair{0.25, 0.75}, std::pair{0.75, 0.25}}) {
    const optics::SegmentLight light = optics::integrateSegment(step, front, back, 2.0);  // half the length each side
    EXPECT_NEAR(light.transmittance, std::exp(-4.0), 1e-14) << front << " -> " << back;
  }
  // Rising: white-to-red below (depth 1) in front of blue (depth 3); the exact light.
  const optics::SegmentLight up = optics::integrateSegment(step, 0.25, 0.75, 2.0);
  const double belowAlpha = 1.0 - std::exp(-1.0), aboveAlpha = 1.0 - std::exp(-3.0);
  EXPECT_NEAR(up.color.b, optics::linearSegment({1, 0.5, 0.5}, 1.0, {1, 0, 0}, 1.0, 1.0).color.b + (1.0 - belowAlpha) * aboveAlpha, 1e-12);
  const optics::TransferSample below = optics::sampleSide(step, 0.5, true), above = optics::sampleSide(step, 0.5, false);
  EXPECT_EQ(below.extinction, 1.0);
  EXPECT_EQ(above.extinction, 3.0);
  EXPECT_EQ(below.color, glm::dvec3(1, 0, 0));
  EXPECT_EQ(optics::sampleSide(step, 0.25, true).extinction, 1.0);
  EXPECT_EQ(optics::sampleSide(step, 2.0, true).extinction, 3.0);
  EXPECT_EQ(optics::sampleSide(step, -1.0, false).extinction, 1.0);
}


// SPDX-License-Identifier: MIT
#include <volpost/core/Quantity.hpp>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat3x3.hpp>
#include <gtest/gtest.h>

#include <cmath>

using namespace volpost;

TEST(VonMises, UniaxialStressIsTheStress) {
  const double t[6] = {100, 0, 0, 0, 0, 0};
  EXPECT_DOUBLE_EQ(vonMises(t), 100.0);
}

TEST(VonMises, PureShearIsSqrt3TimesTau) {
  const double t[6] = {0, 0, 0, 10, 0, 0};
  EXPECT_NEAR(vonMises(t), std::sqrt(3.0) * 10.0, 1e-12);
}

TEST(VonMises, HydrostaticStressIsZero) {
  const double t[6] = {-5, -5, -5, 0, 0, 0};
  EXPECT_NEAR(vonMises(t), 0.0, 1e-12);
}

TEST(PrincipalValues, RecoverEigenvaluesOfARotatedDiagonalTensor) {
  const glm::dmat3 r = glm::dmat3(glm::rotate(glm::dmat4(1.0), 0.7, glm::normalize(glm::dvec3(1, 2, 3))));
  const glm::dmat3 d(glm::dvec3(30, 0, 0), glm::dvec3(0, -20, 0), glm::dvec3(0, 0, 5));
  const glm::dmat3 s = r * d * glm::transpose(r);
  const double t[6] = {s[0][0], s[1][1], s[2][2], s[0][1], s[1][2], s[0][2]};
  const auto p = principalValues(t);
  EXPECT_NEAR(p[0], 30.0, 1e-10);
  EXPECT_NEAR(p[1], 5.0, 1e-10);
  EXPECT_NEAR(p[2], -20.0, 1e-10);
}

TEST(PrincipalValues, RepeatedAndZeroEigenvalues) {
  const double iso[6] = {2, 2, 2, 0, 0, 0};
  for (double v : principalValues(iso)) EXPECT_DOUBLE_EQ(v, 2.0);
  const double zero[6] = {0, 0, 0, 0, 0, 0};
  for (double v : principalValues(zero)) EXPECT_DOUBLE_EQ(v, 0.0);
}

TEST(Quantity, KeysRoundTripForEveryKind) {
  const auto vec = Field::fromValues("U", FieldLocation::Node, 3, {{3, 4, 0, 0, 0, 0}});
  const auto ten = Field::fromValues("S", FieldLocation::Cell, 6, {{1, 2, 3, 4, 5, 6}});
  const auto sca = Field::fromValues("T", FieldLocation::Node, 1, {{20, 30}});
  for (const auto* f : {vec.get(), ten.get(), sca.get()})
    for (const Quantity& q : quantitiesOf(*f)) {
      const auto parsed = parseQuantity(q.key(), *f);
      ASSERT_TRUE(parsed) << q.key();
      EXPECT_EQ(*parsed, q);
    }
  EXPECT_EQ(parseQuantity("U.magnitude", *vec)->op, ScalarOp::Magnitude);
  EXPECT_EQ(parseQuantity("S.mises", *ten)->op, ScalarOp::VonMises);
  EXPECT_EQ(parseQuantity("S.zx", *ten)->component, 5);
  EXPECT_FALSE(parseQuantity("U.mises", *vec));
  EXPECT_FALSE(parseQuantity("T.x", *sca));
}

TEST(Quantity, EvaluatesMagnitudeAndComponents) {
  const auto vec = Field::fromValues("U", FieldLocation::Node, 3, {{3, 4, 0, 0, 0, 2}});
  EXPECT_EQ(evaluate(*vec, *parseQuantity("U.magnitude", *vec), 0), (std::vector<double>{5, 2}));
  EXPECT_EQ(evaluate(*vec, *parseQuantity("U.y", *vec), 0), (std::vector<double>{4, 0}));
}

TEST(Quantity, NaNStaysNaNAndIsCountedApartFromTheRange) {
  const auto ten = Field::fromValues("S", FieldLocation::Node, 6, {{1, 0, 0, 0, 0, 0, std::nan(""), 0, 0, 0, 0, 0}});
  for (const Quantity& q : quantitiesOf(*ten)) {
    const auto v = evaluate(*ten, q, 0);
    const ValueRange r = rangeOf(v);
    if (q.op == ScalarOp::Component && q.component != 0) continue;
    EXPECT_EQ(r.nanCount, 1u) << q.key();
    EXPECT_EQ(r.finiteCount, 1u) << q.key();
  }
}

TEST(Field, LoadsEachStepOnceAndOnlyWhenAsked) {
  int calls = 0;
  Field f("T", FieldLocation::Node, 1, 2, {{"a", 0.0}, {"b", 1.0}}, [&](std::size_t step) {
    ++calls;
    return std::vector<double>{double(step), double(step)};
  });
  EXPECT_EQ(calls, 0);
  EXPECT_FALSE(f.isLoaded(1));
  EXPECT_EQ(f.values(1)[0], 1.0);
  EXPECT_EQ(f.values(1)[0], 1.0);
  EXPECT_EQ(calls, 1);
  EXPECT_TRUE(f.isLoaded(1));
  EXPECT_FALSE(f.isLoaded(0));
  EXPECT_THROW(f.values(2), std::out_of_range);
}

TEST(Field, WrongValueCountFromTheLoaderIsAnError) {
  Field f("T", FieldLocation::Node, 3, 2, {{"", 0.0}}, [](std::size_t) { return std::vector<double>(5); });
  EXPECT_THROW(f.values(0), std::runtime_error);
}

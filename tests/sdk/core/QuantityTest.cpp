// SPDX-License-Identifier: MIT
#include <volpost/core/Quantity.hpp>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat3x3.hpp>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>

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

// The directions are the rotation's columns (up to sign), each with its value: S d = s d.
TEST(PrincipalAxes, DirectionsOfARotatedDiagonalTensor) {
  const glm::dmat3 r = glm::dmat3(glm::rotate(glm::dmat4(1.0), 0.7, glm::normalize(glm::dvec3(1, 2, 3))));
  const glm::dmat3 d(glm::dvec3(30, 0, 0), glm::dvec3(0, -20, 0), glm::dvec3(0, 0, 5));
  const glm::dmat3 s = r * d * glm::transpose(r);
  const double t[6] = {s[0][0], s[1][1], s[2][2], s[0][1], s[1][2], s[0][2]};
  const PrincipalAxes a = principalAxes(t);
  EXPECT_NEAR(a.values[0], 30.0, 1e-10);
  EXPECT_NEAR(a.values[1], 5.0, 1e-10);
  EXPECT_NEAR(a.values[2], -20.0, 1e-10);
  const glm::dvec3 expected[3] = {r[0], r[2], r[1]};  // the columns of 30, 5, -20
  for (int k = 0; k < 3; ++k) {
    const glm::dvec3 v(a.directions[k][0], a.directions[k][1], a.directions[k][2]);
    EXPECT_NEAR(glm::length(v), 1.0, 1e-12);
    EXPECT_NEAR(std::abs(glm::dot(v, expected[k])), 1.0, 1e-10) << k;
    const glm::dvec3 sv = s * v;
    EXPECT_NEAR(glm::length(sv - a.values[k] * v), 0.0, 1e-9) << k;
  }
  // Equal values: any orthonormal pair in their plane, still eigenvectors.
  const double uniaxial[6] = {0, 7, 7, 0, 0, 0};
  const PrincipalAxes u = principalAxes(uniaxial);
  EXPECT_NEAR(std::abs(u.directions[2][0]), 1.0, 1e-12) << "the zero value's direction is x";
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

namespace {

// A tensor with the given principal values along a rotated frame, as (xx yy zz xy yz zx).
std::array<double, 6> rotatedTensor(double p1, double p2, double p3) {
  const glm::dmat3 r = glm::dmat3(glm::rotate(glm::dmat4(1.0), 0.9, glm::normalize(glm::dvec3(2, -1, 3))));
  const glm::dmat3 d(glm::dvec3(p1, 0, 0), glm::dvec3(0, p2, 0), glm::dvec3(0, 0, p3));
  const glm::dmat3 s = r * d * glm::transpose(r);
  return {s[0][0], s[1][1], s[2][2], s[0][1], s[1][2], s[0][2]};
}

}  // namespace

// Principal values 10, 10, -5 (two equal): mean 5, deviator (5, 5, -10).
TEST(TensorScalars, TwoEqualPrincipalValuesByHand) {
  const auto t = rotatedTensor(10, 10, -5);
  EXPECT_NEAR(tensorScalar(ScalarOp::Tresca, t.data()), 15.0, 1e-10);
  EXPECT_NEAR(tensorScalar(ScalarOp::MaxShear, t.data()), 7.5, 1e-10);
  EXPECT_NEAR(tensorScalar(ScalarOp::VonMises, t.data()), 15.0, 1e-10);
  EXPECT_NEAR(tensorScalar(ScalarOp::Pressure, t.data()), -5.0, 1e-10);
  EXPECT_NEAR(tensorScalar(ScalarOp::SignedVonMises, t.data()), 15.0, 1e-10);
  EXPECT_NEAR(tensorScalar(ScalarOp::Triaxiality, t.data()), 1.0 / 3.0, 1e-12);
  EXPECT_NEAR(tensorScalar(ScalarOp::FirstInvariant, t.data()), 15.0, 1e-10);
  EXPECT_NEAR(tensorScalar(ScalarOp::DeviatoricJ2, t.data()), 75.0, 1e-9);    // (25 + 25 + 100) / 2
  EXPECT_NEAR(tensorScalar(ScalarOp::DeviatoricJ3, t.data()), -250.0, 1e-8);  // 5 * 5 * -10
  EXPECT_NEAR(tensorScalar(ScalarOp::LodeAngle, t.data()), 60.0, 1e-5);       // like uniaxial compression
}

TEST(TensorScalars, UniaxialTensionAndCompression) {
  const auto tension = rotatedTensor(90, 0, 0);
  EXPECT_NEAR(tensorScalar(ScalarOp::Tresca, tension.data()), 90.0, 1e-10);
  EXPECT_NEAR(tensorScalar(ScalarOp::Triaxiality, tension.data()), 1.0 / 3.0, 1e-12);
  EXPECT_NEAR(tensorScalar(ScalarOp::LodeAngle, tension.data()), 0.0, 1e-5);
  EXPECT_NEAR(tensorScalar(ScalarOp::DeviatoricJ3, tension.data()), 2.0 * 90 * 90 * 90 / 27, 1e-6);
  const auto compression = rotatedTensor(0, 0, -90);
  EXPECT_NEAR(tensorScalar(ScalarOp::SignedVonMises, compression.data()), -90.0, 1e-10);
  EXPECT_NEAR(tensorScalar(ScalarOp::Pressure, compression.data()), 30.0, 1e-10);
  EXPECT_NEAR(tensorScalar(ScalarOp::Triaxiality, compression.data()), -1.0 / 3.0, 1e-12);
  EXPECT_NEAR(tensorScalar(ScalarOp::LodeAngle, compression.data()), 60.0, 1e-5);
}

// Pure shear tau = 10 on xy: principal 10, 0, -10; no trace.
TEST(TensorScalars, PureShearByHand) {
  const double t[6] = {0, 0, 0, 10, 0, 0};
  EXPECT_NEAR(tensorScalar(ScalarOp::Tresca, t), 20.0, 1e-12);
  EXPECT_NEAR(tensorScalar(ScalarOp::MaxShear, t), 10.0, 1e-12);
  EXPECT_NEAR(tensorScalar(ScalarOp::DeviatoricJ2, t), 100.0, 1e-12);
  EXPECT_NEAR(tensorScalar(ScalarOp::DeviatoricJ3, t), 0.0, 1e-12);
  EXPECT_NEAR(tensorScalar(ScalarOp::LodeAngle, t), 30.0, 1e-10);
  EXPECT_NEAR(tensorScalar(ScalarOp::Triaxiality, t), 0.0, 1e-12);
  EXPECT_NEAR(tensorScalar(ScalarOp::SignedVonMises, t), std::sqrt(300.0), 1e-12);  // zero trace counts as +
}

// Three equal principal values: no shear, no deviator; the triaxiality and the Lode angle
// are undefined (NaN, shown as "no value"), everything else exact.
TEST(TensorScalars, HydrostaticTensorHasNoDeviatoricDirection) {
  const auto t = rotatedTensor(-7, -7, -7);
  EXPECT_NEAR(tensorScalar(ScalarOp::Tresca, t.data()), 0.0, 1e-12);
  EXPECT_NEAR(tensorScalar(ScalarOp::Pressure, t.data()), 7.0, 1e-12);
  EXPECT_NEAR(tensorScalar(ScalarOp::DeviatoricJ2, t.data()), 0.0, 1e-20);
  const double exact[6] = {-7, -7, -7, 0, 0, 0};
  EXPECT_TRUE(std::isnan(tensorScalar(ScalarOp::Triaxiality, exact)));
  EXPECT_TRUE(std::isnan(tensorScalar(ScalarOp::LodeAngle, exact)));
  EXPECT_EQ(tensorScalar(ScalarOp::SignedVonMises, exact), 0.0);
}

TEST(TensorScalars, ANonFiniteComponentGivesNaNForEveryScalar) {
  const double t[6] = {1, 2, std::numeric_limits<double>::infinity(), 0, 0, 0};
  for (ScalarOp op : {ScalarOp::VonMises, ScalarOp::Tresca, ScalarOp::LodeAngle, ScalarOp::Principal1})
    EXPECT_TRUE(std::isnan(tensorScalar(op, t)));
}

TEST(Quantity, AnglesOfAVectorToTheAxesInDegrees) {
  const auto vec = Field::fromValues("U", FieldLocation::Node, 3, {{1, 1, 0, 0, 0, -2, 0, 0, 0}});
  EXPECT_EQ(parseQuantity("U.anglez", *vec)->op, ScalarOp::AngleZ);
  const auto x = evaluate(*vec, *parseQuantity("U.anglex", *vec), 0);
  const auto z = evaluate(*vec, *parseQuantity("U.anglez", *vec), 0);
  EXPECT_NEAR(x[0], 45.0, 1e-12);
  EXPECT_NEAR(z[0], 90.0, 1e-12);
  EXPECT_NEAR(z[1], 180.0, 1e-12);
  EXPECT_TRUE(std::isnan(x[2]));  // a zero vector has no direction
  EXPECT_EQ(parseQuantity("U.anglex", *vec)->displayName(), "U angle to X");
}

TEST(Quantity, EveryTensorScalarIsOfferedReadAndNamed) {
  const auto ten = Field::fromValues("S", FieldLocation::Cell, 6, {{10, 0, 0, 0, 0, 0}});
  for (const char* key :
       {"S.tresca", "S.maxshear", "S.pressure", "S.smises", "S.triaxiality", "S.i1", "S.j2", "S.j3", "S.lode"}) {
    const auto q = parseQuantity(key, *ten);
    ASSERT_TRUE(q) << key;
    EXPECT_TRUE(std::isfinite(evaluate(*ten, *q, 0)[0])) << key;
  }
  EXPECT_EQ(parseQuantity("S.smises", *ten)->displayName(), "S signed von Mises");
  EXPECT_EQ(parseQuantity("S.lode", *ten)->displayName(), "S Lode angle");
  EXPECT_FALSE(parseQuantity("S.anglex", *ten));
  const auto vec = Field::fromValues("U", FieldLocation::Node, 3, {{1, 0, 0}});
  EXPECT_FALSE(parseQuantity("U.tresca", *vec));
  EXPECT_THROW(evaluateComponents(*parseQuantity("S.tresca", *ten), std::vector<double>{1, 2, 3}),
               std::invalid_argument);
}

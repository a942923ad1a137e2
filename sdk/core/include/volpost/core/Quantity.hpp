// SPDX-License-Identifier: MIT
// Scalar quantities derived from fields: components, magnitude, angles of vectors; von Mises,
// principal values, Tresca, pressure, triaxiality and the invariants of symmetric tensors.
#pragma once

#include <volpost/core/Field.hpp>
#include <volpost/core/SampleView.hpp>

#include <array>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace volpost {

enum class ScalarOp {
  Component,
  Magnitude,
  // vectors: the angle to a coordinate axis, in degrees (0 to 180)
  AngleX,
  AngleY,
  AngleZ,
  // symmetric tensors (docs/user/quantities.md has each formula)
  VonMises,
  Principal1,
  Principal2,
  Principal3,
  Tresca,
  MaxShear,
  Pressure,
  SignedVonMises,
  Triaxiality,
  FirstInvariant,
  DeviatoricJ2,
  DeviatoricJ3,
  LodeAngle,
};

/// A scalar the user can color by. Written as "NAME" for a scalar field, "NAME.x",
/// "NAME.magnitude", "NAME.anglex" for vectors, "NAME.xx", "NAME.mises", "NAME.p1"
/// (largest principal), "NAME.tresca" ... for symmetric tensors, "NAME.2" for generic arrays.
struct Quantity {
  std::string field;
  ScalarOp op = ScalarOp::Component;
  int component = 0;
  FieldKind fieldKind = FieldKind::Scalar;  ///< kind of the source field (names components)

  std::string key() const;         ///< the written form above
  std::string displayName() const; ///< e.g. "S von Mises", "U magnitude"
  bool operator==(const Quantity&) const = default;
};

/// Every quantity a field offers, in menu order (magnitude / von Mises first).
std::vector<Quantity> quantitiesOf(const Field& field);
/// Parses the written form; nullopt if the suffix does not fit the field's kind.
std::optional<Quantity> parseQuantity(const std::string& text, const Field& field);

/// Whether the quantity is the field's stored samples themselves (a scalar field kept in its
/// file's type, as itself): field.samples() then holds its values, no evaluation needed.
bool isStoredSamples(const Field& field, const Quantity& quantity);
/// Evaluates the quantity for all entities of one step. NaN inputs give NaN.
std::vector<double> evaluate(const Field& field, const Quantity& quantity, std::size_t step);
/// Evaluates the quantity on one entity's components (e.g. a field interpolated at a point).
double evaluateComponents(const Quantity& quantity, std::span<const double> components);

/// Principal values of the symmetric tensor (xx yy zz xy yz zx), sorted descending.
std::array<double, 3> principalValues(const double* t);
/// The principal values (descending) and their unit directions (one per value; for equal
/// values any orthonormal choice in their plane).
struct PrincipalAxes {
  std::array<double, 3> values{};
  std::array<std::array<double, 3>, 3> directions{};
};
PrincipalAxes principalAxes(const double* t);
double vonMises(const double* t);
/// The tensor's scalar for a tensor operation (VonMises .. LodeAngle); NaN where undefined
/// (a NaN component; the triaxiality or Lode angle of a tensor without deviatoric part).
double tensorScalar(ScalarOp op, const double* t);

struct ValueRange {
  double min = 0.0, max = 0.0;
  std::size_t finiteCount = 0;
  std::size_t nanCount = 0;  ///< NaN or infinite values, ignored by min/max
  bool valid() const { return finiteCount > 0; }
};
ValueRange rangeOf(SampleView values);

}  // namespace volpost

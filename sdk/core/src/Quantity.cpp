// SPDX-License-Identifier: MIT
#include <volpost/core/Quantity.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace volpost {
namespace {

constexpr const char* kVectorSuffix[] = {"x", "y", "z"};
constexpr const char* kTensorSuffix[] = {"xx", "yy", "zz", "xy", "yz", "zx"};
constexpr const char* kTensorLabel[] = {"XX", "YY", "ZZ", "XY", "YZ", "ZX"};

std::string suffixOf(const Quantity& q, FieldKind kind) {
  switch (q.op) {
    case ScalarOp::Magnitude: return "magnitude";
    case ScalarOp::VonMises: return "mises";
    case ScalarOp::Principal1: return "p1";
    case ScalarOp::Principal2: return "p2";
    case ScalarOp::Principal3: return "p3";
    case ScalarOp::Component: break;
  }
  if (kind == FieldKind::Vector) return kVectorSuffix[q.component];
  if (kind == FieldKind::SymTensor) return kTensorSuffix[q.component];
  return std::to_string(q.component);
}

// Cyclic Jacobi rotations: robust for every symmetric 3x3 (repeated eigenvalues too).
std::array<double, 3> symmetricEigenvalues(double a[3][3]) {
  for (int sweep = 0; sweep < 50; ++sweep) {
    const double off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
    const double diag = a[0][0] * a[0][0] + a[1][1] * a[1][1] + a[2][2] * a[2][2];
    if (off <= 1e-30 * diag || off == 0.0) break;
    for (int p = 0; p < 2; ++p)
      for (int q = p + 1; q < 3; ++q) {
        if (a[p][q] == 0.0) continue;
        const double theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
        const double t = std::copysign(1.0, theta) / (std::abs(theta) + std::sqrt(theta * theta + 1.0));
        const double c = 1.0 / std::sqrt(t * t + 1.0), s = t * c;
        for (int k = 0; k < 3; ++k) {  // A <- J^T A J, rows then columns
          const double akp = a[k][p], akq = a[k][q];
          a[k][p] = c * akp - s * akq;
          a[k][q] = s * akp + c * akq;
        }
        for (int k = 0; k < 3; ++k) {
          const double apk = a[p][k], aqk = a[q][k];
          a[p][k] = c * apk - s * aqk;
          a[q][k] = s * apk + c * aqk;
        }
      }
  }
  std::array<double, 3> ev = {a[0][0], a[1][1], a[2][2]};
  std::sort(ev.begin(), ev.end(), std::greater<>());
  return ev;
}

}  // namespace

std::string Quantity::key() const {
  if (fieldKind == FieldKind::Scalar) return field;
  return field + "." + suffixOf(*this, fieldKind);
}

std::array<double, 3> principalValues(const double* t) {
  double a[3][3] = {{t[0], t[3], t[5]}, {t[3], t[1], t[4]}, {t[5], t[4], t[2]}};
  return symmetricEigenvalues(a);
}

double vonMises(const double* t) {
  const double dxy = t[0] - t[1], dyz = t[1] - t[2], dzx = t[2] - t[0];
  return std::sqrt(0.5 * (dxy * dxy + dyz * dyz + dzx * dzx) +
                   3.0 * (t[3] * t[3] + t[4] * t[4] + t[5] * t[5]));
}

std::vector<Quantity> quantitiesOf(const Field& field) {
  std::vector<Quantity> out;
  const std::string& n = field.name();
  switch (field.kind()) {
    case FieldKind::Scalar: out.push_back({n, ScalarOp::Component, 0}); break;
    case FieldKind::Vector:
      out.push_back({n, ScalarOp::Magnitude, 0});
      for (int i = 0; i < 3; ++i) out.push_back({n, ScalarOp::Component, i});
      break;
    case FieldKind::SymTensor:
      out.push_back({n, ScalarOp::VonMises, 0});
      out.push_back({n, ScalarOp::Principal1, 0});
      out.push_back({n, ScalarOp::Principal2, 0});
      out.push_back({n, ScalarOp::Principal3, 0});
      for (int i = 0; i < 6; ++i) out.push_back({n, ScalarOp::Component, i});
      break;
    case FieldKind::Array:
      out.push_back({n, ScalarOp::Magnitude, 0});
      for (int i = 0; i < field.components(); ++i) out.push_back({n, ScalarOp::Component, i});
      break;
  }
  for (auto& q : out) q.fieldKind = field.kind();
  return out;
}

std::optional<Quantity> parseQuantity(const std::string& text, const Field& field) {
  for (const Quantity& q : quantitiesOf(field))
    if (q.key() == text) return q;
  // A bare name picks the field's first (headline) quantity.
  if (text == field.name()) return quantitiesOf(field).front();
  return std::nullopt;
}

std::string Quantity::displayName() const {
  switch (op) {
    case ScalarOp::Magnitude: return field + " magnitude";
    case ScalarOp::VonMises: return field + " von Mises";
    case ScalarOp::Principal1: return field + " max principal";
    case ScalarOp::Principal2: return field + " mid principal";
    case ScalarOp::Principal3: return field + " min principal";
    case ScalarOp::Component: break;
  }
  if (fieldKind == FieldKind::Vector) return field + " " + kVectorSuffix[component];
  if (fieldKind == FieldKind::SymTensor) return field + " " + kTensorLabel[component];
  if (fieldKind == FieldKind::Array) return field + " [" + std::to_string(component) + "]";
  return field;
}

namespace {

void checkQuantityFits(const Quantity& q, const std::string& fieldName, int nc) {
  if (q.op == ScalarOp::Component && (q.component < 0 || q.component >= nc))
    throw std::out_of_range("field " + fieldName + " has no component " + std::to_string(q.component));
  if ((q.op == ScalarOp::VonMises || q.op >= ScalarOp::Principal1) && nc != 6)
    throw std::invalid_argument("field " + fieldName + " is not a symmetric tensor");
}

double scalarOf(const Quantity& q, const double* t, int nc) {
  switch (q.op) {
    case ScalarOp::Component: return t[q.component];
    case ScalarOp::Magnitude: {
      double s = 0.0;
      for (int c = 0; c < nc; ++c) s += t[c] * t[c];
      return std::sqrt(s);
    }
    case ScalarOp::VonMises: return vonMises(t);
    case ScalarOp::Principal1:
    case ScalarOp::Principal2:
    case ScalarOp::Principal3: {
      bool finite = true;
      for (int c = 0; c < 6; ++c) finite = finite && std::isfinite(t[c]);
      return finite ? principalValues(t)[int(q.op) - int(ScalarOp::Principal1)] : std::numeric_limits<double>::quiet_NaN();
    }
  }
  return std::numeric_limits<double>::quiet_NaN();
}

}  // namespace

bool isStoredSamples(const Field& field, const Quantity& q) {
  return field.storesSamples() && field.components() == 1 && q.op == ScalarOp::Component && q.component == 0 &&
         q.field == field.name();
}

std::vector<double> evaluate(const Field& field, const Quantity& q, std::size_t step) {
  const int nc = field.components();
  checkQuantityFits(q, field.name(), nc);
  if (field.storesSamples() && nc == 1) {
    // A scalar kept in the file's type (a 16-bit seismic cube): converted straight into the
    // result, so the field never holds a double copy of its samples.
    std::vector<double> out = field.valuesCopy(step);
    for (double& x : out) x = scalarOf(q, &x, 1);
    return out;
  }
  const std::vector<double>& v = field.values(step);
  std::vector<double> out(field.entityCount());
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = scalarOf(q, v.data() + i * std::size_t(nc), nc);
  return out;
}

double evaluateComponents(const Quantity& q, std::span<const double> components) {
  checkQuantityFits(q, q.field, int(components.size()));
  return scalarOf(q, components.data(), int(components.size()));
}

ValueRange rangeOf(SampleView values) {
  ValueRange r;
  r.min = std::numeric_limits<double>::infinity();
  r.max = -r.min;
  values.visit([&r](auto typed) {
    for (const auto v : typed) {
      const double x = double(v);
      if (!std::isfinite(x)) {
        ++r.nanCount;
        continue;
      }
      ++r.finiteCount;
      r.min = std::min(r.min, x);
      r.max = std::max(r.max, x);
    }
  });
  if (!r.valid()) r.min = r.max = 0.0;
  return r;
}

}  // namespace volpost

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

// The written suffix and the words of each operation other than a plain component.
struct OpNames {
  ScalarOp op;
  const char* suffix;
  const char* words;
};
constexpr OpNames kOpNames[] = {
    {ScalarOp::Magnitude, "magnitude", "magnitude"},
    {ScalarOp::AngleX, "anglex", "angle to X"},
    {ScalarOp::AngleY, "angley", "angle to Y"},
    {ScalarOp::AngleZ, "anglez", "angle to Z"},
    {ScalarOp::VonMises, "mises", "von Mises"},
    {ScalarOp::Principal1, "p1", "max principal"},
    {ScalarOp::Principal2, "p2", "mid principal"},
    {ScalarOp::Principal3, "p3", "min principal"},
    {ScalarOp::Tresca, "tresca", "Tresca"},
    {ScalarOp::MaxShear, "maxshear", "max shear"},
    {ScalarOp::Pressure, "pressure", "pressure"},
    {ScalarOp::SignedVonMises, "smises", "signed von Mises"},
    {ScalarOp::Triaxiality, "triaxiality", "triaxiality"},
    {ScalarOp::FirstInvariant, "i1", "first invariant"},
    {ScalarOp::DeviatoricJ2, "j2", "deviatoric J2"},
    {ScalarOp::DeviatoricJ3, "j3", "deviatoric J3"},
    {ScalarOp::LodeAngle, "lode", "Lode angle"},
};

const OpNames* namesOf(ScalarOp op) {
  for (const OpNames& n : kOpNames)
    if (n.op == op) return &n;
  return nullptr;  // a plain component
}

bool isTensorOp(ScalarOp op) { return op >= ScalarOp::VonMises; }
bool isAngleOp(ScalarOp op) { return op >= ScalarOp::AngleX && op <= ScalarOp::AngleZ; }

std::string suffixOf(const Quantity& q, FieldKind kind) {
  if (const OpNames* n = namesOf(q.op)) return n->suffix;
  if (kind == FieldKind::Vector) return kVectorSuffix[q.component];
  if (kind == FieldKind::SymTensor) return kTensorSuffix[q.component];
  return std::to_string(q.component);
}

// Cyclic Jacobi rotations: robust for every symmetric 3x3 (repeated eigenvalues too).
// `v` (when given, the identity on entry) gathers the rotations: its columns end as the
// unit eigenvectors of a's diagonal, in a's diagonal order.
void jacobiDiagonalize(double a[3][3], double (*v)[3]) {
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
        if (v)
          for (int k = 0; k < 3; ++k) {  // V <- V J
            const double vkp = v[k][p], vkq = v[k][q];
            v[k][p] = c * vkp - s * vkq;
            v[k][q] = s * vkp + c * vkq;
          }
      }
  }
}

std::array<double, 3> symmetricEigenvalues(double a[3][3]) {
  jacobiDiagonalize(a, nullptr);
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

PrincipalAxes principalAxes(const double* t) {
  double a[3][3] = {{t[0], t[3], t[5]}, {t[3], t[1], t[4]}, {t[5], t[4], t[2]}};
  double v[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  jacobiDiagonalize(a, v);
  std::array<int, 3> order{0, 1, 2};
  std::sort(order.begin(), order.end(), [&](int i, int j) { return a[i][i] > a[j][j]; });
  PrincipalAxes out;
  for (int k = 0; k < 3; ++k) {
    out.values[std::size_t(k)] = a[order[std::size_t(k)]][order[std::size_t(k)]];
    for (int r = 0; r < 3; ++r) out.directions[std::size_t(k)][std::size_t(r)] = v[r][order[std::size_t(k)]];
  }
  return out;
}

double vonMises(const double* t) {
  const double dxy = t[0] - t[1], dyz = t[1] - t[2], dzx = t[2] - t[0];
  return std::sqrt(0.5 * (dxy * dxy + dyz * dyz + dzx * dzx) +
                   3.0 * (t[3] * t[3] + t[4] * t[4] + t[5] * t[5]));
}

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kDegrees = 180.0 / 3.14159265358979323846;

double secondDeviatoricInvariant(const double* t) {
  const double dxy = t[0] - t[1], dyz = t[1] - t[2], dzx = t[2] - t[0];
  return (dxy * dxy + dyz * dyz + dzx * dzx) / 6.0 + t[3] * t[3] + t[4] * t[4] + t[5] * t[5];
}

// The determinant of the deviator s = t - (trace/3) I.
double thirdDeviatoricInvariant(const double* t) {
  const double mean = (t[0] + t[1] + t[2]) / 3.0;
  const double sx = t[0] - mean, sy = t[1] - mean, sz = t[2] - mean;
  const double xy = t[3], yz = t[4], zx = t[5];
  return sx * sy * sz + 2.0 * xy * yz * zx - sx * yz * yz - sy * zx * zx - sz * xy * xy;
}

// The Lode angle in degrees, 0 for uniaxial tension, 30 for pure shear, 60 for uniaxial
// compression: cos(3 theta) = (3 sqrt(3) / 2) J3 / J2^(3/2).
double lodeAngle(const double* t) {
  const double j2 = secondDeviatoricInvariant(t);
  if (!(j2 > 0.0)) return kNaN;  // no deviatoric part: the angle is undefined
  const double c = 1.5 * std::sqrt(3.0) * thirdDeviatoricInvariant(t) / std::pow(j2, 1.5);
  return std::acos(std::clamp(c, -1.0, 1.0)) / 3.0 * kDegrees;
}

}  // namespace

double tensorScalar(ScalarOp op, const double* t) {
  for (int c = 0; c < 6; ++c)
    if (!std::isfinite(t[c])) return kNaN;
  const double trace = t[0] + t[1] + t[2];
  switch (op) {
    case ScalarOp::VonMises:
      return vonMises(t);
    case ScalarOp::Principal1:
      return principalValues(t)[0];
    case ScalarOp::Principal2:
      return principalValues(t)[1];
    case ScalarOp::Principal3:
      return principalValues(t)[2];
    case ScalarOp::Tresca: {
      const auto p = principalValues(t);
      return p[0] - p[2];
    }
    case ScalarOp::MaxShear: {
      const auto p = principalValues(t);
      return 0.5 * (p[0] - p[2]);
    }
    case ScalarOp::Pressure:
      return -trace / 3.0;  // positive in compression
    case ScalarOp::SignedVonMises:
      return trace < 0.0 ? -vonMises(t) : vonMises(t);
    case ScalarOp::Triaxiality: {
      const double mises = vonMises(t);
      return mises > 0.0 ? trace / 3.0 / mises : kNaN;
    }
    case ScalarOp::FirstInvariant:
      return trace;
    case ScalarOp::DeviatoricJ2:
      return secondDeviatoricInvariant(t);
    case ScalarOp::DeviatoricJ3:
      return thirdDeviatoricInvariant(t);
    case ScalarOp::LodeAngle:
      return lodeAngle(t);
    default:
      break;
  }
  throw std::invalid_argument("not an operation on a symmetric tensor");
}

std::vector<Quantity> quantitiesOf(const Field& field) {
  std::vector<Quantity> out;
  const std::string& n = field.name();
  switch (field.kind()) {
    case FieldKind::Scalar: out.push_back({n, ScalarOp::Component, 0}); break;
    case FieldKind::Vector:
      out.push_back({n, ScalarOp::Magnitude, 0});
      for (int i = 0; i < 3; ++i) out.push_back({n, ScalarOp::Component, i});
      for (ScalarOp op : {ScalarOp::AngleX, ScalarOp::AngleY, ScalarOp::AngleZ}) out.push_back({n, op, 0});
      break;
    case FieldKind::SymTensor:
      for (ScalarOp op : {ScalarOp::VonMises, ScalarOp::Principal1, ScalarOp::Principal2, ScalarOp::Principal3})
        out.push_back({n, op, 0});
      for (int i = 0; i < 6; ++i) out.push_back({n, ScalarOp::Component, i});
      for (ScalarOp op :
           {ScalarOp::Tresca, ScalarOp::MaxShear, ScalarOp::Pressure, ScalarOp::SignedVonMises, ScalarOp::Triaxiality,
            ScalarOp::FirstInvariant, ScalarOp::DeviatoricJ2, ScalarOp::DeviatoricJ3, ScalarOp::LodeAngle})
        out.push_back({n, op, 0});
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
  if (const OpNames* n = namesOf(op)) return field + " " + n->words;
  if (fieldKind == FieldKind::Vector) return field + " " + kVectorSuffix[component];
  if (fieldKind == FieldKind::SymTensor) return field + " " + kTensorLabel[component];
  if (fieldKind == FieldKind::Array) return field + " [" + std::to_string(component) + "]";
  return field;
}

namespace {

void checkQuantityFits(const Quantity& q, const std::string& fieldName, int nc) {
  if (q.op == ScalarOp::Component && (q.component < 0 || q.component >= nc))
    throw std::out_of_range("field " + fieldName + " has no component " + std::to_string(q.component));
  if (isTensorOp(q.op) && nc != 6) throw std::invalid_argument("field " + fieldName + " is not a symmetric tensor");
  if (isAngleOp(q.op) && nc != 3) throw std::invalid_argument("field " + fieldName + " is not a vector");
}

// Degrees between the vector and a coordinate axis; NaN for a zero vector (no direction).
double angleToAxis(const double* v, int axis) {
  const double length = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  if (!(length > 0.0) || !std::isfinite(length)) return kNaN;
  return std::acos(std::clamp(v[axis] / length, -1.0, 1.0)) * kDegrees;
}

double scalarOf(const Quantity& q, const double* t, int nc) {
  switch (q.op) {
    case ScalarOp::Component: return t[q.component];
    case ScalarOp::Magnitude: {
      double s = 0.0;
      for (int c = 0; c < nc; ++c) s += t[c] * t[c];
      return std::sqrt(s);
    }
    case ScalarOp::AngleX:
      return angleToAxis(t, 0);
    case ScalarOp::AngleY:
      return angleToAxis(t, 1);
    case ScalarOp::AngleZ:
      return angleToAxis(t, 2);
    default:
      return tensorScalar(q.op, t);
  }
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

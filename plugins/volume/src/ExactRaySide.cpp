// SPDX-License-Identifier: MIT
// Built in a library of its own: CGAL's exact number type wants -frounding-math, which the
// renderer's inner loop should not pay for.
#include "ExactRaySide.hpp"

#include <CGAL/Mpzf.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <utility>

namespace volpost::volume {
namespace {

// Exact arithmetic on doubles (sums and products without rounding), for the few signs that
// neither float nor double can decide.
using Exact = CGAL::Mpzf;
struct ExactVec {
  Exact x, y, z;
  explicit ExactVec(const glm::dvec3& v) : x(v.x), y(v.y), z(v.z) {}
  ExactVec(Exact a, Exact b, Exact c) : x(std::move(a)), y(std::move(b)), z(std::move(c)) {}
};
ExactVec operator-(const ExactVec& a, const ExactVec& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
ExactVec cross(const ExactVec& a, const ExactVec& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
Exact dot(const ExactVec& a, const ExactVec& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
int signOf(const Exact& e) { return int(e.sign()); }
int firstNonZeroSign(const ExactVec& v) {
  for (const Exact* c : {&v.x, &v.y, &v.z})
    if (const int s = signOf(*c)) return s;
  return 0;
}

}  // namespace

// The perturbation: the ray's origin moved by (e, e^2, e^3), then its direction by
// (h, h^2, h^3), h << e^3 (Edelsbrunner and Muecke's simulation of simplicity).
bool rayEdgeSidePositive(const glm::dvec3& o, const glm::dvec3& d, const glm::dvec3& a, const glm::dvec3& b,
                         double& value) {
  const glm::dvec3 ao = a - o, bo = b - o;
  const double v = glm::dot(d, glm::cross(ao, bo));
  const auto l1d = [](const glm::dvec3& x) { return std::abs(x.x) + std::abs(x.y) + std::abs(x.z); };
  if (std::abs(v) > 1e-14 * l1d(d) * l1d(ao) * l1d(bo)) return (value = v) > 0.0;
  const ExactVec ea(a), eb(b), eo(o), ed(d);
  const ExactVec eao = ea - eo;
  value = 0.0;
  const int s0 = signOf(dot(ed, cross(eao, eb - eo)));
  if (s0) return s0 > 0;
  // Origin moved by delta: the product changes by delta . ((a - b) x d).
  if (const int s = firstNonZeroSign(cross(ea - eb, ed))) return s > 0;
  // The edge is parallel to the ray (b - a = lambda d): only the direction's move counts,
  // lambda h . ((a - o) x d), and on the ray's own line -lambda h . (delta x d).
  const int lambda = signOf(dot(eb - ea, ed)) > 0 ? 1 : -1;
  if (const int s = firstNonZeroSign(cross(eao, ed))) return lambda * s > 0;
  const int g = d.z != 0.0 ? (d.z > 0.0 ? 1 : -1) : d.y != 0.0 ? (d.y > 0.0 ? -1 : 1) : (d.x > 0.0 ? 1 : -1);
  return -lambda * g > 0;
}


}  // namespace volpost::volume

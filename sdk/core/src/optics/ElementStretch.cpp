// SPDX-License-Identifier: MIT
#include <volpost/core/optics/ElementStretch.hpp>

#include <volpost/core/optics/PolynomialSegment.hpp>

namespace volpost::optics {
namespace {

std::optional<SegmentLight> fittedStretch(const ElementField& field, std::uint32_t cell, const TransferFunction& tf,
                                          const std::vector<IsoSurface>& isoSurfaces, const glm::dvec3& origin,
                                          const glm::dvec3& direction, double t0, double t1, int halvings) {
  const double mid = 0.5 * (t0 + t1), half = 0.5 * (t1 - t0);
  glm::dvec3 xi = field.start(cell);
  double error = 0.0;
  std::optional<ScalarPolynomial> p;
  if (field.affine(cell)) {
    // The natural coordinates move linearly along the ray: two inverse maps, not seventeen.
    glm::dvec3 front = xi, back = xi;
    if (!field.value(cell, origin + t0 * direction, front) || !field.value(cell, origin + t1 * direction, back))
      return std::nullopt;
    p = fitChebyshev(
        [&](double u) -> std::optional<double> {
          return field.valueAt(cell, front + (0.5 * (u + 1.0)) * (back - front));
        },
        error);
    xi = back;
  } else {
    p = fitChebyshev([&](double u) { return field.value(cell, origin + (mid + half * u) * direction, xi); }, error);
  }
  if (!p) return std::nullopt;
  if (error > kElementFitTolerance * field.valueScale() && halvings < kElementMaxHalvings) {
    auto front = fittedStretch(field, cell, tf, isoSurfaces, origin, direction, t0, mid, halvings + 1);
    if (!front) return std::nullopt;
    const auto back = fittedStretch(field, cell, tf, isoSurfaces, origin, direction, mid, t1, halvings + 1);
    if (!back) return std::nullopt;
    compositeBehind(*front, *back);
    return front;
  }
  const auto gradientAt = [&](double u) {
    glm::dvec3 at = xi;
    return field.value(cell, origin + (mid + half * u) * direction, at) ? field.gradient(cell, at) : glm::dvec3(0.0);
  };
  return integratePolynomialSegment(tf, isoSurfaces, *p, t1 - t0, gradientAt, direction);
}

}  // namespace

std::optional<SegmentLight> integrateElementStretch(const ElementField& field, std::uint32_t cell,
                                                    const TransferFunction& tf,
                                                    const std::vector<IsoSurface>& isoSurfaces,
                                                    const glm::dvec3& origin, const glm::dvec3& direction, double t0,
                                                    double t1) {
  return fittedStretch(field, cell, tf, isoSurfaces, origin, direction, t0, t1, 0);
}

}  // namespace volpost::optics

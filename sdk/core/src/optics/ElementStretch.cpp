// SPDX-License-Identifier: MIT
#include <volpost/core/optics/ElementStretch.hpp>

#include <volpost/core/optics/PolynomialSegment.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace volpost::optics {
namespace {

// The brightest color component a piece can show or let through (the background's is 1).
double brightest(const TransferFunction& tf) {
  double most = 1.0;
  for (const ControlPoint& p : tf.points()) most = std::max({most, p.color.r, p.color.g, p.color.b});
  return most;
}

// The most a pixel can move per unit length and unit change of the scalar anywhere in the
// transfer function (infinite at a step: two points at one value).
double steepest(const TransferFunction& tf, double brightestColor) {
  const auto& points = tf.points();
  double most = 0.0;
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    const ControlPoint &a = points[i], &b = points[i + 1];
    if (a.color == b.color && a.extinction == b.extinction) continue;
    const double width = b.value - a.value;
    if (!(width > 0.0)) return std::numeric_limits<double>::infinity();
    most = std::max(most, pixelSensitivity({a.color, a.extinction}, {b.color, b.extinction}, width, brightestColor));
  }
  return most;
}

std::optional<SegmentLight> fittedStretch(const ElementField& field, std::uint32_t cell, const TransferFunction& tf,
                                          const std::vector<IsoSurface>& isoSurfaces, const glm::dvec3& origin,
                                          const glm::dvec3& direction, double t0, double t1,
                                          const StretchAccuracy& accuracy, int halvings) {
  const double mid = 0.5 * (t0 + t1), half = 0.5 * (t1 - t0);
  glm::dvec3 xi = field.start(cell);
  double error = 0.0;
  std::optional<ScalarPolynomial> p;
  if (field.affine(cell)) {
    // The natural coordinates move linearly along the ray (one inverted Jacobian, no Newton
    // steps), and the field along it is a polynomial of known degree: interpolated exactly.
    const glm::dvec3 ends[2] = {origin + t0 * direction, origin + t1 * direction};
    glm::dvec3 natural[2];
    if (!field.affineCoordinates(cell, ends, natural, 2)) return std::nullopt;
    const glm::dvec3 front = natural[0], back = natural[1];
    if (field.degreeAlongLine(cell) >= 0) {
      p = field.polynomialAlong(cell, front, back);
    } else {
      p = fitChebyshev(
          [&](double u) -> std::optional<double> {
            return field.valueAt(cell, front + (0.5 * (u + 1.0)) * (back - front));
          },
          error);
    }
    xi = back;
  } else {
    p = fitChebyshev([&](double u) { return field.value(cell, origin + (mid + half * u) * direction, xi); }, error);
  }
  if (!p) return std::nullopt;
  if (error > accuracy.fitTolerance && halvings < kElementMaxHalvings) {
    auto front = fittedStretch(field, cell, tf, isoSurfaces, origin, direction, t0, mid, accuracy, halvings + 1);
    if (!front) return std::nullopt;
    const auto back = fittedStretch(field, cell, tf, isoSurfaces, origin, direction, mid, t1, accuracy, halvings + 1);
    if (!back) return std::nullopt;
    compositeBehind(*front, *back);
    return front;
  }
  const auto gradientAt = [&](double u) {
    glm::dvec3 at = xi;
    return field.value(cell, origin + (mid + half * u) * direction, at) ? field.gradient(cell, at) : glm::dvec3(0.0);
  };
  return integratePolynomialSegment(tf, isoSurfaces, *p, t1 - t0, gradientAt, direction, accuracy.emission);
}

}  // namespace

StretchAccuracy exactStretches(const ElementField& field) {
  StretchAccuracy exact;
  exact.fitTolerance = kElementFitTolerance * field.valueScale();
  return exact;
}

StretchAccuracy toleratedStretches(const ElementField& field, const TransferFunction& tf, bool isoSurfaces,
                                   double tolerance) {
  StretchAccuracy accuracy = exactStretches(field);
  if (!(tolerance > 0.0) || !(field.diagonal() > 0.0)) return accuracy;
  // Half for the chords, half for the fit: a fit off by e moves a pixel by at most
  // e * weight per unit length of the ray.
  accuracy.emission = {0.5 * tolerance, field.diagonal(), brightest(tf)};
  const double weight = steepest(tf, accuracy.emission.brightest);
  if (!isoSurfaces && std::isfinite(weight))
    accuracy.fitTolerance = weight > 0.0
                                ? std::max(accuracy.fitTolerance, 0.5 * tolerance / (field.diagonal() * weight))
                                : field.valueScale();
  return accuracy;
}

std::optional<SegmentLight> integrateElementStretch(const ElementField& field, std::uint32_t cell,
                                                    const TransferFunction& tf,
                                                    const std::vector<IsoSurface>& isoSurfaces,
                                                    const glm::dvec3& origin, const glm::dvec3& direction, double t0,
                                                    double t1, const StretchAccuracy& accuracy) {
  return fittedStretch(field, cell, tf, isoSurfaces, origin, direction, t0, t1, accuracy, 0);
}

}  // namespace volpost::optics

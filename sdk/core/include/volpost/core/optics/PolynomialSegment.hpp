// SPDX-License-Identifier: MIT
// A ray segment over which the scalar is a polynomial of the position along it, integrated
// against a piecewise-linear transfer function to rounding. Along a straight ray through a
// cell with straight edges, a finite element's own interpolation is such a polynomial
// (cubic in a hex8, quadratic in a tet10, up to quartic in a hex20); through a distorted
// cell it is fitted to a checked tolerance (fitChebyshev, halved where it does not fit).
//
// The segment is cut where the scalar turns (zeros of its derivative, found recursively
// from the derivative's own turning points) and where it crosses a control point or an
// iso-value. Between cuts the scalar is monotone and the extinction and the color are
// linear in it, so the optical depth is the polynomial's integral (exact) and only the
// emission needs quadrature: Gauss-Legendre, 16 points, on panels of optical depth at most
// 0.1 (the polynomial part is integrated exactly; the exponential's truncation is below
// 1e-15). See docs/methods/element_field.md.
#pragma once

#include <volpost/core/TransferFunction.hpp>
#include <volpost/core/optics/IsoTables.hpp>
#include <volpost/core/optics/SegmentIntegral.hpp>

#include <glm/vec3.hpp>

#include <array>
#include <functional>
#include <optional>
#include <span>
#include <vector>

namespace volpost::optics {

/// s(u) = sum c[k] u^k for u in [-1, 1], u = -1 at the segment's front.
struct ScalarPolynomial {
  static constexpr int kMaxDegree = 8;
  std::array<double, kMaxDegree + 2> c{};  ///< one more than fitted: room for an antiderivative
  int degree = 0;

  double at(double u) const;
  ScalarPolynomial derivative() const;
  /// The antiderivative that is 0 at u = 0.
  ScalarPolynomial antiderivative() const;
};

/// The zeros of p in the open interval (a, b), ascending (a zero of even multiplicity that
/// touches zero counts once, where it is found exactly).
std::vector<double> zerosIn(const ScalarPolynomial& p, double a, double b);

/// The polynomial of degree <= 8 interpolating f at the 9 Chebyshev points of [-1, 1],
/// trailing coefficients below rounding dropped. `error` gets the largest difference from
/// f at the 8 points halfway between them (how well it fits). nullopt where f does.
/// With a `degree` below 8, f is known to be a polynomial of at most that degree: it is
/// interpolated at degree + 1 points, exactly, and `error` is 0.
std::optional<ScalarPolynomial> fitChebyshev(const std::function<std::optional<double>(double u)>& f, double& error,
                                             int degree = ScalarPolynomial::kMaxDegree);

/// How closely the emission is integrated. `tolerance` 0: to rounding (Gauss-Legendre
/// above). Otherwise each monotone piece whose color changes is cut into chords, each lit
/// by the closed form of a linear segment, with the polynomial within
///   delta = tolerance (alpha / length + 1 / rayLength) / (2 W)
/// of its chords, where alpha is the piece's opacity and W = max |d(tau C)/ds| + brightest
/// |d tau/ds| bounds how far a pixel moves per unit length and unit change of the scalar on
/// that piece. Weighted by the transmittance in front, the pieces' opacities add up to at
/// most 1 and their lengths to at most rayLength, so a pixel moves by at most `tolerance`
/// (docs/methods/element_field.md); pieces the transfer function cannot tell apart stay whole.
struct EmissionAccuracy {
  double tolerance = 0.0;
  double rayLength = 1.0;  ///< the longest ray through the mesh
  double brightest = 1.0;  ///< the largest color component in front of or behind the piece
};

/// The n Chebyshev points of [-1, 1] (1 <= n <= kMaxDegree + 1), ascending.
std::span<const double> chebyshevPoints(int n);
/// The polynomial of degree < n through `values` at chebyshevPoints(n), n = values.size(),
/// trailing coefficients below rounding dropped.
ScalarPolynomial interpolateChebyshev(std::span<const double> values);

/// How far a pixel (color or opacity) can move per unit length and per unit change of the
/// scalar where the transfer function goes linearly from `a` to `b` over `valueSpan`
/// (non-zero): max |d(tau C)/ds| + brightest |d tau/ds|, both linear in s there, largest at
/// an end. `brightest` bounds the color in front of or behind (the background's is 1).
double pixelSensitivity(const TransferSample& a, const TransferSample& b, double valueSpan, double brightest);

/// What the ray needs to shade an iso-surface met at u: the field's gradient there.
using GradientAlong = std::function<glm::dvec3(double u)>;

/// The segment of `length` (front at u = -1) with the scalar `s`, with the iso-surfaces it
/// crosses (a surface counts where the scalar reaches its value coming from the front: in
/// (s(-1), s(1)] along each monotone stretch), composited front to back. Iso-surfaces are
/// shaded 0.3 + 0.7 |cos| against the unit `direction` with gradientAt.
SegmentLight integratePolynomialSegment(const TransferFunction& tf, const std::vector<IsoSurface>& isoSurfaces,
                                        const ScalarPolynomial& s, double length, const GradientAlong& gradientAt,
                                        const glm::dvec3& direction, const EmissionAccuracy& accuracy = {});

}  // namespace volpost::optics

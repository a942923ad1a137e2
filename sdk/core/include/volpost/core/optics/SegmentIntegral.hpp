// SPDX-License-Identifier: MIT
// Exact integration of the emission-absorption model over a ray segment (Williams & Max
// 1992; Moreland & Angel 2004). A segment of length D goes from its front (nearest the
// eye) to its back; color C and extinction tau are linear along it. With
//   tf = tau_front * D, tb = tau_back * D,
//   zeta = exp(-(tf + tb) / 2)                                 (its transmittance)
//   psi  = integral_0^1 exp(-tf x - (tb - tf) x^2 / 2) dx       (mean transmittance)
// the light leaving the front is  I0 * zeta + C_back (psi - zeta) + C_front (1 - psi),
// exactly, for linear C (integration by parts of C tau T with T' = -tau D T).
#pragma once

#include <volpost/core/TransferFunction.hpp>

#include <glm/vec3.hpp>

namespace volpost::optics {

/// exp(-(tf + tb) / 2).
double zeta(double tf, double tb);

/// psi(tf, tb) for tf, tb >= 0 in double precision, stable from 0 to 1e4 and for nearly
/// equal arguments: expm1 when tf == tb, a 9-term series for thin segments (optical depth
/// <= 0.1), otherwise Gauss-Legendre quadrature of the (monotone, positive) integrand on
/// panels of bounded optical depth and slope, cut where it falls below 1e-17. No closed form with erf/erfi (unstable)
/// is used. Worst relative error measured against a 113-bit adaptive quadrature: see docs/methods/optics.md and
/// PsiTest.
double psi(double tf, double tb);

/// What a segment adds when composited front to back: `color` is the associated
/// (premultiplied) color it emits toward the eye; `transmittance` multiplies what is
/// behind it (alpha = 1 - transmittance).
struct SegmentLight {
  glm::dvec3 color{0.0};
  double transmittance = 1.0;
};

/// Color and extinction linear from front to back over `length`.
SegmentLight linearSegment(const glm::dvec3& colorFront, double tauFront, const glm::dvec3& colorBack, double tauBack,
                           double length);

/// Constant color and extinction: alpha = 1 - exp(-tau D), associated color C alpha.
SegmentLight constantSegment(const glm::dvec3& color, double tau, double length);

/// The function at s as a piece of a segment sees it: `fromBelow`, a piece reaching s from
/// lower values (where several points share the value s, the first); otherwise a piece
/// going on to higher values (the last). Two points at one value are a step, and each side
/// of it integrates its own limit.
struct TransferSample {
  glm::dvec3 color{0.0};
  double extinction = 0.0;
};
TransferSample sampleSide(const TransferFunction& tf, double s, bool fromBelow);

/// A segment over which the scalar goes linearly from sFront to sBack: cut at every
/// control point crossed, each piece integrated exactly, composited front to back.
SegmentLight integrateSegment(const TransferFunction& tf, double sFront, double sBack, double length);

/// Front-to-back "over": accumulates a segment behind what was accumulated so far.
inline void compositeBehind(SegmentLight& accumulated, const SegmentLight& segment) {
  accumulated.color += accumulated.transmittance * segment.color;
  accumulated.transmittance *= segment.transmittance;
}

}  // namespace volpost::optics

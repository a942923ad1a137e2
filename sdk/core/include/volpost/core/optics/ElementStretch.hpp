// SPDX-License-Identifier: MIT
// One straight stretch of a ray inside one cell, lit through the cell's own interpolation
// (ElementField): the field along it fitted by a polynomial, halved until the fit holds,
// each piece integrated to rounding (PolynomialSegment). What the reference and the CPU ray
// caster share; docs/methods/element_field.md derives its error.
#pragma once

#include <volpost/core/TransferFunction.hpp>
#include <volpost/core/optics/ElementField.hpp>
#include <volpost/core/optics/IsoTables.hpp>
#include <volpost/core/optics/PolynomialSegment.hpp>
#include <volpost/core/optics/SegmentIntegral.hpp>

#include <glm/vec3.hpp>

#include <cstdint>
#include <optional>
#include <vector>

namespace volpost::optics {

/// How far the fitted polynomial may stray from the element's field, relative to the
/// field's range (ElementField::valueScale), before a stretch is halved; and how often it may
/// be halved (pieces down to 1/1024 of the stretch).
inline constexpr double kElementFitTolerance = 1e-10;
inline constexpr int kElementMaxHalvings = 10;

/// How closely a stretch is drawn: to rounding (the reference; `exact`), or within a
/// tolerance on each pixel channel (the fast path: docs/methods/element_field.md).
struct StretchAccuracy {
  EmissionAccuracy emission;  ///< chords where the transfer function's slope allows
  double fitTolerance = 0.0;  ///< how far the fitted polynomial may stray, field units
};

/// To rounding: the fit within kElementFitTolerance of the field's range, emission by
/// quadrature.
StretchAccuracy exactStretches(const ElementField& field);

/// Each pixel channel within `tolerance` (> 0) of the exact picture on top of what the
/// caller's own approximations add: half of it spent on the fit, half on chords, both
/// spread over the longest ray (the field's diagonal) and weighed by the transfer
/// function's steepest change. With iso-surfaces the fit stays exact (a surface's position
/// follows the polynomial).
StretchAccuracy toleratedStretches(const ElementField& field, const TransferFunction& tf, bool isoSurfaces,
                                   double tolerance);

/// The ray origin + t direction (field coordinates, unit direction) from t0 to t1 inside
/// `cell`, with the iso-surfaces it crosses. nullopt where the cell's map could not be
/// inverted at a point of the stretch (the caller draws the split's field there).
std::optional<SegmentLight> integrateElementStretch(const ElementField& field, std::uint32_t cell,
                                                    const TransferFunction& tf,
                                                    const std::vector<IsoSurface>& isoSurfaces,
                                                    const glm::dvec3& origin, const glm::dvec3& direction, double t0,
                                                    double t1, const StretchAccuracy& accuracy);

}  // namespace volpost::optics

// SPDX-License-Identifier: MIT
// One straight stretch of a ray inside one cell, lit through the cell's own interpolation
// (ElementField): the field along it fitted by a polynomial, halved until the fit holds,
// each piece integrated to rounding (PolynomialSegment). What the reference and the CPU ray
// caster share; docs/methods/element_field.md derives its error.
#pragma once

#include <volpost/core/TransferFunction.hpp>
#include <volpost/core/optics/ElementField.hpp>
#include <volpost/core/optics/IsoTables.hpp>
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

/// The ray origin + t direction (field coordinates, unit direction) from t0 to t1 inside
/// `cell`, with the iso-surfaces it crosses. nullopt where the cell's map could not be
/// inverted at a point of the stretch (the caller draws the split's field there).
std::optional<SegmentLight> integrateElementStretch(const ElementField& field, std::uint32_t cell,
                                                    const TransferFunction& tf,
                                                    const std::vector<IsoSurface>& isoSurfaces,
                                                    const glm::dvec3& origin, const glm::dvec3& direction, double t0,
                                                    double t1);

}  // namespace volpost::optics

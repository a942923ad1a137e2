// SPDX-License-Identifier: MIT
// The exact integral of a segment with linear color and extinction (SegmentIntegral.hpp),
// made cheap for a renderer's inner loop: most pieces of a fine mesh are optically thin,
// and for them psi comes from a short series instead of quadrature.
#pragma once

#include <volpost/core/optics/SegmentIntegral.hpp>

namespace volpost::optics {

/// psi(tf, tb) for a thin piece, (tf + tb) / 2 <= 0.5, from its series (order 3 to 8 as the
/// depth needs), within 6e-9 of psi.
double thinPsi(double tf, double tb);

/// As linearSegment, with psi from thinPsi where the piece is thin (optical depth <= 0.5)
/// and from psi otherwise: within 6e-9 of it.
SegmentLight quickLinearSegment(const glm::dvec3& colorFront, double tauFront, const glm::dvec3& colorBack,
                                double tauBack, double length);

}  // namespace volpost::optics

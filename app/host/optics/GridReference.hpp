// SPDX-License-Identifier: MIT
// The exact CPU reference for regular grids: the trilinear interpolant of the point values,
// integrated along each ray in double precision without sampling. A ray is cut where it
// crosses a grid plane; inside one cell the trilinear field along a line is exactly a cubic
// in the ray parameter, which is cut again where it crosses a control-point value or an
// iso-value (roots of the cubic, by bisection on its monotone pieces). Between cuts the
// extinction and the color are cubics in the parameter: the optical depth is integrated
// exactly (a quartic) and the emitted light by 8-point Gauss-Legendre on panels of optical
// depth <= 0.25 (the truncation is below 1e-20 of the panel). The yardstick of the texture
// renderers, which sample the same trilinear field along rays.
#pragma once

#include "host/optics/ReferenceRenderer.hpp"

#include <volpost/core/RegularGrid.hpp>
#include <volpost/core/SampleView.hpp>
#include <volpost/core/TransferFunction2D.hpp>

#include <span>

namespace volpost::optics {

/// One ray: origin (model units), direction of any length (distances along the unit
/// direction), over [tMin, tMax].
SegmentLight integrateGridRay(const RegularGrid& grid, SampleView values, const TransferFunction& tf,
                              glm::dvec3 origin, glm::dvec3 direction, double tMin, double tMax,
                              const RaySettings& settings = {});

/// The picture, with the same rays as every renderer (pixel centres). Throws
/// std::invalid_argument for a grid with a defect or a wrong value count; Cancelled.
ReferenceImage renderGridReference(const RegularGrid& grid, SampleView values, const TransferFunction& tf,
                                   const Camera& camera, int width, int height, const RaySettings& settings = {},
                                   const Progress& progress = {}, int threads = 0);

/// With a 2D transfer function (value, gradient magnitude), which has no exact integral along
/// a ray: the midpoint rule in each cell with the cell's exact trilinear value and gradient,
/// the step halved from a quarter of the shortest spacing until the ray's light changes by
/// at most `tolerance` per channel in one halving after at most twice that in the one
/// before (at most ten halvings); iso-surfaces as above.
SegmentLight integrateGridRay2D(const RegularGrid& grid, SampleView values, const TransferFunction2D& tf,
                                glm::dvec3 origin, glm::dvec3 direction, double tMin, double tMax,
                                const RaySettings& settings = {}, double tolerance = 1e-5);
ReferenceImage renderGridReference2D(const RegularGrid& grid, SampleView values,
                                     const TransferFunction2D& tf, const Camera& camera, int width, int height,
                                     const RaySettings& settings = {}, double tolerance = 1e-5,
                                     const Progress& progress = {}, int threads = 0);

}  // namespace volpost::optics

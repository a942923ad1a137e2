// SPDX-License-Identifier: MIT
// The exact CPU reference: one ray per pixel through the tetrahedra, in double precision.
// Every tet the ray meets contributes the interval where the ray is inside it (clipped by
// the clip planes); intervals are integrated exactly (cut at every control point crossed)
// and composited front to back. Robust by construction: a shared face is one plane for
// both tets, so intervals of neighbours meet at the same parameter, and points exactly on
// a plane are given to one side by a symbolic perturbation; rays through vertices, along
// edges and in faces are neither lost nor counted twice. Non-convex meshes need nothing
// special: a ray that leaves and re-enters just has a gap between intervals.
#pragma once

#include <volpost/core/Camera.hpp>
#include <volpost/core/ClipPlane.hpp>
#include <volpost/core/Progress.hpp>
#include <volpost/core/TransferFunction.hpp>
#include <volpost/core/optics/ElementField.hpp>
#include <volpost/core/optics/IsoTables.hpp>
#include <volpost/core/optics/SegmentIntegral.hpp>
#include "host/optics/CurvedCells.hpp"
#include "host/optics/TetVolume.hpp"

#include <glm/vec4.hpp>

#include <functional>
#include <string>
#include <vector>

namespace volpost::optics {

struct RaySettings {
  std::vector<ClipPlane> clipPlanes;  ///< in model coordinates
  /// Surfaces where the scalar crosses these values, composited where the ray meets them,
  /// shaded by the cell gradient (0.3 + 0.7 |cos| headlight; unshaded for element results).
  std::vector<IsoSurface> isoSurfaces;
  double terminationTransmittance = 0.0;  ///< stop when what is behind counts less (0: never)
  /// Regular grids: the emission shaded by the trilinear gradient with the light at the eye
  /// (volpost/core/optics/Headlight.hpp), exactly at every quadrature point.
  bool shading = false;
  /// The field as the cells' own shape functions interpolate it (null: linear on the
  /// tetrahedra). It must be built on the same split and origin as the volume.
  const ElementField* elementField = nullptr;
  /// With elementField: its curved cells, whose own shape the rays follow (renderReference
  /// finds them when null; integrateRay alone then draws them as the split's facets).
  const CurvedCells* curvedCells = nullptr;
};

/// Integrates one ray: origin in model coordinates, direction of any length (distances
/// are measured along the unit direction), over t in [tMin, tMax] of the unit direction.
SegmentLight integrateRay(const TetVolume& volume, const TransferFunction& tf, glm::dvec3 origin,
                          glm::dvec3 direction, double tMin, double tMax, const RaySettings& settings = {});

/// Total length of the ray inside the (clipped) mesh: a check that nothing is lost or
/// counted twice.
double lengthInside(const TetVolume& volume, glm::dvec3 origin, glm::dvec3 direction, double tMin, double tMax,
                    const RaySettings& settings = {});

/// A piece over which the scalar goes linearly from sFront to sBack, cut at the
/// iso-surfaces it crosses (in (sFront, sBack]), each composited there, shaded by
/// `gradient` (0.3 + 0.7 |cos| headlight against the unit `direction`).
SegmentLight segmentWithSurfaces(const TransferFunction& tf, const RaySettings& settings, double sFront, double sBack,
                                 double length, const glm::dvec3& gradient, const glm::dvec3& direction);

struct ReferenceImage {
  int width = 0, height = 0;
  std::vector<glm::dvec4> pixels;  ///< premultiplied RGB and alpha, top row first
  std::vector<std::string> notes;  ///< what the user should know about how it was drawn
};

/// Renders the volume as seen by the camera (the same rays as the GPU renderers: through
/// pixel centres, perspective or orthographic). Multithreaded (threads = 0: all cores).
/// Throws Cancelled if progress says so.
/// The pixel loop every reference shares: one ray per pixel centre (perspective or
/// orthographic, near plane to far plane), `ray(origin, direction, tMin, tMax)` on
/// `threads` cores (0: all), rows handed out in turn. Throws Cancelled.
using PixelRay = std::function<SegmentLight(glm::dvec3 origin, glm::dvec3 direction, double tMin, double tMax)>;
ReferenceImage renderPixelRays(const Camera& camera, int width, int height, const PixelRay& ray,
                               const Progress& progress = {}, int threads = 0);

ReferenceImage renderReference(const TetVolume& volume, const TransferFunction& tf, const Camera& camera, int width,
                               int height, const RaySettings& settings = {}, const Progress& progress = {},
                               int threads = 0);

}  // namespace volpost::optics

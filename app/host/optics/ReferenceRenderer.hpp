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
#include <volpost/core/optics/IsoTables.hpp>
#include <volpost/core/optics/SegmentIntegral.hpp>
#include "host/optics/TetVolume.hpp"

#include <glm/vec4.hpp>

#include <vector>

namespace volpost::optics {

struct RaySettings {
  std::vector<ClipPlane> clipPlanes;  ///< in model coordinates
  /// Surfaces where the scalar crosses these values, composited where the ray meets them,
  /// shaded by the cell gradient (0.3 + 0.7 |cos| headlight; unshaded for element results).
  std::vector<IsoSurface> isoSurfaces;
  double terminationTransmittance = 0.0;  ///< stop when what is behind counts less (0: never)
};

/// Integrates one ray: origin in model coordinates, direction of any length (distances
/// are measured along the unit direction), over t in [tMin, tMax] of the unit direction.
SegmentLight integrateRay(const TetVolume& volume, const TransferFunction& tf, glm::dvec3 origin,
                          glm::dvec3 direction, double tMin, double tMax, const RaySettings& settings = {});

/// Total length of the ray inside the (clipped) mesh: a check that nothing is lost or
/// counted twice.
double lengthInside(const TetVolume& volume, glm::dvec3 origin, glm::dvec3 direction, double tMin, double tMax,
                    const RaySettings& settings = {});

struct ReferenceImage {
  int width = 0, height = 0;
  std::vector<glm::dvec4> pixels;  ///< premultiplied RGB and alpha, top row first
};

/// Renders the volume as seen by the camera (the same rays as the GPU renderers: through
/// pixel centres, perspective or orthographic). Multithreaded (threads = 0: all cores).
/// Throws Cancelled if progress says so.
ReferenceImage renderReference(const TetVolume& volume, const TransferFunction& tf, const Camera& camera, int width,
                               int height, const RaySettings& settings = {}, const Progress& progress = {},
                               int threads = 0);

}  // namespace volpost::optics

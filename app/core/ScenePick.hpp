// SPDX-License-Identifier: MIT
// The model point under a pixel of the view: the first hit of the pixel's ray with the
// model's outer surface, found on the CPU in double precision (no GL read-back, so the
// window, tests and scripts pick the same point).
#pragma once

#include "Scene.hpp"

#include <glm/vec3.hpp>

#include <functional>
#include <optional>
#include <span>

namespace volpost::app {

struct PickRay {
  glm::dvec3 origin{0.0};
  glm::dvec3 direction{0.0, 0.0, -1.0};  ///< unit length
};

/// The ray through pixel (x, y) (top left origin, fractional pixels allowed) of a
/// `width` x `height` picture taken with `camera`.
PickRay pixelRay(const Camera& camera, double x, double y, double width, double height);

struct SurfacePick {
  glm::dvec3 point{0.0};
  std::size_t cell = 0;     ///< the element whose face was hit
  double distance = 0.0;    ///< along the ray from its origin
};

/// The first point of the model's boundary surface along the ray that `kept` accepts (all,
/// without one; nullopt: a miss).
std::optional<SurfacePick> pickSurface(const ModelSession& session, const PickRay& ray,
                                       const std::function<bool(const glm::dvec3&)>& kept = {});

/// The first point along the ray of what the scene shows to click on: the boundary surface
/// where the clip planes and box keep it, the section faces they cut, the iso-surfaces of
/// the surface view (their triangles as last drawn: SceneDrawing::isoSurfaceCorners), a
/// regular grid's slices; not the surface while it is hidden. Where the boundary is drawn in
/// the cells' own curved shapes, `curvedBoundaryCorners` (SceneDrawing::curvedBoundaryCorners)
/// are its triangles, picked instead of the model's flat faces. nullopt: a miss.
std::optional<glm::dvec3> pickScenePoint(const Scene& scene, const PickRay& ray,
                                         std::span<const glm::dvec3> isoSurfaceCorners = {},
                                         std::span<const glm::dvec3> curvedBoundaryCorners = {});

}  // namespace volpost::app

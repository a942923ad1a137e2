// SPDX-License-Identifier: MIT
#include "ScenePick.hpp"

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace volpost::app {

PickRay pixelRay(const Camera& camera, double x, double y, double width, double height) {
  const double aspect = height > 0.0 ? width / height : 1.0;
  const glm::dmat4 toModel = glm::inverse(camera.projectionMatrix(aspect) * camera.viewMatrix());
  const double nx = 2.0 * x / width - 1.0, ny = 1.0 - 2.0 * y / height;
  const glm::dvec4 n = toModel * glm::dvec4(nx, ny, -1.0, 1.0), f = toModel * glm::dvec4(nx, ny, 1.0, 1.0);
  const glm::dvec3 a = glm::dvec3(n) / n.w, b = glm::dvec3(f) / f.w;
  return {a, glm::normalize(b - a)};
}

// Moller-Trumbore in double: the ray's parameter where it crosses the triangle (> 0).
std::optional<double> rayHitsTriangle(const PickRay& ray, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  const glm::dvec3 e1 = b - a, e2 = c - a;
  const glm::dvec3 p = glm::cross(ray.direction, e2);
  const double det = glm::dot(e1, p);
  if (!(std::abs(det) > 0.0)) return std::nullopt;
  const glm::dvec3 s = ray.origin - a;
  // A ray along the side two triangles share must land on one of them: each is widened by
  // a rounding's worth (its own rounding could leave the ray just outside both).
  constexpr double kSide = 1e-9;
  const double u = glm::dot(s, p) / det;
  if (u < -kSide || u > 1.0 + kSide) return std::nullopt;
  const glm::dvec3 q = glm::cross(s, e1);
  const double w = glm::dot(ray.direction, q) / det;
  if (w < -kSide || u + w > 1.0 + kSide) return std::nullopt;
  const double t = glm::dot(e2, q) / det;
  return t > 0.0 ? std::optional(t) : std::nullopt;
}

// The ray's parameter where it crosses the plane (> 0), nullopt when it runs along it or the
// crossing is behind.
std::optional<double> rayHitsPlane(const PickRay& ray, const ClipPlane& plane) {
  const double along = glm::dot(ray.direction, plane.normal);
  if (!(std::abs(along) > 0.0)) return std::nullopt;
  const double t = glm::dot(plane.point - ray.origin, plane.normal) / along;
  return t > 0.0 ? std::optional(t) : std::nullopt;
}

std::optional<SurfacePick> pickSurface(const ModelSession& session, const PickRay& ray,
                                       const std::function<bool(const glm::dvec3&)>& kept) {
  const BoundarySurface& surface = session.surface();
  const Model& model = session.model();
  std::optional<SurfacePick> best;
  double nearest = std::numeric_limits<double>::infinity();
  // Moller-Trumbore on every boundary triangle, in double on the model's own node
  // positions (the surface mesh keeps float copies for drawing).
  for (const auto face : surface.mesh.faces()) {
    glm::dvec3 v[3];
    int k = 0;
    for (const auto vertex : surface.mesh.fv_range(face)) v[k++] = model.nodePosition(surface.mesh.property(surface.nodeOfVertex, vertex));
    const auto t = rayHitsTriangle(ray, v[0], v[1], v[2]);
    if (t && *t < nearest && (!kept || kept(ray.origin + *t * ray.direction))) {
      nearest = *t;
      best = SurfacePick{ray.origin + *t * ray.direction, surface.mesh.property(surface.cellOfFace, face), *t};
    }
  }
  return best;
}

namespace {

// The nearest crossing of the ray with the triangles (three corners each) that `kept`
// accepts, nearer than `nearest` (then lowered to it).
std::optional<glm::dvec3> pickTriangles(const PickRay& ray, std::span<const glm::dvec3> corners,
                                        const std::function<bool(const glm::dvec3&)>& kept, double& nearest) {
  std::optional<glm::dvec3> best;
  for (std::size_t i = 0; i + 2 < corners.size(); i += 3)
    if (const auto t = rayHitsTriangle(ray, corners[i], corners[i + 1], corners[i + 2]); t && *t < nearest) {
      const glm::dvec3 point = ray.origin + *t * ray.direction;
      if (!kept(point)) continue;
      nearest = *t;
      best = point;
    }
  return best;
}

}  // namespace

std::optional<glm::dvec3> pickScenePoint(const Scene& scene, const PickRay& ray,
                                         std::span<const glm::dvec3> isoSurfaceCorners,
                                         std::span<const glm::dvec3> curvedBoundaryCorners) {
  const ModelSession* session = scene.session();
  if (!session) return std::nullopt;
  const std::vector<ClipPlane> slices = scene.slicePlanes();
  std::optional<glm::dvec3> best;
  double nearest = std::numeric_limits<double>::infinity();
  // What the clip planes and box cut away cannot be clicked; the faces they cut can.
  const std::vector<ClipPlane> cuts = scene.state().volume.allClipPlanes();
  const double tolerance = 1e-9 * std::max(session->bounds().diagonal(), 1e-300);
  const auto kept = [&](const glm::dvec3& p) {
    for (const ClipPlane& c : cuts)
      if (glm::dot(p - c.point, glm::normalize(c.normal)) < -tolerance) return false;
    return true;
  };
  if (scene.state().surfaceShown) {  // a hidden surface cannot be clicked on
    if (!curvedBoundaryCorners.empty()) {
      best = pickTriangles(ray, curvedBoundaryCorners, kept, nearest);
    } else if (const auto hit = pickSurface(*session, ray, kept)) {
      best = hit->point;
      nearest = hit->distance;
    }
  }
  // Iso-surfaces as drawn in the surface view (already cut by the same planes).
  if (!scene.volumeShown())
    if (const auto hit = pickTriangles(ray, isoSurfaceCorners, kept, nearest)) best = hit;
  for (const ClipPlane& cut : cuts) {
    const auto t = rayHitsPlane(ray, cut);
    if (!t || *t >= nearest) continue;
    const glm::dvec3 point = ray.origin + *t * ray.direction;
    if (!kept(point) || !session->locator().locate(point)) continue;  // on the section: inside the model
    nearest = *t;
    best = point;
  }
  if (!slices.empty()) {
    // A slice point counts where it lies in the grid: its index coordinates within the
    // grid's extent (a millionth of a step of slack for the outermost layers).
    const RegularGrid& g = *session->model().grid;
    const glm::dmat3 toIndex = glm::inverse(glm::dmat3(g.axes[0], g.axes[1], g.axes[2]));
    for (const ClipPlane& plane : slices) {
      const auto t = rayHitsPlane(ray, plane);
      if (!t || *t >= nearest) continue;
      const glm::dvec3 point = ray.origin + *t * ray.direction;
      const glm::dvec3 index = toIndex * (point - g.origin);
      bool inside = true;
      for (int a = 0; a < 3; ++a)
        inside = inside && index[a] >= -1e-6 && index[a] <= double(g.dims[std::size_t(a)] - 1) + 1e-6;
      if (!inside) continue;
      nearest = *t;
      best = point;
    }
  }
  return best;
}

}  // namespace volpost::app

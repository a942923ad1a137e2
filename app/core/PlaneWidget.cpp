// SPDX-License-Identifier: MIT
#include "PlaneWidget.hpp"

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

namespace volpost::app {
namespace {

struct Ray {
  glm::dvec3 origin, direction;
};

// The ray of the picture's point `pixel`, from the near plane into the scene.
Ray rayThrough(const Camera& camera, double width, double height, glm::dvec2 pixel) {
  const glm::dmat4 toModel = glm::inverse(camera.projectionMatrix(width / height) * camera.viewMatrix());
  const double x = 2.0 * pixel.x / width - 1.0, y = 1.0 - 2.0 * pixel.y / height;
  const glm::dvec4 n = toModel * glm::dvec4(x, y, -1.0, 1.0), f = toModel * glm::dvec4(x, y, 1.0, 1.0);
  const glm::dvec3 a = glm::dvec3(n) / n.w, b = glm::dvec3(f) / f.w;
  return {a, glm::normalize(b - a)};
}

double distanceToSegment(glm::dvec2 p, glm::dvec2 a, glm::dvec2 b) {
  const glm::dvec2 ab = b - a;
  const double len2 = glm::dot(ab, ab);
  const double t = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
  return glm::length(p - (a + t * ab));
}

}  // namespace

std::vector<glm::dvec3> planeInBox(const ClipPlane& plane, const Bounds& box) {
  const double n = glm::length(plane.normal);
  if (!box.valid || !(n > 0.0) || !std::isfinite(n)) return {};
  const glm::dvec3 normal = plane.normal / n;
  const auto corner = [&](int i) {
    return glm::dvec3(i & 1 ? box.max.x : box.min.x, i & 2 ? box.max.y : box.min.y, i & 4 ? box.max.z : box.min.z);
  };
  const auto side = [&](int i) { return glm::dot(corner(i) - plane.point, normal); };
  std::vector<glm::dvec3> points;
  // The 12 edges join corners that differ in one bit.
  for (int i = 0; i < 8; ++i)
    for (int bit : {1, 2, 4}) {
      const int j = i | bit;
      if (j == i) continue;
      const double si = side(i), sj = side(j);
      if (si == 0.0) points.push_back(corner(i));
      if ((si < 0.0) != (sj < 0.0) && si != 0.0 && sj != 0.0) points.push_back(corner(i) + (si / (si - sj)) * (corner(j) - corner(i)));
    }
  // Corners on the plane were added once per edge leaving them: keep one of each.
  std::vector<glm::dvec3> unique;
  const double eps = 1e-12 * std::max(box.diagonal(), 1e-300);
  for (const glm::dvec3& p : points)
    if (std::none_of(unique.begin(), unique.end(), [&](const glm::dvec3& q) { return glm::length(p - q) <= eps; }))
      unique.push_back(p);
  if (unique.size() < 3) return {};
  glm::dvec3 c(0.0);
  for (const glm::dvec3& p : unique) c += p;
  c /= double(unique.size());
  // Round the polygon by angle in a basis of the plane.
  const glm::dvec3 helper = std::abs(normal.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
  const glm::dvec3 u = glm::normalize(glm::cross(normal, helper)), v = glm::cross(normal, u);
  std::sort(unique.begin(), unique.end(), [&](const glm::dvec3& a, const glm::dvec3& b) {
    return std::atan2(glm::dot(a - c, v), glm::dot(a - c, u)) < std::atan2(glm::dot(b - c, v), glm::dot(b - c, u));
  });
  return unique;
}

PlaneWidget planeWidget(const ClipPlane& plane, const Bounds& bounds) {
  PlaneWidget w;
  const double n = glm::length(plane.normal);
  if (!bounds.valid || !(n > 0.0)) return w;
  const glm::dvec3 normal = plane.normal / n;
  Bounds box = bounds;
  const glm::dvec3 margin = glm::dvec3(0.02 * bounds.diagonal());
  box.min -= margin;
  box.max += margin;
  w.outline = planeInBox(plane, box);
  if (w.outline.empty()) {  // the plane misses the model: the box's centre brought onto it
    w.center = bounds.center() - glm::dot(bounds.center() - plane.point, normal) * normal;
  } else {
    for (const glm::dvec3& p : w.outline) w.center += p;
    w.center /= double(w.outline.size());
  }
  w.knob = w.center + normal * (0.25 * bounds.diagonal());
  return w;
}

PlaneWidgetPart hitPlaneWidget(const PlaneWidget& widget, const Camera& camera, double width, double height,
                               glm::dvec2 pixel, double tolerance) {
  const auto center = camera.projectToPicture(widget.center, width, height);
  const auto knob = camera.projectToPicture(widget.knob, width, height);
  if (!center || !knob) return PlaneWidgetPart::None;
  if (glm::length(pixel - *knob) <= tolerance + 3.0) return PlaneWidgetPart::Knob;  // the knob is drawn larger
  // A handle seen end on (the normal at the viewer) has no shaft to take: the knob only.
  if (glm::length(*knob - *center) > 2.0 * tolerance && distanceToSegment(pixel, *center, *knob) <= tolerance)
    return PlaneWidgetPart::Shaft;
  return PlaneWidgetPart::None;
}

ClipPlane turnedPlane(const ClipPlane& plane, const PlaneWidget& widget, const Camera& camera, double width,
                      double height, glm::dvec2 pixel) {
  const Ray ray = rayThrough(camera, width, height, pixel);
  const glm::dvec3 facing = -camera.viewDirection();
  const double den = glm::dot(ray.direction, facing);
  if (!(std::abs(den) > 1e-12)) return plane;
  const glm::dvec3 hit = ray.origin + (glm::dot(widget.knob - ray.origin, facing) / den) * ray.direction;
  const glm::dvec3 normal = hit - widget.center;
  const double length = glm::length(normal);
  if (!(length > 0.0) || !std::isfinite(length)) return plane;
  return {widget.center, normal / length};
}

double dragAlong(const glm::dvec3& anchor, const glm::dvec3& direction, double length, const Camera& camera,
                 double width, double height, glm::dvec2 from, glm::dvec2 to) {
  const auto a = camera.projectToPicture(anchor, width, height);
  const auto b = camera.projectToPicture(anchor + length * direction, width, height);
  const glm::dvec2 move = to - from;
  if (a && b && glm::length(*b - *a) > 8.0) {  // the direction on the screen
    const glm::dvec2 s = *b - *a;
    return glm::dot(move, s) / glm::dot(s, s) * length;
  }
  // Along the line of sight: up the screen is toward the viewer.
  const double towardViewer = glm::dot(direction, -camera.viewDirection()) >= 0.0 ? 1.0 : -1.0;
  return -move.y / height * camera.viewHeight() * towardViewer;
}

ClipPlane slidPlane(const ClipPlane& plane, const PlaneWidget& widget, const Camera& camera, double width,
                    double height, glm::dvec2 from, glm::dvec2 to) {
  const double handle = glm::length(widget.knob - widget.center);
  const double n = glm::length(plane.normal);
  if (!(handle > 0.0) || !(n > 0.0)) return plane;
  const glm::dvec3 normal = plane.normal / n;
  ClipPlane out = plane;
  out.point += dragAlong(widget.center, normal, handle, camera, width, height, from, to) * normal;
  return out;
}

}  // namespace volpost::app

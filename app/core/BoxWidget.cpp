// SPDX-License-Identifier: MIT
#include "BoxWidget.hpp"

#include "PlaneWidget.hpp"

#include <glm/geometric.hpp>

#include <algorithm>

namespace volpost::app {

BoxWidget boxWidget(const ClipBox& b) {
  BoxWidget w;
  for (int c = 0; c < 8; ++c) w.corners[std::size_t(c)] = {b[c & 1 ? 1 : 0], b[c & 2 ? 3 : 2], b[c & 4 ? 5 : 4]};
  const glm::dvec3 mid(0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5]));
  for (int f = 0; f < 6; ++f) {
    glm::dvec3 c = mid;
    c[f / 2] = b[std::size_t(f)];
    w.faceCenters[std::size_t(f)] = c;
  }
  return w;
}

const std::array<std::array<int, 2>, 12>& boxEdges() {
  static const std::array<std::array<int, 2>, 12> edges = {
      {{0, 1}, {2, 3}, {4, 5}, {6, 7}, {0, 2}, {1, 3}, {4, 6}, {5, 7}, {0, 4}, {1, 5}, {2, 6}, {3, 7}}};
  return edges;
}

std::optional<int> hitBoxWidget(const BoxWidget& widget, const Camera& camera, double width, double height,
                                glm::dvec2 pixel, double tolerance) {
  std::optional<int> best;
  double nearest = tolerance;
  for (int f = 0; f < 6; ++f) {
    const auto at = camera.projectToPicture(widget.faceCenters[std::size_t(f)], width, height);
    if (!at) continue;
    const double d = glm::length(pixel - *at);
    if (d <= nearest) {
      nearest = d;
      best = f;
    }
  }
  return best;
}

ClipBox draggedBox(const ClipBox& box, int face, const Camera& camera, double width, double height, glm::dvec2 from,
                   glm::dvec2 to) {
  if (face < 0 || face > 5) return box;
  const BoxWidget w = boxWidget(box);
  const double diagonal = glm::length(w.corners[7] - w.corners[0]);
  glm::dvec3 axis(0.0);
  axis[face / 2] = 1.0;
  const double moved = dragAlong(w.faceCenters[std::size_t(face)], axis, 0.25 * diagonal, camera, width, height, from, to);
  ClipBox out = box;
  const std::size_t lo = std::size_t(face / 2 * 2), hi = lo + 1;
  const double gap = 1e-3 * diagonal;
  if (face % 2 == 0) out[lo] = std::min(box[lo] + moved, box[hi] - gap);
  else out[hi] = std::max(box[hi] + moved, box[lo] + gap);
  return out;
}

}  // namespace volpost::app

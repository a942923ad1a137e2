// SPDX-License-Identifier: MIT
#include "CellSection.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace volpost::app {

std::vector<SectionPoint> cellSection(const Model& model, std::size_t cell, const ClipPlane& plane) {
  const Mesh& mesh = model.mesh();
  const CellTopology& t = topology(mesh.cellType(cell));
  const auto nodes = mesh.cellNodes(cell);
  const glm::dvec3 n = glm::normalize(plane.normal);
  std::vector<SectionPoint> points;
  for (const CellEdge& e : t.edges) {
    const NodeIndex ia = nodes[e.a], ib = nodes[e.b];
    const glm::dvec3 a = model.nodePosition(ia), b = model.nodePosition(ib);
    const double da = glm::dot(a - plane.point, n), db = glm::dot(b - plane.point, n);
    if ((da < 0.0) == (db < 0.0) || da == db) continue;
    const double along = da / (da - db);
    points.push_back({a + (b - a) * along, ia, ib, along});
  }
  if (points.size() < 3) return points;
  // The section of a convex cell is convex: its points in order of angle about their centre.
  glm::dvec3 centre(0.0);
  for (const SectionPoint& p : points) centre += p.at / double(points.size());
  glm::dvec3 u = points[0].at - centre;
  if (!(glm::length(u) > 0.0)) return points;
  u = glm::normalize(u);
  const glm::dvec3 w = glm::cross(n, u);
  const auto angle = [&](const SectionPoint& p) {
    return std::atan2(glm::dot(p.at - centre, w), glm::dot(p.at - centre, u));
  };
  std::sort(points.begin(), points.end(),
            [&](const SectionPoint& x, const SectionPoint& y) { return angle(x) < angle(y); });
  return points;
}

}  // namespace volpost::app

// SPDX-License-Identifier: MIT
#include "FeatureEdges.hpp"

#include <glm/geometric.hpp>

#include <cmath>
#include <numbers>

namespace volpost::app {

std::vector<glm::dvec3> featureEdges(const BoundarySurface& surface, double angleDegrees) {
  const SurfaceMesh& m = surface.mesh;
  const double cosLimit = std::cos(angleDegrees * std::numbers::pi / 180.0);
  const auto unitNormal = [&](SurfaceMesh::FaceHandle f) {
    // Computed here: the surface may not carry face normals.
    const auto h = m.halfedge_handle(f);
    const auto a = m.point(m.from_vertex_handle(h)), b = m.point(m.to_vertex_handle(h)),
               c = m.point(m.to_vertex_handle(m.next_halfedge_handle(h)));
    const glm::dvec3 n = glm::cross(glm::dvec3(b[0] - a[0], b[1] - a[1], b[2] - a[2]), glm::dvec3(c[0] - a[0], c[1] - a[1], c[2] - a[2]));
    const double length = std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
    return length > 0.0 ? n / length : n;
  };
  std::vector<glm::dvec3> out;
  for (const auto e : m.edges()) {
    const auto h0 = m.halfedge_handle(e, 0), h1 = m.halfedge_handle(e, 1);
    const auto f0 = m.face_handle(h0), f1 = m.face_handle(h1);
    bool sharp = !f0.is_valid() || !f1.is_valid();  // a border of the surface
    if (!sharp) {
      const glm::dvec3 n0 = unitNormal(f0), n1 = unitNormal(f1);
      sharp = n0.x * n1.x + n0.y * n1.y + n0.z * n1.z < cosLimit;
    }
    if (!sharp) continue;
    for (const auto v : {m.from_vertex_handle(h0), m.to_vertex_handle(h0)}) {
      const auto p = m.point(v);
      out.push_back(surface.origin + glm::dvec3(p[0], p[1], p[2]));
    }
  }
  return out;
}

}  // namespace volpost::app

// SPDX-License-Identifier: MIT
#include "SectionCut.hpp"

#include <glm/geometric.hpp>

#include <array>
#include <cmath>
#include <limits>

namespace volpost {
namespace {

// A point on edge a-b where the signed distance is zero, with its value.
struct Crossing {
  glm::dvec3 at;
  double value;
};

Crossing crossEdge(const glm::dvec3& a, const glm::dvec3& b, double da, double db, double va, double vb) {
  const double t = da / (da - db);  // da and db have opposite signs: 0 <= t <= 1
  return {a + t * (b - a), va + t * (vb - va)};
}

void addTriangle(SectionTriangles& out, const Crossing& p, const Crossing& q, const Crossing& r, const glm::dvec3& normal) {
  const glm::dvec3 n = glm::cross(q.at - p.at, r.at - p.at);
  if (!(glm::dot(n, n) > 0.0)) return;  // the plane through a node or an edge: no area
  const bool flip = glm::dot(n, normal) < 0.0;
  for (const Crossing* c : {&p, flip ? &r : &q, flip ? &q : &r}) {
    out.positions.push_back(c->at);
    out.values.push_back(c->value);
  }
}

}  // namespace

SectionTriangles cutTetrahedra(const TetMesh& tets, std::span<const double> values, bool perNodeValues,
                               const ClipPlane& plane) {
  SectionTriangles out;
  const Mesh& mesh = tets.mesh;
  const double length = glm::length(plane.normal);
  if (!(length > 0.0) || !std::isfinite(length)) return out;
  const glm::dvec3 normal = plane.normal / length;
  const bool perNode = perNodeValues && values.size() == mesh.nodeCount();
  const bool perTet = !perNodeValues && values.size() == mesh.cellCount();
  const double none = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t c = 0; c < mesh.cellCount(); ++c) {
    const auto nodes = mesh.cellNodes(c);
    if (nodes.size() < 4) continue;
    std::array<glm::dvec3, 4> p;
    std::array<double, 4> d, v;
    int kept = 0;
    for (int k = 0; k < 4; ++k) {
      p[k] = mesh.nodes[nodes[k]];
      // A node on the plane counts as kept: every tet decides it the same way, so the
      // pieces of neighbouring tets meet without gaps or overlaps.
      d[k] = glm::dot(p[k] - plane.point, normal);
      if (d[k] == 0.0) d[k] = 0.0;  // -0 too
      kept += d[k] >= 0.0;
      v[k] = perNode ? values[nodes[k]] : perTet ? values[c] : none;
    }
    if (kept == 0 || kept == 4) continue;
    ++out.cutTets;
    std::array<int, 4> in{}, outside{};
    int ni = 0, no = 0;
    for (int k = 0; k < 4; ++k) (d[k] >= 0.0 ? in[ni++] : outside[no++]) = k;
    const auto cross = [&](int a, int b) { return crossEdge(p[a], p[b], d[a], d[b], v[a], v[b]); };
    if (ni == 1 || no == 1) {  // one corner apart: a triangle
      const int lone = ni == 1 ? in[0] : outside[0];
      std::array<Crossing, 3> t;
      int n = 0;
      for (int k = 0; k < 4; ++k)
        if (k != lone) t[n++] = cross(lone, k);
      addTriangle(out, t[0], t[1], t[2], normal);
    } else {  // two and two: a quadrilateral a0-b0, a0-b1, a1-b1, a1-b0 (in that order around)
      const Crossing q0 = cross(in[0], outside[0]), q1 = cross(in[0], outside[1]);
      const Crossing q2 = cross(in[1], outside[1]), q3 = cross(in[1], outside[0]);
      addTriangle(out, q0, q1, q2, normal);
      addTriangle(out, q0, q2, q3, normal);
    }
  }
  return out;
}

}  // namespace volpost

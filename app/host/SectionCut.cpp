// SPDX-License-Identifier: MIT
#include "SectionCut.hpp"
#include "host/GridCellTets.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
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
  if (db == 0.0) return {b, vb};  // a node on the plane is itself, not a + 1 * (b - a)
  if (da == 0.0) return {a, va};
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

namespace {

// The piece of one tet on the plane: corners p with signed distances d (a node on the plane
// counts as kept: every tet decides it the same way, so the pieces of neighbouring tets
// meet without gaps or overlaps) and values v.
void cutTetrahedron(SectionTriangles& out, const std::array<glm::dvec3, 4>& p, const std::array<double, 4>& d,
                    const std::array<double, 4>& v, const glm::dvec3& normal) {
  std::array<int, 4> in{}, outside{};
  int ni = 0, no = 0;
  for (int k = 0; k < 4; ++k) (d[k] >= 0.0 ? in[ni++] : outside[no++]) = k;
  if (ni == 0 || no == 0) return;
  ++out.cutTets;
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

double signedDistance(const glm::dvec3& p, const ClipPlane& plane, const glm::dvec3& normal) {
  const double d = glm::dot(p - plane.point, normal);
  return d == 0.0 ? 0.0 : d;  // -0 too
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
    for (int k = 0; k < 4; ++k) {
      p[k] = mesh.nodes[nodes[k]];
      d[k] = signedDistance(p[k], plane, normal);
      v[k] = perNode ? values[nodes[k]] : perTet ? values[c] : none;
    }
    cutTetrahedron(out, p, d, v, normal);
  }
  return out;
}

SectionTriangles cutCells(const optics::ElementField& field, std::span<const double> cellValues, const ClipPlane& plane,
                          const RefinementLimits& limits) {
  const double length = glm::length(plane.normal);
  if (!(length > 0.0) || !std::isfinite(length)) return {};
  const glm::dvec3 normal = plane.normal / length;
  const Mesh& cells = field.mesh();
  const TetMesh& split = field.split();
  // A curved cell bulges past its nodes by less than a quarter of their spread across the
  // plane (a midside node's Bezier control point lies twice as far off the chord).
  std::vector<signed char> crossed(cells.cellCount(), -1);
  std::vector<std::uint32_t> chosen;
  for (std::size_t t = 0; t < split.mesh.cellCount(); ++t) {
    const std::uint32_t cell = split.sourceCell(t);
    if (crossed[cell] < 0) {
      double lo = INFINITY, hi = -INFINITY;
      for (NodeIndex n : cells.cellNodes(cell)) {
        const double d = signedDistance(cells.nodes[n], plane, normal);
        lo = std::min(lo, d), hi = std::max(hi, d);
      }
      const double margin = 0.25 * (hi - lo);
      crossed[cell] = lo - margin <= 0.0 && 0.0 <= hi + margin ? 1 : 0;
    }
    if (crossed[cell] == 1) chosen.push_back(std::uint32_t(t));
  }
  const RefinedTetrahedra refined = refineTetrahedra(field, chosen, limits);
  std::vector<double> pieceValues;
  if (!cellValues.empty()) {
    pieceValues.resize(refined.tets.mesh.cellCount());
    for (std::size_t p = 0; p < pieceValues.size(); ++p) {
      const std::uint32_t cell = refined.tets.sourceCell(p);
      pieceValues[p] = cell < cellValues.size() ? cellValues[cell] : std::numeric_limits<double>::quiet_NaN();
    }
  }
  SectionTriangles out = cellValues.empty() ? cutTetrahedra(refined.tets, refined.values, true, plane)
                                            : cutTetrahedra(refined.tets, pieceValues, false, plane);
  out.refinement = refined.level;
  out.toleranceReached = refined.toleranceReached;
  return out;
}

// Each cell the plane crosses is split into the six tets around its diagonal from corner
// (0,0,0) to (1,1,1) (Freudenthal's split: the same in every cell, so neighbours' pieces
// meet), positions and distances from the cell's indices, no hexahedra needed.
SectionTriangles cutGrid(const RegularGrid& grid, SampleView values, bool perNodeValues,
                         const ClipPlane& plane) {
  SectionTriangles out;
  const double length = glm::length(plane.normal);
  if (!(length > 0.0) || !std::isfinite(length) || !grid.defect().empty()) return out;
  const glm::dvec3 normal = plane.normal / length;
  const bool perNode = perNodeValues && values.size() == grid.pointCount();
  const bool perCell = !perNodeValues && values.size() == grid.cellCount();
  const double none = std::numeric_limits<double>::quiet_NaN();
  const std::size_t cx = grid.dims[0] - 1, cy = grid.dims[1] - 1, cz = grid.dims[2] - 1;
  // A grid point within rounding of the plane is on it: a plane through a layer of points
  // (an inline, crossline or time slice) then shows those points and their samples exactly,
  // without slivers between points that rounding put on both sides. Every cell computes a
  // point's distance the same way, so neighbours still agree.
  const double onPlane = 1e-9 * std::min({glm::length(grid.axes[0]), glm::length(grid.axes[1]), glm::length(grid.axes[2])});
  const auto cutCell = [&](std::size_t i, std::size_t j, std::size_t k) {
    std::array<glm::dvec3, 8> p;
    std::array<double, 8> d;
    int kept = 0;
    for (int c = 0; c < 8; ++c) {
      p[std::size_t(c)] = grid.position(double(i + (c & 1)), double(j + (c >> 1 & 1)), double(k + (c >> 2 & 1)));
      const double distance = signedDistance(p[std::size_t(c)], plane, normal);
      d[std::size_t(c)] = std::abs(distance) <= onPlane ? 0.0 : distance;
      kept += d[std::size_t(c)] >= 0.0;
    }
    if (kept == 0 || kept == 8) return;
    std::array<double, 8> v;
    for (int c = 0; c < 8; ++c)
      v[std::size_t(c)] = perNode ? values[grid.pointIndex(i + (c & 1), j + (c >> 1 & 1), k + (c >> 2 & 1))]
                          : perCell ? values[i + cx * (j + cy * k)]
                                    : none;
    for (const auto& t : kGridCellTets)
      cutTetrahedron(out, {p[t[0]], p[t[1]], p[t[2]], p[t[3]]}, {d[t[0]], d[t[1]], d[t[2]], d[t[3]]},
                     {v[t[0]], v[t[1]], v[t[2]], v[t[3]]}, normal);
  };
  // Only the cells near the plane: the distance is linear in the indices, so along the axis
  // it changes most on (m), each column of cells (u, v) meets the plane where the distance
  // at its four edges along m is zero. A slice of a 256^3 cube visits 65K cells, not 16M.
  const std::array<std::size_t, 3> cells = {cx, cy, cz};
  const double d0 = glm::dot(grid.origin - plane.point, normal);
  const std::array<double, 3> step = {glm::dot(grid.axes[0], normal), glm::dot(grid.axes[1], normal),
                                      glm::dot(grid.axes[2], normal)};
  int m = 0;
  for (int a = 1; a < 3; ++a)
    if (std::abs(step[std::size_t(a)]) > std::abs(step[std::size_t(m)])) m = a;
  const int u = (m + 1) % 3, w = (m + 2) % 3;
  for (std::size_t b = 0; b < cells[std::size_t(w)]; ++b)
    for (std::size_t a = 0; a < cells[std::size_t(u)]; ++a) {
      double lo = INFINITY, hi = -INFINITY;  // where along m the column's four edges cross the plane
      for (int c = 0; c < 4; ++c) {
        const double at = d0 + double(a + (c & 1)) * step[std::size_t(u)] + double(b + (c >> 1)) * step[std::size_t(w)];
        const double root = -at / step[std::size_t(m)];
        lo = std::min(lo, root), hi = std::max(hi, root);
      }
      const double last = double(cells[std::size_t(m)] - 1);
      if (!(hi >= -1.0 && lo <= last + 1.0)) continue;  // the plane passes beside the column
      // One cell more on each side: rounding, and points snapped onto the plane.
      const std::size_t first = std::size_t(std::clamp(std::floor(lo) - 1.0, 0.0, last));
      const std::size_t end = std::size_t(std::clamp(std::floor(hi) + 1.0, 0.0, last));
      for (std::size_t q = first; q <= end; ++q) {
        std::array<std::size_t, 3> index{};
        index[std::size_t(m)] = q, index[std::size_t(u)] = a, index[std::size_t(w)] = b;
        cutCell(index[0], index[1], index[2]);
      }
    }
  return out;
}

}  // namespace volpost

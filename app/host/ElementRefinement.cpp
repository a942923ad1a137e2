// SPDX-License-Identifier: MIT
#include "host/ElementRefinement.hpp"

#include "host/ElementCellMap.hpp"

#include <volpost/core/CellShape.hpp>
#include <volpost/core/optics/ElementField.hpp>

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <unordered_map>

namespace volpost {
namespace {

// A point of the lattice on a split tetrahedron, named by the split's nodes it is a
// weighted mean of (weights out of the level): the same name from every tetrahedron that
// shares the face or edge it lies on, so neighbours share it.
using LatticeKey = std::array<std::uint64_t, 4>;

struct LatticeKeyHash {
  std::size_t operator()(const LatticeKey& k) const {
    std::uint64_t h = 0x9E3779B97F4A7C15ull;
    for (std::uint64_t v : k) h = (h ^ v) * 0x100000001B3ull, h ^= h >> 29;
    return std::size_t(h);
  }
};

LatticeKey latticeKey(const std::array<NodeIndex, 4>& corners, const std::array<int, 4>& weights) {
  LatticeKey key;
  key.fill(std::numeric_limits<std::uint64_t>::max());
  int used = 0;
  for (int k = 0; k < 4; ++k)
    if (weights[std::size_t(k)] > 0)
      key[std::size_t(used++)] = (std::uint64_t(corners[std::size_t(k)]) << 8) | std::uint64_t(weights[std::size_t(k)]);
  for (int i = 1; i < used; ++i)  // at most four: an insertion sort
    for (int j = i; j > 0 && key[std::size_t(j - 1)] > key[std::size_t(j)]; --j)
      std::swap(key[std::size_t(j - 1)], key[std::size_t(j)]);
  return key;
}

// How far the split tetrahedron's straight edges and linear values stray from the cell's
// map and field, the larger of the two, relative: at the midpoints of its six edges and of
// the diagonal its pieces get (from the middle of edge 0-1 to the middle of edge 2-3; a
// piece's diagonal is twice as long, relative to the level, so it strays 4 times as far).
double deviationOf(const CellMap& map, double valueScale) {
  struct Segment {
    std::array<double, 4> from, to;
    double weight;
  };
  static const Segment kSegments[] = {{{1, 0, 0, 0}, {0, 1, 0, 0}, 1},        {{1, 0, 0, 0}, {0, 0, 1, 0}, 1},
                                      {{1, 0, 0, 0}, {0, 0, 0, 1}, 1},        {{0, 1, 0, 0}, {0, 0, 1, 0}, 1},
                                      {{0, 1, 0, 0}, {0, 0, 0, 1}, 1},        {{0, 0, 1, 0}, {0, 0, 0, 1}, 1},
                                      {{0.5, 0.5, 0, 0}, {0, 0, 0.5, 0.5}, 4}};
  double worst = 0.0;
  for (const Segment& s : kSegments) {
    std::array<double, 4> mid;
    for (int k = 0; k < 4; ++k) mid[std::size_t(k)] = 0.5 * (s.from[std::size_t(k)] + s.to[std::size_t(k)]);
    glm::dvec3 a, b, m;
    double fa = 0.0, fb = 0.0, fm = 0.0;
    map.at(s.from, a, fa), map.at(s.to, b, fb), map.at(mid, m, fm);
    const double length = glm::length(b - a);
    const glm::dvec3 straight = 0.5 * (a + b), moved = straight - m;
    // The shape counts where the map bends a face; inside a flat-faced cell it only moves
    // the point, which the field's term below sees.
    if (length > 0.0 && !map.flatFaced()) worst = std::max(worst, s.weight * glm::length(moved) / length);
    // The straight piece gives its straight middle the mean of the ends; the field there is
    // the value at m carried along the gradient by the move (to first order: a field linear
    // in space on a distorted flat-faced cell needs no pieces).
    const double fd = s.weight * std::abs(fm + glm::dot(map.gradient(mid), moved) - 0.5 * (fa + fb)) / valueScale;
    if (std::isfinite(fd)) worst = std::max(worst, fd);
  }
  return worst;
}

// The n^3 pieces of a tetrahedron subdivided n times along each edge, as lattice points
// (a, b, c) (weights n - a - b - c, a, b, c on its corners): an upright piece at every
// point, the octahedron between them cut into four along one diagonal, and an inverted piece.
template <typename Emit>
void forEachPiece(int n, Emit emit) {
  using P = std::array<int, 3>;
  for (int a = 0; a < n; ++a)
    for (int b = 0; a + b < n; ++b)
      for (int c = 0; a + b + c < n; ++c) {
        emit(P{a, b, c}, P{a + 1, b, c}, P{a, b + 1, c}, P{a, b, c + 1});
        if (a + b + c > n - 2) continue;
        const P A{a + 1, b, c}, B{a, b + 1, c}, C{a, b, c + 1};
        const P D{a + 1, b + 1, c}, E{a + 1, b, c + 1}, F{a, b + 1, c + 1};
        emit(A, F, B, D), emit(A, F, D, E), emit(A, F, E, C), emit(A, F, C, B);
        if (a + b + c <= n - 3) emit(D, E, F, P{a + 1, b + 1, c + 1});
      }
}

int levelFor(double deviation, const RefinementLimits& limits, std::size_t chosen) {
  const double tolerance = std::max(limits.tolerance, 1e-12);
  int level = deviation <= tolerance ? 1 : int(std::ceil(std::sqrt(deviation / tolerance) - 1e-9));
  level = std::clamp(level, 1, std::max(limits.maxLevel, 1));
  while (level > 1 && double(chosen) * level * level * level > double(limits.maxTetrahedra)) --level;
  return level;
}

}  // namespace

RefinementLimits limitsForElementTolerance(double perChannel) {
  RefinementLimits limits;
  limits.tolerance = perChannel > 0.0 ? 0.1 * perChannel : 1e-12;
  return limits;
}

glm::dvec3 naturalCoordinatesOfSplitNode(const Mesh& cells, std::uint32_t cell, NodeIndex node) {
  const CellType type = cells.cellType(cell);
  const auto ids = cells.cellNodes(cell);
  for (std::size_t i = 0; i < ids.size(); ++i)
    if (ids[i] == node) return naturalCoordinatesOfNode(type, int(i));
  const int corners = topology(type).cornerCount;
  glm::dvec3 mean(0.0);
  for (int i = 0; i < corners; ++i) mean += naturalCoordinatesOfNode(type, i);
  return mean / double(corners);
}

bool hasNonlinearCells(const Mesh& cells) {
  for (CellType type : cells.cellTypes())
    if (type != CellType::Tet4) return true;
  return false;
}

RefinedTetrahedra refineTetrahedra(const optics::ElementField& field, std::span<const std::uint32_t> chosen,
                                   const RefinementLimits& limits, const Progress& progress) {
  const TetMesh& split = field.split();
  const std::vector<double> splitValues = split.nodeValues(field.mesh(), field.values());
  CellMap map(field.mesh(), field, split, splitValues);

  double worst = 0.0;
  for (std::size_t i = 0; i < chosen.size(); ++i)
    if (map.select(chosen[i])) worst = std::max(worst, deviationOf(map, field.valueScale()));
  RefinedTetrahedra out;
  const int n = out.level = levelFor(worst, limits, chosen.size());
  out.deviation = worst / double(n * n);
  out.toleranceReached = out.deviation <= limits.tolerance * (1.0 + 1e-9);

  std::unordered_map<LatticeKey, NodeIndex, LatticeKeyHash> known;
  std::vector<NodeIndex> lattice(std::size_t((n + 1) * (n + 1) * (n + 1)));
  const auto slot = [n](const std::array<int, 3>& p) { return std::size_t((p[0] * (n + 1) + p[1]) * (n + 1) + p[2]); };
  std::vector<NodeIndex> connectivity;
  connectivity.reserve(chosen.size() * std::size_t(n * n * n) * 4);
  out.tets.cellOfTet.reserve(chosen.size() * std::size_t(n * n * n));
  for (std::size_t i = 0; i < chosen.size(); ++i) {
    if (i % 4096 == 0) progress.report(double(i) / double(chosen.size()));
    map.select(chosen[i]);
    for (int a = 0; a <= n; ++a)
      for (int b = 0; a + b <= n; ++b)
        for (int c = 0; a + b + c <= n; ++c) {
          const std::array<int, 4> weights{n - a - b - c, a, b, c};
          const auto [it, added] = known.try_emplace(latticeKey(map.corners(), weights), NodeIndex(out.values.size()));
          if (added) {
            glm::dvec3 position;
            double value = 0.0;
            map.at({weights[0] / double(n), a / double(n), b / double(n), c / double(n)}, position, value);
            out.tets.mesh.nodes.push_back(position);
            out.values.push_back(value);
          }
          lattice[slot({a, b, c})] = it->second;
        }
    forEachPiece(n, [&](const auto& p0, const auto& p1, const auto& p2, const auto& p3) {
      std::array<NodeIndex, 4> piece{lattice[slot(p0)], lattice[slot(p1)], lattice[slot(p2)], lattice[slot(p3)]};
      const auto& x = out.tets.mesh.nodes;
      // Positive, as the split's tetrahedra are (the cell's map keeps orientation).
      if (glm::dot(x[piece[1]] - x[piece[0]], glm::cross(x[piece[2]] - x[piece[0]], x[piece[3]] - x[piece[0]])) < 0.0)
        std::swap(piece[2], piece[3]);
      connectivity.insert(connectivity.end(), piece.begin(), piece.end());
      out.tets.cellOfTet.push_back(map.cell());
    });
  }
  out.tets.mesh.takeCells(CellType::Tet4, std::move(connectivity));
  out.tets.originalNodes = out.tets.mesh.nodes.size();
  progress.report(1.0);
  return out;
}

namespace {

// How far a boundary triangle's straight sides and linear values stray from its cell's map
// and field: at the midpoints of its sides and at its centre. A side that is an element
// edge counts whole (it may bend within the surface: an outline); elsewhere only the part
// across the surface counts, as points moved within a flat face draw the same face (a
// trapezoid's bilinear map moves its diagonal's middle without bending anything).
double triangleDeviation(const CellMap& map, double valueScale, const std::array<bool, 3>& sideIsEdge) {
  struct Probe {
    std::array<double, 4> from, to, at;
    double t;  ///< how far along from `from` to `to` the probe `at` lies
    int side;  ///< the triangle's side it is the middle of; -1: the centre
  };
  constexpr double third = 1.0 / 3.0;
  static const Probe kProbes[] = {{{1, 0, 0, 0}, {0, 1, 0, 0}, {0.5, 0.5, 0, 0}, 0.5, 0},
                                  {{0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0.5, 0.5, 0}, 0.5, 1},
                                  {{0, 0, 1, 0}, {1, 0, 0, 0}, {0.5, 0, 0.5, 0}, 0.5, 2},
                                  // the centre, a third of the way from a side's middle to the far corner
                                  {{0.5, 0.5, 0, 0}, {0, 0, 1, 0}, {third, third, third, 0}, third, -1}};
  glm::dvec3 corner[3];
  double ignored = 0.0;
  map.at({1, 0, 0, 0}, corner[0], ignored), map.at({0, 1, 0, 0}, corner[1], ignored),
      map.at({0, 0, 1, 0}, corner[2], ignored);
  const glm::dvec3 across = glm::cross(corner[1] - corner[0], corner[2] - corner[0]);
  const double area2 = glm::length(across);
  double worst = 0.0;
  for (const Probe& s : kProbes) {
    glm::dvec3 a, b, m;
    double fa = 0.0, fb = 0.0, fm = 0.0;
    map.at(s.from, a, fa), map.at(s.to, b, fb), map.at(s.at, m, fm);
    const double t = s.t;
    const double length = glm::length(b - a);
    const glm::dvec3 off = m - ((1.0 - t) * a + t * b);
    const bool whole = s.side >= 0 && sideIsEdge[std::size_t(s.side)];
    const double stray = whole || area2 == 0.0 ? glm::length(off) : std::abs(glm::dot(off, across)) / area2;
    if (length > 0.0) worst = std::max(worst, stray / length);
    // As for tetrahedra: the field at the straight point is the value at m carried back
    // along the gradient.
    const double fd = std::abs(fm - glm::dot(map.gradient(s.at), off) - ((1.0 - t) * fa + t * fb)) / valueScale;
    if (std::isfinite(fd)) worst = std::max(worst, fd);
  }
  return worst;
}

// A triangle's own level: the fewest subdivisions along its sides that bring `deviation`
// (which falls as the square of the level) within the tolerance, at most `most`.
int ownLevelFor(double deviation, const RefinementLimits& limits, int most) {
  const double tolerance = std::max(limits.tolerance, 1e-12);
  const int level = deviation <= tolerance ? 1 : int(std::ceil(std::sqrt(deviation / tolerance) - 1e-9));
  return std::clamp(level, 1, std::max(most, 1));
}

struct BoundaryTriangle {
  std::uint32_t cell;
  std::array<NodeIndex, 3> nodes;
};

std::vector<BoundaryTriangle> trianglesOf(const BoundarySurface& boundary) {
  const SurfaceMesh& m = boundary.mesh;
  std::vector<BoundaryTriangle> out;
  out.reserve(m.n_faces());
  for (const auto f : m.faces()) {
    BoundaryTriangle t{m.property(boundary.cellOfFace, f), {}};
    int k = 0;
    for (const auto v : f.vertices())
      if (k < 3) t.nodes[std::size_t(k++)] = m.property(boundary.nodeOfVertex, v);
    if (k == 3) out.push_back(t);
  }
  return out;
}

std::array<NodeIndex, 4> cornersOf(const BoundaryTriangle& t) {
  return {t.nodes[0], t.nodes[1], t.nodes[2], t.nodes[2]};
}

// How far each boundary triangle strays from its cell's own shape and field (0 for a cell
// drawn linearly).
std::vector<double> triangleDeviations(CellMap& map, const optics::ElementField& field, const BoundarySurface& boundary,
                                       const std::vector<BoundaryTriangle>& triangles) {
  const auto isEdge = [&](NodeIndex a, NodeIndex b) {
    return std::binary_search(boundary.edges.begin(), boundary.edges.end(),
                              std::array<NodeIndex, 2>{std::min(a, b), std::max(a, b)});
  };
  std::vector<double> out(triangles.size(), 0.0);
  for (std::size_t t = 0; t < triangles.size(); ++t)
    if (map.select(triangles[t].cell, cornersOf(triangles[t]))) {
      const auto& n = triangles[t].nodes;
      const std::array<bool, 3> sideIsEdge{isEdge(n[0], n[1]), isEdge(n[1], n[2]), isEdge(n[2], n[0])};
      out[t] = triangleDeviation(map, field.valueScale(), sideIsEdge);
    }
  return out;
}

// How finely each triangle of the boundary is cut. Each triangle asks for its own level;
// a side shared by triangles takes the largest they ask for (both draw it in the same
// points, so the surface stays closed), and a triangle is cut inside at the largest of its
// own and its sides' levels, stitched to sides cut more coarsely. Flat faces beside curved
// ones are then cut only along the shared side.
struct SurfacePlan {
  std::vector<int> own;                   ///< per triangle, what it asks for
  std::vector<int> inside;                ///< per triangle, the level of its inner lattice
  std::vector<std::array<int, 3>> sides;  ///< per triangle, the level of each side (k: corner k to k + 1)
  double deviation = 0.0;                 ///< the estimated largest deviation left
  std::size_t triangles = 0;              ///< how many pieces
  int most = 1;                           ///< the largest level
};

// How far side k of triangle t bends away from its chord: at its quarter points and middle,
// relative to its length, whichever way it bends (within the surface as well as across it).
double sideBend(CellMap& map, const BoundaryTriangle& triangle, int k) {
  if (!map.select(triangle.cell, cornersOf(triangle))) return 0.0;
  std::array<double, 4> from{0, 0, 0, 0}, to{0, 0, 0, 0};
  from[std::size_t(k)] = 1.0, to[std::size_t((k + 1) % 3)] = 1.0;
  glm::dvec3 a, b;
  double ignored = 0.0;
  map.at(from, a, ignored), map.at(to, b, ignored);
  const double length = glm::length(b - a);
  if (!(length > 0.0)) return 0.0;
  double worst = 0.0;
  for (double u : {0.25, 0.5, 0.75}) {
    std::array<double, 4> w{0, 0, 0, 0};
    w[std::size_t(k)] = 1.0 - u, w[std::size_t((k + 1) % 3)] = u;
    glm::dvec3 m;
    map.at(w, m, ignored);
    worst = std::max(worst, glm::length(m - ((1.0 - u) * a + u * b)) / length);
  }
  return worst;
}

SurfacePlan planSurface(CellMap& map, const std::vector<BoundaryTriangle>& triangles,
                        const std::vector<double>& deviations, const RefinementLimits& limits) {
  std::unordered_map<std::uint64_t, std::uint32_t> sideIds;  // a side by its two nodes
  std::vector<std::array<std::uint32_t, 3>> sideOf(triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const NodeIndex a = triangles[t].nodes[std::size_t(k)], b = triangles[t].nodes[std::size_t((k + 1) % 3)];
      const std::uint64_t key = (std::uint64_t(std::min(a, b)) << 32) | std::uint64_t(std::max(a, b));
      sideOf[t][std::size_t(k)] = sideIds.try_emplace(key, std::uint32_t(sideIds.size())).first->second;
    }
  std::vector<double> bend(sideIds.size(), -1.0);  // measured where needed
  SurfacePlan plan;
  // The most a triangle may ask for comes down until the pieces fit the limit.
  for (int cap = std::max(limits.maxLevel, 1);; --cap) {
    plan = SurfacePlan();
    std::vector<int> sideLevel(sideIds.size(), 1);
    for (std::size_t t = 0; t < triangles.size(); ++t) {
      plan.own.push_back(ownLevelFor(deviations[t], limits, cap));
      for (std::uint32_t side : sideOf[t]) sideLevel[side] = std::max(sideLevel[side], plan.own.back());
    }
    // A side cut more coarsely than a triangle beside it meets that triangle's inner points,
    // which its map places: the side must follow the map's bend within the surface too, or
    // the stitches would fold over it. Raising a side may raise a triangle: until none moves.
    for (bool raised = true; raised;) {
      raised = false;
      plan.inside.assign(triangles.size(), 1);
      for (std::size_t t = 0; t < triangles.size(); ++t) {
        int inside = plan.own[t];
        for (std::uint32_t side : sideOf[t]) inside = std::max(inside, sideLevel[side]);
        plan.inside[t] = inside;
        for (int k = 0; k < 3; ++k) {
          const std::uint32_t side = sideOf[t][std::size_t(k)];
          if (sideLevel[side] >= inside) continue;
          if (bend[side] < 0.0) bend[side] = sideBend(map, triangles[t], k);
          const int follows = ownLevelFor(bend[side], limits, cap);
          if (follows > sideLevel[side]) sideLevel[side] = follows, raised = true;
        }
      }
    }
    for (std::size_t t = 0; t < triangles.size(); ++t) {
      std::array<int, 3> sides{};
      int inside = plan.inside[t];
      for (int k = 0; k < 3; ++k) sides[std::size_t(k)] = sideLevel[sideOf[t][std::size_t(k)]];
      const bool stitched = std::any_of(sides.begin(), sides.end(), [&](int s) { return s != inside; });
      if (stitched) inside = std::max(inside, 3);  // a point inside to stitch the sides to
      plan.inside[t] = inside;
      plan.sides.push_back(sides);
      plan.triangles += std::size_t(inside) * std::size_t(inside);
      plan.most = std::max(plan.most, inside);
      plan.deviation = std::max(plan.deviation, deviations[t] / double(plan.own[t] * plan.own[t]));
    }
    if (cap == 1 || double(plan.triangles) <= double(limits.maxTriangles)) return plan;
  }
}

// A point of a boundary triangle with barycentric weights (a, b, c) / (a + b + c) on its
// corners, named so that every triangle sharing the side or corner it lies on names it so.
LatticeKey boundaryKey(const BoundaryTriangle& t, int a, int b, int c) {
  const int g = std::gcd(std::gcd(a, b), c);
  return latticeKey(cornersOf(t), {a / g, b / g, c / g, 0});
}

}  // namespace

RefinedSurface refineBoundary(const optics::ElementField& field, const BoundarySurface& boundary,
                              const RefinementLimits& limits, const Progress& progress) {
  const TetMesh& split = field.split();
  const std::vector<double> splitValues = split.nodeValues(field.mesh(), field.values());
  CellMap map(field.mesh(), field, split, splitValues);
  const std::vector<BoundaryTriangle> triangles = trianglesOf(boundary);
  const SurfacePlan plan = planSurface(map, triangles, triangleDeviations(map, field, boundary, triangles), limits);

  RefinedSurface out;
  out.level = plan.most;
  out.levels = plan.own;
  out.deviation = plan.deviation;
  out.toleranceReached = out.deviation <= limits.tolerance * (1.0 + 1e-9);
  BoundarySurface& surface = out.surface;
  surface.origin = boundary.origin;
  surface.boundaryFaceCount = boundary.boundaryFaceCount;
  surface.mesh.add_property(surface.nodeOfVertex, "volpost:node");
  surface.mesh.add_property(surface.cellOfFace, "volpost:cell");

  // Points on a triangle's sides may be shared with its neighbours and are found by their
  // key; points inside it are its own.
  const std::size_t pieces = plan.triangles;
  std::unordered_map<LatticeKey, NodeIndex, LatticeKeyHash> known;
  known.reserve(pieces / 2 + 16);
  surface.mesh.reserve(pieces / 2 + 16, pieces * 3 / 2 + 16, pieces);
  std::vector<SurfaceMesh::VertexHandle> vertexOfPoint;
  vertexOfPoint.reserve(pieces / 2 + 16);
  const auto newVertex = [&](NodeIndex point, const glm::dvec3& position) {
    const glm::dvec3 p = position - surface.origin;
    const auto v = surface.mesh.add_vertex(SurfaceMesh::Point(float(p.x), float(p.y), float(p.z)));
    surface.mesh.property(surface.nodeOfVertex, v) = point;
    return v;
  };
  std::vector<glm::dvec3> positions;  // of the points, to place duplicates of non-manifold faces
  positions.reserve(pieces / 2 + 16);
  std::vector<char> edgeDone(boundary.edges.size(), 0);
  std::unordered_map<NodeIndex, float> shortestAt;  // the element edges' spacing, for their fading
  for (const auto& e : boundary.edges) {
    const float length = float(glm::length(split.mesh.nodes[e[1]] - split.mesh.nodes[e[0]]));
    for (NodeIndex node : e) {
      const auto [it, added] = shortestAt.try_emplace(node, length);
      if (!added) it->second = std::min(it->second, length);
    }
  }
  // A point and where it lies in its triangle (u, v: the weights of corners 1 and 2), to
  // keep every piece turned as the triangle is.
  struct Placed {
    NodeIndex point;
    double u, v;
  };
  std::vector<Placed> lattice, ring;
  for (std::size_t ti = 0; ti < triangles.size(); ++ti) {
    if (ti % 4096 == 0) progress.report(double(ti) / double(triangles.size()));
    const BoundaryTriangle& t = triangles[ti];
    map.select(t.cell, cornersOf(t));
    // The point with weights (a, b, c) / level on the triangle's corners.
    const auto place = [&](int a, int b, int c, int level) {
      const NodeIndex next = NodeIndex(out.values.size());
      const bool inside = a > 0 && b > 0 && c > 0;
      const NodeIndex point = inside ? next : known.try_emplace(boundaryKey(t, a, b, c), next).first->second;
      if (point == next) {
        glm::dvec3 position;
        double value = 0.0;
        map.at({a / double(level), b / double(level), c / double(level), 0.0}, position, value);
        out.values.push_back(value);
        out.points.push_back({std::uint32_t(ti), std::uint16_t(b), std::uint16_t(c), std::uint16_t(level)});
        positions.push_back(position);
        vertexOfPoint.push_back(newVertex(point, position));
      }
      return Placed{point, b / double(level), c / double(level)};
    };
    const auto addFace = [&](const Placed& p, const Placed& q, const Placed& r) {
      const bool turned = (q.u - p.u) * (r.v - p.v) - (q.v - p.v) * (r.u - p.u) < 0.0;
      const NodeIndex a = p.point, b = turned ? r.point : q.point, c = turned ? q.point : r.point;
      auto f = surface.mesh.add_face(vertexOfPoint[a], vertexOfPoint[b], vertexOfPoint[c]);
      if (!f.is_valid()) {  // as the boundary did: a face of its own where it could not attach
        f = surface.mesh.add_face(newVertex(a, positions[a]), newVertex(b, positions[b]), newVertex(c, positions[c]));
        ++surface.nonManifoldFaceCount;
      }
      if (f.is_valid()) surface.mesh.property(surface.cellOfFace, f) = t.cell;
    };
    const int n = plan.inside[ti];
    const std::array<int, 3>& sides = plan.sides[ti];
    const bool uniform = sides[0] == n && sides[1] == n && sides[2] == n;
    // The lattice of level n: (i, j) has weights (n - i - j, i, j). Without stitching, all
    // of it; with, the part one step in from every side.
    lattice.assign(std::size_t((n + 1) * (n + 1)), Placed{});
    const auto slot = [n](int i, int j) { return std::size_t(i * (n + 1) + j); };
    const int edge = uniform ? 0 : 1;
    for (int i = edge; i <= n - edge; ++i)
      for (int j = edge; i + j <= n - edge; ++j) lattice[slot(i, j)] = place(n - i - j, i, j, n);
    for (int i = edge; i < n - edge; ++i)
      for (int j = edge; i + j < n - edge; ++j) {
        addFace(lattice[slot(i, j)], lattice[slot(i + 1, j)], lattice[slot(i, j + 1)]);
        if (i + j <= n - 2 - edge)
          addFace(lattice[slot(i + 1, j)], lattice[slot(i + 1, j + 1)], lattice[slot(i, j + 1)]);
      }
    // Each side in its own level's points, from corner k to corner k + 1.
    std::array<std::vector<Placed>, 3> along;
    for (int k = 0; k < 3; ++k) {
      const int s = sides[std::size_t(k)];
      for (int q = 0; q <= s; ++q) {
        std::array<int, 3> w{0, 0, 0};
        w[std::size_t(k)] = s - q, w[std::size_t((k + 1) % 3)] = q;
        along[std::size_t(k)].push_back(uniform ? lattice[slot(w[1], w[2])] : place(w[0], w[1], w[2], s));
      }
    }
    if (!uniform) {
      // The inner lattice's sides, from the inner corner near corner k to the one near k + 1,
      // zipped to the triangle's sides.
      const std::array<std::array<int, 2>, 3> innerCorner{{{1, 1}, {n - 2, 1}, {1, n - 2}}};
      for (int k = 0; k < 3; ++k) {
        const auto [i0, j0] = innerCorner[std::size_t(k)];
        const auto [i1, j1] = innerCorner[std::size_t((k + 1) % 3)];
        const int m = n - 3;
        ring.clear();
        for (int q = 0; q <= m; ++q)
          ring.push_back(lattice[slot(i0 + (m == 0 ? 0 : (i1 - i0) * q / m), j0 + (m == 0 ? 0 : (j1 - j0) * q / m))]);
        const std::vector<Placed>& outer = along[std::size_t(k)];
        const int s = int(outer.size()) - 1;
        for (int o = 0, r = 0; o < s || r < m;) {
          if (r == m || (o < s && (o + 1) * m <= (r + 1) * s)) {
            addFace(outer[std::size_t(o)], outer[std::size_t(o + 1)], ring[std::size_t(r)]);
            ++o;
          } else {
            addFace(outer[std::size_t(o)], ring[std::size_t(r + 1)], ring[std::size_t(r)]);
            ++r;
          }
        }
      }
    }
    // The element edges along this triangle's sides, in pieces, each once.
    for (int side = 0; side < 3; ++side) {
      const NodeIndex a = t.nodes[std::size_t(side)], b = t.nodes[std::size_t((side + 1) % 3)];
      const std::array<NodeIndex, 2> key{std::min(a, b), std::max(a, b)};
      const auto found = std::lower_bound(boundary.edges.begin(), boundary.edges.end(), key);
      if (found == boundary.edges.end() || *found != key) continue;
      char& done = edgeDone[std::size_t(found - boundary.edges.begin())];
      if (done) continue;
      done = 1;
      const float near = std::min(shortestAt[a], shortestAt[b]);
      const std::vector<Placed>& points = along[std::size_t(side)];
      for (std::size_t q = 0; q + 1 < points.size(); ++q) {
        surface.edges.push_back({points[q].point, points[q + 1].point});
        surface.edgeSpacing.push_back(near);
      }
    }
  }
  surface.mesh.request_face_normals();
  surface.mesh.update_face_normals();
  progress.report(1.0);
  return out;
}

std::optional<RefinedValues> revalueBoundary(const optics::ElementField& field, const BoundarySurface& boundary,
                                             const RefinedSurface& refined, const RefinementLimits& limits,
                                             const Progress& progress) {
  const TetMesh& split = field.split();
  const std::vector<double> splitValues = split.nodeValues(field.mesh(), field.values());
  CellMap map(field.mesh(), field, split, splitValues);
  const std::vector<BoundaryTriangle> triangles = trianglesOf(boundary);
  // The points serve where every triangle asks for the cut it has: a fresh refinement would
  // place the same points, so a recolored surface is the one `volpost render` draws.
  const SurfacePlan plan = planSurface(map, triangles, triangleDeviations(map, field, boundary, triangles), limits);
  if (plan.own != refined.levels) return std::nullopt;
  RefinedValues out;
  out.deviation = plan.deviation;
  out.toleranceReached = out.deviation <= limits.tolerance * (1.0 + 1e-9);
  out.values.reserve(refined.points.size());
  std::uint32_t selected = std::numeric_limits<std::uint32_t>::max();
  for (std::size_t k = 0; k < refined.points.size(); ++k) {
    if (k % 65536 == 0) progress.report(double(k) / double(refined.points.size()));
    const RefinedPoint& p = refined.points[k];
    if (p.triangle >= triangles.size() || p.level == 0) return std::nullopt;  // another boundary
    if (p.triangle != selected) {                                             // points come triangle by triangle
      const BoundaryTriangle& t = triangles[p.triangle];
      map.select(t.cell, cornersOf(t));
      selected = p.triangle;
    }
    const double level = p.level;
    glm::dvec3 position;
    double value = 0.0;
    map.at({(level - p.i - p.j) / level, p.i / level, p.j / level, 0.0}, position, value);
    out.values.push_back(value);
  }
  progress.report(1.0);
  return out;
}

}  // namespace volpost

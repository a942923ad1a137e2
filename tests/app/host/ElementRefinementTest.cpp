// SPDX-License-Identifier: MIT
// Surfaces of the cells' own field and shape: iso-surfaces and sections drawn from the
// split's tetrahedra refined in the cells' natural coordinates. Checked against closed
// forms the elements represent exactly (a hex8 carrying xyz, a tet10 carrying a quadratic,
// a hex20 quarter cylinder whose curved faces are arcs): the same surfaces from the split
// miss them by far more, so these tests cannot pass on the split.
#include "host/ElementRefinement.hpp"
#include "host/IsoSurfaceExtraction.hpp"
#include "host/SectionCut.hpp"
#include "support/HexLattice.hpp"
#include "support/ReferenceCells.hpp"
#include "support/TetGrid.hpp"

#include <volpost/core/CellShape.hpp>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <numbers>

using namespace volpost;

namespace {

// The tet4 grid with a midside node on every edge, halfway: straight tet10 cells.
Mesh tet10Grid(int n) {
  const Mesh linear = test::tetGrid(n, n, n, glm::dvec3(0.0), 1.0 / n);
  Mesh mesh;
  mesh.nodes = linear.nodes;
  std::map<std::pair<NodeIndex, NodeIndex>, NodeIndex> midside;
  constexpr int kEdges[6][2] = {{0, 1}, {1, 2}, {0, 2}, {0, 3}, {1, 3}, {2, 3}};  // VTK's tet10 order
  for (std::size_t c = 0; c < linear.cellCount(); ++c) {
    const auto corners = linear.cellNodes(c);
    std::vector<NodeIndex> ids(corners.begin(), corners.end());
    for (const auto& e : kEdges) {
      NodeIndex a = corners[std::size_t(e[0])], b = corners[std::size_t(e[1])];
      const auto key = std::minmax(a, b);
      const auto [it, fresh] = midside.emplace(key, NodeIndex(mesh.nodes.size()));
      if (fresh) mesh.nodes.push_back(0.5 * (mesh.nodes[a] + mesh.nodes[b]));
      ids.push_back(it->second);
    }
    mesh.addCell(CellType::Tet10, ids);
  }
  return mesh;
}

std::vector<double> sampled(const Mesh& mesh, const std::function<double(const glm::dvec3&)>& f) {
  std::vector<double> values;
  for (const glm::dvec3& p : mesh.nodes) values.push_back(f(p));
  return values;
}

double largestMiss(const ExtractedSurface& s, const std::function<double(const glm::dvec3&)>& f, double iso) {
  double worst = 0.0;
  for (const auto v : s.mesh.vertices()) {
    const auto p = s.mesh.point(v);
    worst = std::max(worst, std::abs(f(s.origin + glm::dvec3(p[0], p[1], p[2])) - iso));
  }
  return worst;
}

// Edges with one face: where the surface is open. Inside the mesh there must be none.
std::size_t openEdgesInside(const ExtractedSurface& s, double lo, double hi) {
  std::size_t open = 0;
  for (const auto e : s.mesh.edges()) {
    if (!s.mesh.is_boundary(e)) continue;
    for (const auto v : {e.v0(), e.v1()}) {
      const auto p = s.mesh.point(v);
      const glm::dvec3 x = s.origin + glm::dvec3(p[0], p[1], p[2]);
      bool onBoundary = false;
      for (int a = 0; a < 3; ++a) onBoundary = onBoundary || std::abs(x[a] - lo) < 1e-9 || std::abs(x[a] - hi) < 1e-9;
      if (!onBoundary) ++open;
    }
  }
  return open;
}

double area(const SectionTriangles& s) {
  double sum = 0.0;
  for (std::size_t t = 0; t + 2 < s.positions.size(); t += 3)
    sum += 0.5 * glm::length(glm::cross(s.positions[t + 1] - s.positions[t], s.positions[t + 2] - s.positions[t]));
  return sum;
}

}  // namespace

TEST(ElementRefinement, TheIsoSurfaceOfAHex8FieldIsItsTrilinearLevelSetClosed) {
  const Mesh mesh = test::hexLattice(CellType::Hex8, 4, [](const glm::dvec3& g) { return g / 4.0; });
  const auto f = [](const glm::dvec3& p) { return p.x * p.y * p.z; };
  const std::vector<double> values = sampled(mesh, f);  // the trilinear field is xyz itself
  const TetMesh split = tetrahedralize(mesh);
  const optics::ElementField field(mesh, values, split, glm::dvec3(0.0));
  for (double iso : {0.05, 0.2, 0.5}) {
    SCOPED_TRACE(iso);
    const ExtractedSurface own = extractIsoSurface(field, iso);
    const ExtractedSurface ofSplit = extractIsoSurface(split, split.nodeValues(mesh, values), iso);
    ASSERT_GT(own.mesh.n_faces(), 100u);
    EXPECT_TRUE(own.toleranceReached);
    EXPECT_GT(own.refinement, 1);
    EXPECT_LE(own.deviation, 1e-3);
    // Vertices lie on the surface xyz = iso to the tolerance (1e-3 of the range 1); the
    // split's miss it by several times more.
    EXPECT_LT(largestMiss(own, f, iso), 1e-3);
    EXPECT_GT(largestMiss(ofSplit, f, iso), 4e-3);
    EXPECT_EQ(openEdgesInside(own, 0.0, 1.0), 0u);
    for (const auto face : own.mesh.faces()) {  // facing larger values: along the gradient
      const auto n = own.mesh.calc_face_normal(face);
      const auto c = own.mesh.calc_face_centroid(face);
      const glm::dvec3 x = own.origin + glm::dvec3(c[0], c[1], c[2]);
      EXPECT_GT(n[0] * x.y * x.z + n[1] * x.x * x.z + n[2] * x.x * x.y, 0.0);
    }
  }
}

TEST(ElementRefinement, TheIsoSurfaceOfATet10QuadraticIsItsSphere) {
  const Mesh mesh = tet10Grid(3);
  const auto f = [](const glm::dvec3& p) { return glm::dot(p, p); };
  const std::vector<double> values = sampled(mesh, f);  // quadratic: the tet10 field exactly
  const TetMesh split = tetrahedralize(mesh);
  const optics::ElementField field(mesh, values, split, glm::dvec3(0.0));
  const ExtractedSurface own = extractIsoSurface(field, 0.5);
  const ExtractedSurface ofSplit = extractIsoSurface(split, split.nodeValues(mesh, values), 0.5);
  EXPECT_TRUE(own.toleranceReached);
  // The range of |p|^2 is 3: the tolerance 1e-3 of it.
  EXPECT_LT(largestMiss(own, f, 0.5), 3e-3);
  EXPECT_GT(largestMiss(ofSplit, f, 0.5), 4.0 * largestMiss(own, f, 0.5));
  EXPECT_EQ(openEdgesInside(own, 0.0, 1.0), 0u);
  // A finer tolerance gets closer.
  const ExtractedSurface finer = extractIsoSurface(field, 0.5, RefinementLimits{1e-4, 16});
  EXPECT_GT(finer.refinement, own.refinement);
  EXPECT_TRUE(finer.toleranceReached) << finer.refinement;
  EXPECT_LT(largestMiss(finer, f, 0.5), 3e-4);
  // Where the level is capped, the surface says the tolerance was not reached.
  EXPECT_FALSE(extractIsoSurface(field, 0.5, RefinementLimits{1e-4, 4}).toleranceReached);
}

TEST(ElementRefinement, ASectionOfAHex20QuarterCylinderIsRoundAndColoredByItsField) {
  // r in [1, 2], theta in [0, pi/2], z in [0, 1], 3 cells each way, every node on its arc.
  const auto place = [](const glm::dvec3& g) {
    const double r = 1.0 + g.x / 3.0, theta = std::numbers::pi / 2.0 * g.y / 3.0;
    return glm::dvec3(r * std::cos(theta), r * std::sin(theta), g.z / 3.0);
  };
  const Mesh mesh = test::hexLattice(CellType::Hex20, 3, place);
  const auto f = [](const glm::dvec3& p) { return p.z * (p.x + 2.0 * p.y); };  // not the field: only near it
  const std::vector<double> values = sampled(mesh, f);
  const TetMesh split = tetrahedralize(mesh);
  const optics::ElementField field(mesh, values, split, glm::dvec3(0.0));
  const ClipPlane plane{{0.0, 0.0, 0.4}, {0.0, 0.0, 1.0}};
  const SectionTriangles own = cutCells(field, {}, plane);
  const SectionTriangles ofSplit = cutTetrahedra(split, split.nodeValues(mesh, values), true, plane);
  const double exact = std::numbers::pi / 4.0 * (4.0 - 1.0);
  EXPECT_NEAR(area(own), exact, 2e-3 * exact);
  EXPECT_GT(std::abs(area(ofSplit) - exact), 0.02 * exact);  // chords across 30 degrees
  double innermost = INFINITY, outermost = 0.0;
  for (const glm::dvec3& p : own.positions) {
    const double r = std::hypot(p.x, p.y);
    innermost = std::min(innermost, r), outermost = std::max(outermost, r);
    EXPECT_NEAR(p.z, 0.4, 1e-12);
  }
  EXPECT_NEAR(innermost, 1.0, 1e-3);
  EXPECT_NEAR(outermost, 2.0, 1e-3);
  // The colors are the cells' own field, agreeing with its value found at the same point.
  ASSERT_EQ(own.values.size(), own.positions.size());
  for (std::size_t k = 0; k < own.positions.size(); k += 7) {
    double best = INFINITY;
    for (std::uint32_t cell = 0; cell < mesh.cellCount(); ++cell) {
      glm::dvec3 xi = field.start(cell);
      const auto v = field.value(cell, own.positions[k], xi);
      if (v && outsideReference(mesh.cellType(cell), xi) < 1e-2) best = std::min(best, std::abs(*v - own.values[k]));
    }
    EXPECT_LT(best, 1e-3 * field.valueScale());
  }
  // Element results keep their cell's value on every triangle of its section.
  std::vector<double> perCell(mesh.cellCount());
  for (std::size_t c = 0; c < perCell.size(); ++c) perCell[c] = double(c);
  const SectionTriangles cells = cutCells(field, perCell, plane);
  for (std::size_t t = 0; t + 2 < cells.values.size(); t += 3) {
    EXPECT_EQ(cells.values[t], cells.values[t + 1]);
    EXPECT_EQ(cells.values[t], cells.values[t + 2]);
  }
}

TEST(ElementRefinement, PiecesTileTheirCellsAndNeighboursShareTheirPoints) {
  // 2 x 2 x 2 cubes of the box [0, 2]^3, straight and then bent (their hex8 maps not affine).
  for (const bool bent : {false, true}) {
    const Mesh mesh = test::hexLattice(CellType::Hex8, 2, [bent](const glm::dvec3& g) {
      return bent ? g + 0.1 * glm::dvec3(g.y * g.z, g.x * g.z, g.x * g.y) : g;
    });
    const TetMesh split = tetrahedralize(mesh);
    const optics::ElementField field(mesh, sampled(mesh, [](const glm::dvec3& p) { return p.x * p.y * p.z; }), split,
                                     glm::dvec3(0.0));
    std::vector<std::uint32_t> all(split.mesh.cellCount());
    for (std::uint32_t t = 0; t < all.size(); ++t) all[t] = t;
    for (int level : {1, 2, 3, 5}) {
      SCOPED_TRACE(testing::Message() << (bent ? "bent, " : "straight, ") << level);
      const RefinedTetrahedra r = refineTetrahedra(field, all, RefinementLimits{1e-12, level});
      ASSERT_EQ(r.level, level);
      ASSERT_EQ(r.tets.mesh.cellCount(), all.size() * std::size_t(level * level * level));
      // Closed: the only faces with one piece are the box's, each of its 24 triangles of
      // the split cut into level^2 (a piece face not shared would show here as well).
      EXPECT_EQ(extractBoundary(r.tets.mesh).mesh.n_faces(), std::size_t(48 * level * level));
      double volume = 0.0, smallest = INFINITY;
      for (std::size_t t = 0; t < r.tets.mesh.cellCount(); ++t) {
        const double v = std::abs(signedCellVolume(r.tets.mesh, t));
        volume += v, smallest = std::min(smallest, v);
      }
      EXPECT_GT(smallest, 0.0);
      if (!bent) EXPECT_NEAR(volume, 8.0, 1e-12);  // no gaps, no overlaps
      for (std::size_t p = 0; p < r.tets.mesh.cellCount(); p += 17)
        EXPECT_EQ(r.tets.sourceCell(p), split.sourceCell(all[p / std::size_t(level * level * level)]));
    }
  }
}

TEST(ElementRefinement, EveryCellTypeIsTiledAndCarriesItsOwnField) {
  // One straight cell of each type: the pieces fill it exactly and close over its faces,
  // and every piece's corner carries the cell's own field at that point (a field with a
  // quadratic part, which the split's linear pieces would not carry).
  for (CellType type : kAllCellTypes) {
    SCOPED_TRACE(std::string(cellTypeName(type)));
    const auto [mesh, volume] = test::referenceCell(type);
    const auto f = [](const glm::dvec3& p) { return p.x + 2.0 * p.y * p.z - p.x * p.x + 3.0 * p.x * p.y; };
    const std::vector<double> values = sampled(mesh, f);
    const TetMesh split = tetrahedralize(mesh);
    const optics::ElementField field(mesh, values, split, glm::dvec3(0.0));
    std::vector<std::uint32_t> all(split.mesh.cellCount());
    for (std::uint32_t t = 0; t < all.size(); ++t) all[t] = t;
    const RefinedTetrahedra r = refineTetrahedra(field, all, RefinementLimits{1e-12, 3});
    ASSERT_EQ(r.level, type == CellType::Tet4 ? 1 : 3) << "a tet4's linear field needs no refinement";
    double sum = 0.0;
    for (std::size_t t = 0; t < r.tets.mesh.cellCount(); ++t) sum += signedCellVolume(r.tets.mesh, t);
    EXPECT_NEAR(sum, volume, 1e-12) << "positive pieces, no gaps, no overlaps";
    const BoundarySurface outside = extractBoundary(r.tets.mesh);
    EXPECT_EQ(outside.nonManifoldFaceCount, 0u);
    for (const auto e : outside.mesh.edges()) EXPECT_FALSE(outside.mesh.is_boundary(e)) << "closed";
    for (std::size_t n = 0; n < r.tets.mesh.nodeCount(); ++n) {
      glm::dvec3 xi = field.start(0);
      const auto own = field.value(0, r.tets.mesh.nodes[n], xi);
      ASSERT_TRUE(own.has_value());
      EXPECT_NEAR(r.values[n], *own, 1e-9);
    }
  }
}

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
#include "support/RefinedPieces.hpp"
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
    const RefinedTetrahedra r = refineTetrahedra(field, test::everyTet(split), RefinementLimits{1e-12, 3});
    ASSERT_EQ(r.level, type == CellType::Tet4 ? 1 : 3) << "a tet4's linear field needs no refinement";
    test::expectTheCellTiledWithItsOwnField(r, field, volume);
  }
}

namespace {

double surfaceArea(const BoundarySurface& s) {
  double sum = 0.0;
  for (const auto f : s.mesh.faces()) sum += double(s.mesh.calc_face_area(f));
  return sum;
}

glm::dvec3 positionOf(const BoundarySurface& s, SurfaceMesh::VertexHandle v) {
  const auto p = s.mesh.point(v);
  return s.origin + glm::dvec3(p[0], p[1], p[2]);
}

}  // namespace

TEST(ElementRefinement, TheBoundaryOfAHex20QuarterCylinderIsRoundClosedAndColoredByItsField) {
  // r in [1, 2], theta in [0, pi/2], z in [0, 1], 3 cells each way, every node on its arc.
  const auto place = [](const glm::dvec3& g) {
    const double r = 1.0 + g.x / 3.0, theta = std::numbers::pi / 2.0 * g.y / 3.0;
    return glm::dvec3(r * std::cos(theta), r * std::sin(theta), g.z / 3.0);
  };
  const Mesh mesh = test::hexLattice(CellType::Hex20, 3, place);
  const std::vector<double> values = sampled(mesh, [](const glm::dvec3& p) { return p.z * (p.x + 2.0 * p.y); });
  const TetMesh split = tetrahedralize(mesh);
  const optics::ElementField field(mesh, values, split, glm::dvec3(0.0));
  const BoundarySurface boundary = extractBoundary(mesh);
  // Three cells over 90 degrees are coarse: the default 8 levels leave just over 1/1000.
  const RefinedSurface curved = refineBoundary(field, boundary, RefinementLimits{1e-3, 12});
  const BoundarySurface& s = curved.surface;
  EXPECT_TRUE(curved.toleranceReached);
  EXPECT_GT(curved.level, 1);
  EXPECT_EQ(s.nonManifoldFaceCount, 0u);
  for (const auto e : s.mesh.edges()) ASSERT_FALSE(s.mesh.is_boundary(e)) << "closed: neighbours share their points";
  // The inner and outer cylinders (pi/2 and pi), the two ends (3 pi / 4 each), the two flat
  // sides (1 each). The flat triangles through the nodes zigzag across the cylinders (a
  // Schwarz lantern) and miss it by more than 1/1000.
  const double exact = 3.0 * std::numbers::pi + 2.0;
  EXPECT_NEAR(surfaceArea(s), exact, 2e-4 * exact);
  EXPECT_GT(std::abs(exact - surfaceArea(boundary)), 1e-3 * exact);
  // The pieces' middles on the inner cylinder lie on it (the chords' sag 1 - cos 7.5 deg).
  double worstInner = 0.0, worstInnerOfNodes = 0.0;
  const auto innerMiss = [](const BoundarySurface& b, SurfaceMesh::FaceHandle f, double& worst) {
    glm::dvec3 middle(0.0);
    for (const auto v : b.mesh.fv_range(f)) {
      const glm::dvec3 p = positionOf(b, v);
      if (std::hypot(p.x, p.y) > 1.0 + 1e-5) return;
      middle += p / 3.0;
    }
    worst = std::max(worst, 1.0 - std::hypot(middle.x, middle.y));
  };
  for (const auto f : s.mesh.faces()) innerMiss(s, f, worstInner);
  for (const auto f : boundary.mesh.faces()) innerMiss(boundary, f, worstInnerOfNodes);
  EXPECT_LT(worstInner, 1e-3);
  EXPECT_GT(worstInnerOfNodes, 4e-3);
  // The points carry the cells' own field, as found at their place by the inverse map.
  ASSERT_EQ(curved.values.size(), s.mesh.n_vertices());
  for (const auto v : s.mesh.vertices()) {
    if (v.idx() % 11 != 0) continue;
    const glm::dvec3 p = positionOf(s, v);
    double best = INFINITY;
    for (std::uint32_t cell = 0; cell < mesh.cellCount(); ++cell) {
      glm::dvec3 xi = field.start(cell);
      const auto own = field.value(cell, p, xi);
      if (own && outsideReference(mesh.cellType(cell), xi) < 1e-4)
        best = std::min(best, std::abs(*own - curved.values[s.mesh.property(s.nodeOfVertex, v)]));
    }
    EXPECT_LT(best, 1e-5 * field.valueScale());
  }
  // Every element edge on the boundary, drawn in pieces (as many as its finer side needs).
  EXPECT_GT(s.edges.size(), boundary.edges.size());
  EXPECT_LE(s.edges.size(), boundary.edges.size() * std::size_t(curved.level));
  EXPECT_EQ(s.edgeSpacing.size(), s.edges.size());
}

TEST(ElementRefinement, TheBoundaryOfAHex8BlockIsColoredByItsTrilinearField) {
  // f = xyz is the hex8 field exactly: across each piece of a face the colors are linear
  // between its corners; they stay within 1/1000 of the range of xyz at the piece's
  // middle, where the two flat triangles of each face miss it by far more.
  const Mesh mesh = test::hexLattice(CellType::Hex8, 2, [](const glm::dvec3& g) { return g; });
  const auto f = [](const glm::dvec3& p) { return p.x * p.y * p.z; };
  const std::vector<double> values = sampled(mesh, f);
  const TetMesh split = tetrahedralize(mesh);
  const optics::ElementField field(mesh, values, split, glm::dvec3(0.0));
  const BoundarySurface boundary = extractBoundary(mesh);
  const RefinedSurface curved = refineBoundary(field, boundary);
  const auto worstMiddle = [&](const BoundarySurface& b, const auto& valueOfVertex) {
    double worst = 0.0;
    for (const auto face : b.mesh.faces()) {
      glm::dvec3 middle(0.0);
      double mean = 0.0;
      for (const auto v : face.vertices()) middle += positionOf(b, v) / 3.0, mean += valueOfVertex(v) / 3.0;
      worst = std::max(worst, std::abs(mean - f(middle)) / 8.0);
    }
    return worst;
  };
  const BoundarySurface& s = curved.surface;
  for (const auto v : s.mesh.vertices()) {
    const glm::dvec3 p = positionOf(s, v);
    EXPECT_NEAR(curved.values[s.mesh.property(s.nodeOfVertex, v)], f(p), 1e-5);  // float positions
  }
  EXPECT_LT(worstMiddle(s, [&](auto v) { return curved.values[s.mesh.property(s.nodeOfVertex, v)]; }), 1e-3);
  EXPECT_GT(worstMiddle(boundary, [&](auto v) { return values[boundary.mesh.property(boundary.nodeOfVertex, v)]; }),
            1e-2);
}

// Each triangle is cut as finely as it needs: a block of hex20 cells whose right half
// bulges on top (z = 2 + 0.3 (x - 1)(2 - x) there, which the cells represent exactly) and
// carries a linear field is cut finely on the bulge and along the sides it shares, and not
// elsewhere; the surface stays closed, and its area is the uniformly cut surface's (no
// stitch folds over a side).
TEST(ElementRefinement, EachBoundaryTriangleIsCutAsFinelyAsItNeedsAndTheSurfaceStaysClosed) {
  const auto place = [](const glm::dvec3& g) {
    const double bulge = g.x > 1.0 ? 0.1 * (g.x - 1.0) * (2.0 - g.x) : 0.0;
    return glm::dvec3(g.x, g.y, g.z * (1.0 + bulge / 2.0));
  };
  const Mesh mesh = test::hexLattice(CellType::Hex20, 2, place);
  const std::vector<double> values = sampled(mesh, [](const glm::dvec3& p) { return p.x + p.y - p.z; });
  const TetMesh split = tetrahedralize(mesh);
  const optics::ElementField field(mesh, values, split, glm::dvec3(0.0));
  const BoundarySurface boundary = extractBoundary(mesh);
  const RefinedSurface adaptive = refineBoundary(field, boundary);
  RefinementLimits everywhere;  // as finely everywhere as the finest triangle
  everywhere.tolerance = 1e-12;
  everywhere.maxLevel = adaptive.level;
  const RefinedSurface uniform = refineBoundary(field, boundary, everywhere);
  ASSERT_GT(adaptive.level, 2) << "the bulge needs cutting";
  // One level for the whole surface would cut every triangle so.
  EXPECT_LT(adaptive.surface.mesh.n_faces(),
            boundary.mesh.n_faces() * std::size_t(adaptive.level * adaptive.level) / 2);
  EXPECT_TRUE(adaptive.toleranceReached);
  const BoundarySurface& s = adaptive.surface;
  EXPECT_EQ(s.nonManifoldFaceCount, 0u);
  for (const auto e : s.mesh.edges()) ASSERT_FALSE(s.mesh.is_boundary(e)) << "closed: stitched sides share points";
  EXPECT_NEAR(surfaceArea(s), surfaceArea(uniform.surface), 1e-4 * surfaceArea(uniform.surface));
  EXPECT_GT(std::abs(surfaceArea(boundary) - surfaceArea(uniform.surface)), 1e-3) << "the bulge shows";
  // The face x = 0, away from the bulge, keeps the boundary's triangles.
  const auto onLeftFace = [](const BoundarySurface& b) {
    std::size_t count = 0;
    for (const auto f : b.mesh.faces()) {
      bool left = true;
      for (const auto v : f.vertices()) left = left && std::abs(positionOf(b, v).x) < 1e-6;
      count += left ? 1 : 0;
    }
    return count;
  };
  EXPECT_GT(onLeftFace(boundary), 0u);
  EXPECT_EQ(onLeftFace(s), onLeftFace(boundary));
}

TEST(ElementRefinement, ATet4BoundaryIsLeftAsItIs) {
  const Mesh mesh = test::referenceCell(CellType::Tet4).first;
  const TetMesh split = tetrahedralize(mesh);
  const optics::ElementField field(mesh, sampled(mesh, [](const glm::dvec3& p) { return p.x; }), split,
                                   glm::dvec3(0.0));
  const BoundarySurface boundary = extractBoundary(mesh);
  const RefinedSurface curved = refineBoundary(field, boundary);
  EXPECT_EQ(curved.level, 1);
  EXPECT_EQ(curved.surface.mesh.n_faces(), boundary.mesh.n_faces());
  EXPECT_EQ(curved.surface.edges.size(), boundary.edges.size());
}

TEST(ElementRefinement, EveryCellTypesBoundaryClosesAndCarriesItsOwnField) {
  for (CellType type : kAllCellTypes) {
    SCOPED_TRACE(std::string(cellTypeName(type)));
    const Mesh mesh = test::referenceCell(type).first;
    const std::vector<double> values =
        sampled(mesh, [](const glm::dvec3& p) { return p.x + 2.0 * p.y * p.z - p.x * p.x + 3.0 * p.x * p.y; });
    const TetMesh split = tetrahedralize(mesh);
    const optics::ElementField field(mesh, values, split, glm::dvec3(0.0));
    const RefinedSurface curved = refineBoundary(field, extractBoundary(mesh), RefinementLimits{1e-12, 3});
    const BoundarySurface& s = curved.surface;
    EXPECT_EQ(s.nonManifoldFaceCount, 0u);
    for (const auto e : s.mesh.edges()) EXPECT_FALSE(s.mesh.is_boundary(e)) << "closed";
    for (const auto v : s.mesh.vertices()) {
      glm::dvec3 xi = field.start(0);
      const auto own = field.value(0, positionOf(s, v), xi);
      ASSERT_TRUE(own.has_value());
      EXPECT_NEAR(curved.values[s.mesh.property(s.nodeOfVertex, v)], *own, 1e-5);  // float positions
    }
  }
}

TEST(ElementRefinement, FlatFacesOfDistortedCellsAreNotCutWarpedOnesAre) {
  // Trapezoids: x stretched with y keeps every face of the hex8 cells flat; their bilinear
  // maps move points within the faces only, which draws the same faces.
  const auto shapesOf = [](const Mesh& mesh) {
    const TetMesh split = tetrahedralize(mesh);
    const optics::ElementField field(mesh, std::vector<double>(mesh.nodeCount(), 0.0), split, glm::dvec3(0.0));
    return refineBoundary(field, extractBoundary(mesh));
  };
  const RefinedSurface flat = shapesOf(test::hexLattice(
      CellType::Hex8, 2, [](const glm::dvec3& g) { return glm::dvec3(g.x * (1.0 + 0.3 * g.y), g.y, g.z); }));
  EXPECT_EQ(flat.level, 1);
  // The top lifted by x y: its faces warp, and are cut to follow them.
  const RefinedSurface warped = shapesOf(test::hexLattice(
      CellType::Hex8, 2, [](const glm::dvec3& g) { return glm::dvec3(g.x, g.y, g.z + 0.1 * g.z * g.x * g.y); }));
  EXPECT_GT(warped.level, 1);
  EXPECT_TRUE(warped.toleranceReached);
}

TEST(ElementRefinement, AFieldLinearInSpaceOnDistortedFlatFacedCellsNeedsNoPieces) {
  // Trapezoid hex8 cells carrying f = x + 2 y - z: their own field is that linear function
  // in space (their map is the same trilinear form), which the split's tetrahedra already
  // carry. Their bilinear maps move points within the cells without bending a face, which
  // neither the field nor the shape sees; warped faces still call for pieces.
  const auto levelFor = [](const Mesh& mesh) {
    const TetMesh split = tetrahedralize(mesh);
    const optics::ElementField field(mesh, sampled(mesh, [](const glm::dvec3& p) { return p.x + 2.0 * p.y - p.z; }),
                                     split, glm::dvec3(0.0));
    std::vector<std::uint32_t> all(split.mesh.cellCount());
    for (std::uint32_t t = 0; t < all.size(); ++t) all[t] = t;
    return refineTetrahedra(field, all).level;
  };
  EXPECT_EQ(levelFor(test::hexLattice(
                CellType::Hex8, 2, [](const glm::dvec3& g) { return glm::dvec3(g.x * (1.0 + 0.3 * g.y), g.y, g.z); })),
            1);
  EXPECT_GT(
      levelFor(test::hexLattice(CellType::Hex8, 2,
                                [](const glm::dvec3& g) { return glm::dvec3(g.x, g.y, g.z + 0.1 * g.z * g.x * g.y); })),
      1);
}

// Another step on the same curved surface: the points stay and take the new field's values,
// the very values a fresh refinement gives them; a field that needs another level is
// refused (refine again).
TEST(ElementRefinement, AnotherStepRecolorsTheRefinedBoundaryWithoutMovingItsPoints) {
  const Mesh mesh = test::hex20QuarterAnnulus(2);
  const TetMesh split = tetrahedralize(mesh);
  const BoundarySurface boundary = extractBoundary(mesh);
  const auto fieldOf = [&](const std::function<double(const glm::dvec3&)>& f) {
    return optics::ElementField(mesh, sampled(mesh, f), split, glm::dvec3(0.0));
  };
  const optics::ElementField first = fieldOf([](const glm::dvec3& p) { return p.z * (p.x + 2.0 * p.y); });
  const RefinementLimits limits{1e-3, 16};
  const RefinedSurface refined = refineBoundary(first, boundary, limits);
  ASSERT_GT(refined.level, 1);
  ASSERT_LT(refined.level, 16);
  ASSERT_EQ(refined.points.size(), refined.values.size());
  // The next step: the same field scaled and shifted needs the same level.
  const optics::ElementField next = fieldOf([](const glm::dvec3& p) { return 3.0 * p.z * (p.x + 2.0 * p.y) - 1.0; });
  const RefinedSurface fresh = refineBoundary(next, boundary, limits);
  ASSERT_EQ(fresh.level, refined.level);
  const auto revalued = revalueBoundary(next, boundary, refined, limits);
  ASSERT_TRUE(revalued.has_value());
  ASSERT_EQ(revalued->values.size(), fresh.values.size());
  for (std::size_t k = 0; k < fresh.values.size(); ++k)
    ASSERT_EQ(revalued->values[k], fresh.values[k]) << "point " << k;
  EXPECT_EQ(revalued->deviation, fresh.deviation);
  EXPECT_EQ(revalued->toleranceReached, fresh.toleranceReached);
  // A field that bends far more within each cell needs more pieces: refused.
  const optics::ElementField wavy =
      fieldOf([](const glm::dvec3& p) { return std::sin(9.0 * p.x) * std::cos(7.0 * p.y); });
  ASSERT_NE(refineBoundary(wavy, boundary, limits).level, refined.level);
  EXPECT_FALSE(revalueBoundary(wavy, boundary, refined, limits).has_value());
}

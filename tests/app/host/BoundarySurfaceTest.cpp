// SPDX-License-Identifier: MIT
#include "support/ReferenceCells.hpp"

#include "host/BoundarySurface.hpp"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

using namespace volpost;

namespace {

// Volume enclosed by the surface (divergence theorem): equals the mesh volume only if
// every boundary face is present once and oriented outward. Computed in the surface's
// own (origin-relative) coordinates: a closed surface's volume does not depend on them.
double enclosedVolume(const BoundarySurface& s) {
  double v = 0.0;
  for (const auto f : s.mesh.faces()) {
    std::vector<glm::dvec3> p;
    for (const auto vh : f.vertices()) {
      const auto q = s.mesh.point(vh);
      p.push_back(glm::dvec3(q[0], q[1], q[2]));
    }
    v += glm::dot(p[0], glm::cross(p[1], p[2])) / 6.0;
  }
  return v;
}

Mesh hexBlock(int nx) {  // nx unit hexahedra in a row along x
  Mesh m;
  for (int i = 0; i <= nx; ++i)
    for (auto [y, z] : {std::pair{0, 0}, {1, 0}, {1, 1}, {0, 1}}) m.nodes.push_back({double(i), double(y), double(z)});
  for (int i = 0; i < nx; ++i) {
    const NodeIndex a = NodeIndex(4 * i), b = NodeIndex(4 * (i + 1));
    // VTK hex: bottom quad (z=0... here the x=i face) then the opposite one.
    const NodeIndex cell[8] = {a, NodeIndex(a + 1), NodeIndex(a + 2), NodeIndex(a + 3),
                               b, NodeIndex(b + 1), NodeIndex(b + 2), NodeIndex(b + 3)};
    m.addCell(CellType::Hex8, cell);
  }
  return m;
}

}  // namespace

TEST(BoundarySurface, HexRowKeepsOnlyOuterFaces) {
  const Mesh m = hexBlock(2);
  ASSERT_LT(std::abs(signedCellVolume(m, 0)), 2.0);
  const BoundarySurface s = extractBoundary(m);
  EXPECT_EQ(s.boundaryFaceCount, 10u);
  EXPECT_EQ(s.mesh.n_faces(), 20u);
  EXPECT_EQ(s.edges.size(), 20u);
  EXPECT_NEAR(std::abs(enclosedVolume(s)), 2.0, 1e-6);
  EXPECT_NEAR(enclosedVolume(s), signedCellVolume(m, 0) + signedCellVolume(m, 1), 1e-6);
}

class BoundaryOfEachCell : public ::testing::TestWithParam<CellType> {};

TEST_P(BoundaryOfEachCell, EnclosesTheCellVolumeOutward) {
  const auto [mesh, volume] = test::referenceCell(GetParam());
  const BoundarySurface s = extractBoundary(mesh);
  EXPECT_EQ(s.boundaryFaceCount, topology(GetParam()).faces.size());
  EXPECT_NEAR(enclosedVolume(s), volume, 1e-6);
  EXPECT_EQ(s.nonManifoldFaceCount, 0u);
}

TEST_P(BoundaryOfEachCell, QuadraticFacesUseTheirMidsideNodes) {
  const auto [mesh, volume] = test::referenceCell(GetParam());
  const BoundarySurface s = extractBoundary(mesh);
  std::size_t expectedTriangles = 0, expectedEdges = 0;
  for (const CellFace& f : topology(GetParam()).faces)
    expectedTriangles += topology(GetParam()).quadratic ? (f.size == 3 ? 4 : 6) : std::size_t(f.size - 2);
  expectedEdges = topology(GetParam()).edges.size() * (topology(GetParam()).quadratic ? 2 : 1);
  EXPECT_EQ(s.mesh.n_faces(), expectedTriangles);
  EXPECT_EQ(s.edges.size(), expectedEdges);
  EXPECT_EQ(s.mesh.n_vertices(), std::size_t(topology(GetParam()).nodeCount));
}

INSTANTIATE_TEST_SUITE_P(Cells, BoundaryOfEachCell, ::testing::ValuesIn(kAllCellTypes),
                         [](const auto& p) { return std::string(cellTypeName(p.param)); });

TEST(BoundarySurface, PositionsAreRelativeToTheCenterForFloatPrecision) {
  Mesh m = hexBlock(1);
  for (auto& p : m.nodes) p = p * 1e-3 + glm::dvec3(1e6, -2e6, 3e6);
  const BoundarySurface s = extractBoundary(m);
  EXPECT_NEAR(s.origin.x, 1e6 + 0.5e-3, 1e-9);
  for (const auto v : s.mesh.vertices()) EXPECT_LE(std::abs(s.mesh.point(v)[0]), 0.51e-3f);
  EXPECT_NEAR(enclosedVolume(s), 1e-9, 1e-12);
}

// A grid's boundary from its index ranges is the boundary of its hexahedra: the same
// triangles (nodes and cell), edges and face count, for a left-handed rotated grid too.
TEST(BoundarySurface, AGridsBoundaryIsItsHexahedrasBoundary) {
  for (const bool mirrored : {false, true}) {
    RegularGrid g;
    g.dims = {4, 5, 3};
    g.origin = {10.0, 20.0, -5.0};
    g.axes = {glm::dvec3(0.6, 0.8, 0.0), glm::dvec3(-1.6, 1.2, 0.0), glm::dvec3(0.0, 0.0, mirrored ? -0.5 : 0.5)};
    const BoundarySurface fromCells = extractBoundary(hexahedraOfGrid(g));
    const BoundarySurface fromGrid = extractBoundary(g);
    const auto triangles = [](const BoundarySurface& s) {
      std::multiset<std::array<std::uint32_t, 4>> out;
      for (auto f : s.mesh.faces()) {
        std::array<std::uint32_t, 3> n{};
        int k = 0;
        for (auto v : s.mesh.fv_range(f)) n[std::size_t(k++)] = s.mesh.property(s.nodeOfVertex, v);
        std::rotate(n.begin(), std::min_element(n.begin(), n.end()), n.end());  // same winding, one start
        out.insert({n[0], n[1], n[2], s.mesh.property(s.cellOfFace, f)});
      }
      return out;
    };
    EXPECT_EQ(fromGrid.boundaryFaceCount, fromCells.boundaryFaceCount);
    EXPECT_EQ(fromGrid.boundaryFaceCount, std::size_t(2 * (3 * 4 + 4 * 2 + 3 * 2)));
    EXPECT_EQ(triangles(fromGrid), triangles(fromCells));
    EXPECT_EQ(fromGrid.edges, fromCells.edges);
    EXPECT_EQ(fromGrid.nonManifoldFaceCount, 0u);
    for (auto v : fromGrid.mesh.vertices()) {
      const NodeIndex node = fromGrid.mesh.property(fromGrid.nodeOfVertex, v);
      const auto p = fromGrid.mesh.point(v);
      const glm::dvec3 expected = hexahedraOfGrid(g).nodes[node] - fromGrid.origin;
      EXPECT_NEAR(p[0], expected.x, 1e-5);
      EXPECT_NEAR(p[1], expected.y, 1e-5);
      EXPECT_NEAR(p[2], expected.z, 1e-5);
    }
  }
}

// A mesh of over 2M cells finds its unshared faces in passes over a share of the node
// numbers each: the same boundary as the grid's own sides give, face for face.
TEST(BoundarySurface, ALargeMeshFoundInPassesHasTheGridsBoundary) {
  RegularGrid g;
  g.dims = {131, 131, 131};  // 130^3 = 2.2M hexahedra: two passes
  g.origin = {1.0, 2.0, 3.0};
  g.axes = {glm::dvec3(0.5, 0.0, 0.0), glm::dvec3(0.0, 0.5, 0.0), glm::dvec3(0.0, 0.0, 0.25)};
  const Mesh hexes = hexahedraOfGrid(g);
  ASSERT_GE(hexes.cellCount() >> 20, 2u);
  const BoundarySurface fromCells = extractBoundary(hexes);
  const BoundarySurface fromGrid = extractBoundary(g);
  EXPECT_EQ(fromCells.boundaryFaceCount, std::size_t(6 * 130 * 130));
  EXPECT_EQ(fromCells.boundaryFaceCount, fromGrid.boundaryFaceCount);
  const auto cellsOfFaces = [](const BoundarySurface& s) {
    std::vector<std::uint32_t> cells;
    for (auto f : s.mesh.faces()) cells.push_back(s.mesh.property(s.cellOfFace, f));
    std::sort(cells.begin(), cells.end());
    return cells;
  };
  EXPECT_EQ(cellsOfFaces(fromCells), cellsOfFaces(fromGrid));
  EXPECT_NEAR(enclosedVolume(fromCells), 65.0 * 65.0 * 32.5, 1e-6 * 65.0 * 65.0 * 32.5);
  EXPECT_EQ(fromCells.nonManifoldFaceCount, 0u);
}

// SPDX-License-Identifier: MIT
// Conforming tetrahedralization: volume kept, no inverted tet, every interior triangle
// shared by exactly two tets, the boundary unchanged; on each cell type and on the bundled
// mixed wheel (hexahedra, wedges, pyramids, tetrahedra from gmsh).
#include "ReferenceCells.hpp"

#include <volpost/core/BoundarySurface.hpp>
#include <volpost/core/Tetrahedralize.hpp>

#include <gtest/gtest.h>

#include <array>
#include <map>

using namespace volpost;

namespace {

struct Conformity {
  std::size_t boundary = 0, interior = 0, overShared = 0;
  double volume = 0.0, smallestVolume = 1e300;
};

Conformity check(const TetMesh& t) {
  Conformity c;
  std::map<std::array<NodeIndex, 3>, int> faces;
  for (std::size_t i = 0; i < t.mesh.cellCount(); ++i) {
    const double v = signedCellVolume(t.mesh, i);
    c.volume += v;
    c.smallestVolume = std::min(c.smallestVolume, v);
    const auto n = t.mesh.cellNodes(i);
    for (const CellFace& f : topology(CellType::Tet4).faces) {
      std::array<NodeIndex, 3> k = {n[f.corners[0]], n[f.corners[1]], n[f.corners[2]]};
      std::sort(k.begin(), k.end());
      ++faces[k];
    }
  }
  for (const auto& [k, count] : faces) {
    if (count == 1) ++c.boundary;
    else if (count == 2) ++c.interior;
    else ++c.overShared;
  }
  return c;
}

double meshVolume(const Mesh& m) {
  double v = 0.0;
  for (std::size_t c = 0; c < m.cellCount(); ++c) v += signedCellVolume(m, c);
  return v;
}

}  // namespace

class TetrahedralizeEachCell : public ::testing::TestWithParam<CellType> {};

TEST_P(TetrahedralizeEachCell, KeepsTheVolumeWithPositiveTets) {
  const auto [mesh, volume] = test::referenceCell(GetParam());
  const TetMesh t = tetrahedralize(mesh);
  const Conformity c = check(t);
  EXPECT_NEAR(c.volume, volume, 1e-14);
  EXPECT_GT(c.smallestVolume, 0.0);
  EXPECT_EQ(c.overShared, 0u);
  for (std::uint32_t cell : t.cellOfTet) EXPECT_EQ(cell, 0u);
}

INSTANTIATE_TEST_SUITE_P(Cells, TetrahedralizeEachCell, ::testing::ValuesIn(kAllCellTypes),
                         [](const auto& p) { return std::string(cellTypeName(p.param)); });

TEST(Tetrahedralize, AMixOfEveryLinearTypeConformsAcrossSharedFaces) {
  // Two hexahedra side by side, a pyramid on the first, a wedge on the second (sharing a
  // quad), a tetrahedron on the wedge's triangle: every pair meets on a full face.
  Mesh m;
  m.nodes = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1},   {1, 0, 1},   {1, 1, 1},
             {0, 1, 1}, {2, 0, 0}, {2, 1, 0}, {2, 0, 1}, {2, 1, 1},   {0.5, 0.5, 2}, {1.5, 0, 1.7},
             {1.5, 1, 1.7}, {1.5, -1, 1.3}};
  const auto add = [&](CellType type, std::vector<NodeIndex> n) {
    m.addCell(type, n);
    if (signedCellVolume(m, m.cellCount() - 1) > 0.0) return;
    // Mirror to VTK's orientation: rebuild the cell with the first two faces' order flipped.
    Mesh fixed;
    fixed.nodes = m.nodes;
    for (std::size_t c = 0; c + 1 < m.cellCount(); ++c) fixed.addCell(m.cellType(c), m.cellNodes(c));
    if (type == CellType::Wedge6) std::swap(n[1], n[2]), std::swap(n[4], n[5]);
    if (type == CellType::Tet4) std::swap(n[1], n[2]);
    fixed.addCell(type, n);
    m = fixed;
  };
  add(CellType::Hex8, {0, 1, 2, 3, 4, 5, 6, 7});
  add(CellType::Hex8, {1, 8, 9, 2, 5, 10, 11, 6});
  add(CellType::Pyramid5, {4, 5, 6, 7, 12});
  add(CellType::Wedge6, {5, 10, 13, 6, 11, 14});
  add(CellType::Tet4, {5, 10, 13, 15});
  for (std::size_t c = 0; c < m.cellCount(); ++c) ASSERT_GT(signedCellVolume(m, c), 0.0) << c;
  const TetMesh t = tetrahedralize(m);
  const Conformity c = check(t);
  EXPECT_NEAR(c.volume, meshVolume(m), 1e-12);
  EXPECT_GT(c.smallestVolume, 0.0);
  EXPECT_EQ(c.overShared, 0u);
  // The boundary is the original one, its quads split in two.
  EXPECT_EQ(c.boundary, extractBoundary(m).mesh.n_faces());
}

TEST(Tetrahedralize, ValuesFollowThePieces) {
  const auto [mesh, volume] = test::referenceCell(CellType::Hex8);
  const TetMesh t = tetrahedralize(mesh);
  std::vector<double> x;
  for (const auto& p : mesh.nodes) x.push_back(p.x);
  const auto nodal = t.nodeValues(mesh, x);
  ASSERT_EQ(nodal.size(), t.mesh.nodeCount());
  EXPECT_DOUBLE_EQ(nodal.back(), 0.5);  // the centroid of a unit cube: mean of the corners
  const auto cells = t.cellValues(std::vector<double>{7.0});
  EXPECT_EQ(cells, std::vector<double>(t.mesh.cellCount(), 7.0));
}

// SPDX-License-Identifier: MIT
// Conforming tetrahedralization: volume kept, no inverted tet, every interior triangle
// shared by exactly two tets, the boundary unchanged; on each cell type and on the bundled
// mixed wheel (hexahedra, wedges, pyramids, tetrahedra from gmsh).
#include "support/ReferenceCells.hpp"

#include <volpost/core/Tetrahedralize.hpp>

#include "host/BoundarySurface.hpp"

#include <gtest/gtest.h>

#include <type_traits>

#include <algorithm>
#include <array>
#include <map>
#include <tuple>

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
  for (std::size_t tet = 0; tet < t.mesh.cellCount(); ++tet) EXPECT_EQ(t.sourceCell(tet), 0u);
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

namespace {

// A single cell of `type` with reference corners, its node indices permuted by `order`
// (so the smallest-index diagonal rule meets every configuration).
Mesh permutedCell(CellType type, const std::vector<glm::dvec3>& corners, const std::array<int, 8>& order) {
  Mesh m;
  const int n = topology(type).cornerCount;
  m.nodes.resize(std::size_t(n));
  std::vector<NodeIndex> cell(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k) {
    cell[std::size_t(k)] = NodeIndex(order[std::size_t(k)]);
    m.nodes[std::size_t(order[std::size_t(k)])] = corners[std::size_t(k)];
  }
  m.addCell(type, cell);
  return m;
}

}  // namespace

TEST(Tetrahedralize, EveryIndexOrderOfHexAndWedgeSplitsWithoutSteinerPoints) {
  // Dompierre et al.: with the smallest-index diagonal rule no hexahedron or prism ends
  // in a configuration that needs an interior point. Checked on all 8! and 6! orders.
  const std::vector<glm::dvec3> hex = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  const auto wedgeCell = test::referenceCell(CellType::Wedge6);
  const std::vector<glm::dvec3> wedge = wedgeCell.first.nodes;
  using Case = std::tuple<CellType, std::vector<glm::dvec3>, double>;
  for (const auto& [type, corners, volume] : {Case{CellType::Hex8, hex, 1.0}, Case{CellType::Wedge6, wedge, wedgeCell.second}}) {
    std::array<int, 8> order{0, 1, 2, 3, 4, 5, 6, 7};
    const int n = topology(type).cornerCount;
    std::size_t orders = 0;
    do {
      const TetMesh t = tetrahedralize(permutedCell(type, corners, order));
      ASSERT_TRUE(t.steinerCell.empty()) << cellTypeName(type) << " order " << orders;
      ASSERT_EQ(t.mesh.cellCount(), type == CellType::Hex8 ? 6u : 3u);
      const Conformity c = check(t);
      ASSERT_NEAR(c.volume, volume, 1e-14);
      ASSERT_GT(c.smallestVolume, 0.0);
      ++orders;
    } while (std::next_permutation(order.begin(), order.begin() + n));
    EXPECT_EQ(orders, type == CellType::Hex8 ? 40320u : 720u);
  }
}

TEST(Tetrahedralize, DistortedCellsFallBackToACentroidPointAndValuesFollow) {
  // A distorted hexahedron (corners moved by up to 0.35) whose Steiner-free split for its
  // diagonals would hold an inverted piece: it takes the centroid star instead. (Of 200,000
  // such random hexahedra, 6.1% fell back and 2.1% were folded beyond repair.)
  const std::vector<glm::dvec3> corners = {{-0.093, -0.057, 0.049}, {1.152, -0.147, 0.219}, {1.176, 0.949, 0.079},
                                           {-0.097, 0.950, -0.051}, {0.291, 0.306, 0.757}, {0.675, 0.081, 1.197},
                                           {0.856, 0.741, 1.108},   {-0.298, 0.842, 0.903}};
  const Mesh m = permutedCell(CellType::Hex8, corners, {2, 7, 1, 4, 5, 0, 3, 6});
  const TetMesh t = tetrahedralize(m);
  ASSERT_EQ(t.steinerCell, std::vector<std::uint32_t>{0});
  EXPECT_TRUE(t.foldedCells.empty());
  const Conformity c = check(t);
  EXPECT_GT(c.smallestVolume, 0.0);
  EXPECT_EQ(c.boundary, 12u);
  EXPECT_EQ(c.overShared, 0u);
  std::vector<double> x;
  for (const auto& p : m.nodes) x.push_back(p.x);
  const auto nodal = t.nodeValues(m, x);
  ASSERT_EQ(nodal.size(), t.mesh.nodeCount());
  double mean = 0.0;
  for (const auto& p : corners) mean += p.x / 8.0;
  EXPECT_DOUBLE_EQ(nodal.back(), mean);  // the Steiner point takes the mean of the corners
  const auto cells = t.cellValues(std::vector<double>{7.0});
  EXPECT_EQ(cells, std::vector<double>(cells.size(), 7.0));
}

TEST(Tetrahedralize, MirroredCellsSplitCleanlyAndBowTiesAreListedAsFolded) {
  const auto [mesh, volume] = test::referenceCell(CellType::Hex8);
  const auto n = mesh.cellNodes(0);
  Mesh mirrored;  // top face listed first: negative volume, but a perfectly good shape
  mirrored.nodes = mesh.nodes;
  mirrored.addCell(CellType::Hex8, std::vector<NodeIndex>{n[4], n[5], n[6], n[7], n[0], n[1], n[2], n[3]});
  const TetMesh t = tetrahedralize(mirrored);
  EXPECT_TRUE(t.foldedCells.empty());
  EXPECT_TRUE(t.steinerCell.empty());
  EXPECT_NEAR(check(t).volume, 1.0, 1e-14);
  EXPECT_GT(check(t).smallestVolume, 0.0);
  Mesh bowTie;  // two top nodes swapped: self-intersecting faces, no valid split exists
  bowTie.nodes = mesh.nodes;
  bowTie.addCell(CellType::Hex8, std::vector<NodeIndex>{n[0], n[1], n[2], n[3], n[4], n[5], n[7], n[6]});
  EXPECT_EQ(tetrahedralize(bowTie).foldedCells, std::vector<std::uint32_t>{0});
}

// Two unit tets sharing a face, both positive.
namespace {
volpost::Mesh twoTets() {
  volpost::Mesh m;
  m.nodes = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};
  const std::array<volpost::NodeIndex, 4> a = {0, 1, 2, 3}, b = {1, 2, 3, 4};
  m.addCell(volpost::CellType::Tet4, a);
  m.addCell(volpost::CellType::Tet4, b);
  if (volpost::signedCellVolume(m, 1) < 0.0) {  // orient the second one positively
    volpost::Mesh fixed;
    fixed.nodes = m.nodes;
    fixed.addCell(volpost::CellType::Tet4, a);
    const std::array<volpost::NodeIndex, 4> c = {2, 1, 3, 4};
    fixed.addCell(volpost::CellType::Tet4, c);
    return fixed;
  }
  return m;
}
}  // namespace

// An all-tet mesh (the usual case) is its own tetrahedralization: its cells are shared,
// not copied (17 bytes per tet at 100M tets is 1.7 GB).
TEST(Tetrahedralize, APositiveTetMeshSharesItsCellsInsteadOfCopying) {
  using namespace volpost;
  const Mesh m = twoTets();
  ASSERT_GT(signedCellVolume(m, 0), 0.0);
  ASSERT_GT(signedCellVolume(m, 1), 0.0);
  const TetMesh t = tetrahedralize(m);
  EXPECT_TRUE(t.mesh.sharesCellsWith(m));
  EXPECT_TRUE(t.cellOfTet.empty()) << "no identity map kept";
  EXPECT_EQ(t.sourceCell(0), 0u);
  EXPECT_EQ(t.sourceCell(1), 1u);
  EXPECT_EQ(t.cellValues(std::vector<double>{3.0, 4.0}), (std::vector<double>{3.0, 4.0}));
  EXPECT_EQ(t.mesh.nodeCount(), m.nodeCount());
  // An inverted tet is reoriented in a copy of its own; the source keeps its order.
  Mesh inverted;
  inverted.nodes = m.nodes;
  const std::array<NodeIndex, 4> flipped = {0, 2, 1, 3};
  inverted.addCell(CellType::Tet4, flipped);
  const TetMesh u = tetrahedralize(inverted);
  EXPECT_FALSE(u.mesh.sharesCellsWith(inverted));
  EXPECT_GT(signedCellVolume(u.mesh, 0), 0.0);
  EXPECT_LT(signedCellVolume(inverted, 0), 0.0);
}

// Cells are shared between copies until one of them changes (copy on write); meshes of one
// cell size keep no offsets, and a cell of another size brings them back, exact.
TEST(MeshStorage, CopiesShareCellsUntilChangedAndOneSizeKeepsNoOffsets) {
  using namespace volpost;
  Mesh m = twoTets();
  EXPECT_EQ(m.cellBytes(), 2u * (1 + 16)) << "types and connectivity only";
  Mesh copy = m;
  EXPECT_TRUE(copy.sharesCellsWith(m));
  copy.remapNodes({4, 3, 2, 1, 0});
  EXPECT_FALSE(copy.sharesCellsWith(m));
  EXPECT_EQ(m.cellNodes(0)[0], 0u) << "the original is unchanged";
  EXPECT_EQ(copy.cellNodes(0)[0], 4u);
  // A pyramid after the tets: offsets from then on, every cell still right.
  Mesh mixed = m;
  mixed.nodes.push_back({0.5, 0.5, -1});
  const std::array<NodeIndex, 5> pyramid = {0, 1, 4, 2, 5};
  mixed.addCell(CellType::Pyramid5, pyramid);
  EXPECT_EQ(m.cellCount(), 2u);
  ASSERT_EQ(mixed.cellCount(), 3u);
  EXPECT_EQ(mixed.cellNodes(1).size(), 4u);
  EXPECT_EQ(mixed.cellNodes(1)[3], m.cellNodes(1)[3]);
  ASSERT_EQ(mixed.cellNodes(2).size(), 5u);
  EXPECT_EQ(mixed.cellNodes(2)[4], 5u);
  EXPECT_EQ(mixed.cellBytes(), 3u + 13u * 4u + 4u * 8u);
  // A moved-from mesh is a valid empty one.
  Mesh taken = std::move(mixed);
  EXPECT_EQ(taken.cellCount(), 3u);
  EXPECT_EQ(mixed.cellCount(), 0u);  // NOLINT(bugprone-use-after-move): defined to be empty
  mixed.addCell(CellType::Tet4, std::array<NodeIndex, 4>{0, 1, 2, 3});
  EXPECT_EQ(mixed.cellNodes(0)[3], 3u);
  // Empty meshes (new or moved from) share one empty set of cells, never changed in place:
  // a cell added to one is in that one only, and none counts as sharing with another.
  Mesh a, b;
  Mesh moved = std::move(taken);
  EXPECT_FALSE(a.sharesCellsWith(b));
  a.addCell(CellType::Tet4, std::array<NodeIndex, 4>{0, 1, 2, 3});
  EXPECT_EQ(a.cellCount(), 1u);
  EXPECT_EQ(b.cellCount(), 0u);
  EXPECT_EQ(taken.cellCount(), 0u);  // NOLINT(bugprone-use-after-move): defined to be empty
  EXPECT_EQ(Mesh().cellCount(), 0u);
  static_assert(std::is_nothrow_move_constructible_v<Mesh> && std::is_nothrow_move_assignable_v<Mesh>);
}

// SPDX-License-Identifier: MIT
#include "support/ReferenceCells.hpp"

#include <volpost/core/MeshChecks.hpp>

#include "host/BoundarySurface.hpp"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

using namespace volpost;

namespace {

const Diagnostic* find(const Model& m, const std::string& code) {
  for (const auto& d : m.diagnostics)
    if (d.code == code) return &d;
  return nullptr;
}

Model twoTets() {  // two tets sharing face (1,2,3)
  Model m;
  m.mesh().nodes = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};
  const NodeIndex a[4] = {0, 1, 2, 3}, b[4] = {1, 4, 2, 3};
  m.mesh().addCell(CellType::Tet4, a);
  m.mesh().addCell(CellType::Tet4, b);
  return m;
}

}  // namespace

TEST(MeshChecks, ValidMeshHasNoDiagnostics) {
  Model m = twoTets();
  ASSERT_GT(signedCellVolume(m.mesh(), 1), 0.0);
  checkModel(m);
  EXPECT_TRUE(m.diagnostics.empty()) << m.diagnostics.front().message;
}

TEST(MeshChecks, FlagsInvertedCell) {
  Model m;
  m.mesh().nodes = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const NodeIndex swapped[4] = {0, 2, 1, 3};
  m.mesh().addCell(CellType::Tet4, swapped);
  checkModel(m);
  const Diagnostic* d = find(m, "inverted-cells");
  ASSERT_TRUE(d);
  EXPECT_EQ(d->items, std::vector<std::size_t>{0});
}

TEST(MeshChecks, FlagsSliverAsDegenerateNotInverted) {
  Model m;
  m.mesh().nodes = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.5, 0.5, -1e-9}};
  const NodeIndex c[4] = {0, 1, 2, 3};
  m.mesh().addCell(CellType::Tet4, c);
  checkModel(m);
  EXPECT_TRUE(find(m, "degenerate-cells"));
  EXPECT_FALSE(find(m, "inverted-cells"));
}

TEST(MeshChecks, MergesCoincidentNodesSoCellsShareFaces) {
  Model m = twoTets();
  // Give the second tet its own copies of the shared nodes.
  m.mesh().nodes.push_back(m.mesh().nodes[1]);
  m.mesh().nodes.push_back(m.mesh().nodes[2]);
  m.mesh().nodes.push_back(m.mesh().nodes[3]);
  Model split;
  split.mesh().nodes = m.mesh().nodes;
  const NodeIndex a[4] = {0, 1, 2, 3}, b[4] = {5, 4, 6, 7};
  split.mesh().addCell(CellType::Tet4, a);
  split.mesh().addCell(CellType::Tet4, b);
  EXPECT_EQ(extractBoundary(split.mesh()).boundaryFaceCount, 8u);
  checkModel(split);
  ASSERT_TRUE(find(split, "duplicate-nodes"));
  EXPECT_EQ(find(split, "duplicate-nodes")->items.size(), 3u);
  EXPECT_EQ(extractBoundary(split.mesh()).boundaryFaceCount, 6u);
}

TEST(MeshChecks, FlagsRepeatedNodeAndDuplicateCell) {
  Model m = twoTets();
  const NodeIndex repeated[4] = {0, 1, 1, 3}, again[4] = {3, 2, 1, 0};
  m.mesh().addCell(CellType::Tet4, repeated);
  m.mesh().addCell(CellType::Tet4, again);
  checkModel(m);
  ASSERT_TRUE(find(m, "repeated-node-cells"));
  EXPECT_EQ(find(m, "repeated-node-cells")->items, std::vector<std::size_t>{2});
  ASSERT_TRUE(find(m, "duplicate-cells"));
  EXPECT_EQ(find(m, "duplicate-cells")->items, std::vector<std::size_t>{3});
}

TEST(MeshChecks, FlagsWarpedAndTwistedHexFaces) {
  auto [mesh, volume] = test::referenceCell(CellType::Hex8);
  Model warped;
  warped.mesh() = mesh;
  warped.mesh().nodes[6].z += 0.3;
  checkModel(warped);
  EXPECT_TRUE(find(warped, "warped-faces"));
  Model twisted;
  twisted.mesh().nodes = mesh.nodes;
  std::swap(twisted.mesh().nodes[6], twisted.mesh().nodes[7]);  // bow-tie top face
  twisted.mesh().addCell(CellType::Hex8, mesh.cellNodes(0));
  checkModel(twisted);
  EXPECT_TRUE(find(twisted, "twisted-faces"));
}

// Three nodes at one position all go to the first of them (whatever order the sort met
// them in), and -0 and +0 are one position.
TEST(MeshChecks, CoincidentNodesGoToTheFirstOfTheirPositionAndSignedZerosAreOne) {
  Model m;
  m.mesh().nodes = {{1, 1, 1}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}, {-0.0, 0, 0}, {1, 1, 1}};
  const std::array<NodeIndex, 4> a = {6, 2, 3, 4}, b = {5, 2, 3, 7};
  m.mesh().addCell(CellType::Tet4, a);
  m.mesh().addCell(CellType::Tet4, b);
  checkModel(m);
  EXPECT_EQ(m.mesh().cellNodes(0)[0], 1u) << "-0 is the same point as +0 (node 1)";
  EXPECT_EQ(m.mesh().cellNodes(1)[0], 0u);
  EXPECT_EQ(m.mesh().cellNodes(1)[3], 0u);
  bool reported = false;
  for (const auto& d : m.diagnostics)
    if (d.code == "duplicate-nodes") {
      reported = true;
      EXPECT_EQ(d.items, (std::vector<std::size_t>{5, 6, 7}));
    }
  EXPECT_TRUE(reported);
}

// SPDX-License-Identifier: MIT
#include "support/ReferenceCells.hpp"

#include <volpost/core/Mesh.hpp>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

using namespace volpost;

class EveryCellType : public ::testing::TestWithParam<CellType> {};

TEST_P(EveryCellType, ReferenceCellHasItsExactVolume) {
  const auto [mesh, volume] = test::referenceCell(GetParam());
  EXPECT_NEAR(signedCellVolume(mesh, 0), volume, 1e-14);
}

TEST_P(EveryCellType, FacesPointOutward) {
  const auto [mesh, volume] = test::referenceCell(GetParam());
  const auto& topo = topology(GetParam());
  const auto nodes = mesh.cellNodes(0);
  glm::dvec3 center(0.0);
  for (int i = 0; i < topo.cornerCount; ++i) center += mesh.nodes[nodes[i]];
  center /= double(topo.cornerCount);
  for (const CellFace& f : topo.faces) {
    const glm::dvec3 a = mesh.nodes[nodes[f.corners[0]]], b = mesh.nodes[nodes[f.corners[1]]],
                     c = mesh.nodes[nodes[f.corners[2]]];
    const glm::dvec3 normal = glm::cross(b - a, c - a);
    EXPECT_GT(glm::dot(normal, a - center), 0.0) << cellTypeName(GetParam());
  }
}

TEST_P(EveryCellType, MirroredCellHasNegativeVolume) {
  auto [mesh, volume] = test::referenceCell(GetParam());
  for (auto& p : mesh.nodes) p.z = -p.z;
  EXPECT_NEAR(signedCellVolume(mesh, 0), -volume, 1e-14);
}

TEST_P(EveryCellType, VtkNumberRoundTrips) {
  EXPECT_EQ(cellTypeFromVtk(vtkCellType(GetParam())), GetParam());
  EXPECT_EQ(cellTypeFromName(cellTypeName(GetParam())), GetParam());
}

INSTANTIATE_TEST_SUITE_P(Cells, EveryCellType, ::testing::ValuesIn(kAllCellTypes),
                         [](const auto& p) { return std::string(cellTypeName(p.param)); });

TEST(Mesh, BoundsIgnoreUnusedAndNonFiniteNodes) {
  auto [mesh, volume] = test::referenceCell(CellType::Tet4);
  mesh.nodes.push_back({100.0, 100.0, 100.0});  // used by no cell
  EXPECT_DOUBLE_EQ(mesh.bounds().max.x, 1.0);
  EXPECT_DOUBLE_EQ(mesh.allNodeBounds().max.x, 100.0);
  mesh.nodes[1].y = std::nan("");
  EXPECT_TRUE(std::isfinite(mesh.bounds().max.y));
}

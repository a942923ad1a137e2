// SPDX-License-Identifier: MIT
// Section cuts: the cross-section of a tetrahedralized box has the box's cross-section
// area exactly (no gaps, no overlaps, also when the plane passes through nodes), faces
// the plane's normal, and carries a linear field exactly.
#include "host/SectionCut.hpp"
#include "support/TetGrid.hpp"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>

using namespace volpost;

namespace {

double areaFacing(const SectionTriangles& s, const glm::dvec3& normal, double& wrongWay) {
  double area = 0.0;
  wrongWay = 0.0;
  for (std::size_t t = 0; t + 2 < s.positions.size(); t += 3) {
    const glm::dvec3 n = 0.5 * glm::cross(s.positions[t + 1] - s.positions[t], s.positions[t + 2] - s.positions[t]);
    area += glm::length(n);
    if (glm::dot(n, normal) < 0.0) wrongWay += glm::length(n);
  }
  return area;
}

}  // namespace

TEST(SectionCut, TheBoxCrossSectionExactlyWithALinearFieldAndNodesOnThePlane) {
  // 4 x 3 x 2 cubes of size 0.5: the box [0, 2] x [0, 1.5] x [0, 1].
  const TetMesh tets = tetrahedralize(test::tetGrid(4, 3, 2, glm::dvec3(0.0), 0.5));
  std::vector<double> f(tets.mesh.nodeCount());
  for (std::size_t n = 0; n < f.size(); ++n) f[n] = tets.mesh.nodes[n].x + 2.0 * tets.mesh.nodes[n].y - tets.mesh.nodes[n].z;
  struct Case {
    ClipPlane plane;
    double area;
  };
  for (const Case& c : {Case{{{0.3, 0, 0}, {1, 0, 0}}, 1.5 * 1.0},    // between node layers
                        Case{{{1.0, 0, 0}, {-1, 0, 0}}, 1.5 * 1.0},   // through a node layer
                        Case{{{0, 0.75, 0}, {0, 1, 0}}, 2.0 * 1.0},   // through nodes, other axis
                        Case{{{0, 0, 0.2}, {0, 0, 1}}, 2.0 * 1.5}}) {
    const SectionTriangles s = cutTetrahedra(tets, f, true, c.plane);
    double wrongWay = 0.0;
    EXPECT_NEAR(areaFacing(s, c.plane.normal, wrongWay), c.area, 1e-12);
    EXPECT_EQ(wrongWay, 0.0);
    ASSERT_EQ(s.values.size(), s.positions.size());
    for (std::size_t k = 0; k < s.positions.size(); ++k) {
      const glm::dvec3& p = s.positions[k];
      EXPECT_NEAR(s.values[k], p.x + 2.0 * p.y - p.z, 1e-12);
      EXPECT_NEAR(glm::dot(p - c.plane.point, glm::normalize(c.plane.normal)), 0.0, 1e-12);
    }
  }
  // A plane beside the model cuts nothing; element values stay constant per triangle.
  EXPECT_TRUE(cutTetrahedra(tets, f, true, ClipPlane{{5, 0, 0}, {1, 0, 0}}).positions.empty());
  std::vector<double> perTet(tets.mesh.cellCount());
  for (std::size_t c = 0; c < perTet.size(); ++c) perTet[c] = double(c);
  const SectionTriangles cells = cutTetrahedra(tets, perTet, false, ClipPlane{{0.3, 0, 0}, {1, 0, 0}});
  for (std::size_t t = 0; t + 2 < cells.values.size(); t += 3) {
    EXPECT_EQ(cells.values[t], cells.values[t + 1]);
    EXPECT_EQ(cells.values[t], cells.values[t + 2]);
  }
  // No values: geometry only (NaN values), and a zero normal cuts nothing.
  const SectionTriangles bare = cutTetrahedra(tets, {}, true, ClipPlane{{0.3, 0, 0}, {1, 0, 0}});
  EXPECT_FALSE(bare.positions.empty());
  EXPECT_TRUE(std::isnan(bare.values.front()));
  EXPECT_TRUE(cutTetrahedra(tets, f, true, ClipPlane{{0.3, 0, 0}, {0, 0, 0}}).positions.empty());
}

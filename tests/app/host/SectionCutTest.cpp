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

// A grid cut without its cells: on a left-handed rotated grid, an oblique plane's section has
// the area of the cells' section (the tetrahedralized hexahedra cut the same way), faces
// the kept side, and reproduces a linear field; a plane through grid points shows the
// samples exactly, whatever the field; cell values stay constant per cell.
TEST(SectionCut, AGridIsCutWithoutItsCellsAsItsCellsAreCut) {
  RegularGrid g;
  g.dims = {5, 4, 3};
  g.origin = {10.0, -3.0, 2.0};
  const double c = std::cos(0.4), s = std::sin(0.4);
  g.axes = {glm::dvec3(0.5 * c, 0.5 * s, 0.0), glm::dvec3(-0.4 * s, 0.4 * c, 0.0), glm::dvec3(0.0, 0.0, -0.3)};
  const Mesh hexes = hexahedraOfGrid(g);
  std::vector<double> linear(g.pointCount()), wiggly(g.pointCount());
  for (std::size_t n = 0; n < linear.size(); ++n) {
    const glm::dvec3& p = hexes.nodes[n];
    linear[n] = 3.0 * p.x - p.y + 2.0 * p.z;
    wiggly[n] = std::sin(double(n) * 1.7);
  }
  const ClipPlane oblique{g.position(2.2, 1.4, 0.9), glm::dvec3(0.3, -0.5, 0.8)};
  const SectionTriangles fromGrid = cutGrid(g, linear, true, oblique);
  const TetMesh tets = tetrahedralize(hexes);
  const SectionTriangles fromCells = cutTetrahedra(tets, tets.nodeValues(hexes, linear), true, oblique);
  double wrongWay = 0.0, ignored = 0.0;
  const double area = areaFacing(fromGrid, oblique.normal, wrongWay);
  EXPECT_GT(area, 0.1);
  EXPECT_NEAR(area, areaFacing(fromCells, oblique.normal, ignored), 1e-12 * area + 1e-13);
  EXPECT_EQ(wrongWay, 0.0);
  ASSERT_EQ(fromGrid.values.size(), fromGrid.positions.size());
  for (std::size_t k = 0; k < fromGrid.positions.size(); ++k) {
    const glm::dvec3& p = fromGrid.positions[k];
    EXPECT_NEAR(fromGrid.values[k], 3.0 * p.x - p.y + 2.0 * p.z, 1e-9);
    EXPECT_NEAR(glm::dot(p - oblique.point, glm::normalize(oblique.normal)), 0.0, 1e-9);
  }
  // The plane of inline index 2 (through grid points): every corner of the section is a
  // grid point, holding its own sample.
  const ClipPlane inline2{g.position(2.0, 0.0, 0.0), glm::cross(g.axes[1], g.axes[2])};
  const SectionTriangles layer = cutGrid(g, wiggly, true, inline2);
  EXPECT_NEAR(areaFacing(layer, inline2.normal, wrongWay), 3.0 * 0.4 * 2.0 * 0.3, 1e-9);
  ASSERT_FALSE(layer.positions.empty());
  for (std::size_t k = 0; k < layer.positions.size(); ++k) {
    const glm::dvec3 index = g.indexOf(layer.positions[k]);
    const glm::dvec3 nearest = glm::round(index);
    ASSERT_LT(glm::length(index - nearest), 1e-9) << "corner " << k << " is not a grid point";
    EXPECT_EQ(layer.values[k], wiggly[g.pointIndex(std::size_t(nearest.x), std::size_t(nearest.y), std::size_t(nearest.z))]);
  }
  std::vector<double> perCell(g.cellCount());
  for (std::size_t n = 0; n < perCell.size(); ++n) perCell[n] = double(n);
  const SectionTriangles cells = cutGrid(g, perCell, false, oblique);
  for (std::size_t t = 0; t + 2 < cells.values.size(); t += 3) {
    EXPECT_EQ(cells.values[t], cells.values[t + 1]);
    EXPECT_EQ(cells.values[t], cells.values[t + 2]);
    const glm::dvec3 centre = g.indexOf((cells.positions[t] + cells.positions[t + 1] + cells.positions[t + 2]) / 3.0);
    EXPECT_EQ(cells.values[t], double(std::size_t(centre.x) + 4 * (std::size_t(centre.y) + 3 * std::size_t(centre.z))));
  }
  EXPECT_TRUE(cutGrid(g, linear, true, ClipPlane{{1e3, 0, 0}, {1, 0, 0}}).positions.empty());
}

// SPDX-License-Identifier: MIT
// Shape functions of every cell type: a partition of unity, one at their own node and zero
// at the others, reproducing the polynomials their element reproduces; and the inverse map
// from a point back to natural coordinates on distorted elements.
#include <volpost/core/CellShape.hpp>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <random>
#include <vector>

using namespace volpost;

namespace {

// A point inside the reference cell of the type, uniformly over its bounding box then kept.
glm::dvec3 randomInside(CellType type, std::mt19937& random) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (;;) {
    glm::dvec3 xi(u(random), u(random), u(random));
    if (type != CellType::Hex8 && type != CellType::Hex20) xi = glm::dvec3(0.5) + 0.5 * xi;
    if (type == CellType::Wedge6 || type == CellType::Wedge15) xi.z = 2.0 * xi.z - 1.0;
    if (type == CellType::Pyramid5) xi.z *= 0.95;  // the apex is singular
    if (outsideReference(type, xi) == 0.0) return xi;
  }
}

// The cell's nodes placed by a smooth, non-affine map of its natural coordinates: curved
// faces, midside nodes on them.
std::vector<glm::dvec3> curvedCell(CellType type) {
  std::vector<glm::dvec3> x;
  for (int i = 0; i < topology(type).nodeCount; ++i) {
    const glm::dvec3 xi = naturalCoordinatesOfNode(type, i);
    x.push_back(glm::dvec3(100.0 + 2.0 * xi.x + 0.3 * xi.y * xi.y, -50.0 + 1.5 * xi.y + 0.2 * xi.x * xi.z,
                           7.0 + 1.0 * xi.z + 0.1 * xi.x * xi.x));
  }
  return x;
}

glm::dvec3 mapped(CellType type, const std::vector<glm::dvec3>& nodes, const glm::dvec3& xi) {
  const ShapeValues n = shapeFunctions(type, xi);
  glm::dvec3 x(0.0);
  for (std::size_t i = 0; i < nodes.size(); ++i) x += n[i] * nodes[i];
  return x;
}

}  // namespace

class EachCellType : public ::testing::TestWithParam<CellType> {};

TEST_P(EachCellType, ShapeFunctionsArePartitionOfUnityAndNodal) {
  const CellType type = GetParam();
  const int count = topology(type).nodeCount;
  for (int j = 0; j < count; ++j) {
    const ShapeValues n = shapeFunctions(type, naturalCoordinatesOfNode(type, j));
    for (int i = 0; i < count; ++i) EXPECT_NEAR(n[std::size_t(i)], i == j ? 1.0 : 0.0, 1e-14) << i << " at node " << j;
  }
  std::mt19937 random(3);
  for (int k = 0; k < 200; ++k) {
    const ShapeValues n = shapeFunctions(type, randomInside(type, random));
    double sum = 0.0;
    for (int i = 0; i < count; ++i) sum += n[std::size_t(i)];
    EXPECT_NEAR(sum, 1.0, 1e-14);
  }
}

TEST_P(EachCellType, ReproducesLinearFieldsOnDistortedCellsAndQuadraticOnesOnStraightQuadraticCells) {
  const CellType type = GetParam();
  const std::vector<glm::dvec3> nodes = curvedCell(type);
  const auto linear = [](const glm::dvec3& p) { return 3.0 * p.x - 2.0 * p.y + 0.5 * p.z + 1.0; };
  // Straight edges (an affine map): quadratic elements reproduce every quadratic.
  std::vector<glm::dvec3> straight;
  for (int i = 0; i < topology(type).nodeCount; ++i) {
    const glm::dvec3 xi = naturalCoordinatesOfNode(type, i);
    straight.push_back(glm::dvec3(2.0 * xi.x + 0.5 * xi.y, 1.5 * xi.y - 0.25 * xi.z, xi.z + 0.1 * xi.x));
  }
  const auto quadratic = [](const glm::dvec3& p) { return p.x * p.x - 2.0 * p.x * p.y + 0.5 * p.z * p.z + p.y * p.z + p.x; };
  std::mt19937 random(5);
  for (int k = 0; k < 100; ++k) {
    const glm::dvec3 xi = randomInside(type, random);
    const ShapeValues n = shapeFunctions(type, xi);
    double l = 0.0, q = 0.0;
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      l += n[i] * linear(nodes[i]);
      q += n[i] * quadratic(straight[i]);
    }
    EXPECT_NEAR(l, linear(mapped(type, nodes, xi)), 1e-10);
    if (topology(type).quadratic) EXPECT_NEAR(q, quadratic(mapped(type, straight, xi)), 1e-12);
  }
}

TEST_P(EachCellType, InverseMapFindsTheNaturalCoordinatesOnACurvedCellFarFromTheOrigin) {
  const CellType type = GetParam();
  const std::vector<glm::dvec3> nodes = curvedCell(type);
  std::mt19937 random(11);
  for (int k = 0; k < 200; ++k) {
    const glm::dvec3 xi = randomInside(type, random);
    const auto back = naturalCoordinates(type, nodes, mapped(type, nodes, xi), referenceCentre(type));
    ASSERT_TRUE(back) << k;
    EXPECT_LT(glm::length(*back - xi), 1e-10) << k;
  }
  // A point well outside comes back outside the reference cell (or not at all).
  const auto far = naturalCoordinates(type, nodes, mapped(type, nodes, referenceCentre(type)) + glm::dvec3(0.0, 0.0, 5.0),
                                      referenceCentre(type));
  EXPECT_TRUE(!far || outsideReference(type, *far) > 0.5);
  // A degenerate cell (all nodes at one point) does not converge.
  const std::vector<glm::dvec3> collapsed(nodes.size(), glm::dvec3(1.0));
  EXPECT_FALSE(naturalCoordinates(type, collapsed, glm::dvec3(1.0), referenceCentre(type)));
}

TEST_P(EachCellType, GradientOfAFieldItReproducesIsExactOnACurvedCell) {
  // Isoparametric cells reproduce every linear field, curved or not: the field 2x - 3y + z
  // sampled at the nodes has that gradient everywhere inside.
  const CellType type = GetParam();
  const std::vector<glm::dvec3> nodes = curvedCell(type);
  std::vector<double> values;
  for (const glm::dvec3& x : nodes) values.push_back(2.0 * x.x - 3.0 * x.y + x.z);
  std::mt19937 random(5);
  for (int k = 0; k < 50; ++k) {
    const glm::dvec3 g = fieldGradient(type, nodes, values, randomInside(type, random));
    EXPECT_LT(glm::length(g - glm::dvec3(2.0, -3.0, 1.0)), 1e-9) << k;
  }
}

TEST_P(EachCellType, AnInvertedOrCollapsedCellsMapIsNotInvertible) {
  const CellType type = GetParam();
  std::vector<glm::dvec3> nodes = curvedCell(type);
  EXPECT_TRUE(mapInvertible(type, nodes));
  // Pull the first corner through the cell to beyond its opposite side: the Jacobian changes sign.
  const glm::dvec3 centre = mapped(type, nodes, referenceCentre(type));
  nodes[0] = centre + 3.0 * (centre - nodes[0]);
  EXPECT_EQ(mapInvertible(type, nodes), type == CellType::Tet4);  // a mirrored tet4 is still a tet4
  const std::vector<glm::dvec3> collapsed(nodes.size(), glm::dvec3(1.0));
  EXPECT_FALSE(mapInvertible(type, collapsed));
}

INSTANTIATE_TEST_SUITE_P(Cells, EachCellType, ::testing::ValuesIn(kAllCellTypes),
                         [](const auto& p) { return std::string(cellTypeName(p.param)); });

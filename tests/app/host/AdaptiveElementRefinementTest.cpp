// SPDX-License-Identifier: MIT
// The volume's pieces of the cells' own field, bisected where the transfer function shows
// the field: they tile the cells with no hanging points (every face inside is shared by
// exactly two pieces), carry the cells' own field, and are cut where the transfer function
// changes, not where it is flat or transparent.
#include "host/AdaptiveElementRefinement.hpp"
#include "support/HexLattice.hpp"
#include "support/ReferenceCells.hpp"
#include "support/RefinedPieces.hpp"

#include <volpost/core/CellShape.hpp>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

using namespace volpost;

namespace {

std::vector<double> sampled(const Mesh& mesh, double (*f)(const glm::dvec3&)) {
  std::vector<double> values;
  for (const glm::dvec3& p : mesh.nodes) values.push_back(f(p));
  return values;
}

double xyz(const glm::dvec3& p) { return p.x * p.y * p.z; }

// Transparent up to `at` - width, a narrow opaque peak of color ramping across it, then
// transparent again.
TransferFunction peakAt(double at, double width) {
  return TransferFunction(
      {{at - width, glm::dvec3(0.0), 0.0}, {at, glm::dvec3(1.0, 0.5, 0.0), 30.0}, {at + width, glm::dvec3(1.0), 0.0}});
}

// Every face of the pieces, by its three points: a conforming tiling has each face inside
// twice and each face on the outside once (a hanging point would leave faces seen once
// inside the box).
std::map<std::array<NodeIndex, 3>, int> faceUses(const Mesh& pieces) {
  std::map<std::array<NodeIndex, 3>, int> uses;
  for (std::size_t t = 0; t < pieces.cellCount(); ++t) {
    const auto v = pieces.cellNodes(t);
    for (int skip = 0; skip < 4; ++skip) {
      std::array<NodeIndex, 3> f;
      for (int k = 0, j = 0; k < 4; ++k)
        if (k != skip) f[std::size_t(j++)] = v[std::size_t(k)];
      std::sort(f.begin(), f.end());
      ++uses[f];
    }
  }
  return uses;
}

bool onTheBox(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, double size) {
  for (int axis = 0; axis < 3; ++axis)
    for (double side : {0.0, size})
      if (std::abs(a[axis] - side) < 1e-12 && std::abs(b[axis] - side) < 1e-12 && std::abs(c[axis] - side) < 1e-12)
        return true;
  return false;
}

}  // namespace

TEST(AdaptiveElementRefinement, PiecesTileTheCellsWithNoHangingPointsAndCarryTheCellsField) {
  // 3^3 hex8 cubes of [0, 3]^3 carrying xyz (trilinear: the split's pieces miss it), seen
  // through a narrow peak at 4: the pieces across the level set xyz = 4 are cut, many times.
  const Mesh mesh = test::hexLattice(CellType::Hex8, 3, [](const glm::dvec3& g) { return g; });
  const TetMesh split = tetrahedralize(mesh);
  const optics::ElementField field(mesh, sampled(mesh, xyz), split, glm::dvec3(1.5));
  const TransferFunction tf = peakAt(4.0, 0.5);
  VolumeRefinementGoal goal;
  goal.transferFunction = &tf;
  goal.maxTetrahedra = 40000;
  const RefinedTetrahedra r = refineVolumeAdaptively(field, test::everyTet(split), goal);
  const Mesh& pieces = r.tets.mesh;
  ASSERT_GT(pieces.cellCount(), 4 * split.mesh.cellCount());
  EXPECT_LE(pieces.cellCount(), goal.maxTetrahedra + goal.maxTetrahedra / 2) << "near the budget, not far past it";
  EXPECT_GT(r.bisections, 6);

  double volume = 0.0;
  for (std::size_t t = 0; t < pieces.cellCount(); ++t) {
    const double v = signedCellVolume(pieces, t);
    ASSERT_GT(v, 0.0) << "piece " << t;
    volume += v;
  }
  EXPECT_NEAR(volume, 27.0, 1e-9) << "no gaps, no overlaps";
  std::size_t outside = 0;
  for (const auto& [f, uses] : faceUses(pieces)) {
    ASSERT_LE(uses, 2);
    if (uses == 1) {
      ASSERT_TRUE(onTheBox(pieces.nodes[f[0]], pieces.nodes[f[1]], pieces.nodes[f[2]], 3.0))
          << "a face seen once inside the box: a hanging point";
      ++outside;
    }
  }
  EXPECT_GT(outside, 0u);
  for (std::size_t n = 0; n < pieces.nodeCount(); ++n) ASSERT_NEAR(r.values[n], xyz(pieces.nodes[n]), 1e-12);
}

TEST(AdaptiveElementRefinement, CutsWhereTheTransferFunctionChangesNotWhereItIsFlatOrTransparent) {
  // 6^3 cubes of [0, 6]^3 carrying xyz (0..216).
  const Mesh mesh = test::hexLattice(CellType::Hex8, 6, [](const glm::dvec3& g) { return g; });
  const TetMesh split = tetrahedralize(mesh);
  const optics::ElementField field(mesh, sampled(mesh, xyz), split, glm::dvec3(3.0));
  const auto refined = [&](const TransferFunction& tf) {
    VolumeRefinementGoal goal;
    goal.transferFunction = &tf;
    goal.maxTetrahedra = 40000;
    return refineVolumeAdaptively(field, test::everyTet(split), goal);
  };
  // Transparent over the values, or the same color and extinction everywhere: the
  // field's error shows nowhere, and the split's pieces stay as they are.
  EXPECT_EQ(refined(peakAt(300.0, 1.0)).tets.mesh.cellCount(), split.mesh.cellCount());
  const TransferFunction flat({{0.0, glm::dvec3(0.3), 2.0}, {216.0, glm::dvec3(0.3), 2.0}});
  const RefinedTetrahedra none = refined(flat);
  EXPECT_EQ(none.tets.mesh.cellCount(), split.mesh.cellCount());
  EXPECT_TRUE(none.toleranceReached);
  EXPECT_EQ(none.deviation, 0.0);

  // A peak at 2: the smallest pieces lie where xyz is near 2, the pieces far from it stay large.
  const RefinedTetrahedra peak = refined(peakAt(2.0, 0.25));
  double splitSmallest = INFINITY;
  for (std::size_t t = 0; t < split.mesh.cellCount(); ++t)
    splitSmallest = std::min(splitSmallest, signedCellVolume(split.mesh, t));
  double nearPeak = INFINITY, farAway = INFINITY, largestFarAway = 0.0;
  for (std::size_t t = 0; t < peak.tets.mesh.cellCount(); ++t) {
    const auto v = peak.tets.mesh.cellNodes(t);
    double lo = INFINITY, hi = -INFINITY;
    for (NodeIndex n : v) lo = std::min(lo, peak.values[n]), hi = std::max(hi, peak.values[n]);
    const double size = signedCellVolume(peak.tets.mesh, t);
    if (lo <= 2.0 && hi >= 2.0) nearPeak = std::min(nearPeak, size);
    if (lo > 50.0) farAway = std::min(farAway, size), largestFarAway = std::max(largestFarAway, size);
  }
  EXPECT_LT(nearPeak * 100.0, farAway) << "cut a hundred times finer where the peak is";
  // Far from it only the cuts that keep the pieces conforming reach (a few halvings), and
  // pieces of the split stay whole.
  EXPECT_GE(largestFarAway, splitSmallest * (1.0 - 1e-12)) << "the split's own tetrahedra where nothing shows";
  EXPECT_GE(farAway * 16.0, splitSmallest) << "at most four halvings far away";
}

TEST(AdaptiveElementRefinement, MeetsTheToleranceWhereTheBudgetAllowsAndSaysWhenItDoesNot) {
  const Mesh mesh = test::hexLattice(CellType::Hex8, 2, [](const glm::dvec3& g) { return g; });
  const TetMesh split = tetrahedralize(mesh);
  const optics::ElementField field(mesh, sampled(mesh, xyz), split, glm::dvec3(1.0));
  const TransferFunction ramp = TransferFunction::ramp(0.0, 8.0, "viridis", 1.0);
  VolumeRefinementGoal goal;
  goal.transferFunction = &ramp;
  const RefinedTetrahedra enough = refineVolumeAdaptively(field, test::everyTet(split), goal);
  EXPECT_TRUE(enough.toleranceReached);
  EXPECT_LE(enough.deviation, goal.perChannel);
  EXPECT_GT(enough.tets.mesh.cellCount(), split.mesh.cellCount());

  goal.maxTetrahedra = 100;
  const RefinedTetrahedra short_ = refineVolumeAdaptively(field, test::everyTet(split), goal);
  EXPECT_FALSE(short_.toleranceReached);
  EXPECT_GT(short_.deviation, goal.perChannel);
  EXPECT_LT(short_.tets.mesh.cellCount(), enough.tets.mesh.cellCount());
}

TEST(AdaptiveElementRefinement, EveryCellTypeIsTiledAndCarriesItsOwnField) {
  // One straight cell of each type under a ramp: the pieces fill it exactly, close over its
  // faces, and carry the cell's own field at every point.
  for (CellType type : kAllCellTypes) {
    SCOPED_TRACE(std::string(cellTypeName(type)));
    const auto [mesh, volume] = test::referenceCell(type);
    std::vector<double> values;
    for (const glm::dvec3& p : mesh.nodes) values.push_back(p.x + 2.0 * p.y * p.z - p.x * p.x + 3.0 * p.x * p.y);
    const TetMesh split = tetrahedralize(mesh);
    const optics::ElementField field(mesh, values, split, glm::dvec3(0.0));
    const TransferFunction ramp = TransferFunction::ramp(-2.0, 4.0, "viridis", 4.0);
    VolumeRefinementGoal goal;
    goal.transferFunction = &ramp;
    goal.maxTetrahedra = 5000;
    const RefinedTetrahedra r = refineVolumeAdaptively(field, test::everyTet(split), goal);
    if (type == CellType::Tet4) EXPECT_EQ(r.tets.mesh.cellCount(), 1u) << "a tet4's linear field needs no cuts";
    test::expectTheCellTiledWithItsOwnField(r, field, volume);
  }
}

TEST(AdaptiveElementRefinement, APixelChangesWithTheValueAsTheTransferFunctionsSlopesSay) {
  // Color 0 to 1 and extinction 0 to 2 over the values 0 to 1: the color's slope 1 times the
  // extinction 2, plus the extinction's slope 2: 4.
  const TransferFunction tf({{0.0, glm::dvec3(0.0), 0.0}, {1.0, glm::dvec3(1.0, 0.0, 0.0), 2.0}});
  EXPECT_DOUBLE_EQ(pixelChangePerValue(tf, 0.2, 0.4), 4.0);
  EXPECT_DOUBLE_EQ(pixelChangePerValue(tf, -1.0, 0.5), 4.0);
  EXPECT_EQ(pixelChangePerValue(tf, 2.0, 3.0), 0.0) << "past the last point the function holds";
  EXPECT_EQ(pixelChangePerValue(tf, -3.0, -2.0), 0.0);
  const TransferFunction step({{0.0, glm::dvec3(1.0), 0.0},
                               {0.5, glm::dvec3(1.0), 0.0},
                               {0.5, glm::dvec3(1.0), 1.0},
                               {1.0, glm::dvec3(1.0), 1.0}});
  EXPECT_GT(pixelChangePerValue(step, 0.4, 0.6), 1e5) << "a step is as steep as can be";
  EXPECT_EQ(pixelChangePerValue(step, 0.6, 0.9), 0.0);
}

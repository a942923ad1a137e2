// SPDX-License-Identifier: MIT
// Face adjacency against what it must be: on a shuffled tet grid, each tet's neighbour across
// a face shares exactly that face and names it back, and only the grid's outer faces are
// left without one; the same when the mesh is large enough to be matched in several passes
// over the vertex ids; a face shared by three tets (non-manifold) is left as boundary.
#include <volpost/core/TetAdjacency.hpp>

#include "support/TetGrid.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

using namespace volpost;

namespace {

constexpr int kFaces[4][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};

std::vector<glm::uvec4> tetsOf(const Mesh& mesh) {
  std::vector<glm::uvec4> tets(mesh.cellCount());
  for (std::size_t c = 0; c < tets.size(); ++c) {
    const auto n = mesh.cellNodes(c);
    tets[c] = glm::uvec4(n[0], n[1], n[2], n[3]);
  }
  return tets;
}

std::array<std::uint32_t, 3> face(const glm::uvec4& t, int f) {
  std::array<std::uint32_t, 3> v = {t[kFaces[f][0]], t[kFaces[f][1]], t[kFaces[f][2]]};
  std::sort(v.begin(), v.end());
  return v;
}

// Checks every relation; returns the number of faces left without a neighbour.
std::size_t checkNeighbours(const std::vector<glm::uvec4>& tets, const std::vector<glm::ivec4>& across) {
  std::size_t open = 0;
  for (std::size_t t = 0; t < tets.size(); ++t)
    for (int f = 0; f < 4; ++f) {
      const int other = across[t][f];
      if (other < 0) {
        ++open;
        continue;
      }
      int back = -1;
      for (int g = 0; g < 4; ++g)
        if (across[std::size_t(other)][g] == int(t) && face(tets[std::size_t(other)], g) == face(tets[t], f)) back = g;
      EXPECT_GE(back, 0) << "tet " << t << " face " << f << " -> tet " << other << " does not share that face back";
      if (back < 0) return open;
    }
  return open;
}

// The grid's tets in a random order, their nodes renumbered at random (no locality to lean on).
std::vector<glm::uvec4> shuffledGrid(int n, unsigned seed) {
  const Mesh grid = test::tetGrid(n, n, n);
  std::vector<glm::uvec4> tets = tetsOf(grid);
  std::mt19937 random(seed);
  std::vector<std::uint32_t> renumber(grid.nodeCount());
  for (std::size_t i = 0; i < renumber.size(); ++i) renumber[i] = std::uint32_t(i);
  std::shuffle(renumber.begin(), renumber.end(), random);
  for (auto& t : tets)
    for (int k = 0; k < 4; ++k) t[k] = renumber[t[k]];
  std::shuffle(tets.begin(), tets.end(), random);
  return tets;
}

}  // namespace

TEST(TetAdjacency, EveryInnerFaceOfAShuffledGridHasTheTetAcrossIt) {
  const int n = 12;
  const auto tets = shuffledGrid(n, 7);
  EXPECT_EQ(checkNeighbours(tets, faceNeighbors(tets)), std::size_t(12 * n * n)) << "two triangles per outer square";
}

TEST(TetAdjacency, AMeshMatchedInSeveralPassesGivesTheSameRelations) {
  const int n = 72;  // 2.2M tets: matched in two passes over the vertex ids
  const auto tets = shuffledGrid(n, 11);
  ASSERT_GE(tets.size() >> 20, 2u);
  EXPECT_EQ(checkNeighbours(tets, faceNeighbors(tets)), std::size_t(12 * n * n));
}

TEST(TetAdjacency, AFaceSharedByThreeTetsIsLeftAsBoundary) {
  // Three tets on the face (0, 1, 2), apexes 3, 4 and 5; a fourth across (0, 1, 3) from the
  // first shows that the ordinary faces around still match.
  const std::vector<glm::uvec4> tets = {{0, 1, 2, 3}, {0, 2, 1, 4}, {0, 1, 2, 5}, {0, 3, 1, 6}};
  const auto across = faceNeighbors(tets);
  EXPECT_EQ(across[0][3], -1) << "face (0, 1, 2) of three tets has no single neighbour";
  EXPECT_EQ(across[1][3], -1);
  EXPECT_EQ(across[2][3], -1);
  EXPECT_EQ(across[0][2], 3) << "face (0, 1, 3) is shared by tets 0 and 3";
  EXPECT_EQ(across[3][3], 0);
  EXPECT_EQ(checkNeighbours(tets, across), std::size_t(16 - 2));
}

// SPDX-License-Identifier: MIT
// How a grid larger than the GPU memory budget is cut into bricks: bricks that share their
// border points and cover every cell once, their size under a budget, and the order they
// are drawn in, checked against rays walked through them from eyes outside, on the faces
// of and inside the grid.
#include "GridBricks.hpp"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>

using namespace volpost;
using namespace volpost::volume;

TEST(GridBricks, ShareTheirBorderPointsAndCoverEveryCellOnce) {
  const std::array<std::size_t, 3> dims{31, 30, 5};
  const std::vector<GridBrick> bricks = splitIntoBricks(dims, 16);
  ASSERT_EQ(bricks.size(), 2u * 2u * 1u);
  EXPECT_EQ(bricks[0].first, (std::array<std::size_t, 3>{0, 0, 0}));
  EXPECT_EQ(bricks[0].points, (std::array<std::size_t, 3>{16, 16, 5}));
  EXPECT_EQ(bricks[1].first, (std::array<std::size_t, 3>{15, 0, 0}));  // point 15 is in both
  EXPECT_EQ(bricks[1].points, (std::array<std::size_t, 3>{16, 16, 5}));
  EXPECT_EQ(bricks[3].first, (std::array<std::size_t, 3>{15, 15, 0}));
  EXPECT_EQ(bricks[3].points, (std::array<std::size_t, 3>{16, 15, 5}));
  // Every cell of the grid in exactly one brick.
  std::vector<int> owners((dims[0] - 1) * (dims[1] - 1) * (dims[2] - 1), 0);
  for (const GridBrick& b : bricks)
    for (std::size_t k = b.first[2]; k + 1 < b.first[2] + b.points[2]; ++k)
      for (std::size_t j = b.first[1]; j + 1 < b.first[1] + b.points[1]; ++j)
        for (std::size_t i = b.first[0]; i + 1 < b.first[0] + b.points[0]; ++i)
          ++owners[(k * (dims[1] - 1) + j) * (dims[0] - 1) + i];
  EXPECT_TRUE(std::all_of(owners.begin(), owners.end(), [](int n) { return n == 1; }));
  // A last brick of only two points; a flat axis of one point.
  const std::vector<GridBrick> thin = splitIntoBricks({17, 1, 4}, 16);
  ASSERT_EQ(thin.size(), 2u);
  EXPECT_EQ(thin[1].first[0], 15u);
  EXPECT_EQ(thin[1].points, (std::array<std::size_t, 3>{2, 1, 4}));
  EXPECT_THROW(splitIntoBricks(dims, 1), std::invalid_argument);
}

TEST(GridBricks, TheirSideFitsAQuarterOfTheBudgetAndTheLargestTexture) {
  const std::array<std::size_t, 3> dims{100, 80, 60};  // 1.92 MB of floats
  EXPECT_EQ(brickSideFor(dims, 0, 2048), 100u) << "no budget: one texture";
  EXPECT_EQ(brickSideFor(dims, 2'000'000, 2048), 100u) << "it fits";
  const std::size_t side = brickSideFor(dims, 1'000'000, 2048);
  EXPECT_LE(side * side * side * 4 * 4, 1'000'000u);
  EXPECT_GT((side + 1) * (side + 1) * (side + 1) * 4 * 4, 1'000'000u);
  EXPECT_EQ(brickSideFor(dims, 0, 64), 64u) << "larger than the device's textures";
  EXPECT_EQ(brickSideFor({3000, 2, 2}, 0, 2048), 2048u);
  try {
    brickSideFor(dims, 100, 2048);
    FAIL() << "a budget of 100 bytes cannot hold bricks";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("100 bytes"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("100 x 80 x 60"), std::string::npos) << e.what();
  }
}

namespace {

// The bricks a ray meets, nearest first, found by walking it in tiny steps (a brick owns
// the points of its box; on a shared face the brick the ray goes on into).
std::vector<std::size_t> bricksAlong(const std::vector<GridBrick>& bricks, glm::dvec3 origin, glm::dvec3 dir) {
  std::vector<std::size_t> met;
  for (double t = 0.013; t < 200.0; t += 0.013) {  // not the eye itself: on a face it is in two
    const glm::dvec3 p = origin + t * dir;
    for (std::size_t b = 0; b < bricks.size(); ++b) {
      bool inside = true;
      for (int a = 0; a < 3; ++a)
        inside = inside && p[a] >= double(bricks[b].first[std::size_t(a)]) &&
                 p[a] <= double(bricks[b].first[std::size_t(a)] + bricks[b].points[std::size_t(a)] - 1);
      if (inside && (met.empty() || met.back() != b)) met.push_back(b);
    }
  }
  return met;
}

// True when every ray meets its bricks in front-to-back order of `order` (back to front).
void expectVisibilityOrder(const std::vector<GridBrick>& bricks, const std::vector<std::size_t>& order,
                           const std::vector<std::pair<glm::dvec3, glm::dvec3>>& rays) {
  std::vector<std::size_t> position(bricks.size());
  for (std::size_t i = 0; i < order.size(); ++i) position[order[i]] = i;
  ASSERT_EQ(std::set<std::size_t>(order.begin(), order.end()).size(), bricks.size());
  for (const auto& [origin, dir] : rays) {
    const std::vector<std::size_t> met = bricksAlong(bricks, origin, dir);
    for (std::size_t i = 1; i < met.size(); ++i)
      ASSERT_LT(position[met[i]], position[met[i - 1]])
          << "brick " << met[i] << " lies behind brick " << met[i - 1] << " on a ray from (" << origin.x << ", "
          << origin.y << ", " << origin.z << ")";
  }
}

}  // namespace

TEST(GridBricks, AreOrderedBackToFrontFromEveryEyeAndDirection) {
  const std::vector<GridBrick> bricks = splitIntoBricks({22, 15, 10}, 8);  // 3 x 2 x 2, uneven
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const glm::dvec3 centre(10.5, 7.0, 4.5);
  const std::vector<glm::dvec3> eyes = {{-30, 3, 4},   {10, 40, -20},  {7, 7, 7} /* on a shared face */,
                                        {3, 2, 1},     {18, 12, 8},    {60, -50, 40}};
  for (const glm::dvec3& eye : eyes) {
    std::vector<std::pair<glm::dvec3, glm::dvec3>> rays;
    for (int r = 0; r < 200; ++r) {
      const glm::dvec3 target = centre + glm::dvec3(12.0 * unit(random), 8.0 * unit(random), 6.0 * unit(random));
      rays.emplace_back(eye, glm::normalize(target - eye));
    }
    SCOPED_TRACE("perspective eye " + std::to_string(eye.x) + ", " + std::to_string(eye.y));
    expectVisibilityOrder(bricks, bricksBackToFront(bricks, eye, {0, 0, 1}, false), rays);
  }
  for (const glm::dvec3 dir : {glm::dvec3(1, 0, 0), glm::dvec3(-0.3, 0.9, 0.2), glm::dvec3(0.5, -0.5, -0.7)}) {
    const glm::dvec3 d = glm::normalize(dir);
    std::vector<std::pair<glm::dvec3, glm::dvec3>> rays;
    for (int r = 0; r < 200; ++r) {
      const glm::dvec3 target = centre + glm::dvec3(12.0 * unit(random), 8.0 * unit(random), 6.0 * unit(random));
      rays.emplace_back(target - 60.0 * d, d);
    }
    SCOPED_TRACE("orthographic");
    expectVisibilityOrder(bricks, bricksBackToFront(bricks, {0, 0, 0}, d, true), rays);
  }
}

// SPDX-License-Identifier: MIT
// Culling the tets that clip planes hide: fewer tets, same picture (the renderers cut at
// the planes anyway), values carried to the renumbered nodes and cells.
#include "support/TetGrid.hpp"

#include <volpost/core/Camera.hpp>
#include "host/ClipCulling.hpp"
#include "host/optics/ReferenceRenderer.hpp"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

using namespace volpost;

TEST(ClipCulling, KeepsWhatTheBoxCanShowAndThePictureIsTheSame) {
  const Mesh grid = test::tetGrid(8, 6, 5);
  std::vector<double> values;
  for (const auto& p : grid.nodes) values.push_back(p.x + 0.5 * p.y);
  const std::vector<ClipPlane> box = {{{2.5, 0, 0}, {1, 0, 0}}, {{4.5, 0, 0}, {-1, 0, 0}}, {{0, 0, 0.5}, {0, 0, 1}}};
  const CulledMesh culled = cullToClipPlanes(grid, box);
  EXPECT_EQ(culled.mesh.cellCount(), grid.cellCount() * 3 / 8);  // the columns x in [2, 5]
  EXPECT_GT(culled.mesh.cellCount(), 0u);
  const auto kept = culled.values(FieldLocation::Node, values);
  for (std::size_t i = 0; i < kept.size(); ++i) EXPECT_EQ(kept[i], values[culled.nodeOf[i]]);
  EXPECT_EQ(culled.values(FieldLocation::Cell, std::vector<double>(grid.cellCount(), 3.0)).size(), culled.mesh.cellCount());

  const TransferFunction tf({{0.0, {0, 0, 1}, 0.2}, {5.0, {1, 1, 1}, 0.6}, {11.0, {1, 0, 0}, 0.9}});
  Camera camera;
  camera.fit(grid.bounds());
  camera.setView(StandardView::Isometric);
  optics::RaySettings settings;
  settings.clipPlanes = box;
  const auto full = optics::renderReference(optics::TetVolume(grid, FieldLocation::Node, values), tf, camera, 40, 40, settings);
  const auto part = optics::renderReference(optics::TetVolume(culled.mesh, FieldLocation::Node, kept), tf, camera, 40, 40, settings);
  double worst = 0.0;
  for (std::size_t i = 0; i < full.pixels.size(); ++i) worst = std::max(worst, glm::length(full.pixels[i] - part.pixels[i]));
  EXPECT_LT(worst, 1e-12);
  EXPECT_EQ(cullToClipPlanes(grid, {}).mesh.cellCount(), grid.cellCount());
}

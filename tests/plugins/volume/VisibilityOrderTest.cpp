// SPDX-License-Identifier: MIT
// Visibility orders for cell projection: valid back-to-front along every sampled ray on a
// convex grid (MPVO), a non-convex pair where MPVONC's farthest-first heuristic is wrong
// and the image-space order is right, and cycles broken without losing a tet.
#include "support/TetGrid.hpp"

#include "VisibilityOrder.hpp"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>

#include <numeric>

using namespace volpost;
using namespace volpost::volume;

namespace {

// Consecutive tets along rays through the pixel centres that the order draws the wrong
// way round (the nearer one first).
std::size_t violations(const VisibilitySorter& sorter, const VisibilityOrder& order, const Camera& camera, int size) {
  std::vector<std::size_t> position(order.backToFront.size());
  for (std::size_t i = 0; i < order.backToFront.size(); ++i) position[order.backToFront[i]] = i;
  const glm::dmat4 inverse = glm::inverse(camera.projectionMatrix(1.0) * camera.viewMatrix());
  std::size_t wrong = 0;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const double nx = (x + 0.5) / size * 2.0 - 1.0, ny = 1.0 - (y + 0.5) / size * 2.0;
      glm::dvec4 a = inverse * glm::dvec4(nx, ny, -1.0, 1.0), b = inverse * glm::dvec4(nx, ny, 1.0, 1.0);
      a /= a.w;
      b /= b.w;
      const auto along = sorter.tetsAlongRay(glm::dvec3(a), glm::dvec3(b) - glm::dvec3(a));
      for (std::size_t i = 0; i + 1 < along.size(); ++i) wrong += position[along[i + 1]] > position[along[i]];
    }
  return wrong;
}

Mesh twoTets(const std::array<glm::dvec3, 8>& p) {
  Mesh m;
  m.nodes.assign(p.begin(), p.end());
  for (NodeIndex first : {NodeIndex(0), NodeIndex(4)}) {
    std::vector<NodeIndex> t = {first, NodeIndex(first + 1), NodeIndex(first + 2), NodeIndex(first + 3)};
    m.addCell(CellType::Tet4, t);
    if (signedCellVolume(m, m.cellCount() - 1) < 0.0) {  // rebuild it positively oriented
      Mesh fixed;
      fixed.nodes = m.nodes;
      for (std::size_t c = 0; c + 1 < m.cellCount(); ++c) fixed.addCell(CellType::Tet4, m.cellNodes(c));
      std::swap(t[1], t[2]);
      fixed.addCell(CellType::Tet4, t);
      m = fixed;
    }
  }
  return m;
}

}  // namespace

TEST(VisibilityOrder, CyclesAreBrokenAndEveryItemIsPlacedOnce) {
  // 0 -> 1 -> 2 -> 0 and 3 free: the free item first, then the cycle is broken at its
  // farthest item (highest priority) and followed from there.
  std::size_t breaks = 0;
  const auto order = priorityTopologicalOrder(4, {{0, 1}, {1, 2}, {2, 0}}, {1.0, 5.0, 2.0, 0.5}, &breaks);
  EXPECT_EQ(breaks, 1u);
  EXPECT_EQ(order, (std::vector<std::uint32_t>{3, 1, 2, 0}));
}

TEST(VisibilityOrder, MpvoIsValidOnAConvexGridFromEveryStandardView) {
  const Mesh grid = test::tetGrid(5, 4, 3);
  const VisibilitySorter sorter(grid);
  for (StandardView v : {StandardView::PlusX, StandardView::MinusY, StandardView::PlusZ, StandardView::Isometric}) {
    for (Camera::Projection projection : {Camera::Projection::Perspective, Camera::Projection::Orthographic}) {
      Camera camera;
      camera.fit(grid.bounds());
      camera.setView(v);
      camera.orbit(7.0, 5.0);  // off the grid planes
      camera.setProjection(projection);
      const VisibilityOrder order = sorter.order(camera, OrderMethod::Mpvo);
      ASSERT_EQ(order.backToFront.size(), grid.cellCount());
      EXPECT_EQ(order.cycleBreaks, 0u);
      EXPECT_EQ(violations(sorter, order, camera, 24), 0u);
    }
  }
}

TEST(VisibilityOrder, ImageSpaceOrderIsRightWhereMpvoncIsWrongOnANonConvexMesh) {
  // Two separate tets seen along the depth axis: a big tilted one in front whose centroid
  // lies deep (its far end is far away) and a small one behind its near end. MPVONC draws
  // the big one first (its centroid is farther): wrong where a ray meets both.
  Camera camera;
  const std::array<glm::dvec3, 8> points = {glm::dvec3(-30, -12, 14), glm::dvec3(-30, 12, 14), glm::dvec3(14, -8, 0),
                                            glm::dvec3(14, 8, 3),     glm::dvec3(7, -1.5, 5),   glm::dvec3(11, -1.5, 5),
                                            glm::dvec3(9, 2, 5),      glm::dvec3(9, 0, 7)};
  Mesh mesh = twoTets(points);
  camera.fit(mesh.bounds());
  camera.setView(StandardView::PlusZ);
  camera.setProjection(Camera::Projection::Orthographic);
  if (camera.viewDirection().z < 0.0)  // make +z point away from the eye
    for (auto& p : mesh.nodes) p.z = -p.z;
  mesh = twoTets({mesh.nodes[0], mesh.nodes[1], mesh.nodes[2], mesh.nodes[3], mesh.nodes[4], mesh.nodes[5], mesh.nodes[6], mesh.nodes[7]});
  camera.fit(mesh.bounds());
  const VisibilitySorter sorter(mesh);
  const VisibilityOrder mpvonc = sorter.order(camera, OrderMethod::Mpvonc);
  EXPECT_GT(violations(sorter, mpvonc, camera, 48), 0u) << "the construction must fool MPVONC";
  const VisibilityOrder exact = sorter.order(camera, OrderMethod::ImageSpace, 48, 48);
  EXPECT_GT(exact.imageRelations, 0u);
  EXPECT_EQ(violations(sorter, exact, camera, 48), 0u);
  EXPECT_EQ(exact.cycleBreaks, 0u);
}

#include "support/TestSupport.hpp"
#include "VtuReader.hpp"

#include <volpost/core/Tetrahedralize.hpp>

TEST(VisibilityOrder, ImageSpaceOrderIsValidOnTheRealNonConvexWheel) {
  // The wheel's holes and hub make rays leave and re-enter the mesh. Checked on every ray
  // of the image the order was built for.
  VOLPOST_SHARED_OR_SKIP(path, "wheel/tet4/wheel_tet4.vtu");
  const auto model = meshio::VtuReader().read(path, {});
  const TetMesh tets = tetrahedralize(model->mesh());
  const VisibilitySorter sorter(tets.mesh);
  Camera camera;
  camera.fit(tets.mesh.bounds());
  camera.setView(StandardView::Isometric);
  camera.orbit(20.0, -10.0);
  const VisibilityOrder exact = sorter.order(camera, OrderMethod::ImageSpace, 24, 24);
  EXPECT_GT(exact.imageRelations, 0u);
  EXPECT_EQ(violations(sorter, exact, camera, 24), 0u);
  const VisibilityOrder mpvonc = sorter.order(camera, OrderMethod::Mpvonc);
  std::printf("wheel tet4, 24x24 rays: MPVONC %zu wrong pairs, image-space %zu (cycle breaks %zu)\n",
              violations(sorter, mpvonc, camera, 24), violations(sorter, exact, camera, 24), exact.cycleBreaks);
}

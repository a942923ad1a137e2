// SPDX-License-Identifier: MIT
// The exact reference renderer on cases with closed-form answers, and on the hard cases:
// rays through grid vertices, along edges, in faces; re-entry; clipping; slivers; a mesh
// at 1e6 with 1e-3 cells; extreme optical depths.
#include "support/QuadPrecision.hpp"
#include "support/TetGrid.hpp"

#include "host/optics/ReferenceRenderer.hpp"

#include <glm/gtc/matrix_inverse.hpp>
#include <gtest/gtest.h>

using namespace volpost;
using namespace volpost::optics;
using volpost::test::tetGrid;

namespace {

const glm::dvec3 kColor(0.2, 0.5, 0.8);

TransferFunction constantTf(double tau) { return TransferFunction({{0.0, kColor, tau}, {1.0, kColor, tau}}); }

std::vector<double> nodalConstant(const Mesh& m, double v) { return std::vector<double>(m.nodeCount(), v); }

template <typename F>
std::vector<double> nodal(const Mesh& m, F f) {
  std::vector<double> v;
  for (const auto& p : m.nodes) v.push_back(f(p));
  return v;
}

// Rays straight down (-z) at positions on vertices, on edges, in faces and generic.
std::vector<glm::dvec2> awkwardPositions() {
  std::vector<glm::dvec2> out;
  for (double x : {0.0, 1.0, 2.0, 2.5, 1.0 / 3.0, 3.0, 4.0})
    for (double y : {0.0, 1.0, 2.0, 0.25, 2.0 / 3.0, 4.0}) out.push_back({x, y});
  return out;
}

}  // namespace

TEST(ReferenceRays, AxisAlignedRaysThroughVerticesEdgesAndFacesCountEachLengthOnce) {
  const Mesh grid = tetGrid(4, 4, 4);
  const TetVolume volume(grid, FieldLocation::Node, nodalConstant(grid, 0.5));
  EXPECT_EQ(volume.tetCount(), 384u);
  for (const auto& p : awkwardPositions()) {
    // The closed box [0,4]^3: rays on its outer faces touch it without entering.
    const bool interior = p.x > 0 && p.x < 4 && p.y > 0 && p.y < 4;
    const double len = lengthInside(volume, {p.x, p.y, 10.0}, {0, 0, -1}, 0.0, 20.0);
    if (interior) EXPECT_DOUBLE_EQ(len, 4.0) << p.x << "," << p.y;
    for (const glm::dvec3 dir : {glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0)}) {
      const glm::dvec3 start = dir.x > 0 ? glm::dvec3(-5, p.x, p.y) : glm::dvec3(p.x, -5, p.y);
      const double l = lengthInside(volume, start, dir, 0.0, 20.0);
      if (interior) EXPECT_DOUBLE_EQ(l, 4.0) << p.x << "," << p.y;
    }
  }
}

TEST(ReferenceRays, DiagonalRaysThroughGridVertices) {
  const Mesh grid = tetGrid(4, 4, 4);
  const TetVolume volume(grid, FieldLocation::Node, nodalConstant(grid, 0.5));
  // Along the cubes' main diagonals (the Kuhn tets' shared edges) and across them.
  EXPECT_NEAR(lengthInside(volume, {-1, -1, -1}, {1, 1, 1}, 0.0, 100.0), 4.0 * std::sqrt(3.0), 1e-12);
  EXPECT_NEAR(lengthInside(volume, {1, -1, -1}, {0, 1, 1}, 0.0, 100.0), 4.0 * std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(lengthInside(volume, {5, -1, 2}, {-1, 1, 0}, 0.0, 100.0), 4.0 * std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(lengthInside(volume, {-1, 3, 5}, {1, -1, -1}, 0.0, 100.0), 2.0 * std::sqrt(3.0), 1e-12);
}

TEST(ReferenceRays, ConstantFieldGivesTheSlabClosedFormForAllOpticalDepths) {
  const Mesh grid = tetGrid(4, 4, 4);
  for (double tau : {1e-8, 1e-3, 0.3, 2.0, 1e4}) {
    const TetVolume volume(grid, FieldLocation::Cell, std::vector<double>(grid.cellCount(), 0.5));  // s_f == s_b
    for (const auto& p : awkwardPositions()) {
      if (!(p.x > 0 && p.x < 4 && p.y > 0 && p.y < 4)) continue;
      const SegmentLight l = integrateRay(volume, constantTf(tau), {p.x, p.y, 10.0}, {0, 0, -1}, 0.0, 20.0);
      const double alpha = -std::expm1(-4.0 * tau);
      EXPECT_NEAR(l.transmittance, 1.0 - alpha, 1e-13 * (1.0 - alpha) + 1e-300);  // 8 segments composited
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(l.color[k], kColor[k] * alpha, 1e-13 * alpha) << tau;
    }
  }
}

TEST(ReferenceRays, FieldAlongTheRayMatchesTheEmissionIntegral) {
  // s = z, tau and color linear in s: one linear segment of length 4 from s = 4 to s = 0.
  const Mesh grid = tetGrid(4, 4, 4);
  const TetVolume volume(grid, FieldLocation::Node, nodal(grid, [](const glm::dvec3& p) { return p.z; }));
  const glm::dvec3 c0(0.1, 0.2, 0.9), c4(0.9, 0.3, 0.1);
  const double tau0 = 0.05, tau4 = 1.1;
  const TransferFunction tf({{0.0, c0, tau0}, {4.0, c4, tau4}});
  const SegmentLight l = integrateRay(volume, tf, {1.3, 2.0, 9.0}, {0, 0, -1}, 0.0, 20.0);
  using volpost::test::quad;
  for (int k = 0; k < 3; ++k) {
    // x from the front (z = 4) to the back (z = 0).
    const quad e = volpost::test::adaptiveIntegral(
        [&](quad x) {
          const quad tau = tau4 + (quad(tau0) - tau4) * x, col = c4[k] + (quad(c0[k]) - c4[k]) * x;
          return col * tau * 4 * expq(-4 * (tau4 * x + (quad(tau0) - tau4) * x * x / 2));
        },
        0, 1);
    EXPECT_NEAR(l.color[k], double(e), 1e-13);
  }
  EXPECT_NEAR(l.transmittance, std::exp(-0.5 * (tau0 + tau4) * 4.0), 1e-15);
}

TEST(ReferenceRays, RaysLeavingAndReenteringANonConvexMesh) {
  // Five slabs along z separated by gaps: the ray re-enters four times.
  const Mesh m = volpost::test::stackedSlabs(5, 2, 2.0);
  const TetVolume volume(m, FieldLocation::Node, nodalConstant(m, 0.5));
  const double tau = 0.4;
  for (const auto& p : {glm::dvec2(1.0, 1.0), glm::dvec2(0.5, 1.5), glm::dvec2(1.0, 0.25)}) {
    EXPECT_DOUBLE_EQ(lengthInside(volume, {p.x, p.y, 20.0}, {0, 0, -1}, 0.0, 40.0), 5.0);
    const SegmentLight l = integrateRay(volume, constantTf(tau), {p.x, p.y, 20.0}, {0, 0, -1}, 0.0, 40.0);
    EXPECT_NEAR(l.transmittance, std::exp(-5.0 * tau), 1e-15);
    EXPECT_NEAR(l.color.g, 0.5 * (1.0 - std::exp(-5.0 * tau)), 1e-15);
  }
}

TEST(ReferenceRays, ClipPlanesCutTheRayInsideTheTet) {
  const Mesh grid = tetGrid(4, 4, 4);
  const TetVolume volume(grid, FieldLocation::Node, nodalConstant(grid, 0.5));
  RaySettings clip;
  clip.clipPlanes.push_back({{0, 0, 1.37}, {0, 0, 1}});   // keep z >= 1.37
  clip.clipPlanes.push_back({{0, 0, 3.5}, {0, 0, -1}});   // keep z <= 3.5
  EXPECT_NEAR(lengthInside(volume, {1.5, 2.0, 10.0}, {0, 0, -1}, 0.0, 20.0, clip), 3.5 - 1.37, 1e-14);
  clip.clipPlanes.push_back({{2.0, 0, 0}, {1, 0, 0}});    // keep x >= 2: this ray is cut away
  EXPECT_EQ(lengthInside(volume, {1.5, 2.0, 10.0}, {0, 0, -1}, 0.0, 20.0, clip), 0.0);
}

TEST(ReferenceRays, SliversAreNeitherHolesNorNaN) {
  // A flat-ish tet glued under a big one: the ray crosses both.
  Mesh m;
  m.nodes = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {0.5, 0.5, 2}, {0.5, 0.5, -1e-10}};
  const NodeIndex big[4] = {0, 1, 2, 3}, sliver[4] = {0, 2, 1, 4};
  m.addCell(CellType::Tet4, big);
  m.addCell(CellType::Tet4, sliver);
  const TetVolume volume(m, FieldLocation::Node, nodal(m, [](const glm::dvec3& p) { return p.z; }));
  const TransferFunction tf({{-1.0, {1, 0, 0}, 1.0}, {0.0, {0, 1, 0}, 5.0}, {3.0, {0, 0, 1}, 0.1}});
  const SegmentLight l = integrateRay(volume, tf, {0.5, 0.5, 5.0}, {0, 0, -1}, 0.0, 10.0);
  EXPECT_TRUE(std::isfinite(l.color.r) && std::isfinite(l.transmittance));
  EXPECT_NEAR(lengthInside(volume, {0.5, 0.5, 5.0}, {0, 0, -1}, 0.0, 10.0), 2.0 + 1e-10, 1e-14);
}

TEST(ReferenceRays, AMeshFarFromTheOriginWithTinyCellsGivesTheSameLight) {
  // Offset 2^20 (~1e6) and cells of 2^-10 (~1e-3): coordinates, ray origins and field are
  // exact in double there, so any difference would be the renderer's own (a far-away
  // mesh with non-dyadic coordinates carries ~1e-7 relative error in its input already).
  const glm::dvec3 offset(1048576.0, -2097152.0, 1048576.0);
  const double cell = 1.0 / 1024.0;
  const Mesh near = tetGrid(3, 3, 3);
  const Mesh far = tetGrid(3, 3, 3, offset, cell);
  const auto sOf = [](const Mesh& m, glm::dvec3 o, double scale) {
    return nodal(m, [=](const glm::dvec3& p) { return (p.x - o.x) / scale + 0.5 * (p.z - o.z) / scale; });
  };
  const TetVolume a(near, FieldLocation::Node, sOf(near, {0, 0, 0}, 1.0));
  const TetVolume b(far, FieldLocation::Node, sOf(far, offset, cell));
  const TransferFunction tfA({{0.0, {1, 0, 0}, 0.2}, {2.0, {0, 1, 0}, 1.5}, {4.5, {0, 0, 1}, 0.3}});
  std::vector<ControlPoint> scaled = tfA.points();
  for (auto& p : scaled) p.extinction /= cell;  // the same optical depth over 1/1024 the length
  const TransferFunction tfB(scaled);
  for (const auto& p : {glm::dvec2(1.0, 1.0), glm::dvec2(0.375, 2.875), glm::dvec2(2.0, 0.5)}) {
    const SegmentLight la = integrateRay(a, tfA, {p.x, p.y, 10.0}, {0.1, 0, -1}, 0.0, 30.0);
    const SegmentLight lb = integrateRay(b, tfB, offset + cell * glm::dvec3(p.x, p.y, 10.0), {0.1, 0, -1}, 0.0, 30.0 * cell);
    EXPECT_NEAR(la.transmittance, lb.transmittance, 1e-12);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(la.color[k], lb.color[k], 1e-12);
    EXPECT_GT(1.0 - la.transmittance, 0.1);  // the ray did cross material
  }
}

TEST(ReferenceImage, FieldAcrossTheViewMatchesTheClosedFormPerPixel) {
  // s = x, seen from +z (orthographic): each pixel's ray crosses 4 units at constant s,
  // so alpha = 1 - exp(-4 tau(x)) and color = C(x) alpha exactly.
  const Mesh grid = tetGrid(4, 4, 4);
  const TetVolume volume(grid, FieldLocation::Node, nodal(grid, [](const glm::dvec3& p) { return p.x; }));
  const TransferFunction tf({{0.0, {0, 0, 1}, 0.0}, {1.5, {0, 1, 0}, 0.6}, {4.0, {1, 0, 0}, 0.2}});
  Camera camera;
  camera.setProjection(Camera::Projection::Orthographic);
  camera.setView(StandardView::PlusZ);
  camera.fit(grid.bounds());
  const int size = 64;
  const ReferenceImage image = renderReference(volume, tf, camera, size, size);
  const glm::dmat4 toModel = glm::inverse(camera.projectionMatrix(1.0) * camera.viewMatrix());
  double worst = 0.0;
  int inside = 0;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const glm::dvec4 q = toModel * glm::dvec4(2.0 * (x + 0.5) / size - 1.0, 1.0 - 2.0 * (y + 0.5) / size, 0.0, 1.0);
      const double mx = q.x / q.w, my = q.y / q.w;
      const glm::dvec4 px = image.pixels[std::size_t(y * size + x)];
      if (mx < 0 || mx > 4 || my < 0 || my > 4) {
        if (mx < -1e-9 || mx > 4 + 1e-9 || my < -1e-9 || my > 4 + 1e-9) EXPECT_EQ(px.a, 0.0);
        continue;
      }
      ++inside;
      const double alpha = -std::expm1(-4.0 * tf.extinction(mx));
      worst = std::max(worst, std::abs(px.a - alpha));
      for (int k = 0; k < 3; ++k) worst = std::max(worst, std::abs(px[k] - tf.color(mx)[k] * alpha));
    }
  EXPECT_GT(inside, size * size / 4);
  EXPECT_LE(worst, 1e-12);
}

TEST(ReferenceImage, PerspectiveCenterRayAndCancellation) {
  const Mesh grid = tetGrid(2, 2, 2);
  const TetVolume volume(grid, FieldLocation::Node, nodalConstant(grid, 0.5));
  Camera camera;
  camera.setView(StandardView::PlusZ);
  camera.fit(grid.bounds());
  const ReferenceImage image = renderReference(volume, constantTf(0.7), camera, 33, 33);
  // The centre pixel's ray goes straight down the middle: 2 units of material.
  EXPECT_NEAR(image.pixels[16 * 33 + 16].a, -std::expm1(-1.4), 1e-12);
  int calls = 0;
  Progress cancel([&](double, const std::string&) { return ++calls < 3; });
  EXPECT_THROW(renderReference(volume, constantTf(0.7), camera, 33, 33, {}, cancel, 2), Cancelled);
}

TEST(TetVolume, RefusesCellsThatAreNotTetrahedra) {
  Mesh m;
  m.nodes = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  const NodeIndex hex[8] = {0, 1, 2, 3, 4, 5, 6, 7};
  m.addCell(CellType::Hex8, hex);
  try {
    TetVolume v(m, FieldLocation::Cell, std::vector<double>{1.0});
    FAIL() << "accepted a hexahedron";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("1 hex8"), std::string::npos) << e.what();
  }
}

TEST(ReferenceRays, IsoSurfacesAreMetOnceAndCompositedInOrder) {
  // s = z; an opaque red surface at s = 2.5 seen from above behind 1.5 units of fog.
  const Mesh grid = tetGrid(4, 4, 4);
  const TetVolume volume(grid, FieldLocation::Node, nodal(grid, [](const glm::dvec3& p) { return p.z; }));
  const double tau = 0.4;
  const TransferFunction tf({{0.0, kColor, tau}, {4.0, kColor, tau}});
  RaySettings settings;
  settings.isoSurfaces = {{2.5, {1, 0, 0}, 1.0}};
  const SegmentLight l = integrateRay(volume, tf, {1.3, 2.0, 9.0}, {0, 0, -1}, 0.0, 20.0, settings);
  const double t = std::exp(-1.5 * tau);  // fog in front of the surface; gradient along the ray: full light
  EXPECT_NEAR(l.color.r, kColor.r * (1 - t) + t * 1.0, 1e-13);
  EXPECT_NEAR(l.color.g, kColor.g * (1 - t), 1e-13);
  EXPECT_NEAR(l.transmittance, 0.0, 1e-15);
  // On a grid plane (z = 2 is a shared face of many tets) the surface is counted once.
  settings.isoSurfaces = {{2.0, {0, 0, 1}, 0.5}};
  const SegmentLight half = integrateRay(volume, TransferFunction(), {1.3, 2.0, 9.0}, {0, 0, -1}, 0.0, 20.0, settings);
  EXPECT_NEAR(half.transmittance, 0.5, 1e-15);
  EXPECT_NEAR(half.color.b, 0.5, 1e-15);
}

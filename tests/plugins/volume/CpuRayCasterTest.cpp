// SPDX-License-Identifier: MIT
// The CPU ray caster against the exact reference renderer: the same cases as the GPU
// renderers with bounds a hundred times tighter, and the watertightness cases (slivers,
// needles, Delaunay slivers, rays through vertices and along edges, eye inside the mesh).
#include "VolumeImageFixture.hpp"

#include "CpuRayCaster.hpp"
#include "PiecewiseIntegrator.hpp"

#include <volpost/core/optics/QuickSegment.hpp>
#include <volpost/core/optics/SegmentIntegral.hpp>

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <volpost/core/Tetrahedralize.hpp>

#include <filesystem>
#include <random>

using namespace volpost;
using namespace volpost::test;

namespace {

// The reference's image of the same scene, and the largest channel difference.
ImageError cpuAgainstReference(const volume::TetWalkMesh& walk, const Mesh& mesh, FieldLocation loc,
                               const std::vector<double>& values, const TransferFunction& tf, const Camera& camera, int size,
                               volume::CpuRaySettings settings = {}) {
  settings.terminationTransmittance = 0.0;
  const volume::CpuImage image = volume::renderCpu(walk, tf, camera, size, size, settings);
  const optics::TetVolume volume(mesh, loc, values);
  optics::RaySettings ref;
  ref.clipPlanes = settings.clipPlanes;
  ref.isoSurfaces = settings.isoSurfaces;
  return RayCast::compare(image.rgba, optics::renderReference(volume, tf, camera, size, size, ref));
}

Mesh scaled(Mesh m, glm::dvec3 scale) {
  for (auto& p : m.nodes) p *= scale;
  return m;
}

Mesh jittered(Mesh m, double amount, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-amount, amount);
  const Bounds b = m.bounds();
  for (auto& p : m.nodes)
    for (int k = 0; k < 3; ++k)
      if (p[k] > b.min[k] && p[k] < b.max[k]) p[k] += u(rng);  // the box stays a box
  return m;
}

// Delaunay tetrahedralization of a lattice jittered by `jitter` (1e-7: below float
// resolution, so exactly degenerate in float): its cubes' eight nearly co-spherical points
// give many slivers (flat tets with four nearly coplanar corners).
Mesh delaunaySlivers(int n, double jitter = 1e-7) {
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Delaunay = CGAL::Delaunay_triangulation_3<Kernel>;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-jitter, jitter);
  std::vector<Kernel::Point_3> points;
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) points.emplace_back(i + u(rng), j + u(rng), k + u(rng));
  const Delaunay dt(points.begin(), points.end());
  Mesh m;
  std::map<Delaunay::Vertex_handle, NodeIndex> ids;
  for (auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v) {
    ids[v] = NodeIndex(m.nodes.size());
    m.nodes.push_back({v->point().x(), v->point().y(), v->point().z()});
  }
  for (auto c = dt.finite_cells_begin(); c != dt.finite_cells_end(); ++c) {
    NodeIndex t[4];
    for (int i = 0; i < 4; ++i) t[i] = ids[c->vertex(i)];
    m.addCell(CellType::Tet4, t);
  }
  return m;
}

// Constant field, constant extinction: every pixel's alpha is 1 - exp(-tau L), L the ray's
// length inside the mesh. A ray slipping between tets or counted twice shows at once.
double worstAlphaError(const Mesh& mesh, const char* name) {
  const Bounds b = mesh.bounds();
  const glm::dvec3 extent = b.max - b.min;
  const double tau = 1.0 / std::min({extent.x, extent.y, extent.z});
  const std::vector<double> values(mesh.nodeCount(), 1.0);
  const TransferFunction tf({{0.0, {1, 1, 1}, tau}, {2.0, {1, 1, 1}, tau}});
  const volume::TetWalkMesh walk(mesh, FieldLocation::Node, values);
  double worst = 0.0;
  const std::pair<StandardView, Camera::Projection> views[] = {
      {StandardView::PlusZ, Camera::Projection::Orthographic}, {StandardView::PlusX, Camera::Projection::Orthographic},
      {StandardView::MinusY, Camera::Projection::Perspective}, {StandardView::Isometric, Camera::Projection::Orthographic},
      {StandardView::Isometric, Camera::Projection::Perspective}};
  for (auto [view, projection] : views)
    for (int size : {33, 64}) {
      Camera camera;
      camera.setProjection(projection);
      camera.setView(view);
      camera.fit(b);
      const ImageError e = cpuAgainstReference(walk, mesh, FieldLocation::Node, values, tf, camera, size);
      worst = std::max(worst, e.max);
    }
  std::printf("cpu %s (%zu tets): worst alpha error over 10 views %.3g\n", name, walk.tetCount(), worst);
  return worst;
}

}  // namespace

TEST_F(CpuRayCast, LinearSegmentsMatchTheReference) {
  const Mesh grid = test::tetGrid(4, 4, 4);
  const ImageError e = againstReference(grid, FieldLocation::Node, field(grid), kTf, isoCamera(grid), 64);
  std::printf("cpu vs reference: RMSE %.3g, max %.3g\n", e.rmse, e.max);
  EXPECT_LE(e.rmse, 2e-6);  // float geometry; the integration is exact to 1e-8
  EXPECT_LE(e.max, 3e-5);
}

// A step (two control points at one value): the renderer and the reference each integrate
// both sides with their own limits (the reference took the upper one for the piece below).
TEST_F(CpuRayCast, AStepInTheFunctionMatchesTheReference) {
  const Mesh grid = test::tetGrid(4, 4, 4);
  const TransferFunction step({{0.0, {0.2, 0.3, 0.9}, 0.0}, {3.0, {0.2, 0.3, 0.9}, 0.1}, {3.0, {1.0, 0.5, 0.1}, 1.5},
                               {6.0, {0.9, 0.1, 0.1}, 0.8}});
  const ImageError e = againstReference(grid, FieldLocation::Node, field(grid), step, isoCamera(grid), 64);
  std::printf("cpu vs reference, a step in the function: RMSE %.3g, max %.3g\n", e.rmse, e.max);
  EXPECT_LE(e.rmse, 2e-6);
  EXPECT_LE(e.max, 3e-5);
}

TEST_F(CpuRayCast, NoPixelIsLostOnAxisAlignedAndDiagonalViewsOfATetrahedralizedGrid) {
  EXPECT_EQ(lostPixelsOnDegenerateViews(), 0);
}

TEST_F(CpuRayCast, ClipPlanesCutLikeTheReference) {
  const Mesh grid = test::tetGrid(4, 4, 4);
  const std::vector<ClipPlane> clips = {{{0, 0, 1.3}, {0, 0.2, 1}}, {{2.5, 0, 0}, {-1, 0, 0}}};
  const ImageError e = againstReference(grid, FieldLocation::Node, field(grid), kTf, isoCamera(grid), 64, clips);
  std::printf("cpu with 2 clip planes vs reference: RMSE %.3g, max %.3g\n", e.rmse, e.max);
  EXPECT_LE(e.rmse, 2e-6);
  EXPECT_LE(e.max, 3e-5);
}

TEST_F(CpuRayCast, ElementResultsAreConstantPerCell) {
  const Mesh grid = test::tetGrid(3, 3, 3);
  std::vector<double> cells(grid.cellCount());
  for (std::size_t c = 0; c < cells.size(); ++c) cells[c] = double(c % 7);
  const ImageError e = againstReference(grid, FieldLocation::Cell, cells, kTf, isoCamera(grid), 48);
  std::printf("cpu element results vs reference: RMSE %.3g, max %.3g\n", e.rmse, e.max);
  EXPECT_LE(e.rmse, 2e-6);
  EXPECT_LE(e.max, 3e-5);
}

TEST_F(CpuRayCast, RaysReenterANonConvexMeshLikeTheReference) {
  const Mesh m = test::threeSlabs();  // every ray along z enters three times
  const ImageError e = againstReference(m, FieldLocation::Node, field(m), kTf, isoCamera(m), 48);
  std::printf("cpu non-convex (3 slabs) vs reference: RMSE %.3g, max %.3g\n", e.rmse, e.max);
  EXPECT_LE(e.rmse, 2e-6);
  EXPECT_LE(e.max, 3e-5);
}

TEST_F(CpuRayCast, IsoSurfacesMatchTheReference) {
  const Mesh grid = test::tetGrid(4, 4, 4);
  volume::CpuRaySettings settings;
  settings.isoSurfaces = {{1.7, {0.9, 0.8, 0.1}, 0.6}, {3.9, {0.1, 0.7, 0.9}, 1.0}};
  const volume::TetWalkMesh walk(grid, FieldLocation::Node, field(grid));
  const ImageError e = cpuAgainstReference(walk, grid, FieldLocation::Node, field(grid), kTf, isoCamera(grid), 64, settings);
  std::printf("cpu with 2 iso-surfaces vs reference: RMSE %.3g, max %.3g\n", e.rmse, e.max);
  EXPECT_LE(e.rmse, 1e-5);
  EXPECT_LE(e.max, 1e-3);  // a float crossing can fall on the other side of a pixel's surface edge
}

// The surface on inner faces (s = x at a grid plane), as for the GPU renderers: the walk
// hands each exit value on as the next tet's entry value, so it is crossed once.
TEST_F(CpuRayCast, AnIsoSurfaceOnInnerFacesIsDrawnOnce) {
  const Mesh grid = test::tetGrid(4, 4, 4, glm::dvec3(0.1, 0.2, 0.3), 0.7);
  std::vector<double> x;
  for (const auto& p : grid.nodes) x.push_back(p.x);
  const TransferFunction faint({{0.0, {0.2, 0.3, 0.9}, 0.05}, {3.0, {0.9, 0.3, 0.2}, 0.05}});
  volume::CpuRaySettings settings;
  settings.isoSurfaces = {{0.1 + 2.0 * 0.7, {1.0, 0.9, 0.2}, 0.5}};
  const volume::TetWalkMesh walk(grid, FieldLocation::Node, x);
  Camera turned = isoCamera(grid);
  turned.orbit(-41.0, 23.0);
  for (const Camera& camera : {isoCamera(grid), turned}) {
    const ImageError e = cpuAgainstReference(walk, grid, FieldLocation::Node, x, faint, camera, 96, settings);
    std::printf("cpu, iso-surface on inner faces vs reference: RMSE %.3g, max %.3g\n", e.rmse, e.max);
    EXPECT_LE(e.max, 1e-3);
  }
}

TEST_F(CpuRayCast, OpaqueGeometryEndsRaysAtItsDepth) {
  const ImageError e = opaqueDepthAgainstReference();
  std::printf("cpu ended by scene depth vs reference clipped there: RMSE %.3g, max %.3g\n", e.rmse, e.max);
  EXPECT_LE(e.rmse, 1e-5);
  EXPECT_LE(e.max, 1e-4);
}

TEST_F(CpuRayCast, TinyAndOffsetValuesRenderLikeTheReference) {
  const Mesh grid = test::tetGrid(3, 3, 3);
  for (const auto& [offset, scale] : {std::pair{0.0, 1e-30}, std::pair{1e6, 1e-3}}) {
    std::vector<double> values;
    for (double v : field(grid)) values.push_back(offset + scale * v);
    std::vector<ControlPoint> points = kTf.points();
    for (ControlPoint& c : points) c.value = offset + scale * c.value;
    const TransferFunction tf(points);
    const ImageError e = againstReference(grid, FieldLocation::Node, values, tf, isoCamera(grid), 40);
    std::printf("cpu values %g + %g x: RMSE %.3g, max %.3g\n", offset, scale, e.rmse, e.max);
    EXPECT_LE(e.max, 1e-4) << offset << " " << scale;
  }
}

TEST_F(CpuRayCast, EarlyTerminationStaysWithinItsStatedBound) {
  const Mesh grid = test::tetGrid(4, 4, 4);
  const volume::TetWalkMesh walk(grid, FieldLocation::Node, field(grid));
  std::vector<ControlPoint> dense = kTf.points();
  for (ControlPoint& c : dense) c.extinction *= 8.0;  // most rays become opaque
  const TransferFunction tf(dense);
  const Camera camera = isoCamera(grid);
  volume::CpuRaySettings exact, early;
  exact.terminationTransmittance = 0.0;
  early.terminationTransmittance = 1e-2;
  const volume::CpuImage a = volume::renderCpu(walk, tf, camera, 48, 48, exact);
  const volume::CpuImage b = volume::renderCpu(walk, tf, camera, 48, 48, early);
  EXPECT_GT(b.stats.stoppedRays, 100u);
  EXPECT_LT(b.stats.steps, a.stats.steps);
  EXPECT_LT(b.stats.maxStopTransmittance, 1e-2);
  double worst = 0.0;
  for (std::size_t i = 0; i < a.rgba.size(); ++i) worst = std::max(worst, double(std::abs(a.rgba[i] - b.rgba[i])));
  std::printf("cpu early termination at 1e-2: %zu rays stopped, worst difference %.3g (bound %.3g)\n", b.stats.stoppedRays,
              worst, b.stats.maxStopTransmittance);
  EXPECT_LE(worst, b.stats.maxStopTransmittance + 1e-6);
  EXPECT_GT(worst, 0.0);
}

TEST_F(CpuRayCast, TransparentRangesAreSkippedWithoutChangingThePicture) {
  // A narrow opacity peak (most tets transparent) and an iso-surface in the transparent
  // part: rays walk only the tets that show, and the picture is the reference's.
  const Mesh grid = test::tetGrid(6, 6, 6);
  const TransferFunction peak({{0.0, {0.2, 0.3, 0.9}, 0.0}, {4.0, {0.2, 0.3, 0.9}, 0.0}, {4.2, {1.0, 0.6, 0.1}, 3.0},
                               {4.4, {0.9, 0.2, 0.1}, 0.0}, {9.0, {0.9, 0.2, 0.1}, 0.0}});
  volume::CpuRaySettings settings;
  settings.isoSurfaces = {{1.5, {0.9, 0.9, 0.9}, 0.5}};
  const volume::TetWalkMesh walk(grid, FieldLocation::Node, field(grid));
  const ImageError e = cpuAgainstReference(walk, grid, FieldLocation::Node, field(grid), peak, isoCamera(grid), 64, settings);
  std::printf("cpu sharp peak + iso-surface in the transparent range vs reference: RMSE %.3g, max %.3g\n", e.rmse, e.max);
  EXPECT_LE(e.rmse, 1e-6);
  EXPECT_LE(e.max, 3e-5);
  settings.terminationTransmittance = 0.0;
  const volume::CpuImage skipped = volume::renderCpu(walk, peak, isoCamera(grid), 64, 64, settings);
  const volume::CpuImage dense = volume::renderCpu(walk, kTf, isoCamera(grid), 64, 64, settings);
  EXPECT_EQ(dense.stats.visibleTets, walk.tetCount());
  EXPECT_LT(skipped.stats.visibleTets, walk.tetCount() / 2);
  EXPECT_LT(skipped.stats.steps, dense.stats.steps / 2);
}

TEST_F(CpuRayCast, TheWindowGetsAQuickFrameAtOnceAndTheFullOneWhenReady) {
  const Mesh grid = test::tetGrid(5, 5, 5);
  auto& cpu = static_cast<volume::CpuVolumeRenderer&>(*caster_);
  cpu.setVolume(grid, FieldLocation::Node, field(grid));
  cpu.setTransferFunction(kTf);
  cpu.setTerminationThreshold(0.0);
  const Camera camera = isoCamera(grid);
  const auto full = gpuImage(camera, 96, 96);  // synchronous: the command line's way
  ASSERT_EQ(cpu.shownReduction(), 1);
  cpu.setAsynchronousUpdates(true);
  cpu.setQuickFrameBudget(1e-6);  // every full frame is "too slow": a quick one first
  Camera moved = camera;
  moved.orbit(30.0, 0.0);
  (void)gpuImage(moved, 96, 96);
  EXPECT_GT(cpu.shownReduction(), 1);
  EXPECT_TRUE(cpu.hasPendingWork());
  Camera back = camera;  // a newer view cancels the full frame of the previous one
  (void)gpuImage(back, 96, 96);
  for (int i = 0; i < 2000 && cpu.hasPendingWork(); ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    (void)gpuImage(back, 96, 96);
  }
  ASSERT_FALSE(cpu.hasPendingWork());
  EXPECT_EQ(cpu.shownReduction(), 1);
  EXPECT_EQ(gpuImage(back, 96, 96), full) << "the refined frame is the synchronous one";
}

TEST_F(CpuRayCast, TheEyeInsideTheMeshSeesFromTheNearPlaneOn) {
  const Mesh grid = test::tetGrid(4, 4, 4);
  Camera camera;
  camera.setView(StandardView::Isometric);
  camera.fit(grid.bounds());
  camera.lookAt({1.3, 1.7, 2.2}, {3.5, 3.0, 0.5}, {0, 0, 1});  // the eye inside, looking across
  const ImageError e = againstReference(grid, FieldLocation::Node, field(grid), kTf, camera, 48);
  std::printf("cpu eye inside the mesh vs reference: RMSE %.3g, max %.3g\n", e.rmse, e.max);
  EXPECT_LE(e.rmse, 2e-6);
  EXPECT_LE(e.max, 3e-5);
}

TEST(CpuRayCastWatertight, SliversNeedlesAndJitteredCellsLoseNoRay) {
  const Mesh grid = test::tetGrid(5, 5, 5);
  // 1000:1 parts with an extinction of 1 / thickness: float parameters along rays 1000
  // thicknesses long leave ~2e-4 in alpha (the bound is 1e-3); no ray is lost.
  EXPECT_LE(worstAlphaError(scaled(grid, {1.0, 1.0, 1e-3}), "slivers (grid 1000:1 flat)"), 1e-3);
  EXPECT_LE(worstAlphaError(scaled(grid, {1e-3, 1.0, 1.0}), "needles (grid 1:1000 long)"), 1e-3);
  EXPECT_LE(worstAlphaError(jittered(grid, 0.15, 3), "jittered grid"), 1e-4);
  EXPECT_LE(worstAlphaError(delaunaySlivers(5), "Delaunay slivers"), 1e-4);
}

TEST_F(RayCast, GpuWalkLosesNoRayOnSliversAndNeedles) {
  // The GPU ray caster decides entries and exits by the same canonical Plucker signs (in
  // float, double where float cannot tell): every ray's alpha is 1 - exp(-tau L). Its
  // positions are float, so the Delaunay slivers are jittered above float resolution here.
  const Mesh grid = test::tetGrid(5, 5, 5);
  const std::pair<Mesh, const char*> meshes[] = {{scaled(grid, {1.0, 1.0, 1e-3}), "slivers (grid 1000:1 flat)"},
                                                 {scaled(grid, {1e-3, 1.0, 1.0}), "needles (grid 1:1000 long)"},
                                                 {jittered(grid, 0.15, 3), "jittered grid"},
                                                 {delaunaySlivers(5, 1e-5), "Delaunay slivers (jitter 1e-5)"}};
  for (const auto& [mesh, name] : meshes) {
    const Bounds b = mesh.bounds();
    const glm::dvec3 extent = b.max - b.min;
    const double tau = 1.0 / std::min({extent.x, extent.y, extent.z});
    const TransferFunction tf({{0.0, {1, 1, 1}, tau}, {2.0, {1, 1, 1}, tau}});
    const std::vector<double> values(mesh.nodeCount(), 1.0);
    double worst = 0.0;
    for (auto [view, projection] : {std::pair{StandardView::PlusZ, Camera::Projection::Orthographic},
                                    {StandardView::Isometric, Camera::Projection::Perspective},
                                    {StandardView::MinusY, Camera::Projection::Perspective}}) {
      Camera camera;
      camera.setProjection(projection);
      camera.setView(view);
      camera.fit(b);
      caster_->setIntegrationMode(IntegrationMode::LinearSegments);
      worst = std::max(worst, againstReference(mesh, FieldLocation::Node, values, tf, camera, 64).max);
    }
    std::printf("GPU raycast %s: worst alpha error over 3 views %.3g\n", name, worst);
    EXPECT_LE(worst, 5e-4) << name;  // float parameters along rays 1000 thicknesses long
  }
}

TEST(CpuRayCastWatertight, EveryRayOfACurvedThinShellIsKept) {
  // The case of quadratic models of thin parts: a thin curved shell (300 degrees of a tube,
  // 1/500 of its radius thick), cells split into tets: thin, curved, nearly flat tets.
  Mesh shell = test::tetGrid(30, 6, 1);
  for (glm::dvec3& p : shell.nodes) {
    const double a = 5.0 * M_PI / 3.0 * p.x / 30.0, r = 1.0 + 0.002 * p.z;
    p = {r * std::cos(a), r * std::sin(a), 0.2 * p.y};
  }
  EXPECT_LE(worstAlphaError(shell, "curved thin shell"), 1e-3);
}

TEST(CpuRayCastWatertight, NoRayIsLostOnTheCorpusMeshes) {
  // Every tetrahedralized corpus mesh (the bundled bar, and the shared meshes when present),
  // constant field: no pixel may differ from the exact path length's alpha.
  std::vector<std::string> files = {std::string(VOLPOST_TEST_DATA) + "/bar/bar_tet4.vtu"};
  for (const char* shared : {"bar/hex8/bar_hex8.vtu", "bar/tet10/bar_tet10.vtu", "bar/wedge6/bar_wedge6.vtu",
                             "wheel/tet4/wheel_tet4.vtu", "wheel/mixed/wheel_mixed.vtu", "bracket/tet10/bracket_tet10.frd",
                             "post/coarse/post_coarse.vtu", "post/fine/post_fine.vtu"})
    if (const std::string path = test::sharedFile(shared); !path.empty()) files.push_back(path);
    else std::printf("not run on %s: ../shared/data is absent\n", shared);
  for (const std::string& file : files) {
    const auto model = test::meshioReaders().load(file);
    const Mesh tets = tetrahedralize(model->mesh()).mesh;
    EXPECT_LE(worstAlphaError(tets, std::filesystem::path(file).filename().c_str()), 1e-4) << file;
  }
}

TEST(CpuRayCastIntegration, ThinPieceSeriesMatchesTheExactPsi) {
  double worst = 0.0;
  for (double tf = 0.0; tf <= 1.0; tf += 0.01)
    for (double tb = 0.0; tf + tb <= 1.0; tb += 0.01)
      worst = std::max(worst, std::abs(optics::thinPsi(tf, tb) - optics::psi(tf, tb)));
  std::printf("thin-piece psi series: worst error %.3g over (tf + tb) / 2 <= 0.5\n", worst);
  EXPECT_LE(worst, 6e-9);
}

TEST(CpuRayCastIntegration, ThinPieceTransmittanceMatchesExp) {
  // The transmittance of a thin piece comes from a series too: it multiplies everything
  // behind the piece, so it must stay at rounding level, thin and thick alike.
  double worst = 0.0;
  for (double tf = 0.0; tf <= 2.4; tf += 0.01)
    for (double tb = 0.0; tb <= 2.4; tb += 0.01) {
      const optics::SegmentLight s = optics::quickLinearSegment({1, 1, 1}, tf, {1, 1, 1}, tb, 1.0);
      worst = std::max(worst, std::abs(s.transmittance - std::exp(-0.5 * (tf + tb))));
    }
  std::printf("thin-piece transmittance series: worst error %.3g\n", worst);
  EXPECT_LE(worst, 2e-11);
}

TEST(CpuRayCastIntegration, PiecesMatchTheExactSegmentIntegral) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> value(-1.0, 7.0), length(0.0, 3.0);
  const volume::PiecewiseIntegrator pieces(kTf);
  double worst = 0.0;
  for (int i = 0; i < 20000; ++i) {
    const double a = value(rng), b = i % 10 == 0 ? a : value(rng), l = length(rng);
    const optics::SegmentLight x = pieces.integrate(a, b, l), y = optics::integrateSegment(kTf, a, b, l);
    worst = std::max({worst, std::abs(x.transmittance - y.transmittance), glm::length(x.color - y.color)});
  }
  EXPECT_LE(worst, 1e-8);
  // Transparent runs: zero extinction over a whole range, nowhere else.
  const TransferFunction peak({{0.0, {1, 1, 1}, 0.0}, {1.0, {1, 1, 1}, 0.0}, {1.5, {1, 0, 0}, 2.0}, {2.0, {1, 1, 1}, 0.0},
                               {5.0, {1, 1, 1}, 0.0}});
  const volume::PiecewiseIntegrator p(peak);
  EXPECT_TRUE(p.transparent(-3.0, 1.0));
  EXPECT_TRUE(p.transparent(0.2, 0.9));
  EXPECT_FALSE(p.transparent(0.9, 1.2));
  EXPECT_FALSE(p.transparent(1.9, 3.0));
  EXPECT_TRUE(p.transparent(2.0, 9.0));
  EXPECT_TRUE(p.transparent(9.0, 2.0));
  EXPECT_FALSE(p.transparent(-1.0, 9.0));
  // A value that is no number (a grid sample beyond the renderer's float) shows nothing:
  // the walk over the control points never ended on it.
  for (const double nan : {std::nan(""), double(INFINITY), -double(INFINITY)}) {
    EXPECT_TRUE(p.transparent(nan, 1.2));
    const optics::SegmentLight light = p.integrate(1.2, nan, 1.0);
    EXPECT_EQ(light.transmittance, 1.0);
    EXPECT_EQ(p.integrate(nan, nan, 1.0).transmittance, 1.0);
  }
}

// Another step on the same mesh shares the tets and their neighbours (no rebuild of the
// adjacency) and draws what a mesh built for those values draws; values that leave tets out
// (a NaN) build anew.
TEST_F(CpuRayCast, AnotherStepSharesTheTetsAndDrawsLikeAFreshBuild) {
  const Mesh grid = test::tetGrid(4, 4, 4);
  const std::vector<double> first = field(grid);
  std::vector<double> second(first.size());
  for (std::size_t i = 0; i < first.size(); ++i) second[i] = 3.0 - 0.5 * first[i] + 0.01 * double(i % 7);
  const auto previous = std::make_shared<const volume::TetWalkMesh>(grid, FieldLocation::Node, first);
  const auto next = volume::TetWalkMesh::withValues(previous, grid, second);
  EXPECT_EQ(&next->tetNeighbors(0), &previous->tetNeighbors(0)) << "the tets' neighbours are shared";
  EXPECT_TRUE(next->sharesCellsOf(grid)) << "the tets' nodes are the mesh's own cells";
  const volume::TetWalkMesh fresh(grid, FieldLocation::Node, second);
  const Camera camera = isoCamera(grid);
  const volume::CpuImage shared = volume::renderCpu(*next, kTf, camera, 48, 48, {});
  const volume::CpuImage built = volume::renderCpu(fresh, kTf, camera, 48, 48, {});
  ASSERT_EQ(shared.rgba.size(), built.rgba.size());
  for (std::size_t i = 0; i < shared.rgba.size(); ++i) ASSERT_NEAR(shared.rgba[i], built.rgba[i], 1e-6) << i;
  const volume::CpuImage old = volume::renderCpu(*previous, kTf, camera, 48, 48, {});
  EXPECT_NE(old.rgba, shared.rgba) << "the values changed the picture";
  second[5] = std::nan("");
  const auto rebuilt = volume::TetWalkMesh::withValues(next, grid, second);
  EXPECT_NE(&rebuilt->tetNeighbors(0), &previous->tetNeighbors(0));
  EXPECT_GT(rebuilt->skippedTets(), 0u);
  EXPECT_FALSE(rebuilt->sharesCellsOf(grid)) << "with a tet left out, the kept tets are a list of their own";
}

// Tet10 cells are walked through their corners, read from the mesh's own cells (every
// tenth entry): the picture is the one of the tet4 mesh of those corners.
TEST_F(CpuRayCast, Tet10CellsAreWalkedThroughTheirCornersInPlace) {
  const Mesh corners = test::tetGrid(3, 3, 3);
  Mesh quadratic;
  quadratic.nodes = corners.nodes;
  std::vector<double> values = field(corners);
  values.reserve(values.size() + 6 * corners.cellCount());
  constexpr int kEdges[6][2] = {{0, 1}, {1, 2}, {0, 2}, {0, 3}, {1, 3}, {2, 3}};  // VTK's mid-edge order
  for (std::size_t c = 0; c < corners.cellCount(); ++c) {
    const auto n = corners.cellNodes(c);
    NodeIndex cell[10] = {n[0], n[1], n[2], n[3]};
    for (int e = 0; e < 6; ++e) {
      cell[4 + e] = NodeIndex(quadratic.nodes.size());
      quadratic.nodes.push_back(0.5 * (corners.nodes[n[kEdges[e][0]]] + corners.nodes[n[kEdges[e][1]]]));
      values.push_back(0.5 * (values[n[kEdges[e][0]]] + values[n[kEdges[e][1]]]));
    }
    quadratic.addCell(CellType::Tet10, cell);
  }
  const volume::TetWalkMesh walk10(quadratic, FieldLocation::Node, values);
  EXPECT_TRUE(walk10.sharesCellsOf(quadratic));
  EXPECT_EQ(walk10.tetNodes(5), glm::uvec4(corners.cellNodes(5)[0], corners.cellNodes(5)[1], corners.cellNodes(5)[2],
                                           corners.cellNodes(5)[3]));
  const volume::TetWalkMesh walk4(corners, FieldLocation::Node, field(corners));
  const Camera camera = isoCamera(corners);
  const volume::CpuImage a = volume::renderCpu(walk10, kTf, camera, 40, 40, {});
  const volume::CpuImage b = volume::renderCpu(walk4, kTf, camera, 40, 40, {});
  ASSERT_EQ(a.rgba.size(), b.rgba.size());
  for (std::size_t i = 0; i < a.rgba.size(); ++i) ASSERT_NEAR(a.rgba[i], b.rgba[i], 1e-6) << i;
}

// SPDX-License-Identifier: MIT
// Regular grids: the exact trilinear reference against independent truths (a constant
// field against the exact path length through the box; a linear field, where trilinear
// and tetrahedral interpolation agree, against the tetrahedral reference on the grid's
// hexahedra), and the GPU ray marcher against that reference with stated bounds per step
// (second order: halving the step quarters the error), in several passes per frame, with
// clip planes and iso-surfaces, on a rotated, anisotropic grid.
#include "VolumeImageFixture.hpp"

#include "CpuGridMarcher.hpp"
#include "GridRayMarcher.hpp"
#include "GridSlicer.hpp"
#include "host/optics/GridReference.hpp"

#include <volpost/core/Tetrahedralize.hpp>

using namespace volpost;
using namespace volpost::test;

namespace {

// 9 x 7 x 6 points, rotated about z and tilted, spacings 1, 0.8 and 0.6.
RegularGrid skewedGrid() {
  RegularGrid g;
  g.dims = {9, 7, 6};
  const double c = std::cos(0.4), s = std::sin(0.4);
  g.origin = {10.0, -3.0, 2.0};
  g.axes = {glm::dvec3(c, s, 0.1), glm::dvec3(-0.8 * s, 0.8 * c, 0.0), glm::dvec3(0.0, 0.05, -0.6)};
  return g;
}

std::vector<double> wavyValues(const RegularGrid& g) {
  std::vector<double> v(g.pointCount());
  for (std::size_t k = 0; k < g.dims[2]; ++k)
    for (std::size_t j = 0; j < g.dims[1]; ++j)
      for (std::size_t i = 0; i < g.dims[0]; ++i)
        v[g.pointIndex(i, j, k)] = 3.0 + 2.5 * std::sin(0.7 * double(i)) * std::cos(0.9 * double(j)) + 0.3 * double(k);
  return v;
}

Camera gridCamera(const RegularGrid& g) {
  Camera c;
  c.setView(StandardView::Isometric);
  c.fit(g.bounds());
  c.orbit(23.0, -11.0);
  return c;
}

const TransferFunction kGridTf({{0.0, {0.1, 0.2, 0.9}, 0.05}, {2.0, {0.2, 0.9, 0.3}, 0.4},
                                {3.5, {1.0, 1.0, 1.0}, 1.2}, {6.0, {0.9, 0.1, 0.1}, 0.2}});

class GridMarch : public RayCast {
 protected:
  std::unique_ptr<VolumeRenderer> makeRenderer() const override { return std::make_unique<volume::GridRayMarcher>(); }
  volume::GridRayMarcher& marcher() { return static_cast<volume::GridRayMarcher&>(*caster_); }
  /// The renderer as any grid renderer (the slicer's fixture derives from this one).
  GridVolumeRenderer& gridRenderer() { return static_cast<GridVolumeRenderer&>(*caster_); }

  ImageError marchAgainstReference(const RegularGrid& g, const std::vector<double>& values, double step,
                                   const Camera& camera, int size, const optics::RaySettings& settings = {}) {
    GridVolumeRenderer& r = gridRenderer();
    r.setGrid(g, values);
    r.setTransferFunction(kGridTf);
    r.setSamplingStep(step);
    r.setClipPlanes(settings.clipPlanes);
    r.setIsoSurfaces(settings.isoSurfaces);
    r.setShading(settings.shading);
    r.setTerminationThreshold(0.0);
    const auto image = gpuImage(camera, size, size);
    return compare(image, optics::renderGridReference(g, values, kGridTf, camera, size, size, settings));
  }
};

}  // namespace

TEST(GridReference, AConstantFieldGivesTheExactPathLengthThroughTheBox) {
  const RegularGrid g = skewedGrid();
  const std::vector<double> values(g.pointCount(), 2.0);
  const TransferFunction tf({{0.0, {1, 1, 1}, 0.7}, {4.0, {1, 1, 1}, 0.7}});
  const glm::dmat3 toIndex = glm::inverse(g.indexToWorld());
  double worst = 0.0;
  for (int r = 0; r < 50; ++r) {
    const glm::dvec3 target = g.position(0.5 + 0.15 * r, 0.3 + 0.11 * r, 0.2 + 0.09 * r);
    const glm::dvec3 origin = target + glm::dvec3(20.0 * std::cos(r), 15.0 * std::sin(1.3 * r), 9.0 - 0.3 * r);
    const glm::dvec3 d = glm::normalize(target - origin);
    // The path length through the box: slabs in index space.
    const glm::dvec3 o = toIndex * (origin - g.origin), e = toIndex * d;
    double t0 = 0.0, t1 = 1e9;
    for (int a = 0; a < 3; ++a) {
      const double ta = -o[a] / e[a], tb = (double(g.dims[a] - 1) - o[a]) / e[a];
      t0 = std::max(t0, std::min(ta, tb));
      t1 = std::min(t1, std::max(ta, tb));
    }
    const double expected = 1.0 - std::exp(-0.7 * std::max(0.0, t1 - t0));
    const optics::SegmentLight light = optics::integrateGridRay(g, values, tf, origin, d, 0.0, 1e9);
    worst = std::max(worst, std::abs((1.0 - light.transmittance) - expected));
  }
  EXPECT_LE(worst, 1e-12);
}

TEST(GridReference, ALinearFieldMatchesTheTetrahedralReferenceOnTheGridsCells) {
  // Trilinear interpolation of a linear function is that function, as is the tetrahedral
  // one: two independent references must agree.
  const RegularGrid g = skewedGrid();
  std::vector<double> values(g.pointCount());
  for (std::size_t k = 0; k < g.dims[2]; ++k)
    for (std::size_t j = 0; j < g.dims[1]; ++j)
      for (std::size_t i = 0; i < g.dims[0]; ++i) {
        const glm::dvec3 p = g.position(double(i), double(j), double(k));
        values[g.pointIndex(i, j, k)] = 0.4 * (p.x - 10.0) + 0.3 * (p.y + 3.0) - 0.5 * (p.z - 2.0) + 2.0;
      }
  const TetMesh tets = tetrahedralize(hexahedraOfGrid(g));
  std::vector<double> tetValues(tets.mesh.nodeCount());
  for (std::size_t n = 0; n < tetValues.size(); ++n) {
    const glm::dvec3 p = tets.mesh.nodes[n];
    tetValues[n] = 0.4 * (p.x - 10.0) + 0.3 * (p.y + 3.0) - 0.5 * (p.z - 2.0) + 2.0;
  }
  const Camera camera = gridCamera(g);
  optics::RaySettings settings;
  settings.isoSurfaces = {{3.0, {1.0, 0.8, 0.2}, 0.6}};
  settings.clipPlanes = {{g.bounds().center(), {0.2, 1.0, 0.3}}};
  const auto grid = optics::renderGridReference(g, values, kGridTf, camera, 48, 48, settings);
  const auto tet = optics::renderReference(optics::TetVolume(tets.mesh, FieldLocation::Node, tetValues), kGridTf,
                                           camera, 48, 48, settings);
  double worst = 0.0;
  for (std::size_t i = 0; i < grid.pixels.size(); ++i)
    for (int c = 0; c < 4; ++c) worst = std::max(worst, std::abs(grid.pixels[i][c] - tet.pixels[i][c]));
  std::printf("grid reference vs tetrahedral reference, linear field: max %.3g\n", worst);
  EXPECT_LE(worst, 1e-12);  // quadrature against series and root finding: both near double's limits
}

TEST_F(GridMarch, ConvergesToTheReferenceAtSecondOrderInItsStep) {
  const RegularGrid g = skewedGrid();
  const std::vector<double> values = wavyValues(g);
  const Camera camera = gridCamera(g);
  const ImageError half = marchAgainstReference(g, values, 0.3, camera, 64);  // the default: half the shortest spacing
  const ImageError eighth = marchAgainstReference(g, values, 0.075, camera, 64);
  std::printf("texture ray marching vs trilinear reference: step 0.3 RMSE %.3g max %.3g; step 0.075 RMSE %.3g max %.3g\n",
              half.rmse, half.max, eighth.rmse, eighth.max);
  EXPECT_LE(half.rmse, 3e-3);
  EXPECT_LE(half.max, 3e-2);
  EXPECT_LE(eighth.rmse, half.rmse / 8.0);  // second order: 16x in theory
  EXPECT_LE(eighth.rmse, 2e-4);
}

TEST_F(GridMarch, ManyPassesPerFrameGiveTheSamePictureAsFew) {
  const RegularGrid g = skewedGrid();
  const std::vector<double> values = wavyValues(g);
  const Camera camera = gridCamera(g);
  // A step so short that a ray takes several passes of kStepsPerPass steps.
  const ImageError fine = marchAgainstReference(g, values, 0.005, camera, 32);
  EXPECT_GT(marcher().lastPasses(), 1);
  std::printf("texture ray marching, step 0.005 in %d passes: RMSE %.3g max %.3g\n", marcher().lastPasses(), fine.rmse,
              fine.max);
  EXPECT_LE(fine.rmse, 2e-5);
  EXPECT_LE(fine.max, 2e-4);
}

TEST_F(GridMarch, TheWindowGetsAQuickFrameAndTheFullOneInSlicesOfPassesThatEqualsTheSynchronousFrame) {
  const RegularGrid g = skewedGrid();
  const std::vector<double> values = wavyValues(g);
  Camera camera = gridCamera(g);
  marcher().setGrid(g, values);
  marcher().setTransferFunction(kGridTf);
  marcher().setSamplingStep(0.005);  // several passes per frame
  marcher().setTerminationThreshold(0.0);
  const std::vector<float> synchronous = gpuImage(camera, 48, 40);
  const int passes = marcher().lastPasses();
  ASSERT_GT(passes, 2);
  marcher().setAsynchronousUpdates(true);
  marcher().setFrameBudget(1e-3, 1e-3);  // as if every frame were slow: one pass per call
  (void)gpuImage(camera, 48, 40);
  EXPECT_GT(marcher().shownReduction(), 1) << "a quick frame first";
  int calls = 1;
  for (; calls < 1000 && marcher().hasPendingWork(); ++calls) (void)gpuImage(camera, 48, 40);
  ASSERT_FALSE(marcher().hasPendingWork());
  EXPECT_EQ(calls, passes + 1) << "one pass per call after the quick frame";
  EXPECT_EQ(gpuImage(camera, 48, 40), synchronous) << "the refined frame is the synchronous one";
  camera.orbit(8.0, 0.0);
  (void)gpuImage(camera, 48, 40);
  EXPECT_TRUE(marcher().hasPendingWork()) << "another view starts over";
  marcher().setAsynchronousUpdates(false);
}

TEST_F(GridMarch, ClipPlanesAndIsoSurfacesMatchTheReference) {
  const RegularGrid g = skewedGrid();
  const std::vector<double> values = wavyValues(g);
  optics::RaySettings settings;
  settings.clipPlanes = {{g.bounds().center(), {0.3, -1.0, 0.2}}};
  settings.isoSurfaces = {{4.2, {1.0, 0.7, 0.1}, 0.5}};
  const ImageError e = marchAgainstReference(g, values, 0.05, gridCamera(g), 64, settings);
  std::printf("texture ray marching with a clip plane and an iso-surface: RMSE %.3g max %.3g\n", e.rmse, e.max);
  EXPECT_LE(e.rmse, 2e-3);  // the surface's position and shading within a step of 1/12 spacing
  EXPECT_LE(e.max, 0.1);
}

TEST_F(GridMarch, SamplingModeAndOrthographicViewsToo) {
  const RegularGrid g = skewedGrid();
  const std::vector<double> values = wavyValues(g);
  Camera camera = gridCamera(g);
  camera.setProjection(Camera::Projection::Orthographic);
  marcher().setIntegrationMode(IntegrationMode::Sampling);
  const ImageError e = marchAgainstReference(g, values, 0.05, camera, 48);
  std::printf("texture ray marching, sampling step 0.05, orthographic: RMSE %.3g max %.3g\n", e.rmse, e.max);
  EXPECT_LE(e.rmse, 1e-3);
  EXPECT_LE(e.max, 1e-2);
}

TEST_F(GridMarch, RefusesMeshesAndWrongValueCounts) {
  const Mesh tets = test::tetGrid(2, 2, 2);
  EXPECT_THROW(marcher().setVolume(tets, FieldLocation::Node, field(tets)), std::invalid_argument);
  const RegularGrid g = skewedGrid();
  EXPECT_THROW(marcher().setGrid(g, std::vector<double>(5, 1.0)), std::invalid_argument);
  RegularGrid flat = g;
  flat.dims = {9, 1, 6};
  EXPECT_THROW(marcher().setGrid(flat, std::vector<double>(54, 1.0)), std::invalid_argument);
}

// ---- the CPU marcher (renderer "cpu" on grids) -----------------------------------------

namespace {

ImageError cpuAgainstReference(const RegularGrid& g, const std::vector<double>& values, const TransferFunction& tf,
                               double step, const Camera& camera, int size, const optics::RaySettings& settings = {},
                               volume::CpuRenderStats* stats = nullptr) {
  volume::CpuRaySettings cpu;
  cpu.clipPlanes = settings.clipPlanes;
  cpu.isoSurfaces = settings.isoSurfaces;
  cpu.shading = settings.shading;
  cpu.terminationTransmittance = 0.0;
  const volume::CpuImage image =
      volume::renderCpuGrid(volume::GridSamples(g, values), tf, camera, size, size, cpu, step);
  if (stats) *stats = image.stats;
  return RayCast::compare(image.rgba, optics::renderGridReference(g, values, tf, camera, size, size, settings));
}

}  // namespace

TEST(CpuGridMarch, ConvergesToTheReferenceAtSecondOrderInItsStep) {
  const RegularGrid g = skewedGrid();
  const std::vector<double> values = wavyValues(g);
  const Camera camera = gridCamera(g);
  const ImageError half = cpuAgainstReference(g, values, kGridTf, 0.0, camera, 64);  // default: half the shortest spacing
  const ImageError eighth = cpuAgainstReference(g, values, kGridTf, 0.075, camera, 64);
  std::printf("cpu grid march vs trilinear reference: default step RMSE %.3g max %.3g; step 0.075 RMSE %.3g max %.3g\n",
              half.rmse, half.max, eighth.rmse, eighth.max);
  EXPECT_LE(half.rmse, 3e-3);
  EXPECT_LE(half.max, 3e-2);
  EXPECT_LE(eighth.rmse, half.rmse / 8.0);
  EXPECT_LE(eighth.rmse, 2e-4);
}

TEST(CpuGridMarch, SkipsBricksTheTransferFunctionHidesWithoutChangingThePicture) {
  // 40 x 30 x 24 points (5 x 4 x 3 bricks); only values above 4.5 are visible.
  RegularGrid g;
  g.dims = {40, 30, 24};
  g.origin = {0, 0, 0};
  g.axes = {glm::dvec3(0.25, 0, 0), glm::dvec3(0, 0.25, 0), glm::dvec3(0, 0, 0.25)};
  std::vector<double> values(g.pointCount());
  for (std::size_t k = 0; k < g.dims[2]; ++k)
    for (std::size_t j = 0; j < g.dims[1]; ++j)
      for (std::size_t i = 0; i < g.dims[0]; ++i) {
        const glm::dvec3 p = g.position(double(i), double(j), double(k)) - glm::dvec3(7.0, 5.0, 3.0);
        values[g.pointIndex(i, j, k)] = 6.0 * std::exp(-glm::dot(p, p) / 2.0);  // a blob in one corner
      }
  const TransferFunction peak({{4.5, {1, 0.5, 0.2}, 0.0}, {6.0, {1, 1, 0.5}, 3.0}});
  const TransferFunction everywhere({{0.0, {1, 0.5, 0.2}, 0.01}, {6.0, {1, 1, 0.5}, 3.0}});
  const Camera camera = gridCamera(g);
  volume::CpuRenderStats skipping, walking;
  const ImageError e = cpuAgainstReference(g, values, peak, 0.05, camera, 64, {}, &skipping);
  (void)cpuAgainstReference(g, values, everywhere, 0.05, camera, 64, {}, &walking);
  std::printf("cpu grid march, sharp peak in one corner: RMSE %.3g max %.3g; %zu steps (%zu with nothing to skip)\n",
              e.rmse, e.max, skipping.steps, walking.steps);
  EXPECT_LE(e.rmse, 2e-4);
  EXPECT_LE(e.max, 5e-3);
  EXPECT_LT(skipping.steps * 3, walking.steps);  // most of the box is crossed a brick at a time
}

TEST(CpuGridMarch, ClipPlanesAndIsoSurfacesMatchTheReference) {
  const RegularGrid g = skewedGrid();
  const std::vector<double> values = wavyValues(g);
  optics::RaySettings settings;
  settings.clipPlanes = {{g.bounds().center(), {0.3, -1.0, 0.2}}};
  settings.isoSurfaces = {{4.2, {1.0, 0.7, 0.1}, 0.5}};
  const ImageError e = cpuAgainstReference(g, values, kGridTf, 0.05, gridCamera(g), 64, settings);
  std::printf("cpu grid march with a clip plane and an iso-surface: RMSE %.3g max %.3g\n", e.rmse, e.max);
  EXPECT_LE(e.rmse, 2e-3);
  EXPECT_LE(e.max, 0.1);
}

TEST_F(GridMarch, TheCpuAndGpuMarchersAgreeAndTheCpuRendererConvergesToItsFullFrame) {
  const RegularGrid g = skewedGrid();
  const std::vector<double> values = wavyValues(g);
  const Camera camera = gridCamera(g);
  marcher().setGrid(g, values);
  marcher().setTransferFunction(kGridTf);
  marcher().setTerminationThreshold(0.0);
  const std::vector<float> gpu = gpuImage(camera, 64, 64);

  volume::CpuVolumeRenderer cpu;
  cpu.initialize();
  cpu.setGrid(g, values);
  cpu.setTransferFunction(kGridTf);
  cpu.setTerminationThreshold(0.0);
  const std::vector<float> full = imageOf(cpu, camera, 64, 64);
  double worst = 0.0;
  for (std::size_t i = 0; i < gpu.size(); ++i) worst = std::max(worst, std::abs(double(gpu[i]) - full[i]));
  std::printf("cpu vs gpu grid march, same step: max %.3g\n", worst);
  EXPECT_LE(worst, 1e-4);  // the same lattice and pieces; float on the GPU, exact psi on the CPU

  cpu.setAsynchronousUpdates(true);
  cpu.setQuickFrameBudget(0.001);  // forces a reduced frame first
  cpu.setTransferFunction(TransferFunction(kGridTf.points()));  // a change: a new frame
  Camera moved = camera;
  moved.orbit(5.0, 0.0);
  (void)imageOf(cpu, moved, 64, 64);
  EXPECT_GT(cpu.shownReduction(), 1);
  for (int i = 0; i < 500 && cpu.hasPendingWork(); ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
    (void)imageOf(cpu, moved, 64, 64);
  }
  const std::vector<float> converged = imageOf(cpu, moved, 64, 64);
  EXPECT_EQ(cpu.shownReduction(), 1);
  cpu.setAsynchronousUpdates(false);
  cpu.setTransferFunction(TransferFunction(kGridTf.points()));
  EXPECT_EQ(converged, imageOf(cpu, moved, 64, 64));
  cpu.release();
}

// Samples as the file stored them (8/16-bit integers, 32-bit floats) are drawn from their
// own type: the same picture as their values in doubles, on the GPU and the CPU, through
// setGrid and setGridValues alike, with no double copy made on the way.
TEST_F(GridMarch, StoredSampleTypesDrawTheSamePictureAsTheirValuesInDoubles) {
  const RegularGrid g = skewedGrid();
  const std::vector<double> wavy = wavyValues(g);
  const Camera camera = gridCamera(g);
  struct Case {
    SampleType type;
    double scale, offset;  // stored = round((wavy + offset) * scale) for integers
  };
  for (const Case c : {Case{SampleType::Int8, 30.0, -3.7}, Case{SampleType::UInt8, 30.0, 0.0},
                       Case{SampleType::Int16, 3000.0, -3.0}, Case{SampleType::UInt16, 5000.0, 0.0},
                       Case{SampleType::Int32, 1e5, 0.0}, Case{SampleType::Float32, 1.0, 0.0}}) {
    SCOPED_TRACE(toString(c.type));
    SampleArray stored(c.type, wavy.size());
    for (std::size_t i = 0; i < wavy.size(); ++i) {
      const double v = (wavy[i] + c.offset) * c.scale;
      stored.set(i, c.type == SampleType::Float32 ? v : std::round(v));
    }
    const std::vector<double> doubles = stored.toDoubles();
    std::vector<ControlPoint> points = kGridTf.points();
    for (ControlPoint& p : points) p.value = (p.value + c.offset) * c.scale;
    const TransferFunction tf(points);

    marcher().setTransferFunction(tf);
    marcher().setTerminationThreshold(0.0);
    marcher().setGrid(g, doubles);
    const std::vector<float> fromDoubles = gpuImage(camera, 48, 48);
    marcher().setGrid(g, stored);
    EXPECT_EQ(gpuImage(camera, 48, 48), fromDoubles) << "GPU, setGrid";
    marcher().setGrid(g, wavy);
    marcher().setGridValues(stored);
    EXPECT_EQ(gpuImage(camera, 48, 48), fromDoubles) << "GPU, setGridValues";

    volume::CpuVolumeRenderer cpu;
    cpu.initialize();
    cpu.setTransferFunction(tf);
    cpu.setTerminationThreshold(0.0);
    cpu.setGrid(g, doubles);
    const std::vector<float> cpuFromDoubles = imageOf(cpu, camera, 48, 48);
    cpu.setGrid(g, stored);
    EXPECT_EQ(imageOf(cpu, camera, 48, 48), cpuFromDoubles) << "CPU, setGrid";
    cpu.setGrid(g, wavy);
    cpu.setGridValues(stored);
    EXPECT_EQ(imageOf(cpu, camera, 48, 48), cpuFromDoubles) << "CPU, setGridValues";
    cpu.release();
  }
  EXPECT_THROW(marcher().setGridValues(std::vector<double>(3, 0.0)), std::invalid_argument);
}

// ---- view-aligned slices ----------------------------------------------------------------

TEST(SlicePolygons, CutTheBoxBackToFrontOnALatticeOfDepths) {
  // The unit cube seen along +z from z = -5: planes at depths 6, 5.75, 5.5, 5.25 (z = 1 .. 0.25)
  // cut squares, farthest first (the one at 6 is the back face).
  std::size_t slices = 0;
  const std::vector<glm::vec3> t = volume::slicePolygons({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.5, 0.5, -5.0},
                                                        {0, 0, 1}, 0.25, 0.0, &slices);
  EXPECT_EQ(slices, 4u);
  ASSERT_EQ(t.size(), 4u * 2u * 3u);  // two triangles per square
  EXPECT_FLOAT_EQ(t.front().z, 1.0f);
  EXPECT_FLOAT_EQ(t.back().z, 0.25f);
  double area = 0.0;
  for (std::size_t i = 0; i < t.size(); i += 3) area += 0.5 * glm::length(glm::cross(glm::dvec3(t[i + 1] - t[i]), glm::dvec3(t[i + 2] - t[i])));
  EXPECT_NEAR(area, 4.0, 1e-6);
  // Seen along a diagonal, each cut is a triangle or hexagon inside the cube.
  const std::vector<glm::vec3> d = volume::slicePolygons({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-3, -3, -3},
                                                        glm::normalize(glm::dvec3(1, 1, 1)), 0.1, 0.0, &slices);
  EXPECT_EQ(slices, 18u);  // depths 5.2 .. 6.9 lie inside the cube (5.196 .. 6.928)
  for (const glm::vec3& p : d)
    for (int a = 0; a < 3; ++a) EXPECT_TRUE(p[a] >= -1e-6f && p[a] <= 1.0f + 1e-6f);
}

class GridSlices : public GridMarch {
 protected:
  std::unique_ptr<VolumeRenderer> makeRenderer() const override { return std::make_unique<volume::GridSlicer>(); }
  volume::GridSlicer& slicer() { return static_cast<volume::GridSlicer&>(*caster_); }
};

TEST_F(GridSlices, ConvergeToTheReferenceAsTheSlicesCloseUp) {
  const RegularGrid g = skewedGrid();
  const std::vector<double> values = wavyValues(g);
  const Camera camera = gridCamera(g);
  const ImageError coarse = marchAgainstReference(g, values, 0.3, camera, 64);
  const std::size_t coarseSlices = slicer().lastSlices();
  const ImageError fine = marchAgainstReference(g, values, 0.075, camera, 64);
  std::printf("texture slices vs trilinear reference: spacing 0.3 (%zu slices) RMSE %.3g max %.3g; spacing 0.075 (%zu "
              "slices) RMSE %.3g max %.3g\n",
              coarseSlices, coarse.rmse, coarse.max, slicer().lastSlices(), fine.rmse, fine.max);
  EXPECT_GT(slicer().lastSlices(), 3 * coarseSlices);
  EXPECT_LE(coarse.rmse, 3e-3);
  EXPECT_LE(coarse.max, 5e-2);
  EXPECT_LE(fine.rmse, coarse.rmse / 8.0);
  EXPECT_LE(fine.rmse, 2e-4);
}

TEST_F(GridSlices, ClipPlanesIsoSurfacesAndOrthographicViews) {
  const RegularGrid g = skewedGrid();
  const std::vector<double> values = wavyValues(g);
  optics::RaySettings settings;
  settings.clipPlanes = {{g.bounds().center(), {0.3, -1.0, 0.2}}};
  settings.isoSurfaces = {{4.2, {1.0, 0.7, 0.1}, 0.5}};
  const ImageError e = marchAgainstReference(g, values, 0.05, gridCamera(g), 64, settings);
  Camera ortho = gridCamera(g);
  ortho.setProjection(Camera::Projection::Orthographic);
  const ImageError o = marchAgainstReference(g, values, 0.05, ortho, 48);
  std::printf("texture slices, clip plane + iso-surface: RMSE %.3g max %.3g; orthographic: RMSE %.3g max %.3g\n",
              e.rmse, e.max, o.rmse, o.max);
  EXPECT_LE(e.rmse, 2e-3);
  EXPECT_LE(e.max, 0.1);
  EXPECT_LE(o.rmse, 1e-4);
  EXPECT_LE(o.max, 2e-3);
  EXPECT_THROW(slicer().setVolume(test::tetGrid(2, 2, 2), FieldLocation::Node, field(test::tetGrid(2, 2, 2))),
               std::invalid_argument);
}

// From inside the grid (or close to it) the slices are spherical shells round the eye: every
// ray is cut at the same distances from the eye as the ray marcher's lattice, so the two
// pictures agree to float rounding (the slicer blends back to front, the marcher
// accumulates front to back), and both converge to the reference; from afar, planes.
TEST_F(GridSlices, FromInsideTheGridTheSlicesAreShellsThatGiveTheRayMarchersPicture) {
  const RegularGrid g = skewedGrid();
  const std::vector<double> values = wavyValues(g);
  Camera inside = gridCamera(g);
  inside.place(g.position(4.0, 3.0, 2.5), inside.rotation(), 0.6);
  const ImageError e = marchAgainstReference(g, values, 0.1, inside, 48);
  ASSERT_TRUE(slicer().lastUsedShells());
  const std::vector<float> shells = gpuImage(inside, 48, 48);
  volume::GridRayMarcher marcher;
  marcher.initialize();
  marcher.setGrid(g, values);
  marcher.setTransferFunction(kGridTf);
  marcher.setSamplingStep(0.1);
  marcher.setTerminationThreshold(0.0);
  const std::vector<float> marched = imageOf(marcher, inside, 48, 48);
  marcher.release();
  double worst = 0.0, alpha = 0.0;
  for (std::size_t i = 0; i < shells.size(); ++i) worst = std::max(worst, std::abs(double(shells[i]) - marched[i]));
  for (std::size_t i = 3; i < shells.size(); i += 4) alpha += shells[i] / double(shells.size() / 4);
  std::printf("texture slices from inside the grid (shells): RMSE %.3g max %.3g vs the reference; max %.3g vs the ray "
              "marcher (mean alpha %.2f)\n",
              e.rmse, e.max, worst, alpha);
  EXPECT_GT(alpha, 0.2);
  EXPECT_LE(worst, 1e-4);
  EXPECT_LE(e.rmse, 1e-3);
  (void)marchAgainstReference(g, values, 0.1, gridCamera(g), 32);
  EXPECT_FALSE(slicer().lastUsedShells()) << "from afar, planes";
}

// In the window: a quick reduced frame, then the full one in runs of slices over several
// calls, which is the synchronous frame bit for bit (the same triangles, blended in the
// same order); a clip plane moved (a new scene) starts over.
TEST_F(GridSlices, TheWindowGetsAQuickFrameAndTheFullOneInRunsOfSlicesThatEqualsTheSynchronousFrame) {
  const RegularGrid g = skewedGrid();
  const std::vector<double> values = wavyValues(g);
  const Camera camera = gridCamera(g);
  slicer().setGrid(g, values);
  slicer().setTransferFunction(kGridTf);
  slicer().setSamplingStep(0.004);
  slicer().setTerminationThreshold(0.0);
  const std::vector<float> synchronous = gpuImage(camera, 48, 40);
  ASSERT_GT(slicer().lastSlices(), 1000u);
  slicer().setAsynchronousUpdates(true);
  slicer().setFrameBudget(1e-3, 1e-3);  // as if every frame were slow: one run per call
  (void)gpuImage(camera, 48, 40);
  EXPECT_GT(slicer().shownReduction(), 1) << "a quick frame first";
  int calls = 1;
  for (; calls < 100000 && slicer().hasPendingWork(); ++calls) (void)gpuImage(camera, 48, 40);
  ASSERT_FALSE(slicer().hasPendingWork());
  EXPECT_GT(calls, 3) << "the full frame took several calls";
  EXPECT_EQ(slicer().shownReduction(), 1);
  EXPECT_EQ(gpuImage(camera, 48, 40), synchronous) << "the refined frame is the synchronous one";
  slicer().setClipPlanes({{g.bounds().center(), {0.3, -1.0, 0.2}}});
  (void)gpuImage(camera, 48, 40);
  EXPECT_TRUE(slicer().hasPendingWork()) << "a moved plane starts over";
  slicer().setAsynchronousUpdates(false);
}

// ---- shading by the gradient ------------------------------------------------------------

TEST(GridReference, ShadingDarkensWhereTheGradientTurnsAwayFromTheEye) {
  // A field rising along x, seen along x: the gradient faces the eye, full light (1.0 + 0.3
  // white); seen along y: the gradient is across the ray, ambient only (0.3).
  RegularGrid g;
  g.dims = {6, 6, 6};
  std::vector<double> values(g.pointCount());
  for (std::size_t n = 0; n < values.size(); ++n) values[n] = double(n % 6);
  const TransferFunction grey({{0.0, {0.5, 0.5, 0.5}, 0.3}, {5.0, {0.5, 0.5, 0.5}, 0.3}});
  optics::RaySettings lit;
  lit.shading = true;
  const auto along = [&](glm::dvec3 origin, glm::dvec3 dir, const optics::RaySettings& s) {
    return optics::integrateGridRay(g, values, grey, origin, dir, 0.0, 100.0, s);
  };
  const optics::SegmentLight plain = along({-10, 2.5, 2.5}, {1, 0, 0}, {});
  const optics::SegmentLight facing = along({-10, 2.5, 2.5}, {1, 0, 0}, lit);
  const optics::SegmentLight across = along({2.5, -10, 2.5}, {0, 1, 0}, lit);
  const double alpha = 1.0 - plain.transmittance;
  EXPECT_NEAR(plain.color.r, 0.5 * alpha, 1e-12);
  EXPECT_NEAR(facing.color.r, (0.5 * 1.0 + 0.3) * alpha, 1e-12);
  EXPECT_NEAR(across.color.r, 0.5 * 0.3 * alpha, 1e-12);
  EXPECT_EQ(facing.transmittance, plain.transmittance);  // light changes the color, not the opacity
}

TEST_F(GridMarch, ShadedPicturesConvergeToTheShadedReference) {
  const RegularGrid g = skewedGrid();
  const std::vector<double> values = wavyValues(g);
  optics::RaySettings lit;
  lit.shading = true;
  const ImageError coarse = marchAgainstReference(g, values, 0.3, gridCamera(g), 64, lit);
  const ImageError fine = marchAgainstReference(g, values, 0.075, gridCamera(g), 64, lit);
  const ImageError cpu = cpuAgainstReference(g, values, kGridTf, 0.075, gridCamera(g), 64, lit);
  std::printf("shaded texture ray marching vs shaded reference: step 0.3 RMSE %.3g max %.3g; step 0.075 RMSE %.3g "
              "max %.3g; cpu at 0.075 RMSE %.3g max %.3g\n",
              coarse.rmse, coarse.max, fine.rmse, fine.max, cpu.rmse, cpu.max);
  // Second order: the trilinear gradient jumps across cell faces, so the pieces are cut
  // there too and both ends of a piece take its own cell's gradient (before that cut the
  // error was first order: 1.4e-3 and 3.4e-4 at these steps).
  EXPECT_LE(coarse.rmse, 5e-4);
  EXPECT_LE(fine.rmse, coarse.rmse / 8.0);
  EXPECT_LE(fine.rmse, 5e-5);
  EXPECT_LE(cpu.rmse, 5e-5);
}

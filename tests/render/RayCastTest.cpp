// SPDX-License-Identifier: MIT
// The GPU ray caster (headless EGL) against the exact CPU reference renderer, with stated
// error bounds per integration mode, and the hard cases: no pixel lost on axis-aligned
// views of a tetrahedralized grid, clip planes, element results, a far-away tiny mesh.
#include "../TestSupport.hpp"
#include "../core/TetGrid.hpp"
#include "../meshio/ReaderSupport.hpp"

#include "CellProjector.hpp"
#include "RayCaster.hpp"

#include <volpost/core/Quantity.hpp>
#include <volpost/core/optics/ReferenceRenderer.hpp>
#include <volpost/render/HeadlessContext.hpp>
#include <volpost/render/OffscreenTarget.hpp>

#include <glm/gtc/matrix_inverse.hpp>
#include <gtest/gtest.h>

#include <chrono>
#include <functional>
#include <cmath>
#include <thread>
#include <memory>

using namespace volpost;

namespace {

struct ImageError {
  double rmse = 0.0, max = 0.0;
};

class RayCast : public ::testing::Test {
 protected:
  void SetUp() override {
    try {
      context_ = std::make_unique<HeadlessContext>();
    } catch (const std::exception& e) {
      GTEST_SKIP() << "not run: no headless OpenGL 4.5 context: " << e.what();
    }
    caster_ = makeRenderer();
    caster_->initialize();
  }
  virtual std::unique_ptr<volume::RayCaster> makeRenderer() const { return std::make_unique<volume::RayCaster>(); }
  void TearDown() override {
    if (context_ && caster_) caster_->release();
  }

  std::vector<float> gpuImage(const Camera& camera, int w, int h, float sceneDepth = 1.0f) {
    return imageOf(*caster_, camera, w, h, sceneDepth);
  }

  static std::vector<float> imageOf(volume::RayCaster& renderer, const Camera& camera, int w, int h, float sceneDepth = 1.0f) {
    OffscreenTarget target(w, h);
    glClearNamedFramebufferfv(target.framebuffer(), GL_DEPTH, 0, &sceneDepth);
    RenderContext ctx;
    ctx.depthTexture = sceneDepth < 1.0f ? target.depthTexture() : 0;
    ctx.camera = camera;
    ctx.width = w;
    ctx.height = h;
    ctx.framebuffer = target.framebuffer();
    glBindFramebuffer(GL_FRAMEBUFFER, ctx.framebuffer);
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    renderer.render(ctx);
    glFinish();
    return renderer.readImage();
  }

  static ImageError compare(const std::vector<float>& gpu, const optics::ReferenceImage& ref) {
    ImageError e;
    double sum = 0.0;
    for (std::size_t i = 0; i < ref.pixels.size(); ++i)
      for (int k = 0; k < 4; ++k) {
        const double d = double(gpu[4 * i + std::size_t(k)]) - ref.pixels[i][k];
        sum += d * d;
        e.max = std::max(e.max, std::abs(d));
      }
    e.rmse = std::sqrt(sum / double(ref.pixels.size() * 4));
    return e;
  }

  ImageError againstReference(const Mesh& mesh, FieldLocation loc, const std::vector<double>& values,
                              const TransferFunction& tf, const Camera& camera, int size,
                              const std::vector<ClipPlane>& clips = {}) {
    caster_->setVolume(mesh, loc, values);
    caster_->setTransferFunction(tf);
    caster_->setClipPlanes(clips);
    caster_->setTerminationThreshold(0.0);
    const auto gpu = gpuImage(camera, size, size);
    const optics::TetVolume volume(mesh, loc, values);
    optics::RaySettings settings;
    settings.clipPlanes = clips;
    return compare(gpu, optics::renderReference(volume, tf, camera, size, size, settings));
  }

  // A constant field on the Kuhn grid [0,4]^3 seen where rays are degenerate: along the
  // axes (odd image sizes put rays exactly on grid planes and along columns of edges) and
  // along the diagonal, orthographic and perspective (rays along chains of tet edges and
  // through vertices). Each pixel must show 1 - exp(-tau L), L the ray's exact length in
  // the box (in double here); pixels whose ray grazes the box's own faces are left out.
  // Returns how many pixels are off by more than 1e-3.
  int lostPixelsOnDegenerateViews() {
    const Mesh grid = test::tetGrid(4, 4, 4);
    const double tau = 0.3;
    caster_->setIntegrationMode(IntegrationMode::LinearSegments);
    caster_->setVolume(grid, FieldLocation::Node, std::vector<double>(grid.nodeCount(), 1.0));
    caster_->setTransferFunction(TransferFunction({{0.0, {1, 1, 1}, tau}, {2.0, {1, 1, 1}, tau}}));
    caster_->setTerminationThreshold(0.0);
    int lost = 0;
    const std::pair<StandardView, Camera::Projection> views[] = {
        {StandardView::PlusZ, Camera::Projection::Orthographic},  {StandardView::MinusZ, Camera::Projection::Orthographic},
        {StandardView::PlusX, Camera::Projection::Orthographic},  {StandardView::MinusX, Camera::Projection::Orthographic},
        {StandardView::PlusY, Camera::Projection::Orthographic},  {StandardView::MinusY, Camera::Projection::Orthographic},
        {StandardView::Isometric, Camera::Projection::Orthographic}, {StandardView::Isometric, Camera::Projection::Perspective}};
    for (auto [view, projection] : views) {
      for (int size : {33, 65}) {
        Camera camera;
        camera.setProjection(projection);
        camera.setView(view);
        camera.fit(grid.bounds());
        const auto image = gpuImage(camera, size, size);
        const glm::dmat4 toModel = glm::inverse(camera.projectionMatrix(1.0) * camera.viewMatrix());
        const auto lengthInBox = [&](double x, double y) {
          const glm::dvec4 n = toModel * glm::dvec4(2.0 * x / size - 1.0, 1.0 - 2.0 * y / size, -1.0, 1.0);
          const glm::dvec4 f = toModel * glm::dvec4(2.0 * x / size - 1.0, 1.0 - 2.0 * y / size, 1.0, 1.0);
          const glm::dvec3 o = glm::dvec3(n) / n.w, d = glm::normalize(glm::dvec3(f) / f.w - o);
          double t0 = -1e300, t1 = 1e300;
          for (int k = 0; k < 3; ++k) {
            if (d[k] == 0.0) {
              if (o[k] < 0.0 || o[k] > 4.0) return 0.0;
              continue;
            }
            const double a = (0.0 - o[k]) / d[k], b = (4.0 - o[k]) / d[k];
            t0 = std::max(t0, std::min(a, b));
            t1 = std::min(t1, std::max(a, b));
          }
          return std::max(0.0, t1 - t0);
        };
        int checked = 0, lostHere = 0;
        for (int y = 0; y < size; ++y)
          for (int x = 0; x < size; ++x) {
            const double length = lengthInBox(x + 0.5, y + 0.5);
            bool grazing = false;  // the box's own silhouette: the length jumps there
            for (auto [dx, dy] : {std::pair{1e-3, 0.0}, {-1e-3, 0.0}, {0.0, 1e-3}, {0.0, -1e-3}})
              grazing = grazing || std::abs(lengthInBox(x + 0.5 + dx, y + 0.5 + dy) - length) > 1e-2;
            if (grazing) continue;
            ++checked;
            const double expected = 1.0 - std::exp(-tau * length);
            const float a = image[std::size_t(y * size + x) * 4 + 3];
            if (std::abs(a - expected) > 1e-3) {
              ++lostHere;
              ADD_FAILURE() << "view " << int(view) << (projection == Camera::Projection::Orthographic ? " ortho" : " persp")
                            << " size " << size << " pixel (" << x << ", " << y << "): alpha " << a << ", expected " << expected;
            }
          }
        EXPECT_GT(checked, size * size / 4);
        lost += lostHere;
      }
    }
    return lost;
  }

  std::unique_ptr<HeadlessContext> context_;
  std::unique_ptr<volume::RayCaster> caster_;
};

// Cell projection: the same fixture, the tets drawn in visibility order instead of walked.
class CellProjection : public RayCast {
 protected:
  std::unique_ptr<volume::RayCaster> makeRenderer() const override {
    return std::make_unique<volume::CellProjector>(method);
  }
  volume::OrderMethod method = volume::OrderMethod::ImageSpace;
};

std::vector<double> field(const Mesh& m) {
  std::vector<double> v;
  for (const auto& p : m.nodes) v.push_back(p.x + 0.5 * p.z);
  return v;
}

const TransferFunction kTf({{0.0, {0.1, 0.2, 0.9}, 0.05}, {2.0, {0.2, 0.9, 0.3}, 0.6},
                            {3.5, {1.0, 1.0, 1.0}, 1.5}, {6.0, {0.9, 0.1, 0.1}, 0.2}});

Camera isoCamera(const Mesh& m) {
  Camera c;
  c.setView(StandardView::Isometric);
  c.fit(m.bounds());
  c.orbit(17.0, 9.0);
  return c;
}

}  // namespace

TEST_F(RayCast, LinearSegmentsMatchTheReference) {
  const Mesh grid = test::tetGrid(4, 4, 4);
  caster_->setIntegrationMode(IntegrationMode::LinearSegments);
  const ImageError e = againstReference(grid, FieldLocation::Node, field(grid), kTf, isoCamera(grid), 64);
  std::printf("raycast linear-segments vs reference: RMSE %.3g, max %.3g\n", e.rmse, e.max);
  EXPECT_LE(e.rmse, 1e-5);  // float32 and the 512^2 psi table are all that is left
  EXPECT_LE(e.max, 1e-4);
}

TEST_F(RayCast, PreIntegratedAndSamplingAreBoundedToo) {
  const Mesh grid = test::tetGrid(4, 4, 4);
  caster_->setIntegrationMode(IntegrationMode::LinearSegmentsIsoTable);
  const ImageError iso = againstReference(grid, FieldLocation::Node, field(grid), kTf, isoCamera(grid), 64);
  std::printf("raycast linear segments, iso-detection table 256^2 vs reference: RMSE %.3g, max %.3g\n", iso.rmse, iso.max);
  EXPECT_LE(iso.rmse, 2e-3);
  EXPECT_LE(iso.max, 1e-2);
  caster_->setIntegrationMode(IntegrationMode::PreIntegrated);
  const ImageError pre = againstReference(grid, FieldLocation::Node, field(grid), kTf, isoCamera(grid), 64);
  std::printf("raycast pre-integrated 64^3 vs reference: RMSE %.3g, max %.3g\n", pre.rmse, pre.max);
  EXPECT_LE(pre.rmse, 2e-2);
  EXPECT_LE(pre.max, 0.1);
  caster_->setIntegrationMode(IntegrationMode::Sampling);
  caster_->setSamplingStep(0.05);
  const ImageError sampled = againstReference(grid, FieldLocation::Node, field(grid), kTf, isoCamera(grid), 64);
  std::printf("raycast sampling step 0.05 vs reference: RMSE %.3g, max %.3g\n", sampled.rmse, sampled.max);
  EXPECT_LE(sampled.rmse, 2e-4);  // a midpoint rule at 1/20 of the cell size
  EXPECT_LE(sampled.max, 2e-3);
}

TEST_F(RayCast, NoPixelIsLostOnAxisAlignedAndDiagonalViewsOfATetrahedralizedGrid) {
  const int lost = lostPixelsOnDegenerateViews();
  EXPECT_EQ(lost, 0);
}

TEST_F(RayCast, ClipPlanesCutLikeTheReference) {
  const Mesh grid = test::tetGrid(4, 4, 4);
  caster_->setIntegrationMode(IntegrationMode::LinearSegments);
  const std::vector<ClipPlane> clips = {{{0, 0, 1.3}, {0, 0.2, 1}}, {{2.5, 0, 0}, {-1, 0, 0}}};
  const ImageError e = againstReference(grid, FieldLocation::Node, field(grid), kTf, isoCamera(grid), 64, clips);
  std::printf("raycast with 2 clip planes vs reference: RMSE %.3g, max %.3g\n", e.rmse, e.max);
  EXPECT_LE(e.rmse, 1e-5);
  EXPECT_LE(e.max, 1e-4);
}

TEST_F(RayCast, ElementResultsAreConstantPerCell) {
  const Mesh grid = test::tetGrid(3, 3, 3);
  std::vector<double> cells(grid.cellCount());
  for (std::size_t c = 0; c < cells.size(); ++c) cells[c] = double(c % 7);
  caster_->setIntegrationMode(IntegrationMode::LinearSegments);
  const ImageError e = againstReference(grid, FieldLocation::Cell, cells, kTf, isoCamera(grid), 48);
  std::printf("raycast element results vs reference: RMSE %.3g, max %.3g\n", e.rmse, e.max);
  EXPECT_LE(e.rmse, 1e-5);
  EXPECT_LE(e.max, 1e-4);
}

TEST_F(RayCast, FarFromOriginTinyMeshRendersLikeTheReference) {
  const glm::dvec3 offset(1048576.0, -1048576.0, 2097152.0);
  const double cell = 1.0 / 1024.0;
  const Mesh grid = test::tetGrid(4, 4, 4, offset, cell);
  std::vector<double> values;
  for (const auto& p : grid.nodes) values.push_back((p.x - offset.x) / cell + 0.5 * (p.z - offset.z) / cell);
  std::vector<ControlPoint> scaled = kTf.points();
  for (auto& p : scaled) p.extinction /= cell;
  caster_->setIntegrationMode(IntegrationMode::LinearSegments);
  const ImageError e = againstReference(grid, FieldLocation::Node, values, TransferFunction(scaled), isoCamera(grid), 48);
  std::printf("raycast mesh at 1e6 with 1e-3 cells vs reference: RMSE %.3g, max %.3g\n", e.rmse, e.max);
  EXPECT_LE(e.rmse, 1e-5);
  EXPECT_LE(e.max, 1e-4);
}

// Values far from float32's comfort: a concentration of order 1e-38 (where float32 is
// denormal and shader arithmetic flushes to zero) and a field riding on a large offset
// (a temperature of 1e6 + small variations). The same picture must come out as for
// field(), since the transfer function follows the values.
void expectValueScaleInvariance(const char* renderer,
                                const std::function<ImageError(const std::vector<double>&, const TransferFunction&)>& render) {
  const Mesh grid = test::tetGrid(4, 4, 4);
  for (auto [scale, offset] : {std::pair{1e-38, 0.0}, std::pair{1e-6, 1e6}}) {
    std::vector<double> values = field(grid);
    for (double& v : values) v = offset + scale * v;
    std::vector<ControlPoint> points = kTf.points();
    for (ControlPoint& p : points) p.value = offset + scale * p.value;
    const ImageError e = render(values, TransferFunction(points));
    std::printf("%s values x %g + %g vs reference: RMSE %.3g, max %.3g\n", renderer, scale, offset, e.rmse, e.max);
    EXPECT_LE(e.rmse, 1e-5) << scale << " " << offset;
    EXPECT_LE(e.max, 1e-4) << scale << " " << offset;
  }
}

TEST_F(RayCast, TinyAndOffsetValuesRenderLikeTheReference) {
  const Mesh grid = test::tetGrid(4, 4, 4);
  caster_->setIntegrationMode(IntegrationMode::LinearSegments);
  expectValueScaleInvariance("raycast", [&](const std::vector<double>& values, const TransferFunction& tf) {
    return againstReference(grid, FieldLocation::Node, values, tf, isoCamera(grid), 64);
  });
}

TEST_F(RayCast, TransferFunctionEditsDoNotTouchTheMesh) {
  const Mesh grid = test::tetGrid(4, 4, 4);
  caster_->setVolume(grid, FieldLocation::Node, field(grid));
  const std::size_t before = caster_->stats().meshBytes;
  caster_->setTransferFunction(kTf);
  EXPECT_EQ(caster_->stats().meshBytes, before);
  // 32 B per tet (vertex ids, neighbours) + 16 B per node + the boundary BVH; this small
  // grid has many boundary faces per tet (the bench reports ~35 B/tet on real meshes).
  EXPECT_LT(double(before) / double(grid.cellCount()), 56.0);
  EXPECT_GT(caster_->stats().lastTransferFunctionMs, 0.0);
  EXPECT_EQ(caster_->stats().tetrahedra, grid.cellCount());
}

TEST_F(RayCast, AsynchronousPreIntegrationCatchesUpWithTheLatestFunction) {
  // Interactive use: the pre-integrated table is built off the GL thread, frames keep the
  // previous one, rapid changes coalesce; once it is in, the picture is the synchronous one.
  const Mesh grid = test::tetGrid(4, 4, 4);
  const Camera camera = isoCamera(grid);
  caster_->setVolume(grid, FieldLocation::Node, field(grid));
  caster_->setIntegrationMode(IntegrationMode::PreIntegrated);
  caster_->setTerminationThreshold(0.0);
  TransferFunction other = kTf;
  std::vector<ControlPoint> points = kTf.points();
  for (auto& p : points) p.extinction *= 3.0;
  other = TransferFunction(points);
  caster_->setTransferFunction(other);
  const std::vector<float> synchronous = gpuImage(camera, 48, 48);
  caster_->setTransferFunction(kTf);
  caster_->setAsynchronousUpdates(true);
  for (int i = 0; i < 5; ++i) caster_->setTransferFunction(i % 2 ? kTf : other);  // a drag: ends on `other`
  EXPECT_TRUE(caster_->hasPendingWork());
  (void)gpuImage(camera, 48, 48);  // does not wait
  for (int i = 0; i < 2000 && caster_->hasPendingWork(); ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    (void)gpuImage(camera, 48, 48);
  }
  ASSERT_FALSE(caster_->hasPendingWork());
  EXPECT_EQ(gpuImage(camera, 48, 48), synchronous);
  EXPECT_GT(caster_->stats().lastTransferFunctionMs, 0.0);
}

TEST_F(RayCast, RaysReenterANonConvexMeshLikeTheReference) {
  Mesh m;  // three slabs along z with gaps: every ray through them enters three times
  for (int k = 0; k < 3; ++k) {
    const Mesh slab = test::tetGrid(3, 3, 1, {0.0, 0.0, 1.5 * k});
    const NodeIndex base = NodeIndex(m.nodeCount());
    m.nodes.insert(m.nodes.end(), slab.nodes.begin(), slab.nodes.end());
    for (std::size_t c = 0; c < slab.cellCount(); ++c) {
      NodeIndex t[4];
      for (int i = 0; i < 4; ++i) t[i] = slab.cellNodes(c)[std::size_t(i)] + base;
      m.addCell(CellType::Tet4, t);
    }
  }
  caster_->setIntegrationMode(IntegrationMode::LinearSegments);
  const ImageError e = againstReference(m, FieldLocation::Node, field(m), kTf, isoCamera(m), 48);
  std::printf("raycast non-convex (3 slabs) vs reference: RMSE %.3g, max %.3g\n", e.rmse, e.max);
  EXPECT_LE(e.rmse, 2e-3);
  EXPECT_LE(e.max, 1e-2);
}

TEST_F(RayCast, ANewResultUploadsOnlyValues) {
  const Mesh grid = test::tetGrid(4, 4, 4);
  std::vector<double> other;
  for (const auto& p : grid.nodes) other.push_back(4.0 - p.y + 0.3 * p.x);
  caster_->setIntegrationMode(IntegrationMode::LinearSegments);
  caster_->setTerminationThreshold(0.0);
  caster_->setTransferFunction(kTf);
  caster_->setVolume(grid, FieldLocation::Node, field(grid));
  caster_->setValues(other);
  const auto updated = gpuImage(isoCamera(grid), 40, 40);
  caster_->setVolume(grid, FieldLocation::Node, other);
  const auto rebuilt = gpuImage(isoCamera(grid), 40, 40);
  EXPECT_EQ(updated, rebuilt);
  volume::TetMeshGpu gpu = volume::buildTetMeshGpu(grid, FieldLocation::Node, field(grid));
  const auto bvh = gpu.bvh;
  EXPECT_TRUE(volume::replaceValues(gpu, grid, FieldLocation::Node, other));
  EXPECT_EQ(gpu.bvh, bvh);
  EXPECT_FLOAT_EQ(gpu.nodes[7].w, gpu.gpuValue(other[7]));
  other[3] = std::nan("");  // a tet would drop out: the structure must be rebuilt
  EXPECT_FALSE(volume::replaceValues(gpu, grid, FieldLocation::Node, other));
}

TEST_F(RayCast, IsoSurfacesMatchTheReference) {
  const Mesh grid = test::tetGrid(4, 4, 4);
  const std::vector<optics::IsoSurface> isos = {{1.7, {0.9, 0.8, 0.1}, 0.6}, {3.9, {0.1, 0.7, 0.9}, 1.0}};
  caster_->setIntegrationMode(IntegrationMode::LinearSegments);
  caster_->setIsoSurfaces(isos);
  caster_->setVolume(grid, FieldLocation::Node, field(grid));
  caster_->setTransferFunction(kTf);
  caster_->setTerminationThreshold(0.0);
  const Camera camera = isoCamera(grid);
  const auto gpu = gpuImage(camera, 64, 64);
  const optics::TetVolume volume(grid, FieldLocation::Node, field(grid));
  optics::RaySettings settings;
  settings.isoSurfaces = isos;
  const ImageError e = compare(gpu, optics::renderReference(volume, kTf, camera, 64, 64, settings));
  std::printf("raycast with 2 iso-surfaces vs reference: RMSE %.3g, max %.3g\n", e.rmse, e.max);
  EXPECT_LE(e.rmse, 1e-4);
  EXPECT_LE(e.max, 5e-3);
}

TEST_F(RayCast, OpaqueGeometryEndsRaysAtItsDepth) {
  // A constant depth in an orthographic view is a plane facing the camera: the volume
  // behind it must vanish exactly as behind a clip plane there.
  const Mesh grid = test::tetGrid(4, 4, 4);
  Camera camera = isoCamera(grid);
  camera.setProjection(Camera::Projection::Orthographic);
  const float depth = 0.5f;
  caster_->setIntegrationMode(IntegrationMode::LinearSegments);
  caster_->setVolume(grid, FieldLocation::Node, field(grid));
  caster_->setTransferFunction(kTf);
  caster_->setTerminationThreshold(0.0);
  const auto gpu = gpuImage(camera, 64, 64, depth);
  const glm::dvec4 p = glm::inverse(camera.projectionMatrix(1.0) * camera.viewMatrix()) * glm::dvec4(0, 0, 2.0 * depth - 1.0, 1.0);
  optics::RaySettings settings;
  settings.clipPlanes = {{glm::dvec3(p) / p.w, -camera.viewDirection()}};
  const optics::TetVolume volume(grid, FieldLocation::Node, field(grid));
  const ImageError e = compare(gpu, optics::renderReference(volume, kTf, camera, 64, 64, settings));
  std::printf("raycast ended by scene depth vs reference clipped there: RMSE %.3g, max %.3g\n", e.rmse, e.max);
  EXPECT_LE(e.rmse, 1e-4);
  EXPECT_LE(e.max, 5e-3);
}

TEST_F(RayCast, NoRayIsLostOnTheRealWheel) {
  // Regression: at 256 px one ray of the gmsh wheel entered a boundary tet exactly at an
  // edge shared with another boundary face, left through it with no length, and kept
  // re-entering through the same face; the rest of its path was lost.
  VOLPOST_SHARED_OR_SKIP(path, "wheel/tet4/wheel_tet4.vtu");
  const auto model = test::meshioReaders().load(path);
  const Field& s = *model->findField("S_Mises");
  std::vector<double> values = s.values(0);
  const TransferFunction tf = TransferFunction::ramp(0.0, 40.0, "cool-warm", 0.08, 11);
  Camera camera;
  camera.setView(StandardView::Isometric);
  camera.fit(model->mesh.bounds());
  caster_->setIntegrationMode(IntegrationMode::LinearSegments);
  const ImageError e = againstReference(model->mesh, FieldLocation::Node, values, tf, camera, 256);
  std::printf("raycast real wheel 256 px vs reference: RMSE %.3g, max %.3g\n", e.rmse, e.max);
  EXPECT_LE(e.max, 1e-3);
}

TEST_F(CellProjection, ConvexGridMatchesTheReferenceInEveryMode) {
  const Mesh grid = test::tetGrid(4, 4, 4);
  caster_->setIntegrationMode(IntegrationMode::LinearSegments);
  const ImageError linear = againstReference(grid, FieldLocation::Node, field(grid), kTf, isoCamera(grid), 64);
  std::printf("vicp linear-segments vs reference: RMSE %.3g, max %.3g\n", linear.rmse, linear.max);
  EXPECT_LE(linear.rmse, 1e-5);
  EXPECT_LE(linear.max, 1e-4);
  caster_->setIntegrationMode(IntegrationMode::PreIntegrated);
  const ImageError pre = againstReference(grid, FieldLocation::Node, field(grid), kTf, isoCamera(grid), 64);
  std::printf("vicp pre-integrated vs reference: RMSE %.3g, max %.3g\n", pre.rmse, pre.max);
  EXPECT_LE(pre.rmse, 2e-2);
  EXPECT_LE(pre.max, 0.1);
  // Sampling: the samples lie on one lattice along the ray whichever tet takes them, so the
  // picture is the ray caster's, sample for sample.
  caster_->setIntegrationMode(IntegrationMode::Sampling);
  caster_->setSamplingStep(0.05);
  const ImageError sampled = againstReference(grid, FieldLocation::Node, field(grid), kTf, isoCamera(grid), 64);
  const auto projected = gpuImage(isoCamera(grid), 64, 64);
  volume::RayCaster walker;
  walker.initialize();
  walker.setVolume(grid, FieldLocation::Node, field(grid));
  walker.setTransferFunction(kTf);
  walker.setIntegrationMode(IntegrationMode::Sampling);
  walker.setSamplingStep(0.05);
  walker.setTerminationThreshold(0.0);
  const auto walked = imageOf(walker, isoCamera(grid), 64, 64);
  walker.release();
  double apart = 0.0;
  for (std::size_t i = 0; i < walked.size(); ++i) apart = std::max(apart, double(std::abs(walked[i] - projected[i])));
  std::printf("vicp sampling vs raycast sampling: max %.3g\n", apart);
  EXPECT_LE(apart, 1e-4);
  std::printf("vicp sampling step 0.05 vs reference: RMSE %.3g, max %.3g\n", sampled.rmse, sampled.max);
  EXPECT_LE(sampled.rmse, 2e-4);
  EXPECT_LE(sampled.max, 2e-3);
  const auto* projector = dynamic_cast<const volume::CellProjector*>(caster_.get());
  ASSERT_TRUE(projector);
  EXPECT_EQ(projector->lastOrder().backToFront.size(), grid.cellCount());
  EXPECT_GT(caster_->stats().lastSortMs, 0.0);
}

TEST_F(CellProjection, NoPixelIsLostOnAxisAlignedAndDiagonalViewsOfATetrahedralizedGrid) {
  for (volume::OrderMethod order : {volume::OrderMethod::Mpvonc, volume::OrderMethod::ImageSpace}) {
    static_cast<volume::CellProjector*>(caster_.get())->setOrderMethod(order);
    EXPECT_EQ(lostPixelsOnDegenerateViews(), 0) << (order == volume::OrderMethod::Mpvonc ? "MPVONC" : "image-space");
  }
}

TEST_F(CellProjection, TinyAndOffsetValuesRenderLikeTheReference) {
  const Mesh grid = test::tetGrid(4, 4, 4);
  caster_->setIntegrationMode(IntegrationMode::LinearSegments);
  expectValueScaleInvariance("vicp", [&](const std::vector<double>& values, const TransferFunction& tf) {
    return againstReference(grid, FieldLocation::Node, values, tf, isoCamera(grid), 64);
  });
}

TEST_F(CellProjection, ClipPlanesCutLikeTheReference) {
  const Mesh grid = test::tetGrid(4, 4, 4);
  const ImageError clipped = againstReference(grid, FieldLocation::Node, field(grid), kTf, isoCamera(grid), 64,
                                              {{{2.2, 0, 0}, {-1, 0.2, 0}}});
  std::printf("vicp clipped vs reference: RMSE %.3g, max %.3g\n", clipped.rmse, clipped.max);
  EXPECT_LE(clipped.rmse, 1e-5);
  EXPECT_LE(clipped.max, 2e-4);
}

TEST_F(CellProjection, NonConvexRealWheelWithTheImageSpaceOrder) {
  VOLPOST_SHARED_OR_SKIP(path, "wheel/tet4/wheel_tet4.vtu");
  const auto model = test::meshioReaders().load(path);
  const Field& s = *model->findField("S");
  const auto mises = evaluate(s, *parseQuantity("S.mises", s), 0);
  const double lo = *std::min_element(mises.begin(), mises.end()), hi = *std::max_element(mises.begin(), mises.end());
  const double tau = 8.0 / model->mesh.bounds().diagonal();
  const TransferFunction tf({{lo, {0, 0, 1}, 0.2 * tau}, {0.5 * (lo + hi), {1, 1, 1}, tau}, {hi, {1, 0, 0}, 3 * tau}});
  Camera camera;
  camera.fit(model->mesh.bounds());
  camera.setView(StandardView::Isometric);
  camera.orbit(20.0, -10.0);
  const ImageError e = againstReference(model->mesh, FieldLocation::Node, mises, tf, camera, 64);
  std::printf("vicp (image-space order) real wheel 64 px vs reference: RMSE %.3g, max %.3g\n", e.rmse, e.max);
  EXPECT_LE(e.rmse, 1e-5);
  EXPECT_LE(e.max, 1e-4);
}

TEST_F(CellProjection, IsoSurfacesMatchTheReference) {
  const Mesh grid = test::tetGrid(4, 4, 4);
  const std::vector<optics::IsoSurface> surfaces = {{1.5, {1.0, 0.8, 0.1}, 0.6}, {2.5, {0.2, 0.9, 0.3}, 1.0}};
  caster_->setVolume(grid, FieldLocation::Node, field(grid));
  caster_->setTransferFunction(kTf);
  caster_->setIsoSurfaces(surfaces);
  caster_->setTerminationThreshold(0.0);
  const auto gpu = gpuImage(isoCamera(grid), 64, 64);
  optics::RaySettings settings;
  settings.isoSurfaces = surfaces;
  const ImageError e = compare(gpu, optics::renderReference(optics::TetVolume(grid, FieldLocation::Node, field(grid)), kTf,
                                                            isoCamera(grid), 64, 64, settings));
  std::printf("vicp iso-surfaces vs reference: RMSE %.3g, max %.3g\n", e.rmse, e.max);
  EXPECT_LE(e.rmse, 1e-5);
  EXPECT_LE(e.max, 1e-4);
}

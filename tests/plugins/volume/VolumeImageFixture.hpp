// SPDX-License-Identifier: MIT
// The fixture of the volume renderers' image tests: a headless EGL context, a renderer
// (ray caster or cell projection), its image against the exact CPU reference renderer,
// and the lost-pixel check on degenerate views of a tetrahedralized grid.
#pragma once

#include "support/TestSupport.hpp"
#include "support/TetGrid.hpp"
#include "support/ReaderSupport.hpp"

#include "CellProjector.hpp"
#include "CpuVolumeRenderer.hpp"
#include "RayCaster.hpp"
#include "TetVolumeRenderer.hpp"

#include <volpost/core/Quantity.hpp>
#include "host/optics/ReferenceRenderer.hpp"
#include <volpost/render/HeadlessContext.hpp>
#include <volpost/render/OffscreenTarget.hpp>

#include <glm/gtc/matrix_inverse.hpp>
#include <gtest/gtest.h>

#include <chrono>
#include <functional>
#include <cmath>
#include <thread>
#include <memory>

namespace volpost::test {

struct ImageError {
  double rmse = 0.0, max = 0.0;
};

inline std::vector<double> field(const Mesh& m) {
  std::vector<double> v;
  for (const auto& p : m.nodes) v.push_back(p.x + 0.5 * p.z);
  return v;
}

inline const TransferFunction kTf({{0.0, {0.1, 0.2, 0.9}, 0.05}, {2.0, {0.2, 0.9, 0.3}, 0.6},
                            {3.5, {1.0, 1.0, 1.0}, 1.5}, {6.0, {0.9, 0.1, 0.1}, 0.2}});

inline Camera isoCamera(const Mesh& m) {
  Camera c;
  c.setView(StandardView::Isometric);
  c.fit(m.bounds());
  c.orbit(17.0, 9.0);
  return c;
}

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
  virtual std::unique_ptr<VolumeRenderer> makeRenderer() const { return std::make_unique<volume::RayCaster>(); }
  void TearDown() override {
    if (context_ && caster_) caster_->release();
  }

  std::vector<float> gpuImage(const Camera& camera, int w, int h, float sceneDepth = 1.0f) {
    return imageOf(*caster_, camera, w, h, sceneDepth);
  }

  static std::vector<float> imageOf(VolumeRenderer& renderer, const Camera& camera, int w, int h, float sceneDepth = 1.0f) {
    OffscreenTarget target(w, h);
    drawInto(target, renderer, camera, sceneDepth);
    return renderer.readImage();
  }

  /// What the renderer shows on the target (its image composited, 8 bits): a quick frame
  /// while one is shown.
  static std::vector<std::uint8_t> shownPixels(VolumeRenderer& renderer, const Camera& camera, int w, int h) {
    OffscreenTarget target(w, h);
    drawInto(target, renderer, camera, 1.0f);
    return target.readPixels();
  }

  static void drawInto(OffscreenTarget& target, VolumeRenderer& renderer, const Camera& camera, float sceneDepth) {
    glClearNamedFramebufferfv(target.framebuffer(), GL_DEPTH, 0, &sceneDepth);
    RenderContext ctx;
    ctx.depthTexture = sceneDepth < 1.0f ? target.depthTexture() : 0;
    ctx.camera = camera;
    ctx.width = target.width();
    ctx.height = target.height();
    ctx.framebuffer = target.framebuffer();
    glBindFramebuffer(GL_FRAMEBUFFER, ctx.framebuffer);
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    renderer.render(ctx);
    glFinish();
  }


 public:
  static ImageError compare(const std::vector<float>& gpu, const optics::ReferenceImage& ref) {
    ImageError e;
    double sum = 0.0;
    for (std::size_t i = 0; i < ref.pixels.size(); ++i)
      for (int k = 0; k < 4; ++k) {
        const double d = double(gpu[4 * i + std::size_t(k)]) - ref.pixels[i][k];
        sum += d * d;
        e.max = std::isfinite(d) ? std::max(e.max, std::abs(d)) : HUGE_VAL;  // a NaN pixel is no match
      }
    e.rmse = std::sqrt(sum / double(ref.pixels.size() * 4));
    return e;
  }

 protected:

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

  // Functions at the edges of what float holds, drawn as the double reference draws them: a
  // point 1e30 below the values with an extinction of 1e5 (interpolated as a + w (b - a),
  // the values next to it took the far point's rounding: 0.0078 for an extinction of 0.01,
  // 0.07 off on the wheel) and extinctions of 1e300 and 1e-320 (NaN pixels before).
  void expectExtremeExtinctionsLikeTheReference(const char* name) {
    const Mesh grid = test::tetGrid(4, 4, 4);
    const TransferFunction farBelow({{-1e30, {0.1, 0.2, 0.9}, 1e5}, {2.0, {0.2, 0.9, 0.3}, 0.6},
                                     {3.5, {1.0, 1.0, 1.0}, 1.5}, {6.0, {0.9, 0.1, 0.1}, 0.01}});
    const TransferFunction huge({{0.0, {0.1, 0.2, 0.9}, 1e-320}, {3.0, {1.0, 1.0, 1.0}, 1e300}, {6.0, {0.9, 0.1, 0.1}, 0.2}});
    for (IntegrationMode mode :
         {IntegrationMode::LinearSegments, IntegrationMode::LinearSegmentsIsoTable, IntegrationMode::PreIntegrated}) {
      caster_->setIntegrationMode(mode);
      for (const TransferFunction* tf : {&farBelow, &huge}) {
        const ImageError e = againstReference(grid, FieldLocation::Node, field(grid), *tf, isoCamera(grid), 48);
        const char* which = tf == &huge ? "extinctions 1e300 and 1e-320" : "a point 1e30 below";
        std::printf("%s %s, %s vs reference: RMSE %.3g, max %.3g\n", name, std::string(toString(mode)).c_str(), which,
                    e.rmse, e.max);
        // Measured: far point 2.6e-7 / 2.7e-6 (pre-integrated 2.4e-6 / 4.3e-5); 1e300:
        // 1.0e-7 / 1.2e-6 (3.6e-5 / 2.1e-4 while thick pieces took psi from the 2D table).
        EXPECT_LE(e.rmse, 1e-5) << toString(mode) << ", " << which;
        EXPECT_LE(e.max, 1e-4) << toString(mode) << ", " << which;
      }
    }
  }

  // A clear range, then the extinction climbing steeply (an opaque surface at a threshold,
  // as analysts draw one): pieces whose front is clear and whose back is opaque, hundreds of
  // optical depths thick, where the 2D psi table was up to 0.02 off.
  void expectAnOpaqueRampLikeTheReference(const char* name) {
    const Mesh grid = test::tetGrid(4, 4, 4);
    for (double steepest : {300.0, 30000.0}) {
      const TransferFunction ramp({{0.0, {0.1, 0.2, 0.9}, 0.0}, {2.9, {0.1, 0.2, 0.9}, 0.0}, {3.1, {1.0, 0.1, 0.1}, steepest},
                                   {6.0, {1.0, 0.9, 0.1}, steepest}});
      Camera turned = isoCamera(grid);
      turned.orbit(23.0, -17.0);
      for (const Camera& camera : {isoCamera(grid), turned}) {
        const ImageError e = againstReference(grid, FieldLocation::Node, field(grid), ramp, camera, 64);
        std::printf("%s, a clear range then a ramp to %g vs reference: RMSE %.3g, max %.3g\n", name, steepest, e.rmse, e.max);
        EXPECT_LE(e.rmse, 1e-5) << steepest;  // measured <= 9.5e-7; 2.2e-5 with the 2D table alone
        EXPECT_LE(e.max, 1e-4) << steepest;   // <= 5.1e-5; 3.7e-4 with the 2D table alone
      }
    }
  }

  // An iso-surface that lies on inner faces (s = x, the surface at a grid plane): the two
  // tets of such a face compute the value there from different planes, a rounding apart,
  // and both would count the crossing (the surface drawn twice, up to 0.24 too opaque).
  void expectIsoSurfaceOnInnerFacesDrawnOnce(const char* name) {
    const Mesh grid = test::tetGrid(4, 4, 4, glm::dvec3(0.1, 0.2, 0.3), 0.7);
    std::vector<double> x;
    for (const auto& p : grid.nodes) x.push_back(p.x);
    const TransferFunction faint({{0.0, {0.2, 0.3, 0.9}, 0.05}, {3.0, {0.9, 0.3, 0.2}, 0.05}});
    const std::vector<optics::IsoSurface> isos = {{0.1 + 2.0 * 0.7, {1.0, 0.9, 0.2}, 0.5}};
    caster_->setIsoSurfaces(isos);
    caster_->setVolume(grid, FieldLocation::Node, x);
    caster_->setTransferFunction(faint);
    caster_->setTerminationThreshold(0.0);
    Camera turned = isoCamera(grid);
    turned.orbit(-41.0, 23.0);
    for (const Camera& camera : {isoCamera(grid), turned}) {
      const auto gpu = gpuImage(camera, 96, 96);
      optics::RaySettings settings;
      settings.isoSurfaces = isos;
      const ImageError e =
          compare(gpu, optics::renderReference(optics::TetVolume(grid, FieldLocation::Node, x), faint, camera, 96, 96, settings));
      std::printf("%s, iso-surface on inner faces vs reference: RMSE %.3g, max %.3g\n", name, e.rmse, e.max);
      EXPECT_LE(e.max, 1e-3);
    }
  }

  // Empty-space skipping (GpuVolume::setEmptySpaceSkipping): the GPU renderer's picture with
  // the tets the transfer function hides skipped, against the same without skipping and
  // against the reference, for three parts: a narrow opacity peak with an iso-surface in the
  // transparent range, a part of isolated tets (each a part of its own: more faces than the
  // first list holds), nothing at all, and everything.
  void expectSkippingChangesNothing(const char* name) {
    auto& gpu = static_cast<volume::TetVolumeRenderer&>(*caster_);
    const auto compareSkipping = [&](const Mesh& mesh, FieldLocation loc, const std::vector<double>& values,
                                     const TransferFunction& tf, const std::vector<optics::IsoSurface>& isos,
                                     const char* what) {
      gpu.setVolume(mesh, loc, values);
      gpu.setTransferFunction(tf);
      gpu.setIsoSurfaces(isos);
      gpu.setTerminationThreshold(0.0);
      gpu.volume().setEmptySpaceSkipping(true);
      const Camera camera = isoCamera(mesh);
      const auto skipped = gpuImage(camera, 64, 64);
      const volume::VisibleTetsGpu& part = gpu.volume().visibleTets();
      const std::size_t shown = part.visibleTets(), faces = part.boundaryFaces();
      gpu.volume().setEmptySpaceSkipping(false);
      const auto walked = gpuImage(camera, 64, 64);
      double apart = 0.0;
      for (std::size_t i = 0; i < walked.size(); ++i) apart = std::max(apart, double(std::abs(walked[i] - skipped[i])));
      const optics::TetVolume volume(mesh, loc, values);
      optics::RaySettings settings;
      settings.isoSurfaces = isos;
      const ImageError e = compare(skipped, optics::renderReference(volume, tf, camera, 64, 64, settings));
      std::printf("%s, %s: %zu of %zu tets shown, %zu faces; skipping vs not: max %.3g; vs reference: RMSE %.3g, max %.3g\n",
                  name, what, shown, mesh.cellCount(), faces, apart, e.rmse, e.max);
      EXPECT_LE(apart, 2e-5) << what;
      EXPECT_LE(e.rmse, 1e-5) << what;
      EXPECT_LE(e.max, 1e-4) << what;
      return std::pair{shown, faces};
    };
    const Mesh grid = test::tetGrid(6, 6, 6);
    const TransferFunction peak({{0.0, {0.2, 0.3, 0.9}, 0.0}, {4.0, {0.2, 0.3, 0.9}, 0.0}, {4.2, {1.0, 0.6, 0.1}, 3.0},
                                 {4.4, {0.9, 0.2, 0.1}, 0.0}, {9.0, {0.9, 0.2, 0.1}, 0.0}});
    const auto [peakShown, peakFaces] =
        compareSkipping(grid, FieldLocation::Node, field(grid), peak, {{1.5, {0.9, 0.9, 0.9}, 0.5}}, "narrow peak + iso-surface");
    EXPECT_GT(peakShown, 0u);
    EXPECT_LT(peakShown, grid.cellCount() / 2);
    {  // another result on the same tets shows other tets: the part is found again
      std::vector<double> shifted = field(grid);
      for (double& v : shifted) v += 1.5;
      gpu.volume().setEmptySpaceSkipping(true);
      const Camera camera = isoCamera(grid);
      (void)gpuImage(camera, 64, 64);  // the part found for the first result
      gpu.setValues(shifted);
      const auto image = gpuImage(camera, 64, 64);
      const optics::TetVolume volume(grid, FieldLocation::Node, shifted);
      optics::RaySettings settings;
      settings.isoSurfaces = {{1.5, {0.9, 0.9, 0.9}, 0.5}};
      const ImageError e = compare(image, optics::renderReference(volume, peak, camera, 64, 64, settings));
      std::printf("%s, narrow peak, another result: RMSE %.3g, max %.3g\n", name, e.rmse, e.max);
      EXPECT_LE(e.rmse, 1e-5);
      EXPECT_LE(e.max, 1e-4);
    }
    const Mesh fine = test::tetGrid(9, 9, 9);
    std::vector<double> alternate(fine.cellCount());
    for (std::size_t c = 0; c < alternate.size(); ++c) alternate[c] = double(c % 2);
    const TransferFunction ones({{0.0, {0.2, 0.3, 0.9}, 0.0}, {0.5, {0.2, 0.3, 0.9}, 0.0}, {1.0, {1.0, 0.6, 0.1}, 1.5}});
    const auto [isolatedShown, isolatedFaces] = compareSkipping(fine, FieldLocation::Cell, alternate, ones, {}, "isolated tets");
    EXPECT_EQ(isolatedShown, fine.cellCount() / 2);
    EXPECT_GT(isolatedFaces, 4096u);  // past the first list's room: found again with room for all
    const TransferFunction none({{0.0, {1, 1, 1}, 0.0}, {9.0, {1, 1, 1}, 0.0}});
    const auto [noneShown, noneFaces] = compareSkipping(grid, FieldLocation::Node, field(grid), none, {}, "nothing");
    EXPECT_EQ(noneShown, 0u);
    EXPECT_EQ(noneFaces, 0u);
    const auto [allShown, allFaces] = compareSkipping(grid, FieldLocation::Node, field(grid), kTf, {}, "everything");
    EXPECT_EQ(allShown, grid.cellCount());
    EXPECT_EQ(allFaces, 0u);  // the whole mesh is walked: no part listed
  }

  // A constant depth in an orthographic view is a plane facing the camera: the volume
  // behind it must vanish exactly as behind a clip plane there. The renderer's image (opaque
  // geometry at window depth 0.5) against the reference clipped at that plane.
  ImageError opaqueDepthAgainstReference() {
    const Mesh grid = test::tetGrid(4, 4, 4);
    Camera camera = isoCamera(grid);
    camera.setProjection(Camera::Projection::Orthographic);
    const float depth = 0.5f;
    caster_->setIntegrationMode(IntegrationMode::LinearSegments);
    caster_->setVolume(grid, FieldLocation::Node, field(grid));
    caster_->setTransferFunction(kTf);
    caster_->setTerminationThreshold(0.0);
    const auto image = gpuImage(camera, 64, 64, depth);
    const glm::dvec4 p =
        glm::inverse(camera.projectionMatrix(1.0) * camera.viewMatrix()) * glm::dvec4(0, 0, 2.0 * depth - 1.0, 1.0);
    optics::RaySettings settings;
    settings.clipPlanes = {{glm::dvec3(p) / p.w, -camera.viewDirection()}};
    const optics::TetVolume volume(grid, FieldLocation::Node, field(grid));
    return compare(image, optics::renderReference(volume, kTf, camera, 64, 64, settings));
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
  std::unique_ptr<VolumeRenderer> caster_;
};

// Cell projection: the same fixture, the tets drawn in visibility order instead of walked.
class CellProjection : public RayCast {
 protected:
  std::unique_ptr<VolumeRenderer> makeRenderer() const override { return std::make_unique<volume::CellProjector>(method); }
  volume::OrderMethod method = volume::OrderMethod::ImageSpace;
};

// The CPU ray caster: the same fixture and the same comparisons as the GPU renderers.
class CpuRayCast : public RayCast {
 protected:
  std::unique_ptr<VolumeRenderer> makeRenderer() const override { return std::make_unique<volume::CpuVolumeRenderer>(); }
};


// Values far from float32's comfort: a concentration of order 1e-38 (where float32 is
// denormal and shader arithmetic flushes to zero) and a field riding on a large offset
// (a temperature of 1e6 + small variations). The same picture must come out as for
// field(), since the transfer function follows the values.
inline void expectValueScaleInvariance(const char* renderer,
                                const std::function<ImageError(const std::vector<double>&, const TransferFunction&)>& render) {
  const Mesh grid = tetGrid(4, 4, 4);
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

}  // namespace volpost::test

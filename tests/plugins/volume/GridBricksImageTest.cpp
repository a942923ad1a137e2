// SPDX-License-Identifier: MIT
// A grid larger than the GPU memory budget, drawn in bricks streamed through it, gives the
// picture drawn from one texture: the ray marcher and the slicer, from outside and from
// inside the grid, in perspective and orthographic views, with a clip plane, an
// iso-surface and shading; in the window's refined frames too. The bricks split the rays at
// their faces (one more piece per face crossed), so the pictures differ by that extra break
// in the piecewise linear scalar: far below the renderers' own error against the exact
// reference, and shrinking with the step at second order (a seam would not).
#include "RippleGrid.hpp"
#include "VolumeImageFixture.hpp"

#include "GridRayMarcher.hpp"
#include "GridSlicer.hpp"
#include "host/optics/GridReference.hpp"

#include <volpost/core/ResourceLimits.hpp>

using namespace volpost;
using namespace volpost::test;

namespace {

// 20 x 17 x 13 points of the ripple grid.
RegularGrid brickedGrid() { return rippleGrid({20, 17, 13}); }

const TransferFunction kBrickTf({{0.5, {0.1, 0.2, 0.9}, 0.1}, {2.5, {0.2, 0.9, 0.3}, 0.5},
                                 {3.5, {1.0, 1.0, 1.0}, 1.0}, {5.5, {0.9, 0.1, 0.1}, 0.3}});

double maxDifference(const std::vector<float>& a, const std::vector<float>& b) {
  double worst = a.size() == b.size() ? 0.0 : 1e9;
  for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i) worst = std::max(worst, std::abs(double(a[i]) - b[i]));
  return worst;
}

double meanAlpha(const std::vector<float>& rgba) {
  double sum = 0.0;
  for (std::size_t i = 3; i < rgba.size(); i += 4) sum += rgba[i];
  return sum / double(rgba.size() / 4);
}

struct BudgetGuard {
  ~BudgetGuard() { setGpuMemoryBudget(0); }
};

// Renders with the budget unset (one texture) and with a budget of `budget` bytes.
template <typename Renderer>
class BrickedGrid : public RayCast {
 protected:
  std::unique_ptr<VolumeRenderer> makeRenderer() const override { return std::make_unique<Renderer>(); }
  Renderer& renderer() { return static_cast<Renderer&>(*caster_); }

  void setScene(const RegularGrid& g, const std::vector<double>& values, double step) {
    renderer().setGrid(g, values);
    renderer().setTransferFunction(kBrickTf);
    renderer().setSamplingStep(step);
    renderer().setTerminationThreshold(0.0);
  }
  std::vector<float> imageWithBudget(std::size_t budget, const Camera& camera, int size) {
    setGpuMemoryBudget(budget);
    return gpuImage(camera, size, size);
  }
  /// One texture and bricks at `step` from `camera`: their largest difference, and each
  /// one's RMSE against the exact trilinear reference.
  struct Comparison {
    double difference = 0.0, wholeRmse = 0.0, brickedRmse = 0.0;
  };
  Comparison compareBricked(const RegularGrid& g, const std::vector<double>& values, double step,
                            const Camera& camera, int size, const optics::RaySettings& settings = {}) {
    renderer().setSamplingStep(step);
    const std::vector<float> whole = imageWithBudget(0, camera, size);
    EXPECT_EQ(renderer().brickCount(), 1u);
    const std::vector<float> bricked = imageWithBudget(kSmallBudget, camera, size);
    EXPECT_EQ(renderer().brickCount(), 18u);
    EXPECT_GT(meanAlpha(whole), 0.1);
    const optics::ReferenceImage reference = optics::renderGridReference(g, values, kBrickTf, camera, size, size, settings);
    const Comparison c{maxDifference(whole, bricked), compare(whole, reference).rmse, compare(bricked, reference).rmse};
    std::printf("%s in 18 bricks under an 8 KB budget vs one texture, step %g: max difference %.3g; RMSE vs the "
                "reference %.3g bricked, %.3g one texture\n",
                renderer().name().c_str(), step, c.difference, c.brickedRmse, c.wholeRmse);
    return c;
  }
  /// In the window (a quick frame, then the full one refined a pass or a run of slices per
  /// call under a tiny budget): at least one call per brick, and the frame it ends with is
  /// the synchronous one bit for bit.
  void expectRefinedFrameIsTheSynchronousOne(const Camera& camera) {
    const std::vector<float> synchronous = imageWithBudget(kSmallBudget, camera, 48);
    renderer().setAsynchronousUpdates(true);
    renderer().setFrameBudget(1e-3, 1e-3);
    (void)gpuImage(camera, 48, 48);
    int calls = 1;
    for (; calls < 100000 && renderer().hasPendingWork(); ++calls) (void)gpuImage(camera, 48, 48);
    ASSERT_FALSE(renderer().hasPendingWork());
    EXPECT_GE(calls, 18) << "a call per brick at least";
    EXPECT_EQ(gpuImage(camera, 48, 48), synchronous);
    renderer().setAsynchronousUpdates(false);
  }
  /// From outside, inside and orthographic: bricked within 1e-3 of one texture and no
  /// farther from the reference; the difference falling at second order in the step.
  void expectBrickedEqualsUnbricked();
  /// 8 KB: bricks of 8^3 points (2 KB), 18 of them, 4 resident: every frame streams.
  static constexpr std::size_t kSmallBudget = 8 * 1024;
  BudgetGuard guard_;
};

Camera outsideCamera(const RegularGrid& g) {
  Camera c;
  c.setView(StandardView::Isometric);
  c.fit(g.bounds());
  c.orbit(31.0, -17.0);
  return c;
}

// An eye inside the grid, looking across it.
Camera insideCamera(const RegularGrid& g) {
  Camera c = outsideCamera(g);
  c.place(g.position(12.0, 9.0, 6.0), c.rotation(), 1.0);
  return c;
}

}  // namespace

template <typename Renderer>
void BrickedGrid<Renderer>::expectBrickedEqualsUnbricked() {
  const RegularGrid g = brickedGrid();
  const std::vector<double> values = rippleValues(g);
  setScene(g, values, 0.1);
  Camera ortho = outsideCamera(g);
  ortho.setProjection(Camera::Projection::Orthographic);
  for (const Camera& camera : {outsideCamera(g), insideCamera(g), ortho}) {
    const Comparison c = compareBricked(g, values, 0.1, camera, 64);
    EXPECT_LE(c.difference, 1e-3);
    EXPECT_LE(c.brickedRmse, 1.05 * c.wholeRmse + 1e-5);
  }
  const Comparison coarse = compareBricked(g, values, 0.2, outsideCamera(g), 48);
  const Comparison fine = compareBricked(g, values, 0.05, outsideCamera(g), 48);
  EXPECT_LE(fine.difference, coarse.difference / 6.0) << "second order in the step: 16x in theory";
}

using BrickedMarch = BrickedGrid<volume::GridRayMarcher>;
using BrickedSlices = BrickedGrid<volume::GridSlicer>;

TEST_F(BrickedMarch, BrickedEqualsUnbrickedFromOutsideAndInsidePerspectiveAndOrthographic) {
  expectBrickedEqualsUnbricked();
}

TEST_F(BrickedMarch, ClipPlanesIsoSurfacesAndShadingAcrossBricks) {
  const RegularGrid g = brickedGrid();
  const std::vector<double> values = rippleValues(g);
  setScene(g, values, 0.1);
  renderer().setClipPlanes({{g.bounds().center(), {0.3, -1.0, 0.2}}});
  renderer().setIsoSurfaces({{4.2, {1.0, 0.7, 0.1}, 0.5}});
  renderer().setShading(true);
  optics::RaySettings settings;
  settings.clipPlanes = {{g.bounds().center(), {0.3, -1.0, 0.2}}};
  settings.isoSurfaces = {{4.2, {1.0, 0.7, 0.1}, 0.5}};
  settings.shading = true;
  const Comparison c = compareBricked(g, values, 0.1, outsideCamera(g), 64, settings);
  // The shading's gradient jumps at cell faces; a brick face is one, and a piece that ends
  // there takes the gradient of the brick's side: first order, as against the reference.
  EXPECT_LE(c.difference, 5e-3);
  EXPECT_LE(c.brickedRmse, 1.05 * c.wholeRmse + 1e-5);
}

TEST_F(BrickedMarch, TheWindowRefinesABrickedFrameToTheSynchronousOne) {
  const RegularGrid g = brickedGrid();
  setScene(g, rippleValues(g), 0.02);
  expectRefinedFrameIsTheSynchronousOne(outsideCamera(g));
}

TEST_F(BrickedSlices, BrickedEqualsUnbrickedFromOutsideAndInsidePerspectiveAndOrthographic) {
  expectBrickedEqualsUnbricked();
}

TEST_F(BrickedSlices, TheWindowRefinesABrickedFrameToTheSynchronousOne) {
  const RegularGrid g = brickedGrid();
  setScene(g, rippleValues(g), 0.05);
  expectRefinedFrameIsTheSynchronousOne(outsideCamera(g));
}

TEST_F(BrickedSlices, ABudgetTooSmallForAnyBrickIsRefusedNamingIt) {
  const RegularGrid g = brickedGrid();
  setScene(g, rippleValues(g), 0.1);
  setGpuMemoryBudget(100);
  try {
    (void)gpuImage(outsideCamera(g), 32, 32);
    FAIL() << "a 100-byte budget was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("GPU memory budget of 100 bytes"), std::string::npos) << e.what();
  }
  setGpuMemoryBudget(0);
  EXPECT_GT(meanAlpha(gpuImage(outsideCamera(g), 32, 32)), 0.1) << "a larger budget draws again";
}

// Integer samples (8- and 16-bit seismic formats) are kept as integers on the GPU: half or a
// quarter of the memory per point, the same picture (the reference's, within the float
// path's bound), and bricks of twice or four times the points under the same budget.
TEST_F(BrickedMarch, IntegerSamplesTakeTwoOrOneBytesAndGiveTheSamePicture) {
  const RegularGrid g = brickedGrid();
  const std::vector<double> ripple = rippleValues(g);
  for (const double unit : {1000.0, 15.0}) {  // 16-bit (up to 7400), 8-bit (up to 111)
    std::vector<double> integers(ripple.size());
    double largest = 0.0;
    for (std::size_t i = 0; i < ripple.size(); ++i) largest = std::max(largest, integers[i] = std::round(unit * ripple[i]));
    TransferFunction tf = kBrickTf;
    std::vector<ControlPoint> points = tf.points();
    for (ControlPoint& p : points) p.value *= unit;
    renderer().setGrid(g, integers);
    renderer().setTransferFunction(TransferFunction(points));
    renderer().setSamplingStep(0.1);
    renderer().setTerminationThreshold(0.0);
    const std::vector<float> image = imageWithBudget(0, outsideCamera(g), 48);
    const std::size_t bytesPerPoint = renderer().stats().meshBytes / g.pointCount();
    const ImageError e = compare(image, optics::renderGridReference(g, integers, TransferFunction(points),
                                                                    outsideCamera(g), 48, 48));
    std::printf("integer samples up to %.0f: %zu bytes per point on the GPU, RMSE %.3g vs the reference\n", largest,
                bytesPerPoint, e.rmse);
    EXPECT_EQ(bytesPerPoint, largest > 127.0 ? 2u : 1u);
    EXPECT_GT(meanAlpha(image), 0.1);
    EXPECT_LE(e.rmse, 1e-4);  // the float path's error at this step (BrickedEqualsUnbricked: 6.8e-5)
    (void)imageWithBudget(kSmallBudget, outsideCamera(g), 48);
    EXPECT_LT(renderer().brickCount(), 18u) << "more points per brick under the same budget";
  }
}

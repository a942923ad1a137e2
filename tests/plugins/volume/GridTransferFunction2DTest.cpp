// SPDX-License-Identifier: MIT
// 2D transfer functions (value x gradient magnitude) on regular grids: the GPU ray
// marcher, the slicer and the CPU marcher against the reference (midpoint rule with the
// exact trilinear value and gradient, converged by halving the step), first order in the
// step (the trilinear gradient jumps across cell faces, and the samples either side of one
// are interpolated linearly, as for shading); the gradient axis counts (the same widgets over another
// gradient range give another picture); clip planes, iso-surfaces and shading too; meshes
// of tetrahedra refuse it.
#include "RippleGrid.hpp"
#include "VolumeImageFixture.hpp"

#include "CpuVolumeRenderer.hpp"
#include "GridRayMarcher.hpp"
#include "GridSlicer.hpp"
#include "host/optics/GridReference.hpp"

using namespace volpost;
using namespace volpost::test;

namespace {

// 14 x 12 x 10 points of the ripple grid.
RegularGrid testGrid() { return rippleGrid({14, 12, 10}); }

// Quiet regions of middling value in green; where the value changes fast around 4, red.
TransferFunction2D boundaryTf(double gradientShift = 0.0) {
  return TransferFunction2D({{TfWidget2D::Shape::Rectangle, 2.5, 1.5, 0.0 + gradientShift, 1.2 + gradientShift,
                              {0.1, 0.9, 0.2}, 0.8},
                             {TfWidget2D::Shape::Triangle, 4.0, 2.0, 0.4 + gradientShift, 3.0 + gradientShift,
                              {0.9, 0.1, 0.1}, 1.5}});
}

Camera rippleCamera(const RegularGrid& g) {
  Camera c;
  c.setView(StandardView::Isometric);
  c.fit(g.bounds());
  c.orbit(31.0, -17.0);
  return c;
}

template <typename Renderer>
class GridTf2d : public RayCast {
 protected:
  std::unique_ptr<VolumeRenderer> makeRenderer() const override { return std::make_unique<Renderer>(); }
  GridVolumeRenderer& renderer() { return static_cast<GridVolumeRenderer&>(*caster_); }

  ImageError againstReference(const TransferFunction2D& tf, double step, const optics::RaySettings& settings = {},
                              std::vector<float>* image = nullptr) {
    const RegularGrid g = testGrid();
    const std::vector<double> values = rippleValues(g);
    renderer().setGrid(g, values);
    renderer().setTransferFunction(TransferFunction({{0.0, {1, 1, 1}, 0.0}, {6.0, {1, 1, 1}, 0.0}}));  // unused
    renderer().setTransferFunction2D(tf);
    renderer().setSamplingStep(step);
    renderer().setTerminationThreshold(0.0);
    renderer().setClipPlanes(settings.clipPlanes);
    renderer().setIsoSurfaces(settings.isoSurfaces);
    renderer().setShading(settings.shading);
    const std::vector<float> mine = gpuImage(rippleCamera(g), 48, 48);
    if (image) *image = mine;
    const ImageError e =
        compare(mine, optics::renderGridReference2D(g, values, tf, rippleCamera(g), 48, 48, settings, 1e-6));
    std::printf("%s with a 2D transfer function, step %g: RMSE %.3g max %.3g\n", renderer().name().c_str(), step,
                e.rmse, e.max);
    return e;
  }
};

using Tf2dMarch = GridTf2d<volume::GridRayMarcher>;
using Tf2dSlices = GridTf2d<volume::GridSlicer>;
using Tf2dCpu = GridTf2d<volume::CpuVolumeRenderer>;

}  // namespace

TEST(GridReference2D, ConvergesAndSeesTheGradient) {
  const RegularGrid g = testGrid();
  const std::vector<double> values = rippleValues(g);
  const Camera camera = rippleCamera(g);
  const auto fine = optics::renderGridReference2D(g, values, boundaryTf(), camera, 24, 24, {}, 1e-6);
  const auto coarse = optics::renderGridReference2D(g, values, boundaryTf(), camera, 24, 24, {}, 1e-4);
  const auto shifted = optics::renderGridReference2D(g, values, boundaryTf(0.5), camera, 24, 24, {}, 1e-6);
  double converged = 0.0, moved = 0.0, alpha = 0.0;
  for (std::size_t i = 0; i < fine.pixels.size(); ++i) {
    converged = std::max(converged, glm::length(fine.pixels[i] - coarse.pixels[i]));
    moved = std::max(moved, glm::length(fine.pixels[i] - shifted.pixels[i]));
    alpha += fine.pixels[i].a / double(fine.pixels.size());
  }
  std::printf("2D reference: tolerance 1e-4 vs 1e-6 differ by %.3g; widgets 0.5 up the gradient change it by %.3g; "
              "mean alpha %.3f\n",
              converged, moved, alpha);
  EXPECT_GT(alpha, 0.1);
  EXPECT_LE(converged, 1e-3);
  EXPECT_GT(moved, 0.05) << "the gradient axis must matter";
}

TEST_F(Tf2dMarch, ConvergesToTheReferenceAndHonoursTheGradient) {
  const ImageError half = againstReference(boundaryTf(), 0.25);
  const ImageError fine = againstReference(boundaryTf(), 0.0625);
  EXPECT_LE(half.rmse, 3e-2);
  EXPECT_LE(fine.rmse, half.rmse / 3.0);  // first order: 4x in theory
  EXPECT_LE(fine.rmse, 7e-3);
  // Widgets moved up the gradient axis: far from the first reference, close to their own.
  const ImageError shifted = againstReference(boundaryTf(0.5), 0.0625);
  EXPECT_LE(shifted.rmse, 1e-2);
}

TEST_F(Tf2dMarch, ClipPlanesIsoSurfacesAndShading) {
  optics::RaySettings settings;
  const RegularGrid g = testGrid();
  settings.clipPlanes = {{g.bounds().center(), {0.3, -1.0, 0.2}}};
  settings.isoSurfaces = {{4.6, {1.0, 0.7, 0.1}, 0.5}};
  settings.shading = true;
  const ImageError e = againstReference(boundaryTf(), 0.0625, settings);
  EXPECT_LE(e.rmse, 7e-3);
}

TEST_F(Tf2dMarch, BackToTheOneDimensionalFunction) {
  std::vector<float> with2d;
  (void)againstReference(boundaryTf(), 0.25, {}, &with2d);
  renderer().setTransferFunction2D(std::nullopt);
  const std::vector<float> without = gpuImage(rippleCamera(testGrid()), 48, 48);
  double alpha = 0.0;
  for (std::size_t i = 3; i < without.size(); i += 4) alpha = std::max(alpha, double(without[i]));
  EXPECT_EQ(alpha, 0.0) << "the 1D function set here is transparent";
}

TEST_F(Tf2dSlices, ConvergesToTheReference) {
  const ImageError half = againstReference(boundaryTf(), 0.25);
  const ImageError fine = againstReference(boundaryTf(), 0.0625);
  EXPECT_LE(half.rmse, 3e-2);
  EXPECT_LE(fine.rmse, half.rmse / 3.0);
  EXPECT_LE(fine.rmse, 7e-3);
}

TEST_F(Tf2dCpu, ConvergesToTheReferenceAndRefusesMeshes) {
  const ImageError fine = againstReference(boundaryTf(), 0.0625);
  EXPECT_LE(fine.rmse, 7e-3);
  optics::RaySettings lit;
  lit.shading = true;
  EXPECT_LE(againstReference(boundaryTf(), 0.0625, lit).rmse, 7e-3);
  const Mesh tets = test::tetGrid(2, 2, 2);
  renderer().setVolume(tets, FieldLocation::Node, field(tets));
  EXPECT_THROW((void)gpuImage(rippleCamera(testGrid()), 16, 16), std::invalid_argument);
}

// SPDX-License-Identifier: MIT
// The Scene: what each change costs the volume renderer (a dragged plane: only the
// frame), its state as a file and back (the same picture), and what a state file may not
// say (each refusal names the key).
#include "support/BarSession.hpp"
#include "support/QtGuiEnvironment.hpp"
#include "support/RayCasterScene.hpp"
#include "support/ReaderSupport.hpp"
#include "support/TestSupport.hpp"

#include "CpuVolumeRenderer.hpp"

#include <volpost/core/ResourceLimits.hpp>
#include "core/AnimationFrames.hpp"
#include "core/Deformation.hpp"
#include "core/Legend.hpp"
#include "core/Probe.hpp"
#include "core/SceneDrawing.hpp"
#include "core/SceneImage.hpp"
#include "core/SceneOverlay.hpp"
#include "core/VolumeDefaults.hpp"

#include <volpost/render/HeadlessContext.hpp>
#include <volpost/render/OffscreenTarget.hpp>

#include <filesystem>
#include <fstream>
#include <memory>

using namespace volpost;
using namespace volpost::app;

namespace {

using volpost::test::rayCasterOnly;

using volpost::test::barSession;

// A context drawing into `target`, at its size.
RenderContext contextFor(const OffscreenTarget& target) {
  RenderContext ctx;
  ctx.width = target.width();
  ctx.height = target.height();
  ctx.framebuffer = target.framebuffer();
  return ctx;
}

class SceneWithContext : public ::testing::Test {
 protected:
  void SetUp() override {
    try {
      context_ = std::make_unique<HeadlessContext>();
    } catch (const std::exception& e) {
      GTEST_SKIP() << "not run: no headless OpenGL 4.5 context: " << e.what();
    }
  }
  std::unique_ptr<HeadlessContext> context_;
};

}  // namespace

TEST_F(SceneWithContext, ADraggedPlaneCostsOnlyTheFrame) {
  Scene scene(rayCasterOnly());
  SceneDrawing drawing;
  drawing.setAsynchronousUpdates(true);
  scene.setSession(barSession());
  scene.setResult("S.mises", 0);
  scene.setVolumeRenderer("raycast");
  scene.setVolumeShown(true);
  scene.setClipPlanes({{{5.0, 0.5, 0.5}, {1, 0, 0}}});
  OffscreenTarget target(48, 32);
  const RenderContext ctx = contextFor(target);
  drawing.initialize();
  drawing.render(scene, ctx);
  const VolumeStats first = drawing.volumeStats();
  EXPECT_EQ(first.meshUploads, 1u);
  EXPECT_EQ(first.tableBuilds, 1u);
  for (int i = 1; i <= 10; ++i) {  // ten mouse events of a Ctrl+drag
    scene.setClipPlanes({{{5.0 + 0.2 * i, 0.5, 0.5}, {1, 0, 0}}});
    drawing.render(scene, ctx);
  }
  const VolumeStats dragged = drawing.volumeStats();
  EXPECT_EQ(dragged.meshUploads, first.meshUploads) << "no mesh upload";
  EXPECT_EQ(dragged.valueUploads, first.valueUploads) << "no value upload";
  EXPECT_EQ(dragged.tableBuilds, first.tableBuilds) << "no table rebuild";
  // With a clip box on, the dragged plane is not dropped: it cuts too (and still costs
  // only the frame).
  // (Each picture completed: a frame too slow for the interactive budget is refined over
  // several calls.)
  const auto finished = [&] {
    do drawing.render(scene, ctx);
    while (drawing.hasPendingWork());
    return drawing.readVolumeImage();
  };
  scene.setClipBox(ClipBox{1.0, 9.0, -1.0, 2.0, -1.0, 2.0});
  const auto boxed = finished();
  const VolumeStats withBox = drawing.volumeStats();
  scene.setClipPlanes({{{2.0, 0.5, 0.5}, {1, 0, 0}}});
  EXPECT_NE(finished(), boxed) << "the plane moved the cut inside the box";
  EXPECT_EQ(drawing.volumeStats().meshUploads, withBox.meshUploads);
  EXPECT_EQ(drawing.volumeStats().tableBuilds, withBox.tableBuilds);
  // Another step or result: only values travel.
  scene.setResult("U.magnitude", 0);
  drawing.render(scene, ctx);
  EXPECT_EQ(drawing.volumeStats().meshUploads, withBox.meshUploads);
  EXPECT_EQ(drawing.volumeStats().valueUploads, withBox.valueUploads + 1);
  drawing.release();
}

// A volume picture never draws the boundary surface, so it never extracts it (at 12.6M
// tets that is 9 s and 100 bytes per tet); the surface view extracts it when first drawn.
TEST_F(SceneWithContext, AVolumePictureLeavesTheBoundaryUnextracted) {
  const auto session = ModelSession::load(volpost::test::meshioReaders(), volpost::test::dataFile("bar/bar_tet4.vtu"));
  Scene scene(rayCasterOnly());
  scene.setSession(session);
  scene.setResult("S.mises", 0);
  scene.setVolumeRenderer("raycast");
  scene.setVolumeShown(true);
  OffscreenTarget target(32, 24);
  const RenderContext ctx = contextFor(target);
  SceneDrawing drawing;
  drawing.initialize();
  drawing.render(scene, ctx);
  EXPECT_FALSE(session->surfaceExtracted());
  EXPECT_FALSE(drawing.readVolumeImage().empty());
  scene.setVolumeShown(false);
  drawing.render(scene, ctx);
  EXPECT_TRUE(session->surfaceExtracted());
  const std::vector<std::uint8_t> pixels = target.readPixels();
  int drawn = 0;  // the surface is drawn over the background (245, 245, 247)
  for (std::size_t i = 0; i < pixels.size(); i += 4)
    drawn += std::abs(int(pixels[i]) - 245) + std::abs(int(pixels[i + 1]) - 245) + std::abs(int(pixels[i + 2]) - 247) > 30;
  EXPECT_GT(drawn, 20);
  drawing.release();
}

TEST_F(SceneWithContext, AStateFileGivesTheSamePicture) {
  Scene scene(rayCasterOnly());
  scene.setSession(barSession());
  scene.setResult("S.mises", 0);
  scene.setColorMap("viridis");
  scene.setVolumeRenderer("raycast");
  scene.setVolumeShown(true);
  scene.setClipBox(ClipBox{0.5, 8.0, -1.0, 2.0, -1.0, 2.0});
  scene.setClipPlanes({{{5.0, 0.5, 0.5}, {1, 0.2, 0}}});
  scene.setIsoSurfaces({{80.0, {1.0, 0.8, 0.1}, 0.5}});
  scene.setIntegrationMode(IntegrationMode::LinearSegments);
  scene.camera().orbit(25.0, -10.0);
  scene.camera().zoom(1.3);
  const SceneImage before = renderSceneImage(scene, 64, 48);

  const std::string path = (std::filesystem::temp_directory_path() / "volpost_scene_state_test.json").string();
  scene.state().save(path);
  const SceneState loaded = SceneState::load(path);
  EXPECT_EQ(loaded.modelPath, barSession()->model().sourcePath);
  Scene restored(rayCasterOnly());
  restored.setSession(barSession());
  restored.applyState(loaded);
  const SceneImage after = renderSceneImage(restored, 64, 48);
  EXPECT_TRUE(after.picture == before.picture) << "pixel for pixel";
  EXPECT_EQ(after.volumeRgba, before.volumeRgba);
  std::filesystem::remove(path);
}

TEST(SceneState, RoundTripsThroughItsFile) {
  SceneState s;
  s.modelPath = "/data/model.vtu";
  s.quantity = "S.mises";
  s.step = 2;
  s.camera = CameraState{{1, 2, 3}, {0, 0, 0}, {0, 0, 1}, 40.0, true, glm::dquat(0.5, 0.1, -0.7, 0.3), std::sqrt(14.0)};
  s.colorMap = "viridis";
  s.fixedRange = DisplayRange{-1.0, 2.5};
  s.edges = false;
  s.volume.shown = true;
  s.volume.renderer = "vicp";
  s.volume.mode = IntegrationMode::PreIntegrated;
  s.volume.transferFunction = TransferFunction({{0.0, {0, 0, 1}, 0.1}, {1.0, {1, 0, 0}, 2.0}});
  s.volume.clipPlanes = {{{1, 2, 3}, {0, 1, 0}}};
  s.volume.clipBox = ClipBox{0, 1, 0, 1, 0, 1};
  s.volume.isoSurfaces = {{0.5, {1, 0.5, 0}, 0.25}};
  s.volume.samplingStep = 0.01;
  s.volume.termination = 0.0;
  s.volume.interpolation = FieldInterpolation::Element;
  s.volume.elementTolerance = 2.5e-4;
  const SceneState back = SceneState::fromJson(s.toJson(), "/data/view.json");
  EXPECT_EQ(back.modelPath, s.modelPath);
  EXPECT_EQ(back.quantity, s.quantity);
  EXPECT_EQ(back.step, s.step);
  EXPECT_EQ(back.camera, s.camera);
  EXPECT_EQ(back.colorMap, s.colorMap);
  EXPECT_EQ(back.fixedRange, s.fixedRange);
  EXPECT_EQ(back.edges, s.edges);
  EXPECT_EQ(back.volume.renderer, s.volume.renderer);
  EXPECT_EQ(back.volume.mode, s.volume.mode);
  EXPECT_EQ(back.volume.transferFunction, s.volume.transferFunction);
  EXPECT_EQ(back.volume.clipPlanes, s.volume.clipPlanes);
  EXPECT_EQ(back.volume.clipBox, s.volume.clipBox);
  EXPECT_EQ(back.volume.isoSurfaces.size(), 1u);
  EXPECT_EQ(back.volume.samplingStep, s.volume.samplingStep);
  EXPECT_EQ(back.volume.termination, s.volume.termination);
  EXPECT_EQ(back.volume.interpolation, FieldInterpolation::Element);
  EXPECT_EQ(back.volume.elementTolerance, 2.5e-4);
  // A model next to the state file is written relative to it, and found again.
  const SceneState moved = SceneState::fromJson(s.toJson("/data"), "/elsewhere/view.json");
  EXPECT_EQ(moved.modelPath, "/elsewhere/model.vtu");
  // A model given relative to where the command ran, outside the state's folder, is written
  // in full: read relative to the state's folder it named a file that is not there.
  SceneState typed = s;
  typed.modelPath = "models/model.vtu";
  const std::string expected = (std::filesystem::current_path() / "models/model.vtu").lexically_normal().string();
  EXPECT_EQ(SceneState::fromJson(typed.toJson("/some/other/folder"), "/some/other/folder/view.json").modelPath,
            expected);
}

// A model 6e6 units from the origin (a georeferenced survey): the view restored from a
// state is the live one exactly, so the pictures are the same bit for bit; a hand-edited
// eye that no longer agrees with the stored direction wins.
TEST(SceneState, AViewFarFromTheOriginIsRestoredExactly) {
  Camera live;
  Bounds far;
  far.extend({620000.0, 6080000.0, -160.0});
  far.extend({620300.0, 6080330.0, 0.0});
  live.setView(StandardView::Isometric);
  live.fit(far);
  live.orbit(17.0, -9.0);
  CameraState c{live.eye(), live.target(), live.up(), live.fieldOfView(), false, live.rotation(), live.distance()};
  SceneState s;
  s.modelPath = "/data/cube.sgy";
  s.camera = c;
  const CameraState back = *SceneState::fromJson(s.toJson(), "/data/view.json").camera;
  Camera restored;
  restored.fit(far);
  restored.place(back.target, *back.rotation, *back.distance);
  EXPECT_EQ(restored.viewMatrix(far.center()), live.viewMatrix(far.center())) << "bit for bit";
  Camera fromEye;
  fromEye.fit(far);
  fromEye.lookAt(back.eye, back.target, back.up);
  const double lost = glm::length(fromEye.viewDirection() - live.viewDirection());
  EXPECT_GT(lost, 1e-14) << "eye - target alone loses the last bits here";
  EXPECT_LT(lost, 1e-9);
  std::string onlyRotation = s.toJson();
  onlyRotation.replace(onlyRotation.find("\"distance\""), 10, "\"unrelated\"");
  try {
    (void)SceneState::fromJson(onlyRotation, "/data/view.json");
    ADD_FAILURE() << "a rotation without its distance was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("\"rotation\" and \"distance\" together"), std::string::npos) << e.what();
  }
}

TEST(SceneState, RefusalsNameTheFileAndTheKey) {
  const auto message = [](const std::string& text) {
    try {
      (void)SceneState::fromJson(text, "view.json");
    } catch (const std::runtime_error& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  const std::string head = R"({"format": "volpost-state", "version": 1, "model": "m.vtu", )";
  EXPECT_NE(message("{").find("view.json: not valid JSON"), std::string::npos);
  EXPECT_NE(message(R"({"format": "other"})").find("not a volpost state file"), std::string::npos);
  EXPECT_NE(message(R"({"format": "volpost-state", "version": 99, "model": "m"})").find("\"version\""), std::string::npos);
  EXPECT_NE(message(head + R"("volume": {"mode": "fast"}})").find("\"volume.mode\" must be one of: linear"), std::string::npos);
  EXPECT_NE(message(head + R"("camera": {"eye": [0,0,1], "target": [0,0,0], "up": [0,0,1]}})").find("\"camera.up\""),
            std::string::npos);
  EXPECT_NE(message(head + R"("colors": {"range": [2, 1]}})").find("\"colors.range\" needs min < max"), std::string::npos);
  EXPECT_NE(message(head + R"("result": {"step": 0}})").find("\"result.step\""), std::string::npos);
  EXPECT_NE(message(head + R"("volume": {"clipBox": [0,1,0,1,0,1], "clipPlanes": [{"point":[0,0,0],"normal":[1,0,0]},{"point":[0,0,0],"normal":[1,0,0]},{"point":[0,0,0],"normal":[1,0,0]}]}})")
                .find("at most 8"),
            std::string::npos);
  EXPECT_NE(message(head + R"("volume": {"transferFunction": {"format": "volpost-tf", "version": 1, "points": [{"value": "x"}]}}})")
                .find("view.json: \"volume.transferFunction\""),
            std::string::npos);
  EXPECT_NE(message(head + R"("volume": {"clipPlanes": [{"point":[0,0,0],"normal":[0,0,0]}]}})").find("normal"), std::string::npos);
  EXPECT_NE(message(head + R"("volume": {"interpolation": "quadratic"}})")
                .find("\"volume.interpolation\" must be one of: element, tetrahedra"),
            std::string::npos);
  EXPECT_NE(message(head + R"("volume": {"elementTolerance": 0.5}})")
                .find("\"volume.elementTolerance\" must be 0 (exact) or lie in [1e-05, 0.1]"),
            std::string::npos);
  EXPECT_NE(message(head + R"("volume": {"elementTolerance": -1e-3}})").find("\"volume.elementTolerance\""),
            std::string::npos);
}

TEST(Scene, TheDefaultTransferFunctionTakesTheColorMapAndRange) {
  Scene scene(rayCasterOnly());
  scene.setSession(barSession());
  scene.setResult("S.mises", 0);
  scene.setColorMap("grayscale");
  scene.setFixedRange(DisplayRange{50.0, 150.0});
  const TransferFunction tf = scene.transferFunction();
  EXPECT_DOUBLE_EQ(tf.minValue(), 50.0);
  EXPECT_DOUBLE_EQ(tf.maxValue(), 150.0);
  EXPECT_EQ(tf.points().front().color, glm::dvec3(0.0));
  EXPECT_EQ(tf.points().back().color, glm::dvec3(1.0));
  EXPECT_THROW(scene.setResult("S.nothing", 0), std::invalid_argument);
  EXPECT_EQ(scene.state().quantity, "S.mises") << "a refused result changes nothing";
  EXPECT_THROW(scene.setResult("S.mises", 7), std::invalid_argument);
  EXPECT_THROW(scene.setVolumeRenderer("no-such-renderer"), std::invalid_argument);
  EXPECT_THROW(scene.setColorMap("no-such-map"), std::invalid_argument);
}

// Per step, the colors span each step's own values; over all steps, one range for every
// step (and the default transfer function follows); a fixed range turns it off; the
// state file keeps the choice.
TEST(Scene, TheColorRangeCanSpanEveryStep) {
  const auto session = ModelSession::load(volpost::test::meshioReaders(), volpost::test::dataFile("formats/golden.frd"));
  Scene scene(rayCasterOnly());
  scene.setSession(session);
  scene.setResult("T", 0);  // T: [0, 111] at step 1, [0, 222] at step 2
  EXPECT_DOUBLE_EQ(scene.displayRange().max, 111.0);
  scene.setRangeOverSteps(true);
  EXPECT_DOUBLE_EQ(scene.displayRange().min, 0.0);
  EXPECT_DOUBLE_EQ(scene.displayRange().max, 222.0);
  EXPECT_DOUBLE_EQ(scene.transferFunction().maxValue(), 222.0);
  scene.setResult("T", 1);
  EXPECT_DOUBLE_EQ(scene.displayRange().max, 222.0);
  const SceneState back = SceneState::fromJson(scene.state().toJson(), "view.json");
  EXPECT_TRUE(back.rangeOverSteps);
  EXPECT_NE(scene.state().toJson().find("all-steps"), std::string::npos);
  scene.setFixedRange(DisplayRange{10.0, 20.0});
  EXPECT_FALSE(scene.state().rangeOverSteps);
  EXPECT_DOUBLE_EQ(scene.displayRange().max, 20.0);
  scene.setRangeOverSteps(false);
  EXPECT_FALSE(scene.state().fixedRange.has_value()) << "setRangeOverSteps(false) leaves the step's own range";
  scene.setResult("T", 0);
  EXPECT_DOUBLE_EQ(scene.displayRange().max, 111.0);
}

TEST(AnimationFrames, NumbersGoBeforeTheExtensionPaddedToTheCount) {
  EXPECT_EQ(framePath("frames/wheel.png", 0, 2), "frames/wheel_001.png");
  EXPECT_EQ(framePath("frames/wheel.png", 1233, 1234), "frames/wheel_1234.png");
  EXPECT_EQ(framePath("a.b/wheel", 4, 10), "a.b/wheel_005");
  EXPECT_EQ(framePath("out.tar.jpg", 9, 10), "out.tar_010.jpg");
}

// A signed result's default is dense at both ends and clear at zero (no shell of high
// values hides the lowest); a one-signed result's rises from clear with the value.
TEST(VolumeDefaults, SignedResultsAreDenseAtBothEndsAndClearAtZero) {
  ScalarView signedView;
  signedView.setValues({-40.0, 0.0, 100.0});
  signedView.range = rangeOf(signedView.values);
  const TransferFunction tf = defaultTransferFunction(signedView, 1.0);
  const double tauMax = 24.0;
  EXPECT_EQ(tf.extinction(0.0), 0.0);
  EXPECT_NEAR(tf.extinction(100.0), tauMax, 1e-9);
  EXPECT_NEAR(tf.extinction(-40.0), tauMax * 0.4, 1e-9);
  EXPECT_GT(tf.extinction(-40.0), tf.extinction(-10.0));
  ScalarView positive;
  positive.setValues({10.0, 30.0});
  positive.range = rangeOf(positive.values);
  const TransferFunction rising = defaultTransferFunction(positive, 1.0);
  // Clear at the lowest value: a floor of 10 % veiled the whole model in a fog.
  EXPECT_EQ(rising.extinction(10.0), 0.0);
  EXPECT_NEAR(rising.extinction(20.0), 0.5 * tauMax, 1e-9);
  EXPECT_NEAR(rising.extinction(30.0), tauMax, 1e-9);
}

TEST(VolumeDefaults, ATransferFunctionMadeForOtherValuesIsNoted) {
  ScalarView view;
  view.quantity = Quantity{"S", ScalarOp::VonMises, 0, FieldKind::SymTensor};
  view.setValues({58.0, 103.0});
  view.range = rangeOf(view.values);
  EXPECT_FALSE(transferFunctionRangeNote(defaultTransferFunction(view, 1.0), view));
  const TransferFunction other({{1000.0, {0, 0, 1}, 0.5}, {2000.0, {1, 0, 0}, 1.0}});
  const auto note = transferFunctionRangeNote(other, view);
  ASSERT_TRUE(note);
  EXPECT_NE(note->find("misses it"), std::string::npos) << *note;
  EXPECT_NE(note->find("1000"), std::string::npos) << *note;
  const TransferFunction partly({{90.0, {0, 0, 1}, 0.5}, {200.0, {1, 0, 0}, 1.0}});
  EXPECT_NE(transferFunctionRangeNote(partly, view)->find("less than half"), std::string::npos);
}

// The deformed shape: the bar (fixed at x = 0, stretched along x) drawn with its nodes
// moved by U x scale; automatic: the largest displacement becomes 10 % of the model's size;
// probing follows the drawn (deformed) geometry; off gives the model as read back.
TEST(Scene, TheDeformedShapeMovesTheNodesByTheScaledDisplacement) {
  Scene scene(rayCasterOnly());
  scene.setSession(barSession());
  scene.setResult("U.x", 0);
  const Bounds read = barSession()->model().mesh().bounds();
  const double uMax = barSession()->rangeOverSteps(barSession()->findQuantity("U.magnitude")).max;
  DeformationLayer d;
  d.shown = true;
  d.scale = 100.0;
  scene.setDeformation(d);
  ASSERT_NE(scene.session(), scene.baseSession());
  const Bounds moved = scene.session()->model().mesh().bounds();
  const double uxMax = scene.view()->range.max;
  EXPECT_NEAR(moved.max.x, read.max.x + 100.0 * uxMax, 1e-6 * read.diagonal());
  EXPECT_EQ(scene.deformationScale(), 100.0);
  d.scale.reset();
  scene.setDeformation(d);
  EXPECT_NEAR(scene.deformationScale() * uMax, 0.1 * read.diagonal(), 1e-9 * read.diagonal());
  // The loaded end, where it is drawn now, probes to the end's value.
  d.scale = 100.0;
  scene.setDeformation(d);
  const ProbeResult end = probeAt(*scene.session(), glm::dvec3(read.max.x + 100.0 * uxMax - 1e-3, 0.5, 0.5), 0);
  ASSERT_TRUE(end.inside());
  EXPECT_NEAR(*end.value("U.x"), uxMax, 0.02 * uxMax);
  EXPECT_NE(scene.state().toJson().find("\"deformation\""), std::string::npos);
  EXPECT_THROW(scene.setDeformation(DeformationLayer{true, "S", std::nullopt}), std::invalid_argument);
  EXPECT_EQ(scene.deformationScale(), 100.0) << "a refused deformation changes nothing";
  scene.setDeformation(DeformationLayer{});
  EXPECT_EQ(scene.session(), scene.baseSession());
  EXPECT_EQ(scene.deformationScale(), 0.0);
}

// A deformed regular grid is no longer one: its copy holds moved hexahedra and no grid, so
// the grid renderers cannot draw the undeformed samples as if they had moved.
TEST(Scene, ADeformedGridIsDrawnAsItsMovedCells) {
  auto model = std::make_shared<Model>();
  RegularGrid g;
  g.dims = {3, 3, 3};
  model->grid = g;
  std::vector<double> u(27 * 3, 0.0);
  for (std::size_t p = 0; p < 27; ++p) u[3 * p] = double(p % 3);  // x stretched by 2
  model->fields.push_back(Field::fromValues("U", FieldLocation::Node, 3, {u}));
  const auto base = ModelSession::fromModel(model);
  EXPECT_FALSE(base->model().meshBuilt()) << "a session over a grid leaves its cells unbuilt";
  const auto deformed = deformedSession(*base, "U", 0, 1.0);
  EXPECT_FALSE(deformed->model().grid);
  EXPECT_EQ(deformed->model().mesh().cellCount(), 8u);
  EXPECT_EQ(deformed->model().bounds().max.x, 4.0);
  EXPECT_TRUE(base->model().grid) << "the model as read keeps its grid";
}

// A grid's scalar kept in its file's type is shown from the field's own samples: the view
// is 16-bit integers at the field's address (no 8-byte double per point), outlives the
// session that made it, and the extremes are found without building the grid's cells; a
// quantity computed from the samples is doubles the view owns.
TEST(Scene, AGridsStoredSamplesAreShownWithoutADoubleCopy) {
  auto model = std::make_shared<Model>();
  RegularGrid g;
  g.dims = {4, 3, 2};
  g.axes = {glm::dvec3(2, 0, 0), glm::dvec3(0, 1, 0), glm::dvec3(0, 0, 1)};
  model->grid = g;
  SampleArray samples(SampleType::Int16, g.pointCount());
  for (std::size_t p = 0; p < g.pointCount(); ++p) samples.set(p, double(p) * 100.0 - 1000.0);
  samples.set(g.pointIndex(2, 1, 1), 30000.0);  // the largest, inside
  model->fields.push_back(Field::fromSamples("amplitude", FieldLocation::Node, 1, std::move(samples)));
  const Field& field = *model->fields.back();
  auto session = ModelSession::fromModel(model);
  model.reset();

  ScalarView view = session->evaluate(session->findQuantity("amplitude"), 0);
  EXPECT_EQ(view.values.type(), SampleType::Int16);
  EXPECT_EQ(view.values.bytes(), 2 * g.pointCount());
  view.values.visit([&](auto typed) {
    EXPECT_EQ(static_cast<const void*>(typed.data()), static_cast<const void*>(field.samples(0).as<std::int16_t>().data()));
  });
  EXPECT_EQ(view.range.max, 30000.0);
  EXPECT_EQ(view.range.min, -1000.0);

  Quantity magnitude = session->findQuantity("amplitude");
  magnitude.op = ScalarOp::Magnitude;
  const ScalarView computed = session->evaluate(magnitude, 0);
  EXPECT_EQ(computed.values.type(), SampleType::Float64);
  EXPECT_EQ(computed.values[0], 1000.0);

  Scene scene(rayCasterOnly());
  scene.setSession(session);
  scene.setResult("amplitude", 0);
  scene.setMarkExtremes(true);
  const auto extremes = scene.extremes();
  ASSERT_TRUE(extremes);
  EXPECT_EQ(extremes->max, 30000.0);
  EXPECT_EQ(extremes->maxAt, g.position(2, 1, 1));
  EXPECT_EQ(extremes->min, -1000.0);
  EXPECT_FALSE(session->model().meshBuilt()) << "finding the extremes built the grid's hexahedra";

  session.reset();
  scene.setSession(nullptr);
  EXPECT_EQ(view.values[g.pointIndex(2, 1, 1)], 30000.0) << "the view keeps its field alive";
}

// The undeformed outline: the undeformed bar's twelve feature edges in gray over the
// deformed picture (visible where the stretched bar no longer covers them), kept in the
// state file; without a deformation nothing changes.
TEST(Scene, TheUndeformedOutlineIsDrawnUnderTheDeformedShapeAndSaved) {
  Scene scene(rayCasterOnly());
  scene.setSession(barSession());
  scene.setResult("S.mises", 0);
  scene.setShowEdges(false);
  scene.setShowLegend(false);
  scene.setShowTriad(false);
  scene.camera().setView(StandardView::MinusY);  // the bar's side: x to the right, stretched along it
  scene.fitCamera();
  const QImage undeformed = renderSceneImage(scene, 160, 64).picture;
  DeformationLayer d{true, "U", std::nullopt};
  d.undeformedOutline = true;
  scene.setDeformation(DeformationLayer{d.shown, d.field, d.scale});
  const QImage deformed = renderSceneImage(scene, 160, 64).picture;
  scene.setDeformation(d);
  const QImage outlined = renderSceneImage(scene, 160, 64).picture;
  int changed = 0, gray = 0;
  for (int y = 0; y < outlined.height(); ++y)
    for (int x = 0; x < outlined.width(); ++x) {
      const QRgb a = deformed.pixel(x, y), b = outlined.pixel(x, y);
      if (a == b) continue;
      ++changed;
      gray += std::abs(qRed(b) - qBlue(b)) < 40 && std::abs(qRed(b) - qGreen(b)) < 40;
    }
  EXPECT_GT(changed, 20) << "the outline shows";
  EXPECT_GT(gray, changed / 2) << "in gray";
  EXPECT_NE(scene.state().toJson().find("\"undeformedOutline\": true"), std::string::npos);
  scene.setDeformation(DeformationLayer{false, "U", std::nullopt, true});
  EXPECT_TRUE(renderSceneImage(scene, 160, 64).picture == undeformed) << "no deformation: no outline";
}

// Ticks for the legend and charts: nice values inside the range; a range far from zero
// (where adding the step to a tick does not move it) ends with a few ticks, not a hang.
TEST(Legend, NiceTicksAreBoundedEvenFarFromZero) {
  EXPECT_EQ(niceTicks(0.0, 100.0, 6), (std::vector<double>{0, 20, 40, 60, 80, 100}));
  EXPECT_EQ(niceTicks(-0.3, 0.3, 6), (std::vector<double>{-0.2, 0.0, 0.2}));
  for (const auto& [lo, hi] : {std::pair{1e17, 1e17 + 10.0}, std::pair{1e300, 1.0000001e300}, std::pair{-1e308, 1e308},
                                std::pair{5e-324, 2e-323}}) {
    const auto ticks = niceTicks(lo, hi, 6);
    EXPECT_FALSE(ticks.empty());
    EXPECT_LE(ticks.size(), 40u) << lo << " " << hi;
  }
}

// A renderer whose structures would not fit the memory budget is refused before it builds
// them, with the figure; the budget restored, the same scene renders.
TEST_F(SceneWithContext, AVolumeRendererOverTheMemoryBudgetIsRefusedWithTheFigure) {
  Scene scene(rayCasterOnly());
  scene.setSession(barSession());
  scene.setResult("S.mises", 0);
  scene.setVolumeRenderer("raycast");
  scene.setVolumeShown(true);
  OffscreenTarget target(16, 16);
  const RenderContext ctx = contextFor(target);
  SceneDrawing drawing;
  drawing.initialize();
  const std::size_t budget = memoryBudget();
  setMemoryBudget(64 * 1024);
  try {
    drawing.render(scene, ctx);
    ADD_FAILURE() << "rendered over the budget";
  } catch (const std::exception& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("memory budget"), std::string::npos) << m;
    EXPECT_NE(m.find("tetrahedra"), std::string::npos) << m;
  }
  setMemoryBudget(budget);
  drawing.render(scene, ctx);
  EXPECT_FALSE(drawing.readVolumeImage().empty());
  drawing.release();
}

// The CPU renderer on a regular grid: point fields marched on the grid, a per-cell field
// through the grid's tetrahedra. Switching between them in one scene hands the renderer
// the other kind of data each time: every picture equals a fresh scene's.
TEST_F(SceneWithContext, TheCpuRendererSwitchesBetweenAGridsPointAndCellFields) {
  const auto session =
      ModelSession::load(volpost::test::meshioReaders(), volpost::test::dataFile("formats/image_points_ascii.vtk"));
  const VolumeRendererFactory cpu = [](const std::string& name) -> std::unique_ptr<VolumeRenderer> {
    if (name == "cpu") return std::make_unique<volume::CpuVolumeRenderer>();
    return nullptr;
  };
  const auto picture = [&](Scene& scene, const std::string& quantity) {
    scene.setResult(quantity, 0);
    scene.setVolumeRenderer("cpu");
    scene.setVolumeShown(true);
    return renderSceneImage(scene, 40, 32).volumeRgba;
  };
  const auto fresh = [&](const std::string& quantity) {
    Scene scene(cpu);
    scene.setSession(session);
    return picture(scene, quantity);
  };
  const std::vector<float> points = fresh("temperature"), cells = fresh("material");
  ASSERT_EQ(points.size(), 40u * 32u * 4u);
  EXPECT_NE(points, cells);
  Scene scene(cpu);
  scene.setSession(session);
  EXPECT_EQ(picture(scene, "temperature"), points);
  EXPECT_EQ(picture(scene, "material"), cells) << "the grid's tetrahedra, with the cell values";
  EXPECT_EQ(picture(scene, "temperature"), points) << "the grid again";
}

// Under a typed range the legend's footer still names the data's own extremes (it said
// "min -20 max 20" for data down to -42.4), and streamlines add their key beside the
// result's instead of replacing it; a 2D transfer function's volume keeps a legend saying
// where its colors come from.
TEST(Scene, TheLegendNamesTheDataExtremesAndKeepsEveryKey) {
  Scene scene(rayCasterOnly());
  scene.setSession(barSession());
  scene.setResult("S.xx", 0);
  const ValueRange data = scene.view()->range;
  scene.setFixedRange(DisplayRange{data.min / 2, data.max / 2});
  const auto legends = scene.legends();
  ASSERT_EQ(legends.size(), 1u);
  EXPECT_EQ(legends[0].content.min, data.min / 2);
  ASSERT_TRUE(legends[0].content.dataMin && legends[0].content.dataMax);
  EXPECT_EQ(*legends[0].content.dataMin, data.min);
  EXPECT_EQ(*legends[0].content.dataMax, data.max);
  StreamlineLayer lines;
  lines.shown = true;
  lines.field = "U";
  lines.seeds = {"line:0.5,0.2,0.5:0.5,0.8,0.5:5"};
  scene.setStreamlines(lines);
  scene.setStreamlineResult(scene.traceStreamlines());
  const auto both = scene.legends();
  ASSERT_EQ(both.size(), 2u) << "the streamlines' key replaced the result's";
  EXPECT_EQ(both[0].content.title.toStdString(), scene.view()->quantity.displayName());
  EXPECT_EQ(both[1].content.title.toStdString(), "U speed");
}

// A probed point or an extreme where a clip plane removed the model is not drawn over the
// picture (they stayed drawn in empty space).
TEST(Scene, MarkersWhereAClipPlaneRemovedTheModelAreNotDrawn) {
  Scene scene(rayCasterOnly());
  scene.setSession(barSession());
  scene.setResult("S.mises", 0);
  scene.setShowLegend(false);
  scene.setShowTriad(false);
  scene.camera().setView(StandardView::PlusY);
  scene.fitCamera();
  const glm::dvec3 kept(7.5, 0.5, 0.5), removed(2.5, 0.5, 0.5);
  scene.setProbes({kept, removed});
  const auto markedPixels = [&](const glm::dvec3& point) {
    QImage image(400, 200, QImage::Format_ARGB32);
    image.fill(Qt::transparent);
    paintSceneOverlay(image, scene);
    const auto at = scene.pictureCamera(400, 200).projectToPicture(point, 400, 200);
    int n = 0;
    for (int dy = -3; dy <= 3; ++dy)
      for (int dx = -3; dx <= 3; ++dx) n += qAlpha(image.pixel(int(at->x) + dx, int(at->y) + dy)) > 0;
    return n;
  };
  EXPECT_GT(markedPixels(removed), 0);
  scene.setClipPlanes({ClipPlane{{5.0, 0.5, 0.5}, {1.0, 0.0, 0.0}}});  // keeps x > 5
  EXPECT_GT(markedPixels(kept), 0);
  EXPECT_EQ(markedPixels(removed), 0) << "a marker drawn where the model was cut away";
}

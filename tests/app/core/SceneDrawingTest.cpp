// SPDX-License-Identifier: MIT
// A drawing holds what it handed its renderers and catches up with the scene's counts:
// a second drawing of one scene, or a drawing handed another scene, draws everything.
#include "support/BarSession.hpp"
#include "support/HeadlessGl.hpp"
#include "support/HexLattice.hpp"
#include "support/QtGuiEnvironment.hpp"
#include "support/RayCasterScene.hpp"
#include "support/ReaderSupport.hpp"
#include "support/TestSupport.hpp"

#include "core/SceneDrawing.hpp"

#include <volpost/core/Progress.hpp>
#include <volpost/render/HeadlessContext.hpp>
#include <volpost/render/OffscreenTarget.hpp>

#include <atomic>
#include <chrono>
#include <thread>

using namespace volpost;
using namespace volpost::app;

namespace {

using volpost::test::rayCasterOnly;

using volpost::test::barSession;

void showVolume(Scene& scene, const std::string& colorMap) {
  scene.setSession(barSession());
  scene.setResult("S.mises", 0);
  scene.setColorMap(colorMap);
  scene.setVolumeRenderer("raycast");
  scene.setVolumeShown(true);
}

// The frame's pixels, drawn to completion.
std::vector<std::uint8_t> draw(SceneDrawing& drawing, const Scene& scene, const OffscreenTarget& target) {
  RenderContext ctx;
  ctx.width = target.width();
  ctx.height = target.height();
  ctx.framebuffer = target.framebuffer();
  // Until nothing is pending: a refinement on a worker may take seconds while frames are
  // quick (a count of frames ran out first here, and the picture shown was the old pieces'),
  // so the wait is timed, and a test that never settles fails rather than hangs.
  const auto giveUp = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  drawing.render(scene, ctx);
  while (drawing.hasPendingWork()) {
    if (std::chrono::steady_clock::now() > giveUp) {
      ADD_FAILURE() << "the drawing still had work pending after 120 s";
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
    drawing.render(scene, ctx);
  }
  return target.readPixels();
}

// One frame, not waited for: what a window's paint draws.
void renderOnce(SceneDrawing& drawing, const Scene& scene, const OffscreenTarget& target) {
  RenderContext ctx;
  ctx.width = target.width();
  ctx.height = target.height();
  ctx.framebuffer = target.framebuffer();
  drawing.render(scene, ctx);
}

double annulusT(const glm::dvec3& p) { return p.z * (p.x + 2.0 * p.y); }

// A quarter annulus of 2^3 hex20 cells whose midside nodes sit on the arcs, showing its node
// field T (one step per function) at the first step.
void showAnnulus(Scene& scene, const std::vector<std::function<double(const glm::dvec3&)>>& steps) {
  scene.setSession(ModelSession::fromModel(test::quarterAnnulusModel(2, steps)));
  scene.setResult("T", 0);
}

}  // namespace

// A second drawing made after the scene changed (a window's second view, an export in
// the window's process) draws the whole scene, not only what changed since.
TEST(SceneDrawing, ASecondDrawingOfOneSceneDrawsEverything) {
  VOLPOST_SKIP_WITHOUT_GL();
  HeadlessContext context;
  OffscreenTarget target(40, 30);
  Scene scene(rayCasterOnly());
  showVolume(scene, "viridis");
  SceneDrawing first;
  first.initialize();
  const auto firstPixels = draw(first, scene, target);
  scene.setClipPlanes({{{5.0, 0.5, 0.5}, {1, 0, 0}}});
  const auto firstCut = draw(first, scene, target);
  EXPECT_NE(firstCut, firstPixels) << "the plane cut the volume";
  SceneDrawing second;
  second.initialize();
  EXPECT_EQ(draw(second, scene, target), firstCut);
  EXPECT_EQ(second.volumeStats().meshUploads, 1u);
  EXPECT_EQ(first.volumeStats().meshUploads, 1u) << "the first drawing uploaded the mesh once";
  second.release();
  first.release();
}

// One drawing handed another scene draws that scene, whatever its counts.
TEST(SceneDrawing, ADrawingHandedAnotherSceneDrawsThatScene) {
  VOLPOST_SKIP_WITHOUT_GL();
  HeadlessContext context;
  OffscreenTarget target(40, 30);
  Scene viridis(rayCasterOnly()), coolWarm(rayCasterOnly());
  showVolume(viridis, "viridis");
  showVolume(coolWarm, "cool-warm");
  SceneDrawing drawing;
  drawing.initialize();
  const auto first = draw(drawing, viridis, target);
  const auto other = draw(drawing, coolWarm, target);
  EXPECT_NE(other, first);
  SceneDrawing fresh;
  fresh.initialize();
  EXPECT_EQ(draw(fresh, coolWarm, target), other);
  EXPECT_EQ(draw(drawing, viridis, target), first);
  fresh.release();
  drawing.release();
}

// A renderer that draws apart (the exact reference of `volpost render`) is a scene's
// choice a state file can hold, but a drawing says it cannot draw it here and names those
// that can.
TEST(SceneDrawing, ARendererThatDrawsApartIsRefusedNamingThoseThatDrawHere) {
  VOLPOST_SKIP_WITHOUT_GL();
  HeadlessContext context;
  OffscreenTarget target(16, 16);
  VolumeRendererFactory renderers = rayCasterOnly();
  renderers.describeApart("reference", VolumeRendererTraits{});
  Scene scene(renderers);
  showVolume(scene, "viridis");
  scene.setVolumeRenderer("reference");
  SceneDrawing drawing;
  drawing.initialize();
  try {
    (void)draw(drawing, scene, target);
    ADD_FAILURE() << "drew a renderer that draws apart";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("makes its pictures apart (volpost render --renderer reference); choose one "
                                         "that draws here (raycast)"),
              std::string::npos)
        << e.what();
  }
  drawing.release();
}

// With the cells' own interpolation, another quantity or step on a quadratic model recolors
// the curved boundary already drawn (its points stay where every triangle asks for the cut
// it has: here a step that scales the first and turns it over): the picture is the one a
// fresh drawing makes of it, and going back gives the first picture again.
TEST(SceneDrawing, AnotherQuantityOnTheCurvedBoundaryDrawsWhatAFreshDrawingDraws) {
  VOLPOST_SKIP_WITHOUT_GL();
  HeadlessContext context;
  OffscreenTarget target(64, 48);
  Scene scene([](const std::string&) { return nullptr; });
  showAnnulus(scene, {annulusT, [](const glm::dvec3& p) { return 2.0 - 0.5 * annulusT(p); }});
  scene.setInterpolation(FieldInterpolation::Element);
  SceneDrawing drawing;
  drawing.initialize();
  const auto stepOne = draw(drawing, scene, target);
  const std::vector<glm::dvec3> corners = drawing.curvedBoundaryCorners();
  ASSERT_FALSE(corners.empty());
  scene.setResult("T", 1);
  const auto stepTwo = draw(drawing, scene, target);
  EXPECT_NE(stepTwo, stepOne) << "recolored";
  EXPECT_EQ(drawing.curvedBoundaryCorners(), corners) << "the points stayed";
  SceneDrawing fresh;
  fresh.initialize();
  EXPECT_EQ(draw(fresh, scene, target), stepTwo);
  scene.setResult("T", 0);
  EXPECT_EQ(draw(drawing, scene, target), stepOne);
  fresh.release();
  drawing.release();
}

// In the window (asynchronous updates) the surface in the cells' own shapes is refined on a
// worker thread: the first frame draws the flat faces at once and says work is pending; the
// frames after it draw what a synchronous drawing draws.
TEST(SceneDrawing, TheCurvedBoundaryIsRefinedOffTheWindowsThread) {
  VOLPOST_SKIP_WITHOUT_GL();
  HeadlessContext context;
  OffscreenTarget target(64, 48);
  Scene scene([](const std::string&) { return nullptr; });
  showAnnulus(scene, {annulusT});
  SceneDrawing synchronous;
  synchronous.initialize();
  const auto flat = draw(synchronous, scene, target);
  scene.setInterpolation(FieldInterpolation::Element);
  const auto curved = draw(synchronous, scene, target);
  ASSERT_NE(curved, flat);
  scene.setInterpolation(FieldInterpolation::Tetrahedra);
  SceneDrawing window;
  window.initialize();
  window.setAsynchronousUpdates(true);
  EXPECT_EQ(draw(window, scene, target), flat);
  scene.setInterpolation(FieldInterpolation::Element);
  renderOnce(window, scene, target);
  EXPECT_TRUE(window.curvedBoundaryCorners().empty()) << "the flat faces first";
  EXPECT_EQ(target.readPixels(), flat);
  EXPECT_EQ(draw(window, scene, target), curved) << "then the curved surface, once refined";
  EXPECT_FALSE(window.hasPendingWork());
  EXPECT_FALSE(window.curvedBoundaryCorners().empty());
  window.release();
  synchronous.release();
}

// The element tolerance sets how finely surfaces follow the cells' own shapes and field: a
// coarser one draws the curved boundary in fewer pieces, and going back draws the first again.
TEST(SceneDrawing, TheElementToleranceSetsHowFinelyTheCurvedBoundaryIsDrawn) {
  VOLPOST_SKIP_WITHOUT_GL();
  HeadlessContext context;
  OffscreenTarget target(64, 48);
  Scene scene([](const std::string&) { return nullptr; });
  showAnnulus(scene, {annulusT});
  scene.setInterpolation(FieldInterpolation::Element);
  SceneDrawing drawing;
  drawing.initialize();
  const auto fine = draw(drawing, scene, target);
  const std::size_t fineCorners = drawing.curvedBoundaryCorners().size();
  scene.setElementTolerance(0.1);  // the field and shape within 1/100
  const auto coarse = draw(drawing, scene, target);
  EXPECT_LT(4 * drawing.curvedBoundaryCorners().size(), fineCorners);
  EXPECT_NE(coarse, fine);
  scene.setElementTolerance(0.01);
  EXPECT_EQ(draw(drawing, scene, target), fine);
  EXPECT_EQ(drawing.curvedBoundaryCorners().size(), fineCorners);
  drawing.release();
}

// The GPU ray caster draws tetrahedra only: asked for the cells' own field of a curved hex20
// model, it is handed the split refined to the tolerance. In the window (asynchronous
// updates) that refinement runs on a worker thread: the first frame draws the split's field
// and says work is pending, the frames after it draw what a synchronous drawing draws; a new
// step and going back to the split's field draw what a fresh drawing draws.
TEST(SceneDrawing, TheGpuRayCasterDrawsTheCellsOwnFieldOnRefinedPiecesMadeOffTheWindowsThread) {
  VOLPOST_SKIP_WITHOUT_GL();
  HeadlessContext context;
  OffscreenTarget target(48, 40);
  Scene scene(rayCasterOnly());
  showAnnulus(scene, {annulusT, [](const glm::dvec3& p) { return 2.0 - p.z * (2.0 * p.x + p.y); }});
  scene.setVolumeRenderer("raycast");
  scene.setVolumeShown(true);
  SceneDrawing synchronous;
  synchronous.initialize();
  const auto split = draw(synchronous, scene, target);
  EXPECT_TRUE(synchronous.refinedVolumeNotes().empty());
  scene.setInterpolation(FieldInterpolation::Element);
  const auto own = draw(synchronous, scene, target);
  ASSERT_NE(own, split) << "the cells' own field is another picture";
  ASSERT_EQ(synchronous.refinedVolumeNotes().size(), 2u);
  EXPECT_NE(synchronous.refinedVolumeNotes()[0].find("the cells' own field drawn on"), std::string::npos);
  EXPECT_NE(synchronous.refinedVolumeNotes()[1].find("cells bend away from the flat faces of their tetrahedra"),
            std::string::npos)
      << "the annulus' cells are curved: the pieces follow their faces";
  EXPECT_NE(synchronous.refinedVolumeNotes()[1].find("drawn to their own curved faces"), std::string::npos);

  scene.setInterpolation(FieldInterpolation::Tetrahedra);
  SceneDrawing window;
  window.initialize();
  window.setAsynchronousUpdates(true);
  EXPECT_EQ(draw(window, scene, target), split);
  scene.setInterpolation(FieldInterpolation::Element);
  renderOnce(window, scene, target);
  EXPECT_TRUE(window.hasPendingWork());
  EXPECT_TRUE(window.refinedVolumeNotes().empty()) << "the split's field first";
  EXPECT_EQ(draw(window, scene, target), own) << "then the refined pieces";
  EXPECT_FALSE(window.hasPendingWork());

  // Another transfer function cuts the pieces elsewhere; meanwhile the window draws the
  // cells' field on the pieces it holds, with the new function, not the split's field.
  const TransferFunction before = scene.transferFunction();
  std::vector<ControlPoint> points = before.points();
  for (ControlPoint& p : points) p.extinction *= 3.0;
  scene.setTransferFunction(TransferFunction(points));
  renderOnce(window, scene, target);
  EXPECT_TRUE(window.hasPendingWork());
  EXPECT_FALSE(window.refinedVolumeNotes().empty()) << "the pieces it holds, not the split";
  const auto denser = draw(window, scene, target);
  EXPECT_NE(denser, own);
  {
    SceneDrawing fresh;
    fresh.initialize();
    EXPECT_EQ(draw(fresh, scene, target), denser) << "what a fresh drawing draws";
    fresh.release();
  }
  scene.setTransferFunction(before);
  EXPECT_EQ(draw(window, scene, target), own);

  scene.setResult("T", 1);
  const auto stepTwo = draw(window, scene, target);
  EXPECT_NE(stepTwo, own);
  SceneDrawing fresh;
  fresh.initialize();
  EXPECT_EQ(draw(fresh, scene, target), stepTwo);
  scene.setResult("T", 0);
  scene.setInterpolation(FieldInterpolation::Tetrahedra);
  EXPECT_EQ(draw(window, scene, target), split) << "the split again";
  EXPECT_TRUE(window.refinedVolumeNotes().empty());
  fresh.release();
  window.release();
  synchronous.release();
}

// What a refined volume says: how many pieces and how close, where the budget stopped short
// of the tolerance, and where the split leaves too little room to cut (the split is drawn).
TEST(RefinedElementVolume, ItsNoteSaysWhatWasDrawn) {
  RefinedElementMesh mesh;
  mesh.chosen = 6;
  mesh.refined.bisections = 7;
  mesh.refined.deviation = 0.0088;
  mesh.refined.tets.mesh.takeCells(CellType::Tet4, std::vector<NodeIndex>(4 * 27, 0));
  const std::vector<std::string> reached = refinedVolumeNotes(mesh);
  ASSERT_EQ(reached.size(), 1u);
  EXPECT_EQ(reached[0],
            "the cells' own field drawn on 27 tetrahedra (the split's 6, halved up to 7 times where the transfer "
            "function shows the field), a pixel's channel within 0.0088 of it (estimated)");
  mesh.refined.toleranceReached = false;
  EXPECT_NE(refinedVolumeNotes(mesh)[0].find("; the tolerance 0.01 would need more than 4,000,000 tetrahedra: the "
                                             "cpu renderer draws the cells' field itself"),
            std::string::npos);
  mesh.unrefined = true;
  mesh.chosen = 2500000;
  EXPECT_EQ(refinedVolumeNotes(mesh)[0],
            "the cells' own field would be cut from a copy of the split's 2,500,000 tetrahedra, more than half of "
            "the 4,000,000 pieces it may take: drawn linear on the split; the cpu renderer draws the cells' field "
            "itself");
}

// A refinement on the worker thread says how far it has got, is cancelled by a refinement
// for another key (its result never shown), and hands over its result once done.
TEST(RefinedElementVolume, AWorkerSaysHowFarItHasGotAndGivesWayToNewerWork) {
  RefinedElementVolume volume;
  std::atomic<bool> release{false};
  const auto slow = [&release](const Progress& progress) {
    progress.report(0.5);
    for (int i = 0; i < 20000 && !release; ++i) {  // at most 20 s: a broken test must not hang
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
      progress.report(0.5);
    }
    RefinedElementMesh out;
    out.chosen = 1;
    return out;
  };
  RefinedElementKey first;
  first.values = 1;
  EXPECT_EQ(volume.wanted(first, slow, true), nullptr);
  const auto patience = std::chrono::steady_clock::now() + std::chrono::seconds(60);  // a busy machine's thread start
  while (volume.progress().value_or(0.0) < 0.5 && std::chrono::steady_clock::now() < patience)
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  EXPECT_EQ(volume.progress(), std::optional<double>(0.5));
  RefinedElementKey second = first;
  second.values = 2;
  std::atomic<bool> go{false};
  const auto quick = [&go](const Progress&) {
    // Held until the test has seen it running: a worker that finishes at once may hand its
    // result over on the very call that starts it.
    for (int i = 0; i < 20000 && !go; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    RefinedElementMesh out;
    out.chosen = 2;
    return out;
  };
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(volume.wanted(second, quick, true), nullptr) << "the first is cancelled, the second started";
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(10)) << "cancelled, not waited out";
  go = true;
  std::shared_ptr<const RefinedElementMesh> done;
  while (!done && std::chrono::steady_clock::now() < patience) {
    done = volume.wanted(second, quick, true);
    if (!done) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  ASSERT_NE(done, nullptr);
  EXPECT_EQ(done->chosen, 2u);
  EXPECT_FALSE(volume.progress().has_value());
  EXPECT_EQ(volume.wanted(second, quick, true), done) << "kept for its key";
  release = true;
}

// Which renderers draw the cells' own field on refined pieces (and so refuse the exact
// tolerance): the command line, the window and the drawing ask the same question.
TEST(RefinedElementVolume, OnlyARendererWithoutTheCellsFieldOfItsOwnDrawsItOnPieces) {
  Model hexes;
  hexes.mesh() = test::hexLattice(CellType::Hex8, 1, [](const glm::dvec3& g) { return g; });
  Model tets;
  tets.mesh() = tetrahedralize(hexes.mesh()).mesh;
  VolumeRendererTraits gpu;
  gpu.drawsGrids = true;
  VolumeRendererTraits own;
  own.elementInterpolation = true;
  const auto element = FieldInterpolation::Element;
  EXPECT_TRUE(drawsCellsFieldOnPieces(gpu, element, FieldLocation::Node, hexes));
  EXPECT_FALSE(drawsCellsFieldOnPieces(own, element, FieldLocation::Node, hexes)) << "draws the field itself";
  EXPECT_FALSE(drawsCellsFieldOnPieces(gpu, FieldInterpolation::Tetrahedra, FieldLocation::Node, hexes));
  EXPECT_FALSE(drawsCellsFieldOnPieces(gpu, element, FieldLocation::Cell, hexes)) << "one value per cell";
  EXPECT_FALSE(drawsCellsFieldOnPieces(gpu, element, FieldLocation::Node, tets)) << "a tet4 mesh is its own split";
  Model grid;
  grid.grid = RegularGrid{};
  grid.grid->dims = {3, 3, 3};
  EXPECT_FALSE(drawsCellsFieldOnPieces(gpu, element, FieldLocation::Node, grid)) << "drawn as a grid";
  VolumeRendererTraits meshesOnly;
  EXPECT_TRUE(drawsCellsFieldOnPieces(meshesOnly, element, FieldLocation::Node, grid)) << "its hexahedra, split";
}

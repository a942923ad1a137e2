// SPDX-License-Identifier: MIT
// The user's rendering path (ModelSession -> Scene -> headless picture) on a real FE
// result: the bar pulled by 100 MPa shows S11 = 100 in its middle, so with the range
// 90..110 on the gray map the middle of the bar must be exactly mid-gray.
#include "support/ReaderSupport.hpp"
#include "support/TestSupport.hpp"

#include "core/CameraSpec.hpp"
#include "core/PluginRenderers.hpp"
#include "core/Probe.hpp"
#include "core/SceneDrawing.hpp"
#include "core/SceneImage.hpp"
#include "core/ScenePick.hpp"

#include "support/HeadlessGl.hpp"
#include "support/HexLattice.hpp"

#include <volpost/render/HeadlessContext.hpp>

#include <glm/gtc/matrix_inverse.hpp>

#include <numbers>

using namespace volpost;
using namespace volpost::app;

TEST(SceneImage, BarMiddleShowsTheAnalyticAxialStress) {
  VOLPOST_SKIP_WITHOUT_GL();
  Scene scene([](const std::string&) { return nullptr; });
  scene.setSession(ModelSession::load(volpost::test::meshioReaders(), volpost::test::dataFile("bar/bar_tet4.vtu")));
  scene.setResult("S.xx", 0);
  scene.setColorMap("grayscale");
  scene.setFixedRange(DisplayRange{90.0, 110.0});
  scene.setShowEdges(false);
  scene.setShowLegend(false);
  scene.setLighting(false);
  applyCameraSpec(scene.camera(), "-y,ortho,zoom=2");
  const QImage image = renderSceneImage(scene, 128, 64).picture;
  ASSERT_EQ(image.size(), QSize(128, 64));

  const Camera& camera = scene.camera();
  const glm::dmat4 toModel = glm::inverse(camera.projectionMatrix(2.0) * camera.viewMatrix());
  int checked = 0;
  for (int py = 0; py < image.height(); ++py)
    for (int px = 0; px < image.width(); ++px) {
      const glm::dvec4 p = toModel * glm::dvec4(2.0 * (px + 0.5) / 128 - 1.0, 1.0 - 2.0 * (py + 0.5) / 64, 0.0, 1.0);
      const double x = p.x / p.w, z = p.z / p.w;
      if (x < 3.2 || x > 6.8 || z < 0.1 || z > 0.9) continue;
      EXPECT_NEAR(qRed(image.pixel(px, py)), 127.5, 1.5) << "x=" << x << " z=" << z;
      ++checked;
    }
  EXPECT_GT(checked, 200);
}

// Contour bands: each value drawn in the color of its band's middle. S.xx is 100 in the
// bar's middle; over 92..112 in 4 bands it lies in the second band (97..102), drawn at
// t = 1.5 / 4 = 0.375 of the grayscale map; continuous colors give t = 0.4.
TEST(SceneImage, ColorBandsDrawEachBandInTheColorOfItsMiddle) {
  VOLPOST_SKIP_WITHOUT_GL();
  Scene scene([](const std::string&) { return nullptr; });
  scene.setSession(ModelSession::load(volpost::test::meshioReaders(), volpost::test::dataFile("bar/bar_tet4.vtu")));
  scene.setResult("S.xx", 0);
  scene.setColorMap("grayscale");
  scene.setFixedRange(DisplayRange{92.0, 112.0});
  scene.setShowEdges(false);
  scene.setShowLegend(false);
  scene.setShowTriad(false);
  scene.setLighting(false);
  applyCameraSpec(scene.camera(), "-y,ortho,zoom=4");
  const auto centre = [&] {
    const QImage image = renderSceneImage(scene, 64, 32).picture;
    return qRed(image.pixel(32, 16));
  };
  EXPECT_NEAR(centre(), 0.4 * 255.0, 1.5);
  scene.setColorBands(4);
  EXPECT_NEAR(centre(), 0.375 * 255.0, 1.5);
  scene.setColorMap("grayscale-reversed");
  EXPECT_NEAR(centre(), 0.625 * 255.0, 1.5);
  // Outside a typed range: the value 100 below 102..112 in the below color, not the end color.
  scene.setFixedRange(DisplayRange{102.0, 112.0});
  scene.setColorMap("grayscale");
  EXPECT_NEAR(centre(), 0.125 * 255.0, 1.5);  // the first band's middle
  scene.setOutOfRangeColors(glm::dvec3(1.0, 0.0, 0.0), std::nullopt);
  {
    const QImage image = renderSceneImage(scene, 64, 32).picture;
    EXPECT_EQ(image.pixel(32, 16) & 0xffffffu, 0xff0000u);
  }
  EXPECT_THROW(scene.setOutOfRangeColors(glm::dvec3(2.0, 0.0, 0.0), std::nullopt), std::invalid_argument);
  EXPECT_EQ(*SceneState::fromJson(scene.state().toJson(), "/v.json").belowColor, glm::dvec3(1.0, 0.0, 0.0));
  scene.setOutOfRangeColors(std::nullopt, std::nullopt);
  scene.setFixedRange(DisplayRange{92.0, 112.0});
  scene.setColorMap("grayscale-reversed");
  EXPECT_THROW(scene.setColorBands(1), std::invalid_argument);
  EXPECT_THROW(scene.setColorBands(kMaxColorBands + 1), std::invalid_argument);
  EXPECT_EQ(scene.state().colorBands, 4);
  // Symmetric about zero: the values' own range widened, a typed one kept.
  scene.setResult("S.xy", 0);
  scene.setFixedRange(std::nullopt);
  scene.setSymmetricRange(true);
  const ValueRange own = scene.view()->range;
  const double m = std::max(std::abs(own.min), std::abs(own.max));
  EXPECT_EQ(scene.displayRange(), (DisplayRange{-m, m}));
  scene.setShowLegend(true);
  ASSERT_TRUE(scene.legend());
  EXPECT_EQ(scene.legend()->content.min, -m);
  EXPECT_EQ(scene.legend()->content.bands, 4);
  scene.setFixedRange(DisplayRange{-1.0, 2.0});
  EXPECT_EQ(scene.displayRange(), (DisplayRange{-1.0, 2.0}));
  // Through the state file.
  const SceneState back = SceneState::fromJson(scene.state().toJson(), "/data/view.json");
  EXPECT_TRUE(back.symmetricRange);
  EXPECT_EQ(back.colorBands, 4);
  EXPECT_EQ(back.colorMap, "grayscale-reversed");
  std::string text = scene.state().toJson();
  text.replace(text.find("\"bands\": 4"), 10, "\"bands\": 1");
  EXPECT_THROW(SceneState::fromJson(text, "/data/view.json"), std::runtime_error);
}

// The legend's words and numbers: a title per quantity, units per field, the number style
// and label count; kept in the state file, refused when malformed.
TEST(SceneLegend, TitlesUnitsAndNumberStyles) {
  Scene scene([](const std::string&) { return nullptr; });
  scene.setSession(ModelSession::load(volpost::test::meshioReaders(), volpost::test::dataFile("bar/bar_tet4.vtu")));
  scene.setResult("S.mises", 0);
  scene.setUnits("S", "MPa");
  EXPECT_EQ(scene.legend()->content.title.toStdString(), "S von Mises [MPa]");
  scene.setLegendTitle("S.mises", "Equivalent stress");
  EXPECT_EQ(scene.legend()->content.title.toStdString(), "Equivalent stress [MPa]");
  scene.setResult("S.xx", 0);  // a title belongs to its quantity; units to the field
  EXPECT_EQ(scene.legend()->content.title.toStdString(), "S XX [MPa]");
  scene.setLegendNumbers("fixed:2");
  EXPECT_EQ(scene.legend()->content.numbers.text(3.14159).toStdString(), "3.14");
  scene.setLegendNumbers("scientific");
  EXPECT_EQ(scene.legend()->content.numbers.text(1234.5).toStdString(), "1.235e+03");
  scene.setLegendLabels(10);
  EXPECT_EQ(scene.legend()->content.labels, 10);
  EXPECT_THROW(scene.setLegendNumbers("fixed:x"), std::invalid_argument);
  EXPECT_THROW(scene.setLegendNumbers("auto:0"), std::invalid_argument);
  EXPECT_THROW(scene.setLegendLabels(1), std::invalid_argument);
  EXPECT_THROW(scene.setUnits("S", std::string(201, 'x')), std::invalid_argument);
  const SceneState back = SceneState::fromJson(scene.state().toJson(), "/data/view.json");
  EXPECT_EQ(back.units.at("S"), "MPa");
  EXPECT_EQ(back.legendTitles.at("S.mises"), "Equivalent stress");
  EXPECT_EQ(back.legendNumbers, "scientific:3");
  EXPECT_EQ(back.legendLabels, 10);
  std::string text = scene.state().toJson();
  text.replace(text.find("\"scientific:3\""), 14, "\"roman\"");
  EXPECT_THROW(SceneState::fromJson(text, "/data/view.json"), std::runtime_error);
  scene.setUnits("S", "");  // empty: none
  EXPECT_EQ(scene.legend()->content.title.toStdString(), "S XX");
}

// Units the file states show in the legend until the user types others; typed ones are
// saved, the file's are not (they come back with the file).
TEST(SceneLegend, TheFilesUnitsShowUntilOthersAreTyped) {
  auto model = std::make_shared<Model>();
  model->sourcePath = "one_tet";
  Mesh& mesh = model->mesh();
  mesh.nodes = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const NodeIndex tet[4] = {0, 1, 2, 3};
  mesh.addCell(CellType::Tet4, tet);
  auto pressure = Field::fromValues("p", FieldLocation::Node, 1, {{1.0, 2.0, 3.0, 4.0}});
  pressure->setUnits("Pa");
  model->fields.push_back(pressure);
  Scene scene([](const std::string&) { return nullptr; });
  scene.setSession(ModelSession::fromModel(model));
  scene.setResult("p", 0);
  EXPECT_EQ(scene.legend()->content.title.toStdString(), "p [Pa]");
  EXPECT_EQ(scene.unitsByField(), (std::map<std::string, std::string>{{"p", "Pa"}}));
  EXPECT_TRUE(scene.state().units.empty());
  scene.setUnits("p", "kPa");
  EXPECT_EQ(scene.legend()->content.title.toStdString(), "p [kPa]");
  EXPECT_EQ(scene.unitsOf("p"), "kPa");
  scene.setUnits("p", "");
  EXPECT_EQ(scene.legend()->content.title.toStdString(), "p [Pa]");
}

// The picture's caption: the title at the top left, kept in the state; one line only.
TEST(SceneLegend, ATitleIsPaintedAtTheTopLeftAndKept) {
  Scene scene([](const std::string&) { return nullptr; });
  scene.setSession(ModelSession::load(volpost::test::meshioReaders(), volpost::test::dataFile("bar/bar_tet4.vtu")));
  scene.setShowLegend(false);
  scene.setShowTriad(false);
  const auto darkAtTopLeft = [&] {
    QImage image(400, 200, QImage::Format_RGB32);
    image.fill(Qt::white);
    paintSceneOverlay(image, scene);
    int dark = 0;
    for (int y = 0; y < 40; ++y)
      for (int x = 0; x < 200; ++x) dark += qGray(image.pixel(x, y)) < 128;
    return dark;
  };
  EXPECT_EQ(darkAtTopLeft(), 0);
  scene.setTitle("Bar: axial stress");
  EXPECT_GT(darkAtTopLeft(), 50);
  EXPECT_EQ(SceneState::fromJson(scene.state().toJson(), "/v.json").title, "Bar: axial stress");
  EXPECT_THROW(scene.setTitle("two\nlines"), std::invalid_argument);
  EXPECT_THROW(scene.setTitle(std::string(201, 'x')), std::invalid_argument);
  // The step written under it: more words, kept in the file; nothing without a result.
  const int titleOnly = darkAtTopLeft();
  scene.setStepText(true);
  EXPECT_EQ(darkAtTopLeft(), titleOnly) << "no result shown: no step to write";
  scene.setResult("S.mises", 0);
  EXPECT_GT(darkAtTopLeft(), titleOnly + 30);
  EXPECT_TRUE(SceneState::fromJson(scene.state().toJson(), "/v.json").stepText);
}

// A regular grid's slices: nothing drawn without them (surface hidden); a slice draws the
// grid's values across it, and the bottom slice seen from below is the box's bottom face
// (the same values on the same plane); refused on a mesh and outside the grid, naming the
// axis and its range; kept in the state.
TEST(SceneImage, GridSlicesShowTheValuesAcrossTheGrid) {
  VOLPOST_SKIP_WITHOUT_GL();
  Scene scene([](const std::string&) { return nullptr; });
  scene.setSession(
      ModelSession::load(volpost::test::meshioReaders(), volpost::test::dataFile("formats/image_ascii.vti")));
  scene.setResult("temperature", 0);
  scene.setShowEdges(false);
  scene.setShowLegend(false);
  scene.setShowTriad(false);
  scene.setLighting(false);
  const auto coloured = [](const QImage& image) {
    const QRgb background = image.pixel(0, 0);
    int n = 0;
    for (int y = 0; y < image.height(); ++y)
      for (int x = 0; x < image.width(); ++x) n += image.pixel(x, y) != background;
    return n;
  };
  applyCameraSpec(scene.camera(), "-z,ortho");
  const QImage face = renderSceneImage(scene, 96, 96).picture;  // the box's bottom face, k = 2
  scene.setSurfaceShown(false);
  EXPECT_EQ(coloured(renderSceneImage(scene, 96, 96).picture), 0) << "no surface, no slice: nothing";
  scene.setGridSlices({std::nullopt, std::nullopt, 2.0});
  ASSERT_EQ(scene.gridSlicePlanes().size(), 1u);
  const QImage bottom = renderSceneImage(scene, 96, 96).picture;
  EXPECT_GT(coloured(bottom), 400);
  // The face's quads and the slice's cut tets interpolate the same corner values; only the
  // split of each quad into triangles may differ.
  double difference = 0;
  int compared = 0;
  for (int y = 0; y < 96; ++y)
    for (int x = 0; x < 96; ++x)
      if (face.pixel(x, y) != face.pixel(0, 0) && bottom.pixel(x, y) != bottom.pixel(0, 0)) {
        difference += std::abs(qRed(face.pixel(x, y)) - qRed(bottom.pixel(x, y))) +
                      std::abs(qBlue(face.pixel(x, y)) - qBlue(bottom.pixel(x, y)));
        ++compared;
      }
  ASSERT_GT(compared, 400);
  EXPECT_NEAR(compared, coloured(face), 0.05 * coloured(face)) << "the slice covers the face";
  EXPECT_LT(difference / compared, 6.0) << "mean difference per pixel, of 510";
  scene.setGridSlices({std::nullopt, std::nullopt, 4.0});
  EXPECT_NE(renderSceneImage(scene, 96, 96).picture, bottom) << "the top slice has other values";
  // A click picks what shows: the slice (k = 3 lies at z = 6.5) when the surface is hidden,
  // the bottom face (z = 4.5, seen from below) when it shows.
  scene.setGridSlices({std::nullopt, std::nullopt, 3.0});
  const PickRay ray = pixelRay(scene.pictureCamera(96, 96), 48, 48, 96, 96);
  const auto onSlice = pickScenePoint(scene, ray);
  ASSERT_TRUE(onSlice.has_value());
  EXPECT_NEAR(onSlice->z, 6.5, 1e-9);
  scene.setSurfaceShown(true);
  const auto onFace = pickScenePoint(scene, ray);
  ASSERT_TRUE(onFace.has_value());
  EXPECT_NEAR(onFace->z, 4.5, 1e-9);
  scene.setSurfaceShown(false);
  scene.setGridSlices({std::nullopt, std::nullopt, 4.0});
  try {
    scene.setGridSlices({std::nullopt, 7.5, std::nullopt});
    ADD_FAILURE() << "a slice outside the grid was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "the j slice at 7.5 lies outside the grid's j 0 .. 3");
  }
  EXPECT_EQ(scene.state().gridSlices[2], 4.0) << "a refused change leaves the slices";
  const SceneState back = SceneState::fromJson(scene.state().toJson(), "/tmp/s.json");
  EXPECT_EQ(back.gridSlices, scene.state().gridSlices);

  Scene mesh([](const std::string&) { return nullptr; });
  mesh.setSession(ModelSession::load(volpost::test::meshioReaders(), volpost::test::dataFile("bar/bar_tet4.vtu")));
  EXPECT_THROW(mesh.setGridSlices({1.0, std::nullopt, std::nullopt}), std::invalid_argument);
  EXPECT_NO_THROW(mesh.setGridSlices({}));
}

// A click on a section cut probes the cut face, not the surface that was cut away; on the
// kept side of a plane the surface is picked as before.
TEST(ScenePick, ClicksPickTheSectionFaceWhereThePlaneCutsTheSurfaceAway) {
  Scene scene([](const std::string&) { return nullptr; });
  scene.setSession(ModelSession::load(volpost::test::meshioReaders(), volpost::test::dataFile("bar/bar_tet4.vtu")));
  applyCameraSpec(scene.camera(), "+x,ortho");
  const PickRay ray = pixelRay(scene.pictureCamera(64, 64), 32, 32, 64, 64);
  const auto whole = pickScenePoint(scene, ray);
  ASSERT_TRUE(whole.has_value());
  const glm::dvec3 centre = scene.session()->bounds().center();
  const glm::dvec3 away = scene.camera().viewDirection();
  scene.setClipPlanes({{centre, away}});  // keeps the far half: the near end is cut away
  const auto cut = pickScenePoint(scene, ray);
  ASSERT_TRUE(cut.has_value());
  EXPECT_NEAR(glm::dot(*cut - centre, away), 0.0, 1e-9) << "on the section's plane";
  EXPECT_GT(glm::length(*cut - *whole), 1.0);
  scene.setClipPlanes({{centre, -away}});  // keeps the near half: the surface as before
  const auto kept = pickScenePoint(scene, ray);
  ASSERT_TRUE(kept.has_value());
  EXPECT_NEAR(glm::length(*kept - *whole), 0.0, 1e-9);
}

// A click on an iso-surface of the surface view probes the iso-surface: with the surface
// hidden every hit has the iso-value (tet4 and a displacement component: linear in each
// tet, as the extraction is); a hidden surface is not clicked on.
TEST(ScenePick, ClicksPickIsoSurfacesInTheSurfaceView) {
  VOLPOST_SKIP_WITHOUT_GL();
  Scene scene([](const std::string&) { return nullptr; });
  scene.setSession(ModelSession::load(volpost::test::meshioReaders(), volpost::test::dataFile("bar/bar_tet4.vtu")));
  scene.setResult("U.x", 0);  // the stretch along the bar: its iso-surfaces cross it
  scene.setShowLegend(false);
  applyCameraSpec(scene.camera(), "+x,ortho,zoom=6");
  const PickRay centre = pixelRay(scene.pictureCamera(64, 64), 32, 32, 64, 64);
  ASSERT_TRUE(pickScenePoint(scene, centre).has_value());
  scene.setSurfaceShown(false);
  EXPECT_FALSE(pickScenePoint(scene, centre).has_value()) << "a hidden surface is not clicked on";
  const double iso = 0.5 * (scene.view()->range.min + scene.view()->range.max);
  scene.setIsoSurfaces({{iso, {1, 0.8, 0.2}, 1.0}});
  const SceneImage drawn = renderSceneImage(scene, 64, 64);
  ASSERT_GT(drawn.isoSurfaceCorners.size(), 0u);
  int hits = 0;
  for (int y = 1; y < 64; y += 2)
    for (int x = 1; x < 64; x += 2) {
      const auto p =
          pickScenePoint(scene, pixelRay(scene.pictureCamera(64, 64), x, y, 64, 64), drawn.isoSurfaceCorners);
      if (!p) continue;
      ++hits;
      const ProbeResult r = probeAt(*scene.session(), *p, 0);
      ASSERT_TRUE(r.inside());
      EXPECT_NEAR(r.value("U.x").value(), iso, 1e-5 * std::abs(iso)) << "pixel " << x << ", " << y;
    }
  EXPECT_GT(hits, 20) << "clicks land on the iso-surface";
}

// Where the boundary is drawn in the cells' own (curved) shapes, a click lands on the curved
// face drawn, not on the flat faces through the nodes: a quarter annulus of hex20 cells
// whose midside nodes sit on the arcs, clicked from its axis onto the inner cylinder
// (radius 1). The flat faces sag inside it by up to 1 - cos(11.25 degrees) = 0.019; the
// drawn surface follows the cells' own faces (parabolas through three points of each 45
// degree arc: within 7.3e-4 of the circle) to the refinement's tolerance (1/1000 of the
// 0.79 long side). The probe reads the clicked point inside the model.
TEST(ScenePick, ClicksLandOnTheCurvedFacesDrawn) {
  VOLPOST_SKIP_WITHOUT_GL();
  Scene scene([](const std::string&) { return nullptr; });
  scene.setSession(ModelSession::fromModel(
      test::quarterAnnulusModel(2, {[](const glm::dvec3& p) { return p.z * (p.x + 2.0 * p.y); }})));
  scene.setResult("T", 0);
  scene.setInterpolation(FieldInterpolation::Element);
  const SceneImage drawn = renderSceneImage(scene, 64, 64);
  ASSERT_GT(drawn.curvedBoundaryCorners.size(), 0u) << "the boundary is drawn curved";
  double curvedWorst = 0.0, flatWorst = 0.0;
  for (double degrees = 2.0; degrees < 90.0; degrees += 1.7) {
    const double a = degrees * std::numbers::pi / 180.0;
    const PickRay fromAxis{{0.0, 0.0, 0.5}, {std::cos(a), std::sin(a), 0.0}};
    const auto curved = pickScenePoint(scene, fromAxis, {}, drawn.curvedBoundaryCorners);
    const auto flat = pickScenePoint(scene, fromAxis);
    ASSERT_TRUE(curved && flat) << degrees << " degrees";
    curvedWorst = std::max(curvedWorst, std::abs(std::hypot(curved->x, curved->y) - 1.0));
    flatWorst = std::max(flatWorst, std::abs(std::hypot(flat->x, flat->y) - 1.0));
    EXPECT_TRUE(probeAt(*scene.session(), *curved, 0).inside()) << degrees << " degrees";
  }
  EXPECT_LT(curvedWorst, 7.3e-4 + 0.79e-3);
  EXPECT_GT(flatWorst, 1e-2);
}

// A log scale: S.xx = 100 in the bar's middle sits halfway between 10 and 1000 in log
// terms (mid-gray on the gray map); linearly it would be at 0.09 of the way.
TEST(SceneImage, ALogScaleColorsByTheLogarithm) {
  VOLPOST_SKIP_WITHOUT_GL();
  Scene scene([](const std::string&) { return nullptr; });
  scene.setSession(ModelSession::load(volpost::test::meshioReaders(), volpost::test::dataFile("bar/bar_tet4.vtu")));
  scene.setResult("S.xx", 0);
  scene.setColorMap("grayscale");
  scene.setFixedRange(DisplayRange{10.0, 1000.0});
  scene.setShowEdges(false);
  scene.setShowLegend(false);
  scene.setShowTriad(false);
  scene.setLighting(false);
  applyCameraSpec(scene.camera(), "-y,ortho,zoom=4");
  const auto centre = [&] { return qRed(renderSceneImage(scene, 64, 32).picture.pixel(32, 16)); };
  EXPECT_NEAR(centre(), 90.0 / 990.0 * 255.0, 1.5);
  scene.setLogScale(true);
  EXPECT_NEAR(centre(), 0.5 * 255.0, 1.5);
  scene.setColorBands(4);  // log bands: 10..31.6..100..316..1000, 100 at the third's start
  EXPECT_NEAR(centre(), 2.5 / 4.0 * 255.0, 1.5);
  EXPECT_THROW(scene.setFixedRange(DisplayRange{0.0, 10.0}), std::invalid_argument);
  EXPECT_EQ(scene.displayRange(), (DisplayRange{10.0, 1000.0})) << "a refused range changes nothing";
  // The values' own range reaching 0 starts at the smallest positive value.
  scene.setFixedRange(std::nullopt);
  scene.setResult("U.magnitude", 0);
  EXPECT_GT(scene.displayRange().min, 0.0);
  EXPECT_EQ(scene.view()->range.min, 0.0);
  scene.setShowLegend(true);
  ASSERT_TRUE(scene.legend());
  EXPECT_TRUE(scene.legend()->content.logScale);
  EXPECT_TRUE(SceneState::fromJson(scene.state().toJson(), "/data/view.json").logScale);
  scene.setLogScale(false);
  scene.setFixedRange(DisplayRange{-1.0, 1.0});
  EXPECT_THROW(scene.setLogScale(true), std::invalid_argument);
}

TEST(SceneLegend, QuantitiesTakeTheirOwnUnits) {
  Quantity q;
  q.field = "S";
  q.fieldKind = FieldKind::SymTensor;
  q.op = ScalarOp::VonMises;
  EXPECT_EQ(quantityUnits(q, "MPa"), QString("MPa"));
  q.op = ScalarOp::DeviatoricJ2;
  EXPECT_EQ(quantityUnits(q, "MPa"), QString("(MPa)^2"));
  q.op = ScalarOp::DeviatoricJ3;
  EXPECT_EQ(quantityUnits(q, "MPa"), QString("(MPa)^3"));
  q.op = ScalarOp::Triaxiality;
  EXPECT_EQ(quantityUnits(q, "MPa"), QString());
  q.op = ScalarOp::LodeAngle;
  EXPECT_EQ(quantityUnits(q, ""), QString("deg"));
  q.op = ScalarOp::DeviatoricJ2;
  EXPECT_EQ(quantityUnits(q, ""), QString()) << "no units typed: none squared";
}

TEST(SceneLegend, LogTicksArePowersOfTenAndTheirMultiples) {
  EXPECT_EQ(logTicks(1.0, 1000.0, 3), (std::vector<double>{1.0, 10.0, 100.0, 1000.0}));
  const std::vector<double> fine = logTicks(0.03, 200.0, 6);
  EXPECT_EQ(fine.front(), 0.05);
  EXPECT_EQ(fine.back(), 200.0);
  EXPECT_GE(fine.size(), 6u);
  const std::vector<double> wide = logTicks(1.0, 1e12, 6);  // every other power
  EXPECT_LE(wide.size(), 7u);
  EXPECT_EQ(wide.front(), 1.0);
  EXPECT_EQ(logTicks(2.0, 3.0, 6), (std::vector<double>{2.0, 3.0})) << "none inside: the ends";
}

// A diverging map centres zero by default for values of both signs; another map, one-signed
// values or the user's own choice keep the values' own range.
TEST(SceneLegend, ADivergingMapIsSymmetricForSignedValuesUnlessChosenOtherwise) {
  Scene scene([](const std::string&) { return nullptr; });
  scene.setSession(ModelSession::load(volpost::test::meshioReaders(), volpost::test::dataFile("bar/bar_tet4.vtu")));
  scene.setResult("S.xy", 0);
  const ValueRange own = scene.view()->range;
  ASSERT_LT(own.min, 0.0);
  ASSERT_GT(own.max, 0.0);
  const double m = std::max(-own.min, own.max);
  EXPECT_EQ(scene.state().colorMap, "cool-warm");
  EXPECT_EQ(scene.displayRange(), (DisplayRange{-m, m}));
  EXPECT_TRUE(scene.symmetricRangeShown());
  scene.setColorMap("viridis");
  EXPECT_EQ(scene.displayRange(), (DisplayRange{own.min, own.max}));
  scene.setColorMap("seismic-reversed");
  EXPECT_EQ(scene.displayRange(), (DisplayRange{-m, m}));
  scene.setResult("S.mises", 0);  // one sign: its own range
  EXPECT_EQ(scene.displayRange().min, scene.view()->range.min);
  scene.setResult("S.xy", 0);
  EXPECT_EQ(SceneState::fromJson(scene.state().toJson(), "/v.json").symmetricAuto, true);
  scene.setSymmetricRange(false);  // chosen: kept, in the file too
  EXPECT_EQ(scene.displayRange(), (DisplayRange{own.min, own.max}));
  const SceneState back = SceneState::fromJson(scene.state().toJson(), "/v.json");
  EXPECT_FALSE(back.symmetricAuto);
  EXPECT_FALSE(back.symmetricRange);
  scene.setSymmetricRangeAutomatic();
  EXPECT_EQ(scene.displayRange(), (DisplayRange{-m, m}));
}

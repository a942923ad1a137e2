// SPDX-License-Identifier: MIT
// How the boundary is drawn (surface, wireframe, points, feature edges, outline) and free
// slices, on the bar pulled by 100 MPa: S.xx = 100 in its middle, mid-gray over 90..110 on
// the gray map, seen square-on from -y.
#include "support/BarPicture.hpp"
#include "support/ReaderSupport.hpp"
#include "support/TestSupport.hpp"

#include "core/CameraSpec.hpp"
#include "core/PluginRenderers.hpp"
#include "core/SceneDrawing.hpp"
#include "core/SceneImage.hpp"

#include "support/HeadlessGl.hpp"

using namespace volpost;
using namespace volpost::app;

namespace {

std::unique_ptr<Scene> barScene() { return volpost::test::flatBarScene("grayscale"); }

bool midGray(QRgb p) { return std::abs(qRed(p) - 128) <= 3 && qRed(p) == qGreen(p) && qGreen(p) == qBlue(p); }
// The map's colors (viridis has no gray) and the edges' dark gray.
bool colored(QRgb p) {
  return std::max({qRed(p), qGreen(p), qBlue(p)}) - std::min({qRed(p), qGreen(p), qBlue(p)}) > 20;
}
bool dark(QRgb p) { return colored(p) ? false : qRed(p) < 80; }

int count(const QImage& image, bool (*test)(QRgb)) {
  int n = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) n += test(image.pixel(x, y)) ? 1 : 0;
  return n;
}

}  // namespace

TEST(SceneRepresentation, EachRepresentationDrawsWhatItNames) {
  VOLPOST_SKIP_WITHOUT_GL();
  auto scene = barScene();
  scene->setColorMap("viridis");
  const QImage surface = renderSceneImage(*scene, 256, 128).picture;
  const int faces = count(surface, colored);
  ASSERT_GT(faces, 5000) << "the bar's face in the map's colors";
  EXPECT_EQ(count(surface, dark), 0);

  scene->setRepresentation(SurfaceRepresentation::Wireframe);
  const QImage wireframe = renderSceneImage(*scene, 256, 128).picture;
  // No faces, only the element edges, in the result's colors as ParaView draws a wireframe.
  const int edges = count(wireframe, colored);
  EXPECT_GT(edges, 1000);
  EXPECT_EQ(count(wireframe, dark), 0) << "no edge left in the edge color";
  int between = 0;  // the background between the edges, where the surface had its face
  for (int y = 0; y < 128; ++y)
    for (int x = 0; x < 256; ++x) between += colored(surface.pixel(x, y)) && !colored(wireframe.pixel(x, y));
  EXPECT_GT(between, 200);
  // The edge at each pixel has the face's color there (a wireframe of the same values).
  int alike = 0, drawn = 0;
  for (int y = 0; y < 128; ++y)
    for (int x = 0; x < 256; ++x)
      if (colored(wireframe.pixel(x, y)) && colored(surface.pixel(x, y))) {
        ++drawn;
        const QRgb a = wireframe.pixel(x, y), b = surface.pixel(x, y);
        alike += std::abs(qRed(a) - qRed(b)) + std::abs(qGreen(a) - qGreen(b)) + std::abs(qBlue(a) - qBlue(b)) < 40;
      }
  EXPECT_GT(alike, drawn * 9 / 10) << alike << " of " << drawn;
  scene->setResult("", 0);  // without a result: the edge color
  const QImage plain = renderSceneImage(*scene, 256, 128).picture;
  EXPECT_EQ(count(plain, colored), 0);
  EXPECT_GT(count(plain, dark), 1000);
  scene->setResult("S.xx", 0);
  scene->setFixedRange(DisplayRange{90.0, 110.0});

  scene->setRepresentation(SurfaceRepresentation::Points);
  scene->setPointSize(2.0);
  const QImage points = renderSceneImage(*scene, 256, 128).picture;
  const int dots = count(points, colored);
  EXPECT_GT(dots, 300) << "the nodes in their value's color";
  EXPECT_LT(dots, faces * 3 / 4) << "with the background between them";
  EXPECT_EQ(count(points, dark), 0);

  for (const SurfaceRepresentation r : {SurfaceRepresentation::FeatureEdges, SurfaceRepresentation::Outline}) {
    scene->setRepresentation(r);
    const QImage lines = renderSceneImage(*scene, 256, 128).picture;
    EXPECT_EQ(count(lines, colored), 0) << toString(r);
    // The box's edges seen square-on: its rectangle's border, nothing across its face.
    EXPECT_GT(count(lines, dark), 300) << toString(r);
    EXPECT_LT(count(lines, dark), 1200) << toString(r);
    EXPECT_FALSE(dark(lines.pixel(128, 64))) << toString(r);
  }
  EXPECT_THROW(scene->setPointSize(0.5), std::invalid_argument);
  EXPECT_THROW(scene->setPointSize(kMaxPointSize + 1.0), std::invalid_argument);
}

TEST(SceneRepresentation, ASliceShowsTheValuesInsideWithoutCuttingTheModel) {
  VOLPOST_SKIP_WITHOUT_GL();
  auto scene = barScene();
  scene->setSurfaceShown(false);
  EXPECT_EQ(count(renderSceneImage(*scene, 128, 64).picture, midGray), 0) << "nothing drawn";
  scene->setSlicePlanes({ClipPlane{{5.0, 0.5, 0.5}, {0.0, 1.0, 0.0}}});
  const QImage slice = renderSceneImage(*scene, 128, 64).picture;
  EXPECT_TRUE(midGray(slice.pixel(64, 32))) << "S.xx = 100 on the slice through the middle";
  EXPECT_GT(count(slice, midGray), 1000);
  // A clip plane cuts the slice as it cuts the model: x < 5 is gone.
  scene->setClipPlanes({ClipPlane{{5.0, 0.0, 0.0}, {1.0, 0.0, 0.0}}});
  const QImage cut = renderSceneImage(*scene, 128, 64).picture;
  EXPECT_FALSE(midGray(cut.pixel(32, 32)));
  EXPECT_TRUE(midGray(cut.pixel(96, 32)));
  EXPECT_THROW(scene->setSlicePlanes({ClipPlane{{0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}}}), std::invalid_argument);
  EXPECT_THROW(scene->setSlicePlanes(std::vector<ClipPlane>(kMaxSlicePlanes + 1, ClipPlane{{0, 0, 0}, {1, 0, 0}})),
               std::invalid_argument);
  EXPECT_EQ(scene->state().slicePlanes.size(), 1u) << "a refused change keeps what was";
  // Another model has its own slices: none.
  scene->setSession(ModelSession::load(volpost::test::meshioReaders(), volpost::test::dataFile("bar/bar_tet4.vtu")));
  EXPECT_TRUE(scene->state().slicePlanes.empty());
}

TEST(SceneRepresentation, TheStateFileKeepsTheRepresentationSlicesAndOutline) {
  SceneState s;
  s.modelPath = "/data/bar.vtu";
  s.representation = SurfaceRepresentation::Points;
  s.pointSize = 7.0;
  s.slicePlanes = {ClipPlane{{1.0, 2.0, 3.0}, {0.0, 0.0, 0.5}}};
  s.volume.outline = true;
  const SceneState back = SceneState::fromJson(s.toJson(), "/data/view.json");
  EXPECT_EQ(back.representation, SurfaceRepresentation::Points);
  EXPECT_EQ(back.pointSize, 7.0);
  ASSERT_EQ(back.slicePlanes.size(), 1u);
  EXPECT_EQ(back.slicePlanes[0].point, glm::dvec3(1.0, 2.0, 3.0));
  EXPECT_TRUE(back.volume.outline);
  const auto refused = [&](const std::string& from, const std::string& to, const std::string& named) {
    std::string text = s.toJson();
    const auto at = text.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
    try {
      SceneState::fromJson(text, "/data/view.json");
      ADD_FAILURE() << to << " was accepted";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find(named), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("view.json"), std::string::npos) << e.what();
    }
  };
  refused("\"representation\": \"points\"", "\"representation\": \"mesh\"", "wireframe");
  refused("\"pointSize\": 7.0", "\"pointSize\": 0.0", "surface.pointSize");
  refused("0.5", "0.0", "slicePlanes[0].normal");  // the normal's only non-zero component
  for (const char* name : {"surface", "wireframe", "points", "feature-edges", "outline"})
    EXPECT_EQ(toString(*surfaceRepresentationFromString(name)), name);
  EXPECT_FALSE(surfaceRepresentationFromString("Surface"));
}

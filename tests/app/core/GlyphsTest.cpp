// SPDX-License-Identifier: MIT
// Glyphs at the nodes of the bar pulled by 100 MPa: arrows of U that start at their node
// and end where the scaled vector does, principal bars as long as each principal value,
// the automatic scale, the stride, refusals, the state file and the picture.
#include "support/ReaderSupport.hpp"
#include "support/TestSupport.hpp"

#include "core/CameraSpec.hpp"
#include "core/Glyphs.hpp"
#include "core/PluginRenderers.hpp"
#include "core/SceneDrawing.hpp"
#include "core/SceneImage.hpp"

#include "support/HeadlessGl.hpp"

#include <volpost/core/Quantity.hpp>

#include <glm/geometric.hpp>

using namespace volpost;
using namespace volpost::app;

namespace {

std::shared_ptr<ModelSession> bar() {
  return ModelSession::load(volpost::test::meshioReaders(), volpost::test::dataFile("bar/bar_tet4.vtu"));
}

constexpr std::size_t kArrowCorners = 8 * 4 * 3;  // eight sides: shaft (2), cone (1), cone base (1)
constexpr std::size_t kTipCorner = 8;             // the first side's cone apex

}  // namespace

TEST(Glyphs, EachArrowRunsFromItsNodeAlongTheScaledVector) {
  const auto session = bar();
  GlyphLayer layer;
  layer.shown = true;
  layer.field = "U";
  layer.allNodes = true;
  layer.every = 1;
  layer.scale = 500.0;
  const GlyphGeometry g = buildGlyphs(*session, layer, 0);
  const std::vector<double>& u = session->model().findField("U")->values(0);
  const auto& nodes = session->model().mesh().nodes;
  // The nodes with a displacement, in order: the arrows' order.
  std::vector<std::size_t> moved;
  for (std::size_t n = 0; n < nodes.size(); ++n)
    if (glm::length(glm::dvec3(u[3 * n], u[3 * n + 1], u[3 * n + 2])) > 0.0) moved.push_back(n);
  ASSERT_EQ(g.glyphs, moved.size());
  EXPECT_EQ(g.candidates, nodes.size());
  ASSERT_EQ(g.corners.size(), g.glyphs * kArrowCorners);
  ASSERT_EQ(g.values.size(), g.corners.size());
  double largest = 0.0;
  for (std::size_t k = 0; k < g.glyphs; k += 97) {
    const std::size_t n = moved[k];
    const glm::dvec3 v(u[3 * n], u[3 * n + 1], u[3 * n + 2]);
    const glm::dvec3 tip = g.corners[k * kArrowCorners + kTipCorner];
    EXPECT_NEAR(glm::length(tip - (nodes[n] + 500.0 * v)), 0.0, 1e-9 * glm::length(v) * 500.0 + 1e-12) << n;
    EXPECT_DOUBLE_EQ(g.values[k * kArrowCorners], glm::length(v)) << "colored by its length";
    largest = std::max(largest, glm::length(v));
  }
  EXPECT_GT(largest, 0.0);
  // Automatic: the longest arrow is 6 % of the model's diagonal.
  layer.scale.reset();
  const GlyphGeometry automatic = buildGlyphs(*session, layer, 0);
  double longest = 0.0;
  for (std::size_t k = 0; k < automatic.glyphs; ++k)
    longest = std::max(longest, glm::length(automatic.corners[k * kArrowCorners + kTipCorner] - nodes[moved[k]]));
  EXPECT_NEAR(longest, kAutomaticGlyphSize * session->bounds().diagonal(), 1e-9);
  // Fixed length: every arrow as long as the scale.
  layer.fixedLength = true;
  layer.scale = 0.25;
  const GlyphGeometry fixed = buildGlyphs(*session, layer, 0);
  for (std::size_t k = 0; k < fixed.glyphs; k += 101)
    EXPECT_NEAR(glm::length(fixed.corners[k * kArrowCorners + kTipCorner] - nodes[moved[k]]), 0.25, 1e-12);
  // A stride: one node in 10, and the surface's nodes alone are fewer.
  layer.every = 10;
  EXPECT_EQ(buildGlyphs(*session, layer, 0).candidates, nodes.size());
  EXPECT_LE(buildGlyphs(*session, layer, 0).glyphs, (nodes.size() + 9) / 10);
  layer.allNodes = false;
  EXPECT_LT(buildGlyphs(*session, layer, 0).candidates, nodes.size());
}

TEST(Glyphs, PrincipalBarsAreAsLongAsEachPrincipalValueAndColoredByIt) {
  const auto session = bar();
  GlyphLayer layer;
  layer.shown = true;
  layer.field = "S";
  layer.allNodes = true;
  layer.every = 500;
  layer.scale = 0.001;
  const GlyphGeometry g = buildGlyphs(*session, layer, 0);
  ASSERT_GT(g.glyphs, 0u);
  constexpr std::size_t kBarCorners = (4 * 2 + 2 * 2) * 3;
  ASSERT_EQ(g.corners.size() % kBarCorners, 0u);
  // The first node's bars: one per non-zero principal value, the longest along S.p1's direction.
  const double* s = session->model().findField("S")->values(0).data();
  const PrincipalAxes axes = principalAxes(s);  // node 0 is used (every 500th from the first)
  std::size_t bars = 0;
  for (double v : axes.values) bars += v != 0.0 ? 1 : 0;
  ASSERT_GE(g.corners.size() / kBarCorners, bars);
  for (std::size_t b = 0; b < bars; ++b) {
    const double value = g.values[b * kBarCorners];
    double extent = 0.0;  // along the bar: its two end faces are the farthest corners apart
    for (std::size_t i = b * kBarCorners; i < (b + 1) * kBarCorners; ++i)
      for (std::size_t j = i + 1; j < (b + 1) * kBarCorners; ++j)
        extent = std::max(extent, glm::length(g.corners[i] - g.corners[j]));
    const double length = std::abs(value) * 0.001;
    EXPECT_NEAR(extent, std::sqrt(length * length + 2.0 * std::pow(0.08 * length, 2.0)), 1e-9 * (1.0 + length));
    EXPECT_NEAR(value, axes.values[b], 1e-9 * std::abs(axes.values[b]));
  }
  EXPECT_EQ(g.min, -g.max) << "tension and compression either side of the middle";
  EXPECT_EQ(g.valueName, "S principal values");
}

TEST(Glyphs, RefusalsNameTheChoices) {
  const auto session = bar();
  GlyphLayer layer;
  layer.shown = true;
  layer.field = "S11";
  try {
    checkGlyphLayer(*session, layer);
    ADD_FAILURE();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("this model has: U, S"), std::string::npos) << e.what();
  }
  layer.field = "U";
  layer.colorBy = "region";
  EXPECT_THROW(checkGlyphLayer(*session, layer), std::invalid_argument);
  layer.colorBy = "nothing";
  EXPECT_THROW(checkGlyphLayer(*session, layer), std::invalid_argument);
  layer.colorBy.clear();
  layer.scale = -1.0;
  EXPECT_THROW(checkGlyphLayer(*session, layer), std::invalid_argument);
  Scene scene([](const std::string&) { return nullptr; });
  scene.setSession(bar());
  layer.scale.reset();
  layer.colorBy = "S.mises";
  scene.setGlyphs(layer);
  layer.field = "T";
  EXPECT_THROW(scene.setGlyphs(layer), std::invalid_argument);
  EXPECT_EQ(scene.glyphLayer().field, "U") << "a refused change keeps what was";
  const SceneState back = SceneState::fromJson(scene.state().toJson(), "/data/view.json");
  EXPECT_EQ(back.glyphs, scene.glyphLayer());
  ASSERT_TRUE(scene.glyphs());
  ASSERT_EQ(scene.legends().size(), 1u) << "no result shown: the glyphs' key alone";
  EXPECT_EQ(scene.legends().back().content.title, QString("S.mises"));
}

TEST(Glyphs, TheyAreDrawnWhereTheModelIsNot) {
  VOLPOST_SKIP_WITHOUT_GL();
  Scene scene([](const std::string&) { return nullptr; });
  scene.setSession(bar());
  scene.setShowLegend(false);
  scene.setShowTriad(false);
  scene.setSurfaceShown(false);
  applyCameraSpec(scene.camera(), "-y,ortho,zoom=2");
  const auto drawn = [&] {
    const QImage image = renderSceneImage(scene, 128, 64).picture;
    int n = 0;
    for (int y = 0; y < 64; ++y)
      for (int x = 0; x < 128; ++x) n += image.pixel(x, y) != image.pixel(0, 0) ? 1 : 0;
    return n;
  };
  EXPECT_EQ(drawn(), 0);
  GlyphLayer layer;
  layer.shown = true;
  layer.field = "U";
  scene.setGlyphs(layer);
  EXPECT_GT(drawn(), 100);
}

// A clip plane cuts the glyphs at their places: a node it removes has none, a kept one is
// drawn whole; the cut faces carry one glyph per cut element, at its face's centre, its
// vector interpolated along the cut edges (exact for a linear field).
TEST(Glyphs, OnTheCutFacesAndNotOnWhatTheCutRemoves) {
  // A block of 2 x 2 x 2 unit hexahedra with U = (x, 2y, 0) at its nodes.
  auto model = std::make_shared<Model>();
  Mesh mesh;
  const auto id = [](int i, int j, int k) { return NodeIndex((k * 3 + j) * 3 + i); };
  for (int k = 0; k <= 2; ++k)
    for (int j = 0; j <= 2; ++j)
      for (int i = 0; i <= 2; ++i) mesh.nodes.push_back(glm::dvec3(i, j, k));
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) {
        const NodeIndex hex[8] = {id(i, j, k),     id(i + 1, j, k),     id(i + 1, j + 1, k),     id(i, j + 1, k),
                                  id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)};
        mesh.addCell(CellType::Hex8, hex);
      }
  std::vector<double> u;
  for (const glm::dvec3& p : mesh.nodes) u.insert(u.end(), {p.x, 2.0 * p.y, 0.0});
  model->setMesh(std::move(mesh));
  model->fields.push_back(Field::fromValues("U", FieldLocation::Node, 3, {u}, {Step{"1", 1.0}}));
  const auto session = ModelSession::fromModel(model);
  GlyphLayer layer;
  layer.shown = true;
  layer.field = "U";
  layer.every = 1;
  layer.scale = 0.1;
  const std::size_t surfaceNodes = 26;  // all 27 nodes but the centre
  EXPECT_EQ(buildGlyphs(*session, layer, 0).candidates, surfaceNodes);
  // Keep x <= 1.5: the x = 2 nodes go; the four cells with x in [1, 2] are cut at 1.5.
  const std::vector<ClipPlane> cut{ClipPlane{{1.5, 0.0, 0.0}, {-1.0, 0.0, 0.0}}};
  const GlyphGeometry g = buildGlyphs(*session, layer, 0, cut);
  EXPECT_EQ(g.candidates, surfaceNodes - 9 + 4);
  // The cut glyphs come last, at the faces' centres (1.5, y, z) with y, z = 0.5 or 1.5, their
  // vectors (1.5, 2y, 0) interpolated: the tip at (1.5, y) + 0.1 (1.5, 2y), the color |U|.
  ASSERT_GE(g.glyphs, 4u);
  for (std::size_t k = g.glyphs - 4; k < g.glyphs; ++k) {
    const double length = g.values[k * kArrowCorners];
    const double y = std::sqrt((length * length - 2.25) / 4.0);
    EXPECT_TRUE(std::abs(y - 0.5) < 1e-9 || std::abs(y - 1.5) < 1e-9) << y;
    const glm::dvec3 tip = g.corners[k * kArrowCorners + kTipCorner];
    EXPECT_NEAR(tip.x, 1.5 + 0.15, 1e-9);
    EXPECT_NEAR(tip.y, 1.2 * y, 1e-9);
  }
  EXPECT_EQ(buildGlyphs(*session, layer, 0, cut, false).candidates, surfaceNodes - 9) << "a volume: no cut faces";
  layer.allNodes = true;
  EXPECT_EQ(buildGlyphs(*session, layer, 0, cut).candidates, 27u - 9) << "every node: the cut removes, adds none";
}

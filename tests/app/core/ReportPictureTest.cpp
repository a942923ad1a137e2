// SPDX-License-Identifier: MIT
// Report pictures: a transparent background recovered from pictures over black and white,
// a background color of one's own with words that stay readable, and the words' size.
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

std::unique_ptr<Scene> barScene() { return volpost::test::flatBarScene("viridis"); }

}  // namespace

TEST(ReportPicture, ATransparentBackgroundKeepsTheModelsColorsAndPartialCover) {
  VOLPOST_SKIP_WITHOUT_GL();
  auto scene = barScene();
  const QImage opaque = renderSceneImage(*scene, 128, 64).picture;
  const auto draw = [&] { return renderSceneImage(*scene, 128, 64, false); };
  const QImage clear = renderTransparent(*scene, draw).picture;
  EXPECT_EQ(scene->shown().background, SceneState{}.background) << "the scene's own background is back";
  EXPECT_EQ(qAlpha(clear.pixel(2, 2)), 0) << "the background is gone";
  const QRgb a = opaque.pixel(64, 32), b = clear.pixel(64, 32);
  EXPECT_EQ(qAlpha(b), 255) << "the opaque face covers its pixel";
  EXPECT_NEAR(qRed(b), qRed(a), 2);
  EXPECT_NEAR(qGreen(b), qGreen(a), 2);
  EXPECT_NEAR(qBlue(b), qBlue(a), 2);
  // A see-through surface covers its pixels in part: its front and back faces at 0.5
  // each leave 0.25 of the background, alpha 0.75.
  scene->setSurfaceOpacity(0.5);
  const QImage half = renderTransparent(*scene, draw).picture;
  EXPECT_NEAR(qAlpha(half.pixel(64, 32)), 191, 3);
  EXPECT_NEAR(qRed(half.pixel(64, 32)), qRed(a), 4) << "its color without the background's";
  EXPECT_TRUE(formatKeepsTransparency("a/b.PNG"));
  EXPECT_FALSE(formatKeepsTransparency("b.jpg"));
}

TEST(ReportPicture, ADarkBackgroundTurnsTheWordsLightAndTheTextScaleSizesThem) {
  VOLPOST_SKIP_WITHOUT_GL();
  auto scene = barScene();
  scene->setShowLegend(true);
  scene->setBackground({0.0, 0.0, 0.0});
  EXPECT_THROW(scene->setBackground({1.5, 0.0, 0.0}), std::invalid_argument);
  const QImage dark = renderSceneImage(*scene, 320, 240).picture;
  EXPECT_EQ(dark.pixel(2, 2) & 0xffffffu, 0u) << "black behind the model";
  // The legend's words (the strip's top right corner) are light on black.
  int light = 0;
  for (int y = 0; y < 40; ++y)
    for (int x = 200; x < 320; ++x) light += qGray(dark.pixel(x, y)) > 150 ? 1 : 0;
  EXPECT_GT(light, 20);
  ASSERT_TRUE(scene->legend());
  EXPECT_TRUE(scene->legend()->content.onDark);
  // Twice the words: a wider legend strip, so the model gives it room.
  const double margin = scene->pictureCamera(320, 240).rightMargin();
  scene->setTextScale(2.0);
  EXPECT_GT(scene->pictureCamera(320, 240).rightMargin(), margin * 1.5);
  EXPECT_THROW(scene->setTextScale(0.1), std::invalid_argument);
  EXPECT_THROW(scene->setTextScale(9.0), std::invalid_argument);
  const SceneState back = SceneState::fromJson(scene->state().toJson(), "/data/view.json");
  EXPECT_EQ(back.background, glm::dvec3(0.0));
  EXPECT_EQ(back.textScale, 2.0);
  std::string text = scene->state().toJson();
  text.replace(text.find("\"textScale\": 2.0"), 16, "\"textScale\": 20.");
  EXPECT_THROW(SceneState::fromJson(text, "/data/view.json"), std::runtime_error);
}

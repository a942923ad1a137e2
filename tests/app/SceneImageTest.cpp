// SPDX-License-Identifier: MIT
// The user's rendering path (ModelSession -> Scene -> headless picture) on a real FE
// result: the bar pulled by 100 MPa shows S11 = 100 in its middle, so with the range
// 90..110 on the gray map the middle of the bar must be exactly mid-gray.
#include "support/ReaderSupport.hpp"
#include "support/TestSupport.hpp"

#include "core/CameraSpec.hpp"
#include "core/PluginRenderers.hpp"
#include "core/SceneImage.hpp"

#include <volpost/render/HeadlessContext.hpp>

#include <glm/gtc/matrix_inverse.hpp>

using namespace volpost;
using namespace volpost::app;

TEST(SceneImage, BarMiddleShowsTheAnalyticAxialStress) {
  try {
    HeadlessContext probe;
  } catch (const std::exception& e) {
    GTEST_SKIP() << "not run: no headless OpenGL 4.5 context: " << e.what();
  }
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

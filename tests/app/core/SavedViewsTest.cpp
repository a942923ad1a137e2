// SPDX-License-Identifier: MIT
// Views saved under names and the views before: kept in the scene and its state file,
// shown again exactly, refused with the names there are, dropped with the model.
#include "support/BarSession.hpp"
#include "support/ReaderSupport.hpp"
#include "support/TestSupport.hpp"

#include "core/Scene.hpp"

#include <stdexcept>

using namespace volpost;
using namespace volpost::app;

namespace {

using volpost::test::barSession;

std::string refusal(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "accepted";
}

}  // namespace

TEST(SavedViews, AViewComesBackExactlyAndThroughTheStateFile) {
  Scene scene{VolumeRendererFactory{}};
  scene.setSession(barSession());
  scene.camera().setView(StandardView::PlusZ);
  scene.camera().orbit(30.0, -20.0);
  scene.camera().setProjection(Camera::Projection::Orthographic);
  const glm::dvec3 eye = scene.camera().eye(), up = scene.camera().up();
  scene.saveView("top");
  scene.camera().setView(StandardView::Isometric);
  scene.camera().setProjection(Camera::Projection::Perspective);
  scene.showView("top");
  EXPECT_EQ(scene.camera().eye(), eye);
  EXPECT_EQ(scene.camera().up(), up);
  EXPECT_EQ(scene.camera().projection(), Camera::Projection::Orthographic);
  // Through the file: the views and their cameras as saved.
  const SceneState back = SceneState::fromJson(scene.state().toJson(), "/data/view.json");
  ASSERT_EQ(back.views.size(), 1u);
  EXPECT_EQ(back.views[0], scene.views()[0]);
  Scene other{VolumeRendererFactory{}};
  other.setSession(barSession());
  other.applyState(back);
  other.camera().setView(StandardView::MinusX);
  other.showView("top");
  EXPECT_EQ(other.camera().eye(), eye);
  // The same name replaces the view; another model drops them (they are cameras on this one).
  scene.camera().setView(StandardView::MinusY);
  scene.saveView("top");
  EXPECT_EQ(scene.views().size(), 1u);
  EXPECT_EQ(scene.views()[0].camera.eye, scene.camera().eye());
  scene.setSession(barSession());
  EXPECT_TRUE(scene.views().empty());
}

TEST(SavedViews, RefusalsNameWhatIsWrong) {
  Scene scene{VolumeRendererFactory{}};
  scene.setSession(barSession());
  EXPECT_EQ(refusal([&] { scene.showView("front"); }), "no view is saved as \"front\": none is saved");
  scene.saveView("left");
  scene.saveView("right");
  EXPECT_EQ(refusal([&] { scene.showView("front"); }),
            "no view is saved as \"front\"; the saved views: \"left\", \"right\"");
  EXPECT_EQ(refusal([&] { scene.saveView("  "); }), "the view's name is empty");
  EXPECT_EQ(refusal([&] { scene.saveView("a\nb"); }), "the view's name holds a control character");
  scene.removeView("left");
  ASSERT_EQ(scene.views().size(), 1u);
  EXPECT_EQ(scene.views()[0].name, "right");
  const std::string head = R"({"format": "volpost-state", "version": 1, "model": "m.vtu", "views": )";
  const std::string camera = R"("camera": {"eye": [0,0,1], "target": [0,0,0], "up": [0,1,0]})";
  const auto fileRefusal = [&](const std::string& views) {
    return refusal([&] { (void)SceneState::fromJson(head + views + "}", "view.json"); });
  };
  EXPECT_NE(fileRefusal(R"([{"name": "a", )" + camera + R"(}, {"name": "a", )" + camera + "}]")
                .find("\"views[1].name\" repeats the name \"a\""),
            std::string::npos);
  EXPECT_NE(fileRefusal(R"([{"name": "a", "camera": {"eye": [0,0,0], "target": [0,0,0], "up": [0,1,0]}}])")
                .find("\"views[0].camera\" has the eye on the target"),
            std::string::npos);
  EXPECT_NE(fileRefusal(R"([{"name": "a"}])").find("\"views[0]\" needs \"name\" and \"camera\""), std::string::npos);
}

// Previous View steps back through the cameras remembered before each move, skipping
// those equal to the present one, and says when there is none left.
TEST(SavedViews, PreviousViewStepsBackThroughTheRememberedCameras) {
  Scene scene{VolumeRendererFactory{}};
  scene.setSession(barSession());
  EXPECT_FALSE(scene.previousView());
  const glm::dvec3 first = scene.camera().eye();
  scene.rememberView();
  scene.camera().setView(StandardView::PlusX);
  scene.fitCamera();
  const glm::dvec3 second = scene.camera().eye();
  scene.rememberView();
  scene.rememberView();  // a click that moved nothing
  scene.camera().zoom(2.0);
  EXPECT_TRUE(scene.previousView());
  EXPECT_EQ(scene.camera().eye(), second);
  EXPECT_TRUE(scene.previousView());
  EXPECT_EQ(scene.camera().eye(), first);
  EXPECT_FALSE(scene.previousView());
  for (std::size_t i = 0; i < 2 * Scene::kViewHistory; ++i) {  // bounded
    scene.rememberView();
    scene.camera().zoom(1.01);
  }
  std::size_t back = 0;
  while (scene.previousView()) ++back;
  EXPECT_EQ(back, Scene::kViewHistory);
}

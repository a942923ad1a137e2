// SPDX-License-Identifier: MIT
// The window's views alone (a plain main window and a scene, no OpenGL): a view saved by
// name is listed, turned to and removed; Previous View steps back; the menu lists what the
// scene holds after a state file or a new model.
#include "gui/SavedViews.hpp"

#include "support/WindowParts.hpp"

#include <QAction>
#include <QApplication>
#include <QMenu>
#include <QMenuBar>
#include <QTest>

#include <memory>

using namespace volpost;
using namespace volpost::app;

class SavedViewsMenuTest : public QObject {
  Q_OBJECT

 private:
  std::unique_ptr<QMainWindow> window_;
  std::unique_ptr<Scene> scene_;
  SavedViews* views_ = nullptr;
  int redraws_ = 0;

  QStringList listed() {
    QStringList names;
    for (QAction* a : window_->findChild<QMenu*>("savedViewsMenu")->actions()) names << a->text();
    return names;
  }
  QString status() { return window_->statusBar()->currentMessage(); }

 private slots:
  void init() {
    window_ = std::make_unique<QMainWindow>();
    scene_ = std::make_unique<Scene>(VolumeRendererFactory{});
    QMenu* view = window_->menuBar()->addMenu("View");
    redraws_ = 0;
    views_ = new SavedViews(*window_, *scene_, *view, volpost::test::changingScene(*window_, *scene_),
                            [this] { ++redraws_; });
    scene_->setSession(volpost::test::loadTestModel("bar/bar_tet4.vtu"));
  }

  void cleanup() {
    window_.reset();
    scene_.reset();
  }

  void aSavedViewIsListedTurnedToAndRemoved() {
    QVERIFY(!window_->findChild<QMenu*>("savedViewsMenu")->isEnabled());
    scene_->camera().setView(StandardView::PlusZ);
    QVERIFY(views_->saveAs("top"));
    QCOMPARE(listed(), QStringList{"top"});
    QVERIFY(status().startsWith("Saved the view as \"top\""));
    const glm::dvec3 top = scene_->camera().eye();
    scene_->camera().setView(StandardView::MinusX);
    window_->findChild<QAction*>("view:top")->trigger();
    QCOMPARE(scene_->camera().eye(), top);
    window_->findChild<QAction*>("previousViewAction")->trigger();  // back to the -X view
    QVERIFY(scene_->camera().eye() != top);
    QVERIFY(redraws_ > 0);
    window_->findChild<QAction*>("removeView:top")->trigger();
    QVERIFY(scene_->views().empty());
    QVERIFY(listed().isEmpty());
  }

  void aNameThatCannotBeOneIsRefusedSayingWhy() {
    QVERIFY(!views_->saveAs(""));
    QCOMPARE(status(), QString("the view's name is empty"));
    QVERIFY(scene_->views().empty());
  }

  void withNoEarlierViewPreviousSaysSo() {
    QVERIFY(!views_->previous());
    QCOMPARE(status(), QString("No earlier view to go back to"));
  }

  void theMenuListsTheScenesViews() {
    SceneState state = scene_->state();
    state.views = {{"left", *state.camera}, {"right", *state.camera}};
    scene_->applyState(state);  // as a state file would
    views_->syncToScene();
    QCOMPARE(listed(), (QStringList{"left", "right"}));
    scene_->setSession(volpost::test::loadTestModel("bar/bar_tet4.vtu"));  // a new model drops them
    views_->syncToScene();
    QVERIFY(listed().isEmpty());
  }
};

int main(int argc, char** argv) {
  qputenv("QT_QPA_PLATFORM", "offscreen");  // menus and actions only: no display needed
  QApplication app(argc, argv);
  SavedViewsMenuTest test;
  return QTest::qExec(&test, argc, argv);
}

#include "SavedViewsMenuTest.moc"

// SPDX-License-Identifier: MIT
// The window's clip menu alone (a plain main window and a scene, no OpenGL): the axis
// entries set the scene's plane, and the menu always shows the scene's first plane as it
// is: its axis, none for a turned plane, Off without one (after a state or a new model too).
#include "gui/ClipActions.hpp"

#include "support/WindowParts.hpp"

#include <QAction>
#include <QApplication>
#include <QMainWindow>
#include <QMenu>
#include <QMenuBar>
#include <QStatusBar>
#include <QTest>

#include <memory>

using namespace volpost;
using namespace volpost::app;

class ClipActionsTest : public QObject {
  Q_OBJECT

 private:
  std::unique_ptr<QMainWindow> window_;
  std::unique_ptr<Scene> scene_;
  ClipActions* clips_ = nullptr;
  int redraws_ = 0;

  QAction* entry(int axis) { return window_->findChild<QAction*>(QString("clip:%1").arg(axis)); }
  // The checked entries, by axis (-1: Off).
  QList<int> checked() {
    QList<int> out;
    for (int i = -1; i < 3; ++i)
      if (entry(i)->isChecked()) out << i;
    return out;
  }
  void open() { scene_->setSession(volpost::test::loadTestModel("bar/bar_tet4.vtu")); }

 private slots:
  void init() {
    window_ = std::make_unique<QMainWindow>();
    scene_ = std::make_unique<Scene>(VolumeRendererFactory{});
    QMenu* results = window_->menuBar()->addMenu("Results");
    redraws_ = 0;
    clips_ = new ClipActions(
        *window_, *scene_, *results, volpost::test::changingScene(*window_, *scene_), [this] { ++redraws_; },
        [] { return std::size_t(0); });
    open();
  }

  void cleanup() {
    window_.reset();
    scene_.reset();
  }

  void anAxisEntrySetsAPlaneThroughTheCentre() {
    QCOMPARE(checked(), QList<int>{-1});
    entry(1)->trigger();
    const auto& planes = scene_->volume().clipPlanes;
    QCOMPARE(planes.size(), std::size_t(1));
    QCOMPARE(planes.front().normal, glm::dvec3(0.0, 1.0, 0.0));
    QCOMPARE(planes.front().point, scene_->session()->model().bounds().center());
    QCOMPARE(checked(), QList<int>{1});
    entry(-1)->trigger();
    QVERIFY(scene_->volume().clipPlanes.empty());
    QCOMPARE(checked(), QList<int>{-1});
  }

  void aTurnedPlaneChecksNoEntryAndADraggedOneItsAxis() {
    entry(0)->trigger();
    clips_->planeDragged({{5.0, 0.5, 0.5}, {0.0, -1.0, 0.0}});  // -Y: no entry says that
    QCOMPARE(checked(), QList<int>{});
    QVERIFY(window_->statusBar()->currentMessage().contains("normal (0, -1, 0)"));
    clips_->planeDragged({{5.0, 0.5, 0.5}, {0.0, 0.0, 2.0}});
    QCOMPARE(checked(), QList<int>{2});
  }

  // A state file's planes or a new model's none: the menu follows the scene.
  void theMenuFollowsTheScenesPlanes() {
    scene_->setClipPlanes({{{5.0, 0.5, 0.5}, {0.0, 0.0, 1.0}}});
    clips_->syncToScene();
    QCOMPARE(checked(), QList<int>{2});
    scene_->setClipPlanes({{{5.0, 0.5, 0.5}, {1.0, 1.0, 0.0}}});
    clips_->syncToScene();
    QCOMPARE(checked(), QList<int>{});
    open();  // another model: no planes
    clips_->syncToScene();
    QCOMPARE(checked(), QList<int>{-1});
  }

  void theHandlesEntryShowsAndHidesThePlanesHandles() {
    entry(0)->trigger();
    QVERIFY(scene_->showsPlaneWidget());
    QAction* handles = window_->findChild<QAction*>("planeHandle");
    handles->setChecked(false);
    QVERIFY(!scene_->showsPlaneWidget());
    handles->setChecked(true);
    QVERIFY(scene_->showsPlaneWidget());
  }
};

int main(int argc, char** argv) {
  qputenv("QT_QPA_PLATFORM", "offscreen");  // menus and actions only: no display needed
  QApplication app(argc, argv);
  ClipActionsTest test;
  return QTest::qExec(&test, argc, argv);
}

#include "ClipActionsTest.moc"

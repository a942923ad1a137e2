// SPDX-License-Identifier: MIT
// The window's streamlines alone (a plain main window and a scene, no OpenGL): a rake or
// the menu shows a layer, the lines are traced on a worker thread in the model as drawn
// (deformed too) and handed to the scene once, and the menu shows what the scene shows.
#include "gui/StreamlineActions.hpp"

#include "support/WindowParts.hpp"

#include <QAction>
#include <QApplication>
#include <QMainWindow>
#include <QMenu>
#include <QMenuBar>
#include <QSignalSpy>
#include <QStatusBar>
#include <QTest>

#include <memory>

using namespace volpost;
using namespace volpost::app;

class StreamlineActionsTest : public QObject {
  Q_OBJECT

 private:
  std::unique_ptr<QMainWindow> window_;
  std::unique_ptr<Scene> scene_;
  StreamlineActions* actions_ = nullptr;
  int rakes_ = 0, redraws_ = 0;

  QAction* shown() { return window_->findChild<QAction*>("streamlinesAction"); }
  // A rake across the bar (10 x 1 x 1), through its middle.
  std::vector<glm::dvec3> rake() {
    std::vector<glm::dvec3> seeds;
    for (int i = 0; i < 5; ++i) seeds.push_back({1.0 + 2.0 * i, 0.5, 0.5});
    return seeds;
  }
  // Waits for the worker's trace to come back; the count of traced() signals.
  int settle(QSignalSpy& traced) {
    for (int i = 0; i < 600 && scene_->streamlinesNeedTracing(); ++i) QTest::qWait(50);
    QTest::qWait(100);  // a second trace, if one were started, would show here
    return int(traced.count());
  }

 private slots:
  void init() {
    window_ = std::make_unique<QMainWindow>();
    scene_ = std::make_unique<Scene>(VolumeRendererFactory{});
    QMenu* results = window_->menuBar()->addMenu("Results");
    rakes_ = redraws_ = 0;
    actions_ = new StreamlineActions(
        *window_, *scene_, *results, volpost::test::changingScene(*window_, *scene_), [this] { ++rakes_; },
        [this] { ++redraws_; });
    scene_->setSession(volpost::test::loadTestModel("bar/bar_tet4.vtu"));
  }

  void cleanup() {
    window_.reset();  // the actions are the window's child
    scene_.reset();
  }

  void aRakeShowsTheFirstNodalVectorsLinesTracedOnce() {
    QSignalSpy traced(actions_, &StreamlineActions::traced);
    window_->findChild<QAction*>("placeRake")->trigger();
    QCOMPARE(rakes_, 1);
    actions_->placeRake(rake());
    QCOMPARE(settle(traced), 1);
    QVERIFY2(traced.first().first().toBool(), qPrintable(traced.first().at(1).toString()));
    QVERIFY(scene_->streamlines().shown);
    QCOMPARE(scene_->streamlines().field, std::string("U"));
    QCOMPARE(scene_->streamlines().seeds.size(), std::size_t(5));
    QVERIFY(scene_->streamlinesDrawn());
    QVERIFY(shown()->isChecked());
    QVERIFY2(scene_->shown().surfaceOpacity < 1.0, "the surface turns see-through so the lines show");
    QVERIFY(redraws_ > 0);
  }

  // The deformed shape is the model drawn: its lines are traced in it, once (they were
  // traced in the undeformed model, which the scene never takes as its own: traced again
  // and again).
  void onTheDeformedShapeTheLinesAreTracedOnceInIt() {
    DeformationLayer deformed;
    deformed.shown = true;
    scene_->setDeformation(deformed);
    QVERIFY(scene_->session() != scene_->baseSession());
    QSignalSpy traced(actions_, &StreamlineActions::traced);
    actions_->placeRake(rake());
    QCOMPARE(settle(traced), 1);
    QVERIFY(traced.first().first().toBool());
    QCOMPARE(scene_->streamlineResult()->session, scene_->session());
    QVERIFY(!scene_->streamlinesNeedTracing());
  }

  void theMenuShowsAndHidesTheScenesLines() {
    QSignalSpy traced(actions_, &StreamlineActions::traced);
    actions_->placeRake(rake());
    settle(traced);
    shown()->setChecked(false);
    QVERIFY(!scene_->streamlines().shown);
    QVERIFY(!shown()->isChecked());
    shown()->setChecked(true);
    QVERIFY(scene_->streamlines().shown);
    QVERIFY2(scene_->streamlinesDrawn(), "the same lines: nothing to trace again");
    scene_->setSession(volpost::test::loadTestModel("bar/bar_tet4.vtu"));  // another model drops the lines
    actions_->syncToScene();
    QVERIFY(!shown()->isChecked());
  }

  void aModelWithoutNodalVectorsSaysSoAndChangesNothing() {
    scene_->setSession(volpost::test::loadTestModel("formats/image_points_ascii.vtk"));
    actions_->placeRake(rake());
    QVERIFY(!scene_->streamlines().shown);
    QVERIFY(!shown()->isChecked());
    QVERIFY2(window_->statusBar()->currentMessage().contains("no nodal vector field"),
             qPrintable(window_->statusBar()->currentMessage()));
  }
};

int main(int argc, char** argv) {
  qputenv("QT_QPA_PLATFORM", "offscreen");  // menus and actions only: no display needed
  QApplication app(argc, argv);
  StreamlineActionsTest test;
  return QTest::qExec(&test, argc, argv);
}

#include "StreamlineActionsTest.moc"

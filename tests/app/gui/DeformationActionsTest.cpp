// SPDX-License-Identifier: MIT
// The window's deformed shape alone (a plain main window and a scene, no OpenGL): the
// menu shows the model deformed by its displacement, says so, tells the window the drawn
// model changed, refuses a model without nodal vectors, and shows the scene's deformation
// after a state or a new model.
#include "gui/DeformationActions.hpp"

#include "support/WindowParts.hpp"

#include <QAction>
#include <QApplication>
#include <QMenu>
#include <QMenuBar>
#include <QTest>

#include <memory>

using namespace volpost;
using namespace volpost::app;

class DeformationActionsTest : public QObject {
  Q_OBJECT

 private:
  std::unique_ptr<QMainWindow> window_;
  std::unique_ptr<Scene> scene_;
  DeformationActions* actions_ = nullptr;
  int changes_ = 0;

  QAction* shown() { return window_->findChild<QAction*>("deformAction"); }
  QAction* outline() { return window_->findChild<QAction*>("undeformedAction"); }

 private slots:
  void init() {
    window_ = std::make_unique<QMainWindow>();
    scene_ = std::make_unique<Scene>(VolumeRendererFactory{});
    QMenu* results = window_->menuBar()->addMenu("Results");
    changes_ = 0;
    actions_ = new DeformationActions(*window_, *scene_, *results, volpost::test::changingScene(*window_, *scene_),
                                      [this] { ++changes_; });
    scene_->setSession(volpost::test::loadTestModel("bar/bar_tet4.vtu"));
  }

  void cleanup() {
    window_.reset();
    scene_.reset();
  }

  void theEntryDeformsTheModelByItsDisplacement() {
    shown()->setChecked(true);
    QVERIFY(scene_->deformation().shown);
    QCOMPARE(scene_->deformation().field, std::string("U"));
    QVERIFY(scene_->deformationScale() > 0.0);
    QVERIFY(scene_->session() != scene_->baseSession());
    QCOMPARE(changes_, 1);
    QVERIFY2(window_->statusBar()->currentMessage().startsWith("Deformed: U x "),
             qPrintable(window_->statusBar()->currentMessage()));
    outline()->setChecked(true);
    QVERIFY(scene_->deformation().undeformedOutline);
    shown()->setChecked(false);
    QVERIFY(!scene_->deformation().shown);
    QVERIFY(scene_->session() == scene_->baseSession());
  }

  void aTypedScaleIsTheScenes() {
    actions_->show(true, 2.5);
    QCOMPARE(scene_->deformationScale(), 2.5);
    QVERIFY(shown()->isChecked());
  }

  void aModelWithoutNodalVectorsIsRefusedAndTheEntryStaysOff() {
    scene_->setSession(volpost::test::loadTestModel("formats/image_points_ascii.vtk"));
    shown()->setChecked(true);
    QVERIFY(!scene_->deformation().shown);
    QVERIFY(!shown()->isChecked());
    QVERIFY2(window_->statusBar()->currentMessage().contains("no nodal vector field"),
             qPrintable(window_->statusBar()->currentMessage()));
  }

  void theMenuFollowsTheScene() {
    DeformationLayer d;
    d.shown = true;
    d.undeformedOutline = true;
    scene_->setDeformation(d);  // as a state file would
    actions_->syncToScene();
    QVERIFY(shown()->isChecked());
    QVERIFY(outline()->isChecked());
    scene_->setSession(volpost::test::loadTestModel("bar/bar_tet4.vtu"));  // a new model: undeformed
    actions_->syncToScene();
    QVERIFY(!shown()->isChecked());
  }
};

int main(int argc, char** argv) {
  qputenv("QT_QPA_PLATFORM", "offscreen");  // menus and actions only: no display needed
  QApplication app(argc, argv);
  DeformationActionsTest test;
  return QTest::qExec(&test, argc, argv);
}

#include "DeformationActionsTest.moc"

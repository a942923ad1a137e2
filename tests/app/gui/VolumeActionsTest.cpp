// SPDX-License-Identifier: MIT
// The window's volume entries alone (a plain main window and a scene, no OpenGL): they
// show the scene's volume and shading, refuse what the model cannot take (saying why,
// the entry left off), and tell the window when the volume or its 2D transfer function
// comes or goes.
#include "gui/VolumeActions.hpp"

#include "support/WindowParts.hpp"

#include "support/RayCasterScene.hpp"

#include "CpuVolumeRenderer.hpp"

#include <QAction>
#include <QApplication>
#include <QMenu>
#include <QMenuBar>
#include <QTest>

#include <filesystem>
#include <fstream>
#include <memory>

using namespace volpost;
using namespace volpost::app;

class VolumeActionsTest : public QObject {
  Q_OBJECT

 private:
  std::unique_ptr<QMainWindow> window_;
  std::unique_ptr<Scene> scene_;
  VolumeActions* actions_ = nullptr;
  int shown_ = 0, viewChanges_ = 0, tableChanges_ = 0;

  QAction* volume() { return window_->findChild<QAction*>("volumeAction"); }
  QAction* shading() { return window_->findChild<QAction*>("shadingAction"); }
  QString status() { return window_->statusBar()->currentMessage(); }
  static TransferFunction2D boundaries() {
    return TransferFunction2D::fromJson(R"({"format":"volpost-tf2d","version":1,"widgets":[
      {"shape":"triangle","value":0.0,"width":0.5,"gradient":[0.0,0.25],"color":[0.95,0.45,0.1],"extinction":0.02}]})");
  }

 private slots:
  void init() {
    window_ = std::make_unique<QMainWindow>();
    scene_ = std::make_unique<Scene>(volpost::test::rayCasterOnly());
    QMenu* view = window_->menuBar()->addMenu("View");
    shown_ = viewChanges_ = tableChanges_ = 0;
    actions_ = new VolumeActions(*window_, *scene_, *view, true, volpost::test::changingScene(*window_, *scene_),
                                 {[this] { ++shown_; }, [this] { ++viewChanges_; }, [this] { ++tableChanges_; }});
    scene_->setSession(volpost::test::loadTestModel("bar/bar_tet4.vtu"));
  }

  void cleanup() {
    window_.reset();
    scene_.reset();
  }

  void theVolumeNeedsAResultAndTheEntryShowsTheScene() {
    volume()->setChecked(true);
    QVERIFY(!scene_->volumeShown());
    QVERIFY(!volume()->isChecked());
    QCOMPARE(status(), QString("Choose a result to render as a volume"));
    scene_->setResult("S.mises", 0);
    volume()->setChecked(true);
    QVERIFY(scene_->volumeShown());
    QVERIFY(volume()->isChecked());
    QCOMPARE(shown_, 1);
    QVERIFY(status().startsWith("Volume rendering of S von Mises"));
    volume()->setChecked(false);
    QVERIFY(!scene_->volumeShown());
    QCOMPARE(viewChanges_, 2);
    scene_->setVolumeShown(true);  // as a state file would
    actions_->syncToScene();
    QVERIFY(volume()->isChecked());
  }

  void aMeshRefusesShadingAndTwoDimensionalTransferFunctions() {
    shading()->setChecked(true);
    QVERIFY(!scene_->volume().shading);
    QVERIFY(!shading()->isChecked());
    QVERIFY2(status().contains("regular grids"), qPrintable(status()));
    QVERIFY(!actions_->setTransferFunction2D(boundaries()));
    QVERIFY(!scene_->volume().transferFunction2D);
    QCOMPARE(tableChanges_, 0);
  }

  void aGridTakesThemAndTheEditorsAreTold() {
    scene_->setSession(volpost::test::loadTestModel("formats/image_points_ascii.vtk"));
    shading()->setChecked(true);
    QVERIFY(scene_->volume().shading);
    QVERIFY(actions_->setTransferFunction2D(boundaries()));
    QVERIFY(scene_->volume().transferFunction2D);
    QCOMPARE(tableChanges_, 1);
    window_->findChild<QAction*>("clear2dAction")->trigger();
    QVERIFY(!scene_->volume().transferFunction2D);
    QCOMPARE(tableChanges_, 2);  // the 1D editor draws again
    QCOMPARE(status(), QString("Volume colors from the 1D transfer function"));
  }

  // Every renderer the window draws with takes the cells' own interpolation: the CPU ray
  // caster draws it itself, the GPU ray caster on refined tetrahedra, which the status says.
  void theCellsOwnInterpolationIsDrawnByEveryRendererOfTheWindow() {
    QAction* entry = window_->findChild<QAction*>("elementInterpolationAction");
    entry->setChecked(true);  // the GPU ray caster alone
    QVERIFY(entry->isChecked());
    QVERIFY(scene_->volume().interpolation == FieldInterpolation::Element);
    entry->setChecked(false);
    QVERIFY(scene_->volume().interpolation == FieldInterpolation::Tetrahedra);

    QMainWindow window;
    Scene scene(app::VolumeRendererFactory{[](const std::string& name) -> std::unique_ptr<VolumeRenderer> {
                                             if (name == "raycast") return std::make_unique<volume::RayCaster>();
                                             if (name == "cpu") return std::make_unique<volume::CpuVolumeRenderer>();
                                             return nullptr;
                                           },
                                           {"raycast", "cpu"}});
    QMenu* view = window.menuBar()->addMenu("View");
    auto* actions = new VolumeActions(window, scene, *view, true, volpost::test::changingScene(window, scene), {});
    scene.setSession(volpost::test::loadTestModel("bar/bar_tet4.vtu"));
    scene.setVolumeRenderer("cpu");
    QAction* own = window.findChild<QAction*>("elementInterpolationAction");
    own->setChecked(true);
    QVERIFY(own->isChecked());
    QVERIFY(scene.volume().interpolation == FieldInterpolation::Element);
    QVERIFY2(!window.statusBar()->currentMessage().contains("refined"),
             qPrintable(window.statusBar()->currentMessage()));
    scene.setVolumeRenderer("raycast");  // taken: it draws the cells' field on refined pieces
    QCOMPARE(scene.volume().renderer, std::string("raycast"));
    QVERIFY(scene.volume().interpolation == FieldInterpolation::Element);
    own->setChecked(false);
    QVERIFY(scene.volume().interpolation == FieldInterpolation::Tetrahedra);
    scene.setInterpolation(FieldInterpolation::Element);  // as a state file would
    actions->syncToScene();
    QVERIFY(own->isChecked());

    // A hexahedron whose first corner is pulled through it: no inverse map. Turned on, the
    // entry says it is drawn linear on its tetrahedra, by its id.
    const std::string folded = (std::filesystem::temp_directory_path() / "volpost_folded_hex.vtk").string();
    std::ofstream(folded) << "# vtk DataFile Version 4.2\nfolded\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 8 double\n"
                             "0.9 0.8 0.8  1 0 0  1 1 0  0 1 0  0 0 1  1 0 1  1 1 1  0 1 1\n"
                             "CELLS 1 9\n8 0 1 2 3 4 5 6 7\nCELL_TYPES 1\n12\n"
                             "POINT_DATA 8\nSCALARS T double 1\nLOOKUP_TABLE default\n0 1 2 3 4 5 6 7\n";
    scene.setSession(volpost::test::loadTestModel(folded));
    scene.setResult("T", 0);
    own->setChecked(false);
    own->setChecked(true);
    QVERIFY2(window.statusBar()->currentMessage().contains(
                 "1 cell folded, inverted or collapsed (no inverse map): drawn linear on their tetrahedra; cell id 1"),
             qPrintable(window.statusBar()->currentMessage()));
    QVERIFY2(window.statusBar()->currentMessage().contains("Ray casting draws it on tetrahedra refined to the "
                                                           "tolerance"),
             qPrintable(window.statusBar()->currentMessage()));
    std::filesystem::remove(folded);
  }

  void theToleranceEntryShowsTheSceneAndRefusesWhatItCannotHonour() {
    QAction* entry = window_->findChild<QAction*>("elementToleranceAction");
    QVERIFY(entry);
    QCOMPARE(entry->text(), QString("Tolerance of the Cells' Own Field: 0.01..."));
    QVERIFY(actions_->setElementTolerance(1e-3));
    QCOMPARE(scene_->volume().elementTolerance, 1e-3);
    QCOMPARE(entry->text(), QString("Tolerance of the Cells' Own Field: 0.001..."));
    QVERIFY2(status().contains("within 0.001 of its exact picture"), qPrintable(status()));
    QVERIFY(!actions_->setElementTolerance(1e-7));  // below what the fast path can keep
    QCOMPARE(scene_->volume().elementTolerance, 1e-3);
    QVERIFY2(status().contains("must be 0 (exact) or lie in [1e-05, 0.1]"), qPrintable(status()));
    QCOMPARE(entry->text(), QString("Tolerance of the Cells' Own Field: 0.001..."));
    // Exact is for renderers that draw the cells' field themselves, not the GPU ray caster's
    // refined pieces; the surfaces take it.
    const std::string hex = (std::filesystem::temp_directory_path() / "volpost_one_hex.vtk").string();
    std::ofstream(hex) << "# vtk DataFile Version 4.2\nhex\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 8 double\n"
                          "0 0 0  1 0 0  1 1 0  0 1 0  0 0 1  1 0 1  1 1 1  0 1 1\n"
                          "CELLS 1 9\n8 0 1 2 3 4 5 6 7\nCELL_TYPES 1\n12\n"
                          "POINT_DATA 8\nSCALARS T double 1\nLOOKUP_TABLE default\n0 1 2 3 4 5 6 7\n";
    scene_->setSession(volpost::test::loadTestModel(hex));
    std::filesystem::remove(hex);
    scene_->setResult("T", 0);
    scene_->setVolumeShown(true);
    scene_->setInterpolation(FieldInterpolation::Element);
    QVERIFY(!actions_->setElementTolerance(0.0));
    QCOMPARE(scene_->volume().elementTolerance, 1e-3);
    QVERIFY2(status().contains("Ray casting draws the cells' own field on tetrahedra refined to a tolerance above 0"),
             qPrintable(status()));
    scene_->setVolumeShown(false);
    QVERIFY(actions_->setElementTolerance(0.0));
    QCOMPARE(entry->text(), QString("Tolerance of the Cells' Own Field: exact..."));
    scene_->setInterpolation(FieldInterpolation::Tetrahedra);
    scene_->setElementTolerance(0.05);  // as a state file would
    actions_->syncToScene();
    QCOMPARE(entry->text(), QString("Tolerance of the Cells' Own Field: 0.05..."));
  }

  void withoutRenderersTheEntrySaysWhy() {
    QMainWindow bare;
    QMenu* view = bare.menuBar()->addMenu("View");
    new VolumeActions(bare, *scene_, *view, false, volpost::test::changingScene(bare, *scene_), {});
    QAction* entry = bare.findChild<QAction*>("volumeAction");
    QVERIFY(!entry->isEnabled());
    QCOMPARE(entry->toolTip(), QString("No volume renderer plugin is loaded"));
  }
};

int main(int argc, char** argv) {
  qputenv("QT_QPA_PLATFORM", "offscreen");  // menus and actions only: no display needed
  QApplication app(argc, argv);
  VolumeActionsTest test;
  return QTest::qExec(&test, argc, argv);
}

#include "VolumeActionsTest.moc"

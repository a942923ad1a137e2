// SPDX-License-Identifier: MIT
// The window's state files alone (a plain main window and a scene, no OpenGL): a saved
// view comes back, a state of another model reads that model first, and what cannot be
// done is said without changing the view.
#include "gui/StateFiles.hpp"

#include "support/WindowParts.hpp"

#include "support/RayCasterScene.hpp"

#include <QApplication>
#include <QMenu>
#include <QMenuBar>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <memory>

using namespace volpost;
using namespace volpost::app;

class StateFilesTest : public QObject {
  Q_OBJECT

 private:
  std::unique_ptr<QMainWindow> window_;
  std::unique_ptr<Scene> scene_;
  StateFiles* files_ = nullptr;
  QStringList modelsOpened_;
  bool busy_ = false;
  int followed_ = 0;
  QTemporaryDir dir_;

 private slots:
  void init() {
    window_ = std::make_unique<QMainWindow>();
    // The ray caster, and the reference described as drawn apart (as the app's factory does).
    VolumeRendererFactory renderers = volpost::test::rayCasterOnly();
    VolumeRendererTraits exact;
    exact.label = "Exact reference";
    renderers.describeApart("reference", exact);
    scene_ = std::make_unique<Scene>(renderers);
    QMenu* file = window_->menuBar()->addMenu("File");
    modelsOpened_.clear();
    busy_ = false;
    followed_ = 0;
    // Reads the model at once, as the window would on its worker.
    files_ = new StateFiles(
        *window_, *scene_, *file,
        [this](const QString& path, const ReaderOptions&, std::function<void(bool, const QString&)> then) {
          if (busy_) return false;
          modelsOpened_ << path;
          scene_->setSession(ModelSession::load(meshio::allReadersRegistry(), path.toStdString()));
          then(true, {});
          return true;
        },
        [this] { ++followed_; });
    scene_->setSession(volpost::test::loadTestModel("bar/bar_tet4.vtu"));
    scene_->setResult("S.mises", 0);
  }

  void cleanup() {
    window_.reset();
    scene_.reset();
  }

  void aSavedViewComesBack() {
    scene_->setColorMap("viridis");
    const QString path = dir_.filePath("view.json");
    QVERIFY(files_->save(path));
    QVERIFY(window_->statusBar()->currentMessage().startsWith("Saved the view to "));
    scene_->setColorMap("rainbow");
    scene_->setResult("", 0);
    QSignalSpy applied(files_, &StateFiles::applied);
    files_->open(path);
    QCOMPARE(applied.count(), 1);
    QVERIFY2(applied.first().first().toBool(), qPrintable(applied.first().at(1).toString()));
    QCOMPARE(scene_->shown().colorMap, std::string("viridis"));
    QCOMPARE(scene_->shown().quantity, std::string("S.mises"));
    QCOMPARE(followed_, 1);
    QVERIFY(modelsOpened_.isEmpty());  // the model shown is the state's: not read again
  }

  void aStateOfAnotherModelReadsItFirst() {
    const QString path = dir_.filePath("other.json");
    QVERIFY(files_->save(path));
    scene_->setSession(volpost::test::loadTestModel("bar/bar_tet4.vtk"));
    QSignalSpy applied(files_, &StateFiles::applied);
    files_->open(path);
    QCOMPARE(modelsOpened_.size(), 1);
    QVERIFY(modelsOpened_.first().endsWith("bar_tet4.vtu"));
    QCOMPARE(applied.count(), 1);
    QVERIFY(applied.first().first().toBool());
    QCOMPARE(scene_->shown().quantity, std::string("S.mises"));
  }

  void whileAnotherModelIsReadTheStateIsRefusedSayingWhy() {
    const QString path = dir_.filePath("busy.json");
    QVERIFY(files_->save(path));
    scene_->setSession(volpost::test::loadTestModel("bar/bar_tet4.vtk"));
    busy_ = true;
    QSignalSpy applied(files_, &StateFiles::applied);
    files_->open(path);
    QCOMPARE(applied.count(), 1);
    QVERIFY(!applied.first().first().toBool());
    QCOMPARE(applied.first().at(1).toString(), QString("still loading the previous file"));
    QCOMPARE(followed_, 0);
  }

  // A state whose volume the exact reference drew (volpost render --renderer reference
  // --save-state) opens with the window's renderer, which the status bar names.
  void aReferenceVolumeIsDrawnByTheWindowsRenderer() {
    SceneState state = scene_->state();
    state.volume.shown = true;
    state.volume.renderer = "reference";
    const QString path = dir_.filePath("reference.json");
    state.save(path.toStdString());
    QSignalSpy applied(files_, &StateFiles::applied);
    files_->open(path);
    QCOMPARE(applied.count(), 1);
    QVERIFY2(applied.first().first().toBool(), qPrintable(applied.first().at(1).toString()));
    QVERIFY(scene_->volumeShown());
    QCOMPARE(scene_->volume().renderer, std::string("raycast"));
    QVERIFY2(window_->statusBar()->currentMessage().contains("drawn by the reference renderer with volpost render) "
                                                             "is drawn here by raycast"),
             qPrintable(window_->statusBar()->currentMessage()));
  }

  void aStateThatCannotBeWrittenSaysWhyAndLeavesNoFile() {
    const QString path = dir_.filePath("no/such/folder/view.json");
    QVERIFY(!files_->save(path));
    QVERIFY2(window_->statusBar()->currentMessage().startsWith("Could not save the state"),
             qPrintable(window_->statusBar()->currentMessage()));
    QVERIFY(!QFileInfo::exists(path));
  }
};

int main(int argc, char** argv) {
  qputenv("QT_QPA_PLATFORM", "offscreen");  // no display needed
  QApplication app(argc, argv);
  StateFilesTest test;
  return QTest::qExec(&test, argc, argv);
}

#include "StateFilesTest.moc"

// SPDX-License-Identifier: MIT
// The window's renderer menus alone (a plain main window and a scene, no OpenGL): what they
// offer, check and choose follows what the renderers say of themselves, and the scene stays
// the one record of the choice.
#include "gui/RendererMenu.hpp"

#include "core/PluginRenderers.hpp"
#include "core/Scene.hpp"

#include <volpost/plugin/PluginManager.hpp>

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

class RendererMenuTest : public QObject {
  Q_OBJECT

 private:
  std::unique_ptr<PluginManager> plugins_;
  std::unique_ptr<QMainWindow> window_;
  std::unique_ptr<Scene> scene_;
  RendererMenu* menu_ = nullptr;
  int shown_ = 0;

  QAction* renderer(const char* name) { return window_->findChild<QAction*>(QString("renderer:") + name); }
  QAction* mode(const char* name) { return window_->findChild<QAction*>(QString("mode:") + name); }
  QStringList checkedRenderers() {
    QStringList names;
    for (QAction* a : window_->findChild<QMenu*>("rendererMenu")->actions())
      if (a->isChecked()) names << a->objectName().mid(9);
    return names;
  }
  QString scenes() { return QString::fromStdString(scene_->volume().renderer); }

 private slots:
  void initTestCase() {
    plugins_ = std::make_unique<PluginManager>();
    plugins_->loadFrom({VOLPOST_PLUGIN_DIR});
    QVERIFY(!volumeRenderers(*plugins_).empty());
  }

  void init() {
    window_ = std::make_unique<QMainWindow>();
    scene_ = std::make_unique<Scene>(volumeRendererFactory(*plugins_));
    QMenu* view = window_->menuBar()->addMenu("View");
    shown_ = 0;
    menu_ = new RendererMenu(
        *window_, *scene_, volumeRenderers(*plugins_), *view,
        [this](const std::function<void(Scene&)>& change) {
          try {
            change(*scene_);
          } catch (const std::exception& e) {
            window_->statusBar()->showMessage(e.what());
            return false;
          }
          return true;
        },
        [this] { ++shown_; });
  }

  void cleanup() {
    window_.reset();  // the menu is the window's child
    scene_.reset();
  }

  void theMenuListsEveryRendererInItsOwnWordsAndChecksTheScenes() {
    const auto entries = menu_->renderers();
    const QList<QAction*> actions = window_->findChild<QMenu*>("rendererMenu")->actions();
    QCOMPARE(qsizetype(actions.size()), qsizetype(entries.size()));
    for (std::size_t i = 0; i < entries.size(); ++i)
      QCOMPARE(actions[qsizetype(i)]->text(), QString::fromStdString(entries[i].traits.label));
    QCOMPARE(checkedRenderers(), QStringList{entries.front().name});
    QCOMPARE(scenes(), entries.front().name);
  }

  void softwareOpenGlPutsTheCpuRendererFirstAndChoosesIt() {
    menu_->preferCpuOnSoftwareGl("NVIDIA H200/PCIe/SSE2");
    QCOMPARE(scenes(), QString("raycast"));  // a GPU's OpenGL: nothing changes
    QVERIFY(!renderer("raycast")->text().contains("slow"));
    menu_->preferCpuOnSoftwareGl("llvmpipe (LLVM 15.0.6, 256 bits)");
    QCOMPARE(scenes(), QString("cpu"));
    QCOMPARE(checkedRenderers(), QStringList{"cpu"});
    QCOMPARE(window_->findChild<QMenu*>("rendererMenu")->actions().first(), renderer("cpu"));
    QVERIFY2(renderer("vicp")->text().endsWith("; slow here: OpenGL is drawn by the CPU)"),
             qPrintable(renderer("vicp")->text()));
    QVERIFY(!mode("linear")->isEnabled());
    QVERIFY(mode("linear")->toolTip().contains("exactly"));
    menu_->preferCpuOnSoftwareGl("llvmpipe (LLVM 15.0.6, 256 bits)");  // again: no second mark
    QCOMPARE(renderer("raycast")->text().count("slow here"), 1);
  }

  void aChoiceFromTheMenuReachesTheSceneAndStaysAfterSoftwareOpenGl() {
    renderer("vicp")->trigger();
    QCOMPARE(scenes(), QString("vicp"));
    QCOMPARE(checkedRenderers(), QStringList{"vicp"});
    QCOMPARE(shown_, 1);
    QVERIFY(mode("sampling")->isEnabled());
    menu_->preferCpuOnSoftwareGl("llvmpipe");
    QCOMPARE(scenes(), QString("vicp"));  // the user's choice stays
  }

  void aMeshDisablesGridRenderersAndOneChosenForAGridGivesWay() {
    renderer("texture-raymarch")->trigger();
    QCOMPARE(scenes(), QString("texture-raymarch"));
    menu_->fitToModel(false);
    QVERIFY(!renderer("texture-raymarch")->isEnabled());
    QVERIFY(renderer("texture-raymarch")->toolTip().contains("regular grids"));
    QVERIFY(renderer("cpu")->isEnabled());
    QCOMPARE(scenes(), QString("raycast"));
    QCOMPARE(checkedRenderers(), QStringList{"raycast"});
    menu_->fitToModel(true);
    QVERIFY(renderer("texture-raymarch")->isEnabled());
  }

  void theMenusFollowTheSceneAfterAState() {
    scene_->setVolumeRenderer("vicp-exact");
    scene_->setIntegrationMode(IntegrationMode::Sampling);
    menu_->syncToScene();
    QCOMPARE(checkedRenderers(), QStringList{"vicp-exact"});
    QVERIFY(mode("sampling")->isChecked());
    QVERIFY(!mode("linear")->isChecked());
    menu_->preferCpuOnSoftwareGl("llvmpipe");
    QCOMPARE(scenes(), QString("vicp-exact"));  // a state names its renderer
  }
};

int main(int argc, char** argv) {
  qputenv("QT_QPA_PLATFORM", "offscreen");  // menus and actions only: no display needed
  QApplication app(argc, argv);
  RendererMenuTest test;
  return QTest::qExec(&test, argc, argv);
}

#include "RendererMenuTest.moc"

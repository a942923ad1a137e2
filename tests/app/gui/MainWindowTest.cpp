// SPDX-License-Identifier: MIT
// The window under a (virtual) X display: open a model, switch the result, take a
// screenshot, fail to open a bad file without losing the model.
#include "core/BoxWidget.hpp"
#include "core/PlaneWidget.hpp"
#include "core/SceneOverlay.hpp"
#include "gui/CalculatorDialog.hpp"
#include "gui/FrameRateActions.hpp"
#include "gui/HistoryPanel.hpp"
#include "gui/LinePlotPanel.hpp"
#include "gui/MainWindow.hpp"
#include "gui/ProbePanel.hpp"
#include "gui/SettledView.hpp"
#include "gui/StepController.hpp"
#include "gui/Viewport.hpp"
#include "support/VideoFrames.hpp"

#include <volpost/render/GL.hpp>

#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMenu>
#include <QMimeData>
#include <QMouseEvent>
#include <QProcess>
#include <QProgressDialog>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QSlider>
#include <QSpinBox>
#include <QStandardPaths>
#include <QStatusBar>
#include <QSurfaceFormat>
#include <QTableWidget>
#include <QTest>
#include <QTextBrowser>
#include <QTextStream>
#include <QTimer>
#include <QUrl>

#include <cstdlib>

using namespace volpost;
using namespace volpost::app;

class MainWindowTest : public QObject {
  Q_OBJECT

 private:
  std::unique_ptr<PluginManager> plugins_;
  std::unique_ptr<MainWindow> window_;

  bool open(const QString& path) {
    QSignalSpy finished(window_.get(), &MainWindow::loadFinished);
    window_->openFile(path);
    if (!finished.wait(30000)) return false;
    return finished.first().first().toBool();
  }

  // Counts pixels that are not background, and a checksum of the picture.
  // The view's frame once the renderer has refined it (the CPU ray caster shows a quick
  // frame at once and the full one when its worker threads are done).
  static QImage settled(Viewport* view) {
    QImage image = view->grabFramebuffer();
    for (int i = 0; i < 3000 && view->drawing().hasPendingWork(); ++i) {
      QTest::qWait(10);
      image = view->grabFramebuffer();
    }
    return image;
  }

  // `volpost render --state STATE -o PNG` at `size`, read back as RGB32; `error` gets its
  // stderr when it fails (the image is then null).
  static QImage renderedHeadless(const QString& state, const QString& png, QSize size, QString& error) {
    QProcess render;
    render.start(VOLPOST_EXECUTABLE, {"render", "--state", state, "-o", png, "--size",
                                      QString("%1x%2").arg(size.width()).arg(size.height())});
    if (!render.waitForFinished(120000) || render.exitCode() != 0) {
      error = "volpost render failed: " + QString::fromLocal8Bit(render.readAllStandardError());
      return {};
    }
    return QImage(png).convertToFormat(QImage::Format_RGB32);
  }

  // Pixels of two same-size pictures that differ, and the largest channel difference.
  static std::pair<int, int> pixelsApart(const QImage& a, const QImage& b) {
    int different = 0, worst = 0;
    for (int y = 0; y < a.height(); ++y)
      for (int x = 0; x < a.width(); ++x) {
        const QRgb p = a.pixel(x, y), q = b.pixel(x, y);
        const int d =
            std::max({std::abs(qRed(p) - qRed(q)), std::abs(qGreen(p) - qGreen(q)), std::abs(qBlue(p) - qBlue(q))});
        different += d > 0;
        worst = std::max(worst, d);
      }
    return {different, worst};
  }

  static std::pair<int, quint64> summarize(const QImage& image) {
    int drawn = 0;
    quint64 sum = 0;
    const QRgb background = image.pixel(2, image.height() - 3);
    for (int y = 0; y < image.height(); ++y)
      for (int x = 0; x < image.width() / 2; ++x) {  // leave the legend out
        const QRgb p = image.pixel(x, y);
        drawn += p != background;
        sum += quint64(p) * quint64(x + 7 * y + 1);
      }
    return {drawn, sum};
  }

 private slots:
  void initTestCase() {
    if (QGuiApplication::platformName() == "offscreen" || QGuiApplication::platformName() == "minimal")
      QSKIP("not run: needs an X display (run under xvfb-run)");
    plugins_ = std::make_unique<PluginManager>();
    plugins_->loadFrom({VOLPOST_PLUGIN_DIR});
    QVERIFY(!plugins_->readers().readers().empty());
  }

  // Every scenario starts from a fresh window with the bar open, so one that fails leaves
  // nothing behind for the next (ctest runs each as its own entry too).
  void init() {
    QSettings("volpost", "volpost").clear();
    window_ = std::make_unique<MainWindow>(*plugins_);
    window_->resize(900, 600);
    window_->show();
    QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
    QVERIFY(open(VOLPOST_TEST_DATA "/bar/bar_tet4.vtu"));
  }

  void cleanup() { window_.reset(); }

  void opensAModelAndColorsItByStress() {
    QVERIFY(open(VOLPOST_TEST_DATA "/bar/bar_tet4.vtu"));
    auto* box = window_->findChild<QComboBox*>("quantityBox");
    QVERIFY(box);
    QCOMPARE(box->currentData().toString(), QString("S.mises"));
    QCOMPARE(window_->session()->model().mesh().cellCount(), std::size_t(12431));
    const QImage image = settled(window_->viewport());
    const auto [drawn, sum] = summarize(image);
    QVERIFY2(drawn > image.width() / 2 * image.height() / 50, "the model covers part of the view");
    if (const char* shot = std::getenv("VOLPOST_SCREENSHOT")) window_->grab().save(shot);
    // The Model panel says what the model takes in memory, per cell, and the budget.
    auto* info = window_->findChild<QTextBrowser*>("modelInfo");
    QVERIFY(info);
    const QString text = info->toPlainText();
    QVERIFY2(text.contains("model: ") && text.contains("bytes per cell") && text.contains("budget: "),
             qPrintable(text));
  }

  void volumeRenderingRunsOnTheCpuWhereOpenGlIsDrawnByIt() {
    Viewport* view = window_->viewport();
    if (!gl::isSoftwareRasterizer(window_->findChild<QLabel*>("glLabel")->text().toStdString()))
      QSKIP("OpenGL here is a GPU's: the GPU ray caster stays the first choice");
    auto* cpu = window_->findChild<QAction*>("renderer:cpu");
    QVERIFY2(cpu && cpu->isChecked(), "software OpenGL: the CPU ray caster is chosen");
    QCOMPARE(view->scene().state().volume.renderer, std::string("cpu"));
    QVERIFY(window_->selectQuantity("S.mises"));
    auto* volume = window_->findChild<QAction*>("volumeAction");
    volume->setChecked(true);
    auto* refining = window_->findChild<QLabel*>("refiningLabel");
    QVERIFY(refining);
    const auto picture = summarize(settled(view));
    QVERIFY(picture.first > 0);
    QTest::qWait(50);
    view->repaint();
    QVERIFY2(!refining->isVisible(), "no \"refining\" once the full frame is shown");
    volume->setChecked(false);
  }

  // `volpost --screenshot` saves what the view settles on: SettledView says so only once a
  // frame was painted after the change and no full frame is computed behind a quick one.
  void aScreenshotWaitsForTheFullPicture() {
    Viewport* view = window_->viewport();
    QVERIFY(window_->selectQuantity("S.mises"));
    auto* volume = window_->findChild<QAction*>("volumeAction");
    volume->setChecked(true);
    window_->resize(1600, 1200);  // a full frame that takes a while on two cores
    settled(view);
    SettledView wait(view, 0);
    QSignalSpy done(&wait, &SettledView::settled);
    view->setStandardView(StandardView::PlusY);  // a new picture to compute
    QVERIFY(done.wait(60000));
    QVERIFY(!view->isRefining());
    QVERIFY(!view->drawing().hasPendingWork());
    const QImage shown = view->grabFramebuffer();
    QCOMPARE(summarize(shown), summarize(settled(view)));  // nothing changes after it
    view->setStandardView(StandardView::Isometric);
    volume->setChecked(false);
    window_->resize(900, 600);
  }

  void switchingTheResultChangesThePicture() {
    // The model alone (the legend's words and numbers differ between results).
    window_->viewport()->scene().setShowLegend(false);
    const auto before = summarize(settled(window_->viewport()));
    QVERIFY(window_->selectQuantity("U.magnitude"));
    QCOMPARE(window_->activeQuantity()->key(), std::string("U.magnitude"));
    const auto after = summarize(settled(window_->viewport()));
    // A bare field name picks its headline quantity, as `volpost render --field U` does.
    QVERIFY(window_->selectQuantity("S"));
    QCOMPARE(window_->activeQuantity()->key(), std::string("S.mises"));
    QVERIFY(window_->selectQuantity("U"));
    QCOMPARE(window_->activeQuantity()->key(), std::string("U.magnitude"));
    QVERIFY(!window_->selectQuantity("Nope"));
    QCOMPARE(window_->activeQuantity()->key(), std::string("U.magnitude"));
    window_->viewport()->scene().setShowLegend(true);
    // Same geometry, the same pixels drawn...
    QVERIFY2(std::abs(after.first - before.first) < before.first / 100,
             qPrintable(QString("%1 vs %2 pixels drawn").arg(after.first).arg(before.first)));
    QVERIFY(after.second != before.second);  // ...other colors
  }

  void standardViewsAndProjectionMoveTheCamera() {
    const auto iso = summarize(settled(window_->viewport()));
    window_->viewport()->setStandardView(StandardView::PlusX);  // looking down the bar's axis
    const auto end = summarize(settled(window_->viewport()));
    QVERIFY(end.first < iso.first);
    window_->viewport()->setStandardView(StandardView::Isometric);
  }

  void volumeRenderingAndADraggedClipPlane() {
    QVERIFY(window_->selectQuantity("S.mises"));
    auto* action = window_->findChild<QAction*>("volumeAction");
    QVERIFY(action);
    QVERIFY2(action->isEnabled(), "the volume plugin provides a renderer");
    Viewport* view = window_->viewport();
    const auto surface = summarize(settled(view));
    auto* colors = window_->findChild<QComboBox*>("colorMapBox");
    QVERIFY(colors->isEnabled());
    action->setChecked(true);
    QVERIFY(view->scene().volumeShown());
    QVERIFY2(!colors->isEnabled(), "one color control: the transfer function's");
    QVERIFY(!view->scene().volume().edges);  // no cage of element edges over the volume
    const auto volume = summarize(settled(view));
    QVERIFY(volume.second != surface.second);
    window_->findChild<QAction*>("clip:0")->trigger();
    QCOMPARE(view->scene().volume().clipPlanes.size(), std::size_t(1));
    const double before = view->scene().volume().clipPlanes[0].point.x;
    const VolumeStats beforeDrag = view->volumeStats();
    const QPoint start = view->rect().center();
    QTest::mousePress(view, Qt::LeftButton, Qt::ControlModifier, start);
    for (int step = 1; step <= 4; ++step) {
      const QPointF at(start + QPoint(0, -10 * step));
      QMouseEvent drag(QEvent::MouseMove, at, view->mapToGlobal(at), Qt::NoButton, Qt::LeftButton, Qt::ControlModifier);
      QApplication::sendEvent(view, &drag);
      view->repaint();
    }
    QTest::mouseRelease(view, Qt::LeftButton, Qt::ControlModifier, start + QPoint(0, -40));
    QVERIFY2(view->scene().volume().clipPlanes[0].point.x > before, "Ctrl+drag upward moves the plane along its normal");
    const auto clipped = summarize(settled(view));
    QVERIFY(clipped.second != volume.second);
    QCOMPARE(view->volumeStats().meshUploads, beforeDrag.meshUploads);   // the drag costs only frames
    QCOMPARE(view->volumeStats().tableBuilds, beforeDrag.tableBuilds);
    // A clip box (View > Clip Plane > Clip Box) and iso-surfaces (View > Iso-surfaces).
    window_->findChild<QAction*>("clip:-1")->trigger();
    window_->findChild<QAction*>("planeHandle")->setChecked(false);  // pixels of the volume only
    view->scene().setClipBox(ClipBox{2.0, 8.0, -1.0, 2.0, -1.0, 2.0});
    view->update();
    const auto boxed = summarize(settled(view));
    window_->findChild<QAction*>("planeHandle")->setChecked(true);
    QVERIFY(boxed.second != volume.second && boxed.first < volume.first);
    QVERIFY2(view->uploadedTetCount() < window_->session()->tetrahedra().mesh.cellCount() * 3 / 4,
             "the GPU holds only the tets the box can show");
    view->scene().setClipBox(std::nullopt);
    view->scene().setIsoSurfaces({{100.0, {1.0, 0.85, 0.2}, 1.0}});
    view->update();
    const auto iso = summarize(settled(view));
    QVERIFY(iso.second != volume.second);
    view->scene().setIsoSurfaces({});
    // The same view by cell projection (View > Volume Renderer): close to the ray caster's.
    auto* vicp = window_->findChild<QAction*>("renderer:vicp-exact");
    QVERIFY2(vicp, "the volume plugin offers cell projection");
    vicp->trigger();
    const auto projected = summarize(settled(view));
    QVERIFY(view->scene().volumeShown());
    QVERIFY2(std::abs(projected.first - volume.first) < volume.first / 20,
             qPrintable(QString("%1 vs %2 pixels").arg(projected.first).arg(volume.first)));
    window_->findChild<QAction*>("renderer:raycast")->trigger();
    window_->findChild<QAction*>("clip:0")->trigger();
    if (const char* shot = std::getenv("VOLPOST_VOLUME_SCREENSHOT")) window_->grab().save(shot);
    window_->findChild<QAction*>("clip:-1")->trigger();
    action->setChecked(false);
    QVERIFY(!view->scene().volumeShown());
  }

  void theRendererMenuShowsThePluginsOwnWords() {
    // The labels come from the renderers themselves (VolumeRenderer::traits), not the host.
    auto* raycast = window_->findChild<QAction*>("renderer:raycast");
    auto* vicp = window_->findChild<QAction*>("renderer:vicp");
    QVERIFY(raycast && vicp);
    QVERIFY2(raycast->text().startsWith("Ray casting"), qPrintable(raycast->text()));
    QVERIFY2(vicp->text().startsWith("Cell projection"), qPrintable(vicp->text()));
    // Where OpenGL is drawn by the CPU, the fast renderer comes first and the GPU ones say
    // they are slow here (the GPU ray caster was first, with no hint).
    if (gl::isSoftwareRasterizer(window_->findChild<QLabel*>("glLabel")->text().toStdString())) {
      auto* menu = window_->findChild<QMenu*>("rendererMenu");
      QVERIFY(menu);
      QCOMPARE(menu->actions().first()->objectName(), QString("renderer:cpu"));
      QVERIFY2(raycast->text().contains("slow here"), qPrintable(raycast->text()));
      QVERIFY2(vicp->text().contains("slow here") && vicp->text().count('(') == 1, qPrintable(vicp->text()));
      QVERIFY2(!window_->findChild<QAction*>("renderer:cpu")->text().contains("slow"), "the fast one is not marked");
    }
    // One renderer checked, the scene's (a renderer checked by the window itself, then
    // another picked from the menu, left both checked).
    const auto checkedRenderers = [&] {
      QStringList names;
      for (QAction* a : window_->findChild<QMenu*>("rendererMenu")->actions())
        if (a->isChecked()) names << a->objectName();
      return names;
    };
    QCOMPARE(checkedRenderers(),
             QStringList{"renderer:" + QString::fromStdString(window_->viewport()->scene().state().volume.renderer)});
    // The CPU ray caster integrates exactly: Volume Integration has nothing to offer it; the
    // GPU ray caster offers every mode.
    auto* linear = window_->findChild<QAction*>("mode:linear");
    QVERIFY(linear);
    window_->findChild<QAction*>("renderer:cpu")->trigger();
    QCOMPARE(checkedRenderers(), QStringList{"renderer:cpu"});
    QVERIFY(!linear->isEnabled());
    QVERIFY2(linear->toolTip().contains("exactly"), qPrintable(linear->toolTip()));
    raycast->trigger();
    QCOMPARE(checkedRenderers(), QStringList{"renderer:raycast"});
    QVERIFY(linear->isEnabled());
    for (QAction* a : window_->findChildren<QAction*>())
      QVERIFY2(!a->text().contains("seed") && !a->text().contains("MPVONC"), qPrintable(a->text()));
  }

  void reversedMapsSymmetricRangeAndBandsFollowTheScene() {
    QVERIFY(window_->selectQuantity("S.xy"));
    Scene& scene = window_->viewport()->scene();
    window_->findChild<QAction*>("reverseColorsAction")->setChecked(true);
    QCOMPARE(scene.state().colorMap, std::string("cool-warm-reversed"));
    auto* colors = window_->findChild<QComboBox*>("colorMapBox");
    colors->setCurrentIndex(colors->findData("viridis"));  // another map stays reversed
    QCOMPARE(scene.state().colorMap, std::string("viridis-reversed"));
    window_->findChild<QAction*>("symmetricRangeAction")->setChecked(true);
    QVERIFY(scene.state().symmetricRange);
    window_->findChild<QAction*>("outOfRangeAction")->setChecked(true);
    QVERIFY(scene.state().belowColor && scene.state().aboveColor);
    QCOMPARE(scene.displayRange().min, -scene.displayRange().max);
    // A state with other colors: the controls show them.
    SceneState state = scene.state();
    state.colorMap = "rainbow";
    state.symmetricRange = false;
    state.colorBands = 12;
    const QString path = QDir::temp().filePath("volpost_gui_colors_test.json");
    state.save(path.toStdString());
    QSignalSpy applied(window_.get(), &MainWindow::stateApplied);
    window_->openStateFile(path);
    QVERIFY(applied.count() == 1 || applied.wait(30000));
    QVERIFY(applied.first().first().toBool());
    QFile::remove(path);
    QVERIFY(!window_->findChild<QAction*>("reverseColorsAction")->isChecked());
    QVERIFY(!window_->findChild<QAction*>("symmetricRangeAction")->isChecked());
    QVERIFY(window_->findChild<QAction*>("outOfRangeAction")->isChecked());  // the state kept them
    QCOMPARE(colors->currentData().toString(), QString("rainbow"));
    QVERIFY(window_->findChild<QAction*>("colorBandsAction")->text().contains("12"));
    // View > Legend Text and Numbers...: the fields show the legend's, OK applies them.
    QString shownTitle;
    QTimer::singleShot(0, [&] {
      auto* dialog = QApplication::activeModalWidget();
      if (!dialog) return;
      shownTitle = dialog->findChild<QLineEdit*>("legendTitle")->placeholderText();
      dialog->findChild<QLineEdit*>("legendUnits")->setText("MPa");
      dialog->findChild<QComboBox*>("legendNumberStyle")->setCurrentIndex(1);
      dialog->findChild<QSpinBox*>("legendDigits")->setValue(2);
      QMetaObject::invokeMethod(dialog, "accept");
    });
    window_->findChild<QAction*>("legendTextAction")->trigger();
    QCOMPARE(shownTitle, QString("S XY"));
    QCOMPARE(scene.state().units.at("S"), std::string("MPa"));
    QCOMPARE(scene.state().legendNumbers, std::string("fixed:2"));
    QCOMPARE(scene.legend()->content.title, QString("S XY [MPa]"));
  }

  void plotOverStepsAtProbedPoints() {
    // Probe panel > Plot Over Steps: the shown quantity at each probe, over every step.
    QVERIFY(open(VOLPOST_TEST_DATA "/formats/golden.frd"));  // T at two steps
    QVERIFY(window_->selectQuantity("T"));
    window_->findChild<QAction*>("probeAction")->setChecked(true);
    auto* typed = window_->findChild<QLineEdit*>("probeTyped");
    for (const char* where : {"node 10", "1.5, 0.5, 0.5"}) {
      typed->setText(where);
      QTest::keyClick(typed, Qt::Key_Return);
    }
    auto* panel = window_->findChild<ProbePanel*>("probePanel");
    QCOMPARE(panel->results().size(), std::size_t(2));
    for (QPushButton* b : panel->findChildren<QPushButton*>())
      if (b->text() == "Plot Over Steps") b->click();
    auto* history = window_->findChild<HistoryPanel*>("historyPanel");
    QVERIFY(history && history->history());
    QVERIFY(window_->findChild<QDockWidget*>("historyDock")->isVisible());
    const History& h = *history->history();
    QCOMPARE(h.curves.size(), std::size_t(2));
    QCOMPARE(h.curves[0].place, std::string("node 10"));
    QCOMPARE(h.curves[1].values, (std::vector<double>{56.5, 113.0}));  // as `volpost probe` gives them
    QVERIFY(window_->findChild<QLabel*>("historyTitle")->text().startsWith("T over 2 steps at node 10"));
    // Two probes selected: their distance in the panel (node 10 is at the origin).
    auto* picks = window_->findChild<QTableWidget*>("probePicks");
    picks->selectAll();
    const QString measure = window_->findChild<QLabel*>("probeMeasure")->text();
    QVERIFY2(measure.startsWith("Distance 1 to 2: 1.65831"), qPrintable(measure));
    // ... and in the picture: the scene measures them, and a state file keeps it.
    QCOMPARE(window_->findChild<Viewport*>()->scene().measure(), (std::vector<std::size_t>{0, 1}));
    picks->clearSelection();
    picks->selectRow(0);
    QVERIFY(window_->findChild<Viewport*>()->scene().measure().empty());
  }

  void theCalculatorsFormulaIsAResultKeptInTheStateFile() {
    // Results > Calculator...: a formula typed there is shown at once and offered in the
    // quantity box; a bad one is refused in the dialog; a state file brings it back.
    QString problem;
    QTimer::singleShot(0, [&] {
      auto* dialog = qobject_cast<CalculatorDialog*>(QApplication::activeModalWidget());
      if (!dialog) return;
      dialog->findChild<QLineEdit*>("formulaName")->setText("ratio");
      dialog->findChild<QLineEdit*>("formulaExpression")->setText("S.mises / +* 250");
      dialog->addFromEditors();
      problem = dialog->problem();
      dialog->findChild<QLineEdit*>("formulaExpression")->setText("S.mises / 250");
      dialog->addFromEditors();
      dialog->reject();
    });
    window_->findChild<QAction*>("calculatorAction")->trigger();
    QVERIFY2(problem.contains("formula 'ratio'") && problem.contains("at character"), qPrintable(problem));
    Viewport* view = window_->viewport();
    QCOMPARE(view->scene().state().quantity, std::string("ratio"));
    auto* box = window_->findChild<QComboBox*>("quantityBox");
    QCOMPARE(box->currentData().toString(), QString("ratio"));
    QVERIFY(std::abs(view->scene().view()->range.max - 102.712 / 250.0) < 1e-4);

    const QString state = QDir::temp().filePath("volpost_gui_formula_test.json");
    QVERIFY(window_->saveStateFile(state));
    QVERIFY(open(VOLPOST_TEST_DATA "/bar/bar_tet4.vtu"));  // another model: the formulas go
    QCOMPARE(box->findData("ratio"), -1);
    QSignalSpy applied(window_.get(), &MainWindow::stateApplied);
    window_->openStateFile(state);
    QVERIFY(applied.count() == 1 || applied.wait(30000));
    QVERIFY(applied.first().first().toBool());
    QCOMPARE(box->currentData().toString(), QString("ratio"));
    QCOMPARE(view->scene().formulas().size(), std::size_t(1));
    QFile::remove(state);
  }

  void aSavedStateRendersTheSamePictureHeadless() {
    // The window's view saved as a state file; `volpost render --state` draws it pixel for
    // pixel (same size, legend and axes off: their text is painted by two font paths).
    QVERIFY(window_->selectQuantity("S.mises"));
    window_->findChild<QAction*>("triadAction")->setChecked(false);
    auto* action = window_->findChild<QAction*>("volumeAction");
    action->setChecked(true);
    window_->findChild<QAction*>("clip:1")->trigger();
    // The plane's handle is a tool of the window, like the cursor: pictures never show it.
    window_->findChild<QAction*>("planeHandle")->setChecked(false);
    Viewport* view = window_->viewport();
    view->scene().setShowLegend(false);
    view->scene().camera().orbit(30.0, 12.0);
    view->update();
    const QImage shown = settled(view);
    const QString state = QDir::temp().filePath("volpost_gui_state_test.json");
    const QString png = QDir::temp().filePath("volpost_gui_state_test.png");
    QVERIFY(window_->saveStateFile(state));
    QString error;
    const QImage headless = renderedHeadless(state, png, shown.size(), error);
    QVERIFY2(!headless.isNull(), qPrintable(error));
    const QImage window = shown.convertToFormat(QImage::Format_RGB32);
    QCOMPARE(headless.size(), window.size());
    const auto [different, worst] = pixelsApart(window, headless);
    QVERIFY2(different == 0, qPrintable(QString("%1 pixels differ, by up to %2").arg(different).arg(worst)));
    // And back: the window opens the state file and shows the same view again.
    window_->findChild<QAction*>("clip:-1")->trigger();
    view->scene().camera().orbit(-60.0, 0.0);
    QSignalSpy applied(window_.get(), &MainWindow::stateApplied);
    window_->openStateFile(state);
    QVERIFY(applied.count() == 1 || applied.wait(30000));
    QVERIFY(applied.first().first().toBool());
    QCOMPARE(view->scene().volume().clipPlanes.size(), std::size_t(1));
    QVERIFY(settled(view).convertToFormat(QImage::Format_RGB32) == window);
    QFile::remove(state);
    QFile::remove(png);
    view->scene().setShowLegend(true);
    window_->findChild<QAction*>("planeHandle")->setChecked(true);
    window_->findChild<QAction*>("clip:-1")->trigger();
    action->setChecked(false);
  }

  void theCellsOwnFieldIsDrawnInTheWindowAsHeadless() {
    // Two hex8 cells carrying x y z (their own trilinear field): the window's CPU volume
    // renderer draws it from Volume > Cells' Own Interpolation, and `volpost render --state`
    // draws the same picture; the split's field is another picture.
    const QString model = QDir::temp().filePath("volpost_gui_hex_xyz.vtk");
    {
      QFile f(model);
      QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Text));
      QTextStream out(&f);
      out << "# vtk DataFile Version 4.2\nhex8 xyz\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 12 double\n";
      for (int k = 0; k < 2; ++k)
        for (int j = 0; j < 2; ++j)
          for (int i = 0; i < 3; ++i) out << 0.5 * i << ' ' << j << ' ' << k << '\n';
      out << "CELLS 2 18\n8 0 1 4 3 6 7 10 9\n8 1 2 5 4 7 8 11 10\nCELL_TYPES 2\n12\n12\n";
      out << "POINT_DATA 12\nSCALARS T double 1\nLOOKUP_TABLE default\n";
      for (int k = 0; k < 2; ++k)
        for (int j = 0; j < 2; ++j)
          for (int i = 0; i < 3; ++i) out << 0.5 * i * j * k << '\n';
    }
    QVERIFY(open(model));
    QVERIFY(window_->selectQuantity("T"));
    window_->findChild<QAction*>("triadAction")->setChecked(false);
    Viewport* view = window_->viewport();
    view->scene().setShowLegend(false);
    window_->findChild<QAction*>("volumeAction")->setChecked(true);
    QCOMPARE(view->scene().volume().renderer, std::string("cpu"));  // OpenGL drawn by the CPU here
    view->scene().camera().orbit(25.0, 15.0);
    view->update();
    const QImage split = settled(view).convertToFormat(QImage::Format_RGB32);
    auto* own = window_->findChild<QAction*>("elementInterpolationAction");
    own->setChecked(true);
    QVERIFY(own->isChecked());
    view->update();
    const QImage shown = settled(view).convertToFormat(QImage::Format_RGB32);
    QVERIFY2(shown != split, "the trilinear field is not the split's");
    const QString state = QDir::temp().filePath("volpost_gui_element_state.json");
    const QString png = QDir::temp().filePath("volpost_gui_element_state.png");
    QVERIFY(window_->saveStateFile(state));
    QString error;
    const QImage headless = renderedHeadless(state, png, shown.size(), error);
    QVERIFY2(!headless.isNull(), qPrintable(error));
    QCOMPARE(headless.size(), shown.size());
    const int different = pixelsApart(shown, headless).first;
    QVERIFY2(different == 0, qPrintable(QString("%1 pixels differ").arg(different)));
    // The GPU ray caster draws it on refined pieces, made on a worker thread: the status bar
    // says so while they are made, and the settled picture is the one `volpost render
    // --state` draws.
    QSignalSpy said(view, &Viewport::refiningMessage);
    window_->findChild<QAction*>("renderer:raycast")->trigger();
    QCOMPARE(view->scene().volume().renderer, std::string("raycast"));
    QVERIFY(own->isChecked());
    const QImage onGpu = settled(view).convertToFormat(QImage::Format_RGB32);
    QStringList messages;
    for (const QList<QVariant>& message : said) messages << message.at(0).toString();
    QVERIFY2(messages.filter("Refining the cells' own field: ").size() > 0, qPrintable(messages.join(" | ")));
    QVERIFY(!window_->findChild<QLabel*>("refiningLabel")->isVisible());
    QVERIFY2(onGpu != split, "the refined pieces are not the split");
    QVERIFY(window_->saveStateFile(state));
    const QImage gpuHeadless = renderedHeadless(state, png, onGpu.size(), error);
    QVERIFY2(!gpuHeadless.isNull(), qPrintable(error));
    const int gpuDifferent = pixelsApart(onGpu, gpuHeadless).first;
    QVERIFY2(gpuDifferent == 0, qPrintable(QString("%1 pixels differ on the GPU ray caster").arg(gpuDifferent)));
    window_->findChild<QAction*>("renderer:cpu")->trigger();
    QCOMPARE(view->scene().volume().renderer, std::string("cpu"));
    // Turned off again, the renderer drops the cells' own field: the split's picture.
    own->setChecked(false);
    view->update();
    const QImage again = settled(view).convertToFormat(QImage::Format_RGB32);
    QVERIFY2(pixelsApart(again, split).first == 0, "the split's picture again");
    QFile::remove(state);
    QFile::remove(png);
    QFile::remove(model);
  }

  void theCellsOwnSectionsAndIsoSurfacesAreDrawnInTheWindowAsHeadless() {
    // A block of 2 x 2 x 2 hex8 cells carrying x y z, in the surface view, cut by a clip
    // plane and holding the iso-surface xyz = 0.1: with the cells' own interpolation the
    // section is colored by the trilinear field and the iso-surface is its level set; the
    // split's are other pictures, and `volpost render --state` draws the window's.
    const QString model = QDir::temp().filePath("volpost_gui_hex_block_xyz.vtk");
    {
      QFile f(model);
      QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Text));
      QTextStream out(&f);
      out << "# vtk DataFile Version 4.2\nhex8 xyz\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 27 double\n";
      for (int k = 0; k < 3; ++k)
        for (int j = 0; j < 3; ++j)
          for (int i = 0; i < 3; ++i) out << 0.5 * i << ' ' << 0.5 * j << ' ' << 0.5 * k << '\n';
      const auto id = [](int i, int j, int k) { return (k * 3 + j) * 3 + i; };
      out << "CELLS 8 72\n";
      for (int k = 0; k < 2; ++k)
        for (int j = 0; j < 2; ++j)
          for (int i = 0; i < 2; ++i)
            out << "8 " << id(i, j, k) << ' ' << id(i + 1, j, k) << ' ' << id(i + 1, j + 1, k) << ' ' << id(i, j + 1, k)
                << ' ' << id(i, j, k + 1) << ' ' << id(i + 1, j, k + 1) << ' ' << id(i + 1, j + 1, k + 1) << ' '
                << id(i, j + 1, k + 1) << '\n';
      out << "CELL_TYPES 8\n";
      for (int c = 0; c < 8; ++c) out << "12\n";
      out << "POINT_DATA 27\nSCALARS T double 1\nLOOKUP_TABLE default\n";
      for (int k = 0; k < 3; ++k)
        for (int j = 0; j < 3; ++j)
          for (int i = 0; i < 3; ++i) out << 0.125 * i * j * k << '\n';
    }
    QVERIFY(open(model));
    QVERIFY(window_->selectQuantity("T"));
    window_->findChild<QAction*>("triadAction")->setChecked(false);
    Viewport* view = window_->viewport();
    view->scene().setShowLegend(false);
    window_->findChild<QAction*>("volumeAction")->setChecked(false);
    auto* handle = window_->findChild<QAction*>("planeHandle");
    const bool handleWasShown = handle->isChecked();
    handle->setChecked(false);  // the window's handle on the plane is not part of the picture
    view->scene().setClipPlanes({ClipPlane{{0.6, 0.6, 0.6}, {-1.0, -1.0, -1.0}}});
    view->scene().setIsoSurfaces({optics::IsoSurface{0.1, {0.9, 0.5, 0.2}, 1.0}});
    view->scene().camera().orbit(25.0, 15.0);
    view->update();
    const QImage split = settled(view).convertToFormat(QImage::Format_RGB32);
    auto* own = window_->findChild<QAction*>("elementInterpolationAction");
    own->setChecked(true);
    QVERIFY(own->isChecked());
    QVERIFY(view->scene().volume().interpolation == FieldInterpolation::Element);
    view->update();
    const QImage shown = settled(view).convertToFormat(QImage::Format_RGB32);
    const int changed = pixelsApart(shown, split).first;
    QVERIFY2(changed > 50, qPrintable(QString("the cells' own section and iso-surface differ from the split's in "
                                              "%1 pixels")
                                          .arg(changed)));
    const QString state = QDir::temp().filePath("volpost_gui_element_sections.json");
    const QString png = QDir::temp().filePath("volpost_gui_element_sections.png");
    QVERIFY(window_->saveStateFile(state));
    QString error;
    const QImage headless = renderedHeadless(state, png, shown.size(), error);
    QVERIFY2(!headless.isNull(), qPrintable(error));
    const int different = pixelsApart(shown, headless).first;
    QVERIFY2(different == 0, qPrintable(QString("%1 pixels differ").arg(different)));
    own->setChecked(false);
    view->update();
    QVERIFY2(pixelsApart(settled(view).convertToFormat(QImage::Format_RGB32), split).first == 0, "the split's again");
    view->scene().setIsoSurfaces({});
    view->scene().setClipPlanes({});
    handle->setChecked(handleWasShown);
    QFile::remove(state);
    QFile::remove(png);
    QFile::remove(model);
  }

  void transferFunctionPanelEditsTheVolumeLive() {
    QVERIFY(window_->selectQuantity("S.mises"));
    auto* dock = window_->findChild<QDockWidget*>("panel:Transfer Function");
    QVERIFY2(dock, "the tfeditor plugin adds its panel");
    auto* curve = dock->findChild<QWidget*>("tfCurve");
    QVERIFY(curve);
    auto* action = window_->findChild<QAction*>("volumeAction");
    action->setChecked(true);
    Viewport* view = window_->viewport();
    const auto before = summarize(settled(view));
    const std::size_t points = window_->transferFunction().points().size();
    // A click low near the top of the range (where most of the bar's stress is, between
    // the last two points) adds a nearly clear point: the host's function and the picture change.
    QTest::mouseClick(curve, Qt::LeftButton, {}, QPoint(6 + int(0.94 * (curve->width() - 12)), curve->height() * 3 / 4));
    QTRY_COMPARE(window_->transferFunction().points().size(), points + 1);
    QCOMPARE(view->scene().transferFunction(), window_->transferFunction());
    const auto after = summarize(settled(view));
    QVERIFY(after.second != before.second);
    if (const char* shot = std::getenv("VOLPOST_TF_SCREENSHOT")) window_->grab().save(shot);
    action->setChecked(false);
  }

  void placingARakeTracesStreamlines() {
    // View > Streamlines > Place a Rake, then a drag across the bar: 20 seeds along it, lines
    // of the displacement field traced on a worker thread and drawn.
    Viewport* view = window_->viewport();
    window_->viewport()->setStandardView(StandardView::PlusY);
    const auto before = summarize(settled(view));
    window_->findChild<QAction*>("placeRake")->trigger();
    QVERIFY(view->rakeMode());
    QTest::keyClick(view, Qt::Key_Escape);  // Esc leaves placement with nothing changed
    QVERIFY(!view->rakeMode());
    QVERIFY(!view->scene().streamlines().shown);
    window_->findChild<QAction*>("placeRake")->trigger();
    QVERIFY(view->rakeMode());
    const QPoint c = view->rect().center();
    const QPoint a = c + QPoint(-view->width() / 3, 0), b = c + QPoint(view->width() / 3, 0);
    QSignalSpy traced(window_.get(), &MainWindow::streamlinesTraced);
    QTest::mousePress(view, Qt::LeftButton, {}, a);
    for (int k = 1; k <= 4; ++k) {
      const QPointF at(a + (b - a) * k / 4);
      QMouseEvent move(QEvent::MouseMove, at, view->mapToGlobal(at), Qt::NoButton, Qt::LeftButton, Qt::NoModifier);
      QApplication::sendEvent(view, &move);
    }
    QTest::mouseRelease(view, Qt::LeftButton, {}, b);
    QVERIFY(!view->rakeMode());
    QVERIFY(traced.count() > 0 || traced.wait(30000));
    QVERIFY2(traced.first().first().toBool(), qPrintable(traced.first().at(1).toString()));
    const StreamlineLayer& layer = view->scene().streamlines();
    QVERIFY(layer.shown);
    QCOMPARE(layer.field, std::string("U"));
    // One seed per point of the dragged line over the bar, each halfway through it.
    QVERIFY2(layer.seeds.size() >= 10 && layer.seeds.size() <= 20, qPrintable(QString::number(layer.seeds.size())));
    for (const std::string& seed : layer.seeds) QVERIFY2(seed.rfind("point:", 0) == 0, seed.c_str());
    QCOMPARE(view->scene().streamlineResult()->outside, std::size_t(0));
    const auto result = view->scene().streamlineResult();
    QVERIFY(result);
    QVERIFY2(result->lines.size() >= 10, qPrintable(QString("%1 lines").arg(result->lines.size())));
    const auto after = summarize(settled(view));
    QVERIFY(after.second != before.second);
    if (const char* shot = std::getenv("VOLPOST_STREAMLINE_SCREENSHOT")) window_->grab().save(shot);
    window_->findChild<QAction*>("streamlinesAction")->setChecked(false);
    QVERIFY(!view->scene().streamlines().shown);
    view->scene().setSurfaceOpacity(1.0);
    window_->viewport()->setStandardView(StandardView::Isometric);
  }

  void aDraggedBoxSelectsElementsAndNodes() {
    // Results > Select Elements, then a box over the middle of the bar seen from +y: the
    // elements seen there are selected, marked, and listed as a set; Through takes more
    // (the ones behind too); Select Nodes takes nodes; Escape ends; Clear forgets.
    Viewport* view = window_->viewport();
    view->setStandardView(StandardView::PlusY);
    const QPoint c = view->rect().center();
    const auto drag = [&](QPoint a, QPoint b, Qt::KeyboardModifiers modifiers = {}) {
      QTest::mousePress(view, Qt::LeftButton, modifiers, a);
      QMouseEvent move(QEvent::MouseMove, QPointF(b), view->mapToGlobal(QPointF(b)), Qt::NoButton, Qt::LeftButton,
                       modifiers);
      QApplication::sendEvent(view, &move);
      QTest::mouseRelease(view, Qt::LeftButton, modifiers, b);
    };
    window_->findChild<QAction*>("selectElements")->trigger();
    QVERIFY(view->selectMode());
    drag(c - QPoint(30, 20), c + QPoint(30, 20));
    const std::size_t seen = view->scene().selection().elements.size();
    QVERIFY2(seen > 0, qPrintable(window_->statusBar()->currentMessage()));
    QVERIFY(window_->statusBar()->currentMessage().contains("elements selected"));
    QCOMPARE(view->scene().setVisibility().marked, std::string("selected elements"));
    QVERIFY(view->selectMode());  // stays on for the next box
    window_->findChild<QAction*>("selectElementsThrough")->trigger();
    drag(c - QPoint(30, 20), c + QPoint(30, 20));
    QVERIFY2(view->scene().selection().elements.size() > seen, "through the depth: the hidden ones too");
    const std::size_t through = view->scene().selection().elements.size();
    drag(c + QPoint(60, -20), c + QPoint(90, 20), Qt::ControlModifier);  // Ctrl adds
    QVERIFY(view->scene().selection().elements.size() > through);
    window_->findChild<QAction*>("selectNodes")->trigger();
    QTest::mouseClick(view, Qt::LeftButton, {}, c);  // a click: the node nearest it
    QCOMPARE(view->scene().selection().nodes.size(), std::size_t(1));
    QVERIFY(!view->scene().selection().elements.empty());  // the other kind stays
    QTest::keyClick(view, Qt::Key_Escape);
    QVERIFY(!view->selectMode());
    QVERIFY(!window_->findChild<QAction*>("selectNodes")->isChecked());
    const SceneState saved = view->scene().state();
    QCOMPARE(saved.selection, view->scene().selection());
    window_->findChild<QAction*>("clearSelectionAction")->trigger();
    QVERIFY(view->scene().selection().empty());
    QVERIFY(view->scene().setVisibility().marked.empty());
    view->setStandardView(StandardView::Isometric);
  }

  void probingByClickAndByTypingListsTheValues() {
    // View > Probe, then a click on the middle of the bar seen from +y: one probed point
    // on its side face, listed with its element; a typed point adds a second.
    Viewport* view = window_->viewport();
    view->setStandardView(StandardView::PlusY);
    QVERIFY(view->scene().probes().empty());
    window_->findChild<QAction*>("probeAction")->setChecked(true);
    QVERIFY(view->probeMode());
    auto* dock = window_->findChild<QDockWidget*>("probeDock");
    QVERIFY(dock && dock->isVisible());
    QTest::mouseClick(view, Qt::LeftButton, {}, view->rect().center());
    QCOMPARE(view->scene().probes().size(), std::size_t(1));
    const glm::dvec3 hit = view->scene().probes()[0];
    QVERIFY2(std::abs(hit.y - 1.0) < 1e-9, "on the face y = 1, facing the viewer from +y");
    auto* panel = window_->findChild<ProbePanel*>("probePanel");
    QVERIFY(panel);
    QCOMPARE(panel->results().size(), std::size_t(1));
    QVERIFY(panel->results()[0].inside());
    auto* typed = window_->findChild<QLineEdit*>("probeTyped");
    typed->setText("5, 0.5, 0.5");
    QTest::keyClick(typed, Qt::Key_Return);
    QCOMPARE(panel->results().size(), std::size_t(2));
    QVERIFY(std::abs(*panel->results()[1].value("S.xx") - 100.0) < 0.05);
    QCOMPARE(window_->findChild<QTableWidget*>("probePicks")->rowCount(), 2);
    typed->setText("node 5");  // the file's own ids: node 5 is at (10, 0, 1)
    QTest::keyClick(typed, Qt::Key_Return);
    QCOMPARE(panel->results().size(), std::size_t(3));
    QCOMPARE(panel->results()[2].point, glm::dvec3(10.0, 0.0, 1.0));
    QCOMPARE(panel->results()[2].nodeId.value_or(0), std::int64_t(5));
    typed->setText("element 999999");  // refused, with the reason in the status bar
    QTest::keyClick(typed, Qt::Key_Return);
    QCOMPARE(panel->results().size(), std::size_t(3));
    QVERIFY(window_->statusBar()->currentMessage().contains("no element 999999"));
    window_->findChild<QTableWidget*>("probePicks")->selectRow(2);
    for (QPushButton* b : panel->findChildren<QPushButton*>())
      if (b->text() == "Remove") b->click();
    QCOMPARE(panel->results().size(), std::size_t(2));
    QVERIFY(window_->findChild<QTableWidget*>("probeDetails")->rowCount() > 10);  // every quantity
    const std::string table = panel->table(',');
    QVERIFY(table.rfind("x,y,z,element,element_type,node,", 0) == 0);
    // Min and max marked: the picture changes; the state keeps both.
    view->fit();
    const QImage before = settled(view);
    window_->findChild<QAction*>("extremesAction")->setChecked(true);
    QVERIFY(view->scene().marksExtremes());
    const QImage after = settled(view);
    QVERIFY(after != before);
    if (const char* shot = std::getenv("VOLPOST_PROBE_SCREENSHOT")) window_->grab().save(shot);
    const SceneState state = view->scene().state();
    QCOMPARE(state.probes.size(), std::size_t(2));
    QVERIFY(state.markExtremes);
    // A drag still orbits and adds nothing.
    QTest::mousePress(view, Qt::LeftButton, {}, view->rect().center());
    QMouseEvent move(QEvent::MouseMove, QPointF(view->rect().center() + QPoint(40, 10)),
                     view->mapToGlobal(QPointF(view->rect().center() + QPoint(40, 10))), Qt::LeftButton, Qt::LeftButton,
                     Qt::NoModifier);
    QApplication::sendEvent(view, &move);
    QTest::mouseRelease(view, Qt::LeftButton, {}, view->rect().center() + QPoint(40, 10));
    QCOMPARE(view->scene().probes().size(), std::size_t(2));
    window_->findChild<QAction*>("probeAction")->setChecked(false);
    window_->findChild<QAction*>("extremesAction")->setChecked(false);
    view->scene().setProbes({});
    window_->viewport()->setStandardView(StandardView::Isometric);
  }

  // View > Show Frame Rate times what the user waits for: a drag's frames and the full
  // picture after it (on the small bar the CPU ray caster's frames are full at once, on a
  // large model quick first); the log writes each one.
  void theFrameRateIsShownAndLogged() {
    Viewport* view = window_->viewport();
    window_->findChild<QAction*>("volumeAction")->setChecked(true);
    (void)settled(view);
    auto* show = window_->findChild<QAction*>("showFrameRateAction");
    QVERIFY(show);
    show->setChecked(true);
    auto* readout = view->findChild<QLabel*>("frameRate");
    QVERIFY(readout && readout->isVisible());
    QVERIFY(readout->text().contains("move the view"));
    const QString logPath = QDir::temp().filePath("volpost_frame_times.txt");
    QFile::remove(logPath);
    auto* actions = window_->findChild<FrameRateActions*>();
    QVERIFY(actions && actions->logTo(logPath));
    QVERIFY(window_->findChild<QAction*>("logFrameTimesAction")->isChecked());
    QPoint at = view->rect().center();
    QTest::mousePress(view, Qt::LeftButton, {}, at);
    for (int i = 0; i < 6; ++i) {
      at += QPoint(8, 2);
      QMouseEvent move(QEvent::MouseMove, QPointF(at), view->mapToGlobal(QPointF(at)), Qt::LeftButton, Qt::LeftButton,
                       Qt::NoModifier);
      QApplication::sendEvent(view, &move);
      QTest::qWait(60);
    }
    QTest::mouseRelease(view, Qt::LeftButton, {}, at);
    QTRY_VERIFY_WITH_TIMEOUT(view->frameTimes().changeToFullMs.has_value(), 60000);
    const FrameTimes::Summary times = view->frameTimes();
    QVERIFY(times.framesAnswered >= 2);
    QVERIFY(*times.inputToFrameMs > 0.0);
    QVERIFY2(readout->text().contains("after input") && readout->text().contains("full picture"),
             qPrintable(readout->text()));
    QVERIFY(actions->logTo({}));
    QFile log(logPath);
    QVERIFY(log.open(QIODevice::ReadOnly));
    const QString lines = QString::fromUtf8(log.readAll());
    QVERIFY2(lines.contains("ms after input, ") && lines.contains("after the last change"), qPrintable(lines));
    QFile::remove(logPath);
    // A log that cannot be written says so and stays off.
    QVERIFY(!actions->logTo("/nonexistent/volpost/frames.txt"));
    QVERIFY(window_->statusBar()->currentMessage().contains("/nonexistent/volpost/frames.txt"));
    QVERIFY(!window_->findChild<QAction*>("logFrameTimesAction")->isChecked());
    show->setChecked(false);
    QVERIFY(!view->findChild<QLabel*>("frameRate"));
  }

  void steppingPlayingAndTheRangeOverSteps() {
    // golden.frd: T is 0..111 at step 1 and 0..222 at step 2 (twice the values).
    QVERIFY(open(VOLPOST_TEST_DATA "/formats/golden.frd"));
    QVERIFY(window_->selectQuantity("T"));
    window_->resize(1280, 600);  // the window's default width: the toolbar shows the range fields
    auto* stepBox = window_->findChild<QComboBox*>("stepBox");
    QCOMPARE(stepBox->count(), 2);
    Viewport* view = window_->viewport();
    view->scene().setShowLegend(false);  // the model alone
    auto* next = window_->findChild<QAction*>("nextStepAction");
    auto* previous = window_->findChild<QAction*>("previousStepAction");
    QVERIFY(next && previous && next->isEnabled());
    const QImage step1 = settled(view);
    next->trigger();
    QCOMPARE(view->scene().state().step, std::size_t(1));
    next->trigger();  // the last step stays
    QCOMPARE(view->scene().state().step, std::size_t(1));
    // Each step spans the map: twice the values, the same picture.
    QCOMPARE(settled(view), step1);
    auto* range = window_->findChild<QComboBox*>("rangeBox");
    range->setCurrentIndex(1);  // all steps
    QVERIFY(view->scene().state().rangeOverSteps);
    const QImage step2All = settled(view);
    previous->trigger();
    QCOMPARE(view->scene().state().step, std::size_t(0));
    QCOMPARE(view->scene().displayRange().max, 222.0);
    QVERIFY2(settled(view) != step2All, "on one scale the steps differ");
    // Typed: a bad range changes nothing and says so; a good one is used.
    range->setCurrentIndex(2);
    auto* min = window_->findChild<QLineEdit*>("rangeMin");
    auto* max = window_->findChild<QLineEdit*>("rangeMax");
    QTRY_VERIFY(min->isVisible() && max->isVisible());
    min->setText("50");
    max->setText("abc");
    QTest::keyClick(max, Qt::Key_Return);
    QCOMPARE(view->scene().displayRange().max, 222.0);
    QVERIFY(window_->statusBar()->currentMessage().contains("min < max"));
    QCOMPARE(min->text(), QString("0"));  // the fields show what is in force again
    min->setText("50");
    max->setText("60");
    QTest::keyClick(max, Qt::Key_Return);
    QCOMPARE(view->scene().displayRange().min, 50.0);
    QCOMPARE(view->scene().displayRange().max, 60.0);
    // Play walks the steps and stops again.
    auto* play = window_->findChild<QAction*>("playStepsAction");
    play->setChecked(true);
    QTRY_COMPARE_WITH_TIMEOUT(view->scene().state().step, std::size_t(1), 3000);
    play->setChecked(false);
    // Export: one numbered picture per step, the step the user had kept.
    range->setCurrentIndex(1);
    const QString dir = QDir::temp().filePath("volpost_gui_animation");
    QDir(dir).removeRecursively();
    QDir().mkpath(dir);
    stepBox->setCurrentIndex(0);
    auto* steps = window_->findChild<StepController*>();
    QVERIFY(steps);
    QCOMPARE(steps->exportAnimation(dir + "/t.png"), 2);
    QVERIFY(QFile::exists(dir + "/t_001.png") && QFile::exists(dir + "/t_002.png"));
    QVERIFY(QImage(dir + "/t_001.png") != QImage(dir + "/t_002.png"));
    QCOMPARE(view->scene().state().step, std::size_t(0));
    // Or one video: a frame per step, the pictures' size (made even), the rate asked for.
    QCOMPARE(steps->exportAnimation(dir + "/t.mp4", 3), 2);
    const test::DecodedVideo video = test::decodeVideo((dir + "/t.mp4").toStdString());
    QCOMPARE(video.frames.size(), std::size_t(2));
    QCOMPARE(video.framesPerSecond, 3.0);
    const QImage first(dir + "/t_001.png");
    QCOMPARE(video.frames[0].width(), first.width() + (first.width() & 1));
    QVERIFY(test::meanColorDifference(video.frames[0], first.scaled(video.frames[0].size())) < 4);
    QVERIFY(window_->statusBar()->currentMessage().contains("Wrote a video of 2 frames"));
    // Two frames between the steps: four pictures, the in-between ones between the steps'.
    QCOMPARE(steps->exportAnimation(dir + "/b.png", 4, 2), 4);
    QCOMPARE(QImage(dir + "/b_001.png"), QImage(dir + "/t_001.png"));
    QCOMPARE(QImage(dir + "/b_004.png"), QImage(dir + "/t_002.png"));
    QVERIFY(QImage(dir + "/b_002.png") != QImage(dir + "/t_001.png"));
    QVERIFY(QImage(dir + "/b_002.png") != QImage(dir + "/b_003.png"));
    QCOMPARE(view->scene().stepBlend(), 0.0);
    view->scene().setShowLegend(true);
    range->setCurrentIndex(0);
    window_->resize(900, 600);
  }

  // `volpost --screenshot`: exit 0 only with the picture written; a missing model or an
  // unwritable path is exit 1 with the reason.
  void screenshotExitCodesSayWhetherThePictureWasWritten() {
    const auto run = [](const QStringList& args) {
      QProcess p;
      p.start(VOLPOST_EXECUTABLE, args);
      if (!p.waitForFinished(60000)) return std::pair(-1, QString("timed out"));
      return std::pair(p.exitCode(), QString::fromUtf8(p.readAllStandardError()));
    };
    const QString shot = QDir::temp().filePath("volpost_screenshot_test.png");
    QFile::remove(shot);
    const auto good = run({"--screenshot", shot, VOLPOST_TEST_DATA "/bar/bar_tet4.vtu"});
    QCOMPARE(good.first, 0);
    QVERIFY(!QImage(shot).isNull());
    const auto missing = run({"--screenshot", shot, "/no/such/model.vtu"});
    QCOMPARE(missing.first, 1);
    QVERIFY2(missing.second.contains("/no/such/model.vtu"), qPrintable(missing.second));
    const auto unwritable = run({"--screenshot", "/no/such/folder/shot.png", VOLPOST_TEST_DATA "/bar/bar_tet4.vtu"});
    QCOMPARE(unwritable.first, 1);
    QVERIFY2(unwritable.second.contains("/no/such/folder"), qPrintable(unwritable.second));
  }

  // A dropped file opens; what opened is in File > Open Recent; a closed panel comes back
  // from View > Panels.
  void dropRecentFilesAndPanels() {
    QSignalSpy finished(window_.get(), &MainWindow::loadFinished);
    auto* mime = new QMimeData;
    mime->setUrls({QUrl::fromLocalFile(VOLPOST_TEST_DATA "/bar/bar_tet4.vtu")});
    QDragEnterEvent enter(QPoint(100, 100), Qt::CopyAction, mime, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(window_.get(), &enter);
    QVERIFY(enter.isAccepted());
    QDropEvent drop(QPointF(100, 100), Qt::CopyAction, mime, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(window_.get(), &drop);
    QVERIFY(finished.wait(30000));
    QVERIFY(finished.first().first().toBool());
    QCOMPARE(window_->session()->model().mesh().cellCount(), std::size_t(12431));
    delete mime;
    auto* recent = window_->findChild<QMenu*>("recentMenu");
    QVERIFY(recent);
    emit recent->aboutToShow();
    QVERIFY(!recent->actions().isEmpty());
    QVERIFY2(recent->actions().first()->text().contains("bar_tet4.vtu"), qPrintable(recent->actions().first()->text()));
    auto* model = window_->findChild<QDockWidget*>("modelDock");
    model->close();
    QVERIFY(!model->isVisible());
    auto* panels = window_->findChild<QMenu*>("panelsMenu");
    QVERIFY(panels && panels->actions().size() >= 3);  // Model, Probe and the plugins' panels
    for (QAction* a : panels->actions())
      if (a == model->toggleViewAction()) a->trigger();
    QVERIFY(model->isVisible());
  }

  // Clip Plane in the surface view: the model is cut and the cut face drawn; Ctrl+drag moves it.
  void aClipPlaneCutsTheSurfaceView() {
    QVERIFY(open(VOLPOST_TEST_DATA "/bar/bar_tet4.vtu"));
    QVERIFY(window_->selectQuantity("U.x"));
    Viewport* view = window_->viewport();
    QVERIFY(!view->scene().volumeShown());
    view->setStandardView(StandardView::Isometric);
    const QImage whole = settled(view);
    window_->findChild<QAction*>("clip:0")->trigger();  // normal +x through the centre
    const QImage cut = settled(view);
    QVERIFY(view->drawing().sectionTriangles() > 0);
    QVERIFY(cut != whole);
    QTest::mousePress(view, Qt::LeftButton, Qt::ControlModifier, view->rect().center());
    QMouseEvent move(QEvent::MouseMove, QPointF(view->rect().center() + QPoint(0, 30)),
                     view->mapToGlobal(QPointF(view->rect().center() + QPoint(0, 30))), Qt::LeftButton, Qt::LeftButton,
                     Qt::ControlModifier);
    QApplication::sendEvent(view, &move);
    QTest::mouseRelease(view, Qt::LeftButton, Qt::ControlModifier, view->rect().center() + QPoint(0, 30));
    QVERIFY(settled(view) != cut);
    window_->findChild<QAction*>("clip:-1")->trigger();
    QVERIFY(view->scene().volume().clipPlanes.empty());
    QCOMPARE(settled(view), whole);
    QCOMPARE(view->drawing().sectionTriangles(), std::size_t(0));
  }

  // The clip plane's widget: its knob turns the plane toward the mouse, its shaft slides it;
  // the cut follows, the status bar says the plane, and View > Clip Plane hides the handle.
  void everyClipPlaneHasAHandle() {
    // Two planes (a state's or typed): the second one's knob turns the second plane only.
    Viewport* view = window_->viewport();
    view->setStandardView(StandardView::Isometric);
    const ModelSession& s = *window_->session();
    const glm::dvec3 c = s.bounds().center();
    view->scene().setClipPlanes({ClipPlane{c + glm::dvec3(-3, 0, 0), {1, 0, 0}}, ClipPlane{c, {0, 1, 0}}});
    view->update();
    const ClipPlane first = view->scene().volume().clipPlanes[0];
    const PlaneWidget widget = planeWidget(view->scene().volume().clipPlanes[1], s.bounds());
    const auto q = view->scene()
                       .pictureCamera(view->width(), view->height())
                       .projectToPicture(widget.knob, view->width(), view->height());
    QVERIFY(q);
    const QPoint knob(int(std::lround(q->x)), int(std::lround(q->y)));
    QTest::mousePress(view, Qt::LeftButton, {}, knob);
    for (int step = 1; step <= 4; ++step) {
      const QPointF at = QPointF(knob) + QPointF(10.0 * step, 0.0);
      QMouseEvent move(QEvent::MouseMove, at, view->mapToGlobal(at), Qt::NoButton, Qt::LeftButton, Qt::NoModifier);
      QApplication::sendEvent(view, &move);
    }
    QTest::mouseRelease(view, Qt::LeftButton, {}, knob + QPoint(40, 0));
    QCOMPARE(view->scene().volume().clipPlanes[0], first);
    QVERIFY2(glm::length(glm::normalize(view->scene().volume().clipPlanes[1].normal) - glm::dvec3(0, 1, 0)) > 0.05,
             "the second plane's knob turned the second plane");
    QVERIFY(window_->statusBar()->currentMessage().startsWith("Clip plane 2 of 2"));
    view->scene().setClipPlanes({});
  }

  void thePlaneWidgetTurnsAndSlidesTheClipPlane() {
    QVERIFY(open(VOLPOST_TEST_DATA "/bar/bar_tet4.vtu"));
    Viewport* view = window_->viewport();
    view->setStandardView(StandardView::Isometric);
    window_->findChild<QAction*>("clip:0")->trigger();  // normal +x through the centre
    QVERIFY(view->scene().showsPlaneWidget());
    const QImage before = settled(view);
    const auto pixelOf = [&](const glm::dvec3& p) {
      const auto q =
          view->scene().pictureCamera(view->width(), view->height()).projectToPicture(p, view->width(), view->height());
      return q ? QPoint(int(std::lround(q->x)), int(std::lround(q->y))) : QPoint(-1, -1);
    };
    const auto drag = [&](QPoint from, QPoint to) {
      QTest::mousePress(view, Qt::LeftButton, {}, from);
      for (int step = 1; step <= 4; ++step) {
        const QPointF at = QPointF(from) + (QPointF(to - from) * step) / 4.0;
        QMouseEvent move(QEvent::MouseMove, at, view->mapToGlobal(at), Qt::NoButton, Qt::LeftButton, Qt::NoModifier);
        QApplication::sendEvent(view, &move);
      }
      QTest::mouseRelease(view, Qt::LeftButton, {}, to);
    };
    const auto widget = [&] {
      return planeWidget(view->scene().volume().clipPlanes.front(), window_->session()->bounds());
    };
    const glm::dvec3 cameraBefore = view->scene().camera().eye();
    const QPoint knob = pixelOf(widget().knob);
    drag(knob, knob + QPoint(0, -40));
    const ClipPlane turned = view->scene().volume().clipPlanes.front();
    QVERIFY2(glm::length(glm::normalize(turned.normal) - glm::dvec3(1, 0, 0)) > 0.05, "the knob turned the plane");
    QCOMPARE(view->scene().camera().eye(), cameraBefore);  // the drag went to the widget, not the camera
    QVERIFY(window_->statusBar()->currentMessage().startsWith("Clip plane "));
    const QImage turnedImage = settled(view);
    QVERIFY(turnedImage != before);
    // The shaft: from the centre's pixel halfway to the knob's slides it along the normal.
    const PlaneWidget w = widget();
    const QPoint center = pixelOf(w.center), tip = pixelOf(w.knob);
    const double offsetBefore = glm::dot(turned.point, glm::normalize(turned.normal));
    drag((center * 3 + tip) / 4, (center + tip) / 2 + (tip - center) / 4);
    const ClipPlane slid = view->scene().volume().clipPlanes.front();
    QVERIFY2(glm::dot(slid.point, glm::normalize(slid.normal)) > offsetBefore, "the shaft slid it toward the knob");
    QVERIFY(settled(view) != turnedImage);
    if (const char* shot = std::getenv("VOLPOST_PLANE_SCREENSHOT")) window_->grab().save(shot);
    // Hidden handle: the same drag turns the camera instead.
    window_->findChild<QAction*>("planeHandle")->setChecked(false);
    QVERIFY(!view->scene().showsPlaneWidget());
    drag(pixelOf(widget().knob), pixelOf(widget().knob) + QPoint(0, -40));
    QCOMPARE(view->scene().volume().clipPlanes.front(), slid);
    window_->findChild<QAction*>("planeHandle")->setChecked(true);
    window_->findChild<QAction*>("clip:-1")->trigger();
    // The clip box: a face's knob moves that face; the box is drawn as it goes and applied
    // when the mouse lets go.
    view->scene().setClipBox(ClipBox{1.0, 9.0, -0.2, 1.2, -0.2, 1.2});
    view->update();
    QVERIFY(view->scene().showsBoxWidget());
    const QImage boxed = settled(view);
    const QPoint xmax = pixelOf(boxWidget(*view->scene().volume().clipBox).faceCenters[1]);
    const QPoint xmin = pixelOf(boxWidget(*view->scene().volume().clipBox).faceCenters[0]);
    const QPoint inward = xmax + (xmin - xmax) / 3;
    const glm::dvec3 eyeBeforeBox = view->scene().camera().eye();
    QTest::mousePress(view, Qt::LeftButton, {}, xmax);
    QMouseEvent move(QEvent::MouseMove, QPointF(inward), view->mapToGlobal(QPointF(inward)), Qt::NoButton, Qt::LeftButton,
                     Qt::NoModifier);
    QApplication::sendEvent(view, &move);
    QCOMPARE((*view->scene().volume().clipBox)[1], 9.0);  // not applied while dragged
    QVERIFY((*view->scene().shownClipBox())[1] < 9.0);   // but drawn where it goes
    QTest::mouseRelease(view, Qt::LeftButton, {}, inward);
    const ClipBox applied = *view->scene().volume().clipBox;
    QVERIFY2(applied[1] < 8.0 && applied[1] > 1.0, qPrintable(QString::number(applied[1])));
    QCOMPARE(applied[0], 1.0);
    QVERIFY(window_->statusBar()->currentMessage().startsWith("Clip box "));
    QVERIFY(settled(view) != boxed);
    QCOMPARE(view->scene().camera().eye(), eyeBeforeBox);  // the drag went to the box, not the camera
    view->scene().setClipBox(std::nullopt);
    view->update();
  }

  void theDeformedShapeIsDrawnAndProbed() {
    Viewport* view = window_->viewport();
    view->setStandardView(StandardView::PlusY);
    const QImage straight = settled(view);
    auto* deform = window_->findChild<QAction*>("deformAction");
    QVERIFY(deform);
    deform->setChecked(true);
    QVERIFY(view->scene().deformation().shown);
    QVERIFY(view->scene().deformationScale() > 0.0);
    QVERIFY(settled(view) != straight);
    QVERIFY(window_->statusBar()->currentMessage().contains("deformed coordinates"));
    deform->setChecked(false);
    QCOMPARE(view->scene().session(), view->scene().baseSession());
    QCOMPARE(settled(view), straight);
  }

  void plotOverLineChartsTheShownQuantity() {
    QVERIFY(window_->selectQuantity("S.xx"));
    window_->findChild<QAction*>("linePlotAction")->trigger();
    auto* panel = window_->findChild<LinePlotPanel*>("linePlotPanel");
    QVERIFY(panel && panel->isVisible());
    window_->findChild<QLineEdit*>("lineFrom")->setText("1, 0.5, 0.5");
    window_->findChild<QLineEdit*>("lineTo")->setText("9, 0.5, 0.5");
    QTest::mouseClick(window_->findChild<QPushButton*>("linePlot"), Qt::LeftButton);
    QVERIFY(panel->samples().has_value());
    const LineSamples& s = *panel->samples();
    QCOMPARE(s.keys, std::vector<std::string>{"S.xx"});
    QVERIFY(std::abs(s.value(s.points.size() / 2, 0) - 100.0) < 0.5);
    // Several quantities at once: checked in the panel's list, in the model's order.
    auto* list = window_->findChild<QListWidget*>("lineQuantities");
    QVERIFY(list && list->count() > 2);
    for (int i = 0; i < list->count(); ++i) {
      const QString key = list->item(i)->data(Qt::UserRole).toString();
      list->item(i)->setCheckState(key == "S.xx" || key == "U.x" ? Qt::Checked : Qt::Unchecked);
    }
    QTest::mouseClick(window_->findChild<QPushButton*>("linePlot"), Qt::LeftButton);
    QCOMPARE(panel->samples()->keys, (std::vector<std::string>{"U.x", "S.xx"}));
    QVERIFY(std::abs(panel->samples()->value(s.points.size() / 2, 1) - 100.0) < 0.5);
    if (const char* shot = std::getenv("VOLPOST_PLOT_SCREENSHOT")) window_->grab().save(shot);
    panel->setQuantities({});  // back to the shown quantity
    window_->findChild<QLineEdit*>("lineTo")->setText("nonsense");
    QVERIFY(!panel->plot());
    QVERIFY(window_->statusBar()->currentMessage().contains("X, Y, Z"));
  }

  void aBadFileLeavesTheModelAsItWas() {
    const auto before = window_->session();
    QTimer closer;  // dismiss the error box the window shows
    connect(&closer, &QTimer::timeout, [] {
      if (QWidget* modal = QApplication::activeModalWidget()) modal->close();
    });
    closer.start(50);
    // No dialog outlives its load: a leftover "Reading..." one would block every button.
    for (const char* bad : {"/bad/truncated_appended.vtu", "/bad/truncated_in_results.frd", "/bad/unknown_cell_type.vtu",
                            "/bad/wrong_count_cells.vtu"}) {
      QVERIFY2(!open(QString(VOLPOST_TEST_DATA) + bad), bad);
      QTest::qWait(400);  // longer than the dialogs' delay before showing
      QCOMPARE(window_->session(), before);
      for (const QProgressDialog* d : window_->findChildren<QProgressDialog*>()) QVERIFY2(!d->isVisible(), bad);
      QVERIFY(!QApplication::activeModalWidget());
    }
    closer.stop();
  }

  void aSeismicCubeIsVolumeRenderedAndAGridRendererMakesWayForAMesh() {
    QVERIFY(open(VOLPOST_TEST_DATA "/seismic/synthetic_12x10x40.sgy"));
    Viewport* view = window_->viewport();
    QVERIFY(window_->session()->model().grid.has_value());
    QVERIFY(window_->selectQuantity("amplitude"));
    auto* volume = window_->findChild<QAction*>("volumeAction");
    auto* marcher = window_->findChild<QAction*>("renderer:texture-raymarch");
    QVERIFY(volume && marcher);
    marcher->trigger();  // the user's choice
    QCOMPARE(view->scene().state().volume.renderer, std::string("texture-raymarch"));
    volume->setChecked(true);
    QVERIFY(settled(view).isNull() == false);
    QVERIFY2(summarize(settled(view)).first > 0, "the cube is drawn");
    volume->setChecked(false);
    // A mesh next: the grid-only renderer gives way to one that draws meshes.
    QVERIFY(open(VOLPOST_TEST_DATA "/bar/bar_tet4.vtu"));
    QVERIFY(view->scene().state().volume.renderer != "texture-raymarch");
    QVERIFY(!marcher->isChecked());
  }

  // View > Grid Slices... (G): the three middle slices at once with the surface out of their
  // way; a slider moves its slice, a box switches it off; the picture follows.
  void gridSlicesFollowTheDialog() {
    QVERIFY(open(VOLPOST_TEST_DATA "/seismic/synthetic_12x10x40.sgy"));
    QVERIFY(window_->selectQuantity("amplitude"));
    Viewport* view = window_->viewport();
    window_->findChild<QAction*>("gridSlicesAction")->trigger();
    const auto& slices = view->scene().state().gridSlices;
    QVERIFY(slices[0] && slices[1] && slices[2]);
    QCOMPARE(*slices[0], 1006.0);  // inlines 1000 .. 1011: the middle one, rounded up
    QCOMPARE(*slices[2], 80.0);    // times 0 .. 156 ms
    QVERIFY(!view->scene().state().surfaceShown);
    const QImage three = settled(view);
    auto* time = window_->findChild<QSlider*>("gridSlice2");
    QVERIFY(time && time->isEnabled());
    time->setValue(5);
    QCOMPARE(*view->scene().state().gridSlices[2], 20.0);
    window_->findChild<QCheckBox*>("gridSliceShown0")->setChecked(false);
    QVERIFY(!view->scene().state().gridSlices[0]);
    QVERIFY(settled(view) != three);
    window_->findChild<QCheckBox*>("gridSlicesSurface")->setChecked(true);
    QVERIFY(view->scene().state().surfaceShown);
    window_->findChild<QCheckBox*>("gridSlicesSurface")->setChecked(false);
    // A mesh next: no slices, its surface shown, the dialog's controls off.
    QVERIFY(open(VOLPOST_TEST_DATA "/bar/bar_tet4.vtu"));
    QVERIFY(!view->scene().state().gridSlices[1]);
    QVERIFY(view->scene().state().surfaceShown);
    QVERIFY(!time->isEnabled());
  }

  // View > Load a 2D Transfer Function (grids)...: the cube's volume takes its colors from the
  // value and the gradient; a broken file is refused and the scene keeps what it had; Use
  // the 1D Transfer Function goes back; a mesh refuses one, and a new model drops it.
  void aTwoDimensionalTransferFunctionDrivesAGridsVolume() {
    const QString dir = QDir::temp().filePath("volpost_gui_tf2d");
    QDir(dir).removeRecursively();
    QDir().mkpath(dir);
    const QString good = dir + "/boundaries.json", broken = dir + "/broken.json";
    QFile g(good), b(broken);
    QVERIFY(g.open(QIODevice::WriteOnly) && b.open(QIODevice::WriteOnly));
    g.write(R"({"format":"volpost-tf2d","version":1,"widgets":[
      {"shape":"triangle","value":0.0,"width":0.5,"gradient":[0.0,0.25],"color":[0.95,0.45,0.1],"extinction":0.02}]})");
    b.write(R"({"format":"volpost-tf2d","version":1,"widgets":[]})");
    g.close();
    b.close();
    QVERIFY(open(VOLPOST_TEST_DATA "/seismic/synthetic_12x10x40.sgy"));
    QVERIFY(window_->selectQuantity("amplitude"));
    Viewport* view = window_->viewport();
    window_->findChild<QAction*>("renderer:cpu")->trigger();  // a grid renderer (an earlier test may have left another)
    window_->findChild<QAction*>("volumeAction")->setChecked(true);
    const QImage oneD = settled(view);
    QVERIFY(window_->loadTransferFunction2D(good));
    QVERIFY(view->scene().state().volume.transferFunction2D.has_value());
    const QImage twoD = settled(view);
    QVERIFY2(twoD != oneD, "the picture follows the 2D transfer function");
    // The editor's second tab shows it, and its edits reach the picture.
    auto* use = window_->findChild<QCheckBox*>("tf2dUse");
    QVERIFY2(use, "the transfer-function panel has a 2D tab");
    QVERIFY(use->isChecked());
    window_->findChild<QPushButton*>("tf2dAddRectangle")->click();
    QTRY_COMPARE(view->scene().state().volume.transferFunction2D->widgets().size(), std::size_t(2));
    QVERIFY(settled(view) != twoD);
    auto* status1d = window_->findChild<QLabel*>("tfStatus");
    QVERIFY(status1d && status1d->text().contains("2D function"));  // the 1D tab says which is drawn
    use->setChecked(false);
    QVERIFY(!view->scene().state().volume.transferFunction2D);
    QVERIFY(!status1d->text().contains("2D function"));
    use->setChecked(true);
    QCOMPARE(view->scene().state().volume.transferFunction2D->widgets().size(), std::size_t(2));
    QTimer::singleShot(0, [] {
      if (QWidget* box = QApplication::activeModalWidget()) box->close();
    });
    QVERIFY(!window_->loadTransferFunction2D(broken));
    QVERIFY2(view->scene().state().volume.transferFunction2D.has_value(), "a refused file keeps the scene's");
    window_->findChild<QAction*>("clear2dAction")->trigger();
    QVERIFY(!view->scene().state().volume.transferFunction2D);
    QCOMPARE(settled(view), oneD);
    QVERIFY(window_->loadTransferFunction2D(good));
    QVERIFY(open(VOLPOST_TEST_DATA "/bar/bar_tet4.vtu"));
    QVERIFY2(!view->scene().state().volume.transferFunction2D, "another model drops it");
    QVERIFY(!window_->loadTransferFunction2D(good));
    QVERIFY(!view->scene().state().volume.transferFunction2D);
    window_->findChild<QAction*>("volumeAction")->setChecked(false);
  }

  // File > Reader Options...: a SEG-Y file whose inline numbers are not at the standard
  // byte fails to open; read again with inline-byte set it opens, the Model panel says the
  // options, and a saved state keeps them (opening that state reads the file the same way).
  void readerOptionsReadAFileAgainAndAreKeptInTheState() {
    const QString dir = QDir::temp().filePath("volpost_gui_reader_options");
    QDir(dir).removeRecursively();
    QDir().mkpath(dir);
    QFile original(VOLPOST_TEST_DATA "/seismic/synthetic_12x10x40.sgy");
    QVERIFY(original.open(QIODevice::ReadOnly));
    QByteArray bytes = original.readAll();
    QCOMPARE(bytes.size(), 42000);
    for (int t = 0; t < 120; ++t) {  // inline numbers from byte 189 to byte 17 of each trace header
      char* h = bytes.data() + 3600 + t * 320;
      std::copy(h + 188, h + 192, h + 16);
      std::fill(h + 188, h + 192, char(0));
    }
    const QString moved = dir + "/moved.sgy";
    QFile out(moved);
    QVERIFY(out.open(QIODevice::WriteOnly));
    out.write(bytes);
    out.close();
    QTimer closer;  // dismiss the error box of the failed open
    connect(&closer, &QTimer::timeout, [] {
      if (QWidget* modal = QApplication::activeModalWidget()) modal->close();
    });
    closer.start(50);
    QVERIFY(!open(moved));
    closer.stop();
    QSignalSpy finished(window_.get(), &MainWindow::loadFinished);
    QVERIFY(window_->reopenWithReaderOptions({{"inline-byte", "17"}}));
    QVERIFY(finished.wait(30000));
    QVERIFY(finished.first().first().toBool());
    QCOMPARE(window_->session()->model().grid->dims[0], std::size_t(12));
    QVERIFY(window_->findChild<QTextBrowser*>("modelInfo")->toPlainText().contains("inline-byte=17"));
    QVERIFY(window_->saveStateFile(dir + "/view.json"));
    QVERIFY(open(VOLPOST_TEST_DATA "/bar/bar_tet4.vtu"));
    QSignalSpy applied(window_.get(), &MainWindow::stateApplied);
    window_->openStateFile(dir + "/view.json");
    QVERIFY(applied.wait(30000));
    QVERIFY(applied.first().first().toBool());
    QCOMPARE(window_->session()->readerOptions().at("inline-byte"), std::string("17"));
    QVERIFY(window_->session()->model().grid.has_value());
  }
};

int main(int argc, char** argv) {
  QSurfaceFormat format;
  format.setVersion(4, 5);
  format.setProfile(QSurfaceFormat::CoreProfile);
  format.setDepthBufferSize(24);
  QSurfaceFormat::setDefaultFormat(format);
  QStandardPaths::setTestModeEnabled(true);  // settings go to a test location, not the user's
  QApplication app(argc, argv);
  QSettings("volpost", "volpost").clear();
  MainWindowTest test;
  return QTest::qExec(&test, argc, argv);
}

#include "MainWindowTest.moc"

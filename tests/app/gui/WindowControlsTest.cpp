// SPDX-License-Identifier: MIT
// The window's controls show the state of what they control, each scenario in a fresh
// window (no scenario inherits another's model, docks or checked actions): what a new
// model drops, the color box after the volume, iso-surfaces that stay in the view the user
// is in, the surface's own opacity control, the clip menu after a typed plane, numbers on
// screen, typed probe points, the plotted line, grid slices in a dock, the renderer menu
// per model, the first-run layout and the memory the Model panel reports.
#include "gui/LinePlotPanel.hpp"
#include "gui/MainWindow.hpp"
#include "gui/Viewport.hpp"

#include "core/Scene.hpp"

#include <volpost/render/GL.hpp>

#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDialog>
#include <QDialogButtonBox>
#include <QDir>
#include <QDockWidget>
#include <QFile>
#include <QInputDialog>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QPushButton>
#include <QRegularExpression>
#include <QSettings>
#include <QSignalSpy>
#include <QSpinBox>
#include <QStandardPaths>
#include <QStatusBar>
#include <QSurfaceFormat>
#include <QTableWidget>
#include <QTest>
#include <QTextBrowser>
#include <QTimer>

#include <fstream>
#include <sstream>

using namespace volpost;
using namespace volpost::app;

class WindowControlsTest : public QObject {
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
  Scene& scene() { return window_->viewport()->scene(); }
  QAction* action(const char* name) { return window_->findChild<QAction*>(name); }

  // Answers the next modal dialog with `answer` (run once it is shown).
  static void whenADialogOpens(const std::function<void(QWidget*)>& answer) {
    QTimer::singleShot(50, [answer] {
      QWidget* dialog = QApplication::activeModalWidget();
      if (!dialog) {
        whenADialogOpens(answer);  // not there yet
        return;
      }
      answer(dialog);
    });
  }

 private slots:
  void initTestCase() {
    if (QGuiApplication::platformName() == "offscreen" || QGuiApplication::platformName() == "minimal")
      QSKIP("not run: needs an X display (run under xvfb-run)");
    plugins_ = std::make_unique<PluginManager>();
    plugins_->loadFrom({VOLPOST_PLUGIN_DIR});
  }

  // A fresh window each time, laid out as on a first run.
  void init() {
    QSettings settings("volpost", "volpost");
    settings.remove("window");
    settings.remove("view/colorMap");
    window_ = std::make_unique<MainWindow>(*plugins_);
    window_->resize(1280, 800);
    window_->show();
    QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
  }
  void cleanup() { window_.reset(); }

  void theFirstRunLayoutLeavesTheModelMostOfTheWindow() {
    // The transfer-function panel took 35 % of the window in the surface view, leaving the
    // model about 420 px at 1280 x 800; it opens with the volume now.
    QVERIFY(open(VOLPOST_TEST_DATA "/bar/bar_tet4.vtu"));
    QTest::qWait(50);
    QVERIFY2(window_->viewport()->width() > 0.6 * window_->width(),
             qPrintable(QString::number(window_->viewport()->width())));
    action("volumeAction")->setChecked(true);
    QTest::qWait(50);
    bool editorShown = false;
    for (QDockWidget* d : window_->findChildren<QDockWidget*>())
      if (d->objectName().startsWith("panel:")) editorShown = editorShown || d->isVisible();
    QVERIFY2(editorShown, "the volume's panel opens with it");
  }

  void theColorBoxFollowsTheViewBackFromTheVolume() {
    QVERIFY(open(VOLPOST_TEST_DATA "/bar/bar_tet4.vtu"));
    auto* colors = window_->findChild<QComboBox*>("colorMapBox");
    QVERIFY(colors->isEnabled());
    action("volumeAction")->setChecked(true);
    QVERIFY(!colors->isEnabled());
    action("volumeAction")->setChecked(false);
    QVERIFY2(colors->isEnabled(), "the Colors box stayed disabled after leaving the volume");
    // Named as the transfer-function editor names the maps.
    QCOMPARE(colors->currentText(), QString("Cool to warm (diverging)"));
  }

  void representationSlicesAndTheVolumeOutlineFollowTheMenus() {
    QVERIFY(open(VOLPOST_TEST_DATA "/bar/bar_tet4.vtu"));
    QVERIFY(action("representation:surface")->isChecked());
    action("representation:wireframe")->trigger();
    QVERIFY(scene().shown().representation == SurfaceRepresentation::Wireframe);
    whenADialogOpens([](QWidget* dialog) {
      auto* input = qobject_cast<QInputDialog*>(dialog);
      input->setDoubleValue(7.0);
      input->accept();
    });
    action("pointSizeAction")->trigger();
    QCOMPARE(scene().shown().pointSize, 7.0);
    QVERIFY(scene().shown().representation == SurfaceRepresentation::Points);
    QVERIFY2(action("representation:points")->isChecked(), "the menu shows the points asked for by their size");
    action("modelShownAction")->setChecked(false);
    QVERIFY(!scene().shown().surfaceShown);
    // A clip plane, inverted, then made a slice: nothing cut away, its section drawn.
    action("clip:0")->trigger();
    QCOMPARE(scene().volume().clipPlanes.size(), std::size_t(1));
    action("invertClipPlane")->trigger();
    QCOMPARE(scene().volume().clipPlanes.front().normal, glm::dvec3(-1.0, 0.0, 0.0));
    action("planeToSlice")->trigger();
    QVERIFY(scene().volume().clipPlanes.empty());
    QCOMPARE(scene().shown().slicePlanes.size(), std::size_t(1));
    QVERIFY2(action("clip:-1")->isChecked(), "the clip menu shows no plane once it became a slice");
    whenADialogOpens([](QWidget* dialog) {
      auto* input = qobject_cast<QInputDialog*>(dialog);
      input->setTextValue("5,0.5,0.5,0,1,0\n5,0.5,0.5,0,0,1");
      input->accept();
    });
    action("typeSlices")->trigger();
    QCOMPARE(scene().shown().slicePlanes.size(), std::size_t(2));
    action("volumeOutlineAction")->setChecked(true);
    QVERIFY(scene().volume().outline);
    // A state applied: the menus show it.
    SceneState state = scene().state();
    state.representation = SurfaceRepresentation::Outline;
    state.surfaceShown = true;
    state.volume.outline = false;
    const QString path = QDir(QStandardPaths::writableLocation(QStandardPaths::TempLocation)).filePath("rep.json");
    state.save(path.toStdString());
    QSignalSpy applied(window_.get(), &MainWindow::stateApplied);
    window_->openStateFile(path);
    QVERIFY(applied.count() == 1 || applied.wait(30000));
    QVERIFY(applied.first().first().toBool());
    QFile::remove(path);
    QVERIFY(action("representation:outline")->isChecked());
    QVERIFY(action("modelShownAction")->isChecked());
    QVERIFY(!action("volumeOutlineAction")->isChecked());
  }

  void saveImageWritesAnySizeWithATransparentBackground() {
    QVERIFY(open(VOLPOST_TEST_DATA "/bar/bar_tet4.vtu"));
    const QString dir = QStandardPaths::writableLocation(QStandardPaths::TempLocation);
    const QString jpg = QDir(dir).filePath("volpost_save.jpg"), png = QDir(dir).filePath("volpost_save.png");
    QFile::remove(png);
    action("clip:0")->trigger();  // its handles show in the window, never in a picture
    bool refusedJpeg = false;
    whenADialogOpens([&](QWidget* dialog) {
      dialog->findChild<QLineEdit*>("imagePath")->setText(jpg);
      dialog->findChild<QSpinBox*>("imageWidth")->setValue(1000);
      dialog->findChild<QSpinBox*>("imageHeight")->setValue(300);
      dialog->findChild<QCheckBox*>("imageTransparent")->setChecked(true);
      static_cast<QDialog*>(dialog)->accept();
      refusedJpeg = dialog->isVisible() && !dialog->findChild<QLabel*>("imageProblem")->text().isEmpty();
      dialog->findChild<QLineEdit*>("imagePath")->setText(png);
      static_cast<QDialog*>(dialog)->accept();
    });
    action("saveImageAction")->trigger();
    QVERIFY2(refusedJpeg, "a JPEG cannot keep a transparent background: the dialog says so and stays");
    const QImage saved(png);
    QCOMPARE(saved.size(), QSize(1000, 300));
    QCOMPARE(qAlpha(saved.pixel(1, 1)), 0);
    QCOMPARE(qAlpha(saved.pixel(450, 150)), 255);  // the bar, seen whole, across the middle
    QVERIFY(scene().showsPlaneWidget());
    QCOMPARE(scene().devicePixelRatio(), window_->viewport()->devicePixelRatioF());
    QFile::remove(png);
  }

  void theGlyphsDialogSetsAndTurnsOffTheGlyphs() {
    QVERIFY(open(VOLPOST_TEST_DATA "/bar/bar_tet4.vtu"));
    whenADialogOpens([](QWidget* dialog) {
      auto* field = dialog->findChild<QComboBox*>("glyphField");
      field->setCurrentIndex(field->findData(QString("S")));
      dialog->findChild<QSpinBox*>("glyphEvery")->setValue(25);
      static_cast<QDialog*>(dialog)->accept();
    });
    action("glyphsAction")->trigger();
    QVERIFY(scene().glyphLayer().shown);
    QCOMPARE(scene().glyphLayer().field, std::string("S"));
    QCOMPARE(scene().glyphLayer().every, 25);
    QVERIFY(window_->statusBar()->currentMessage().contains("glyphs"));
    whenADialogOpens([](QWidget* dialog) {
      QCOMPARE(dialog->findChild<QSpinBox*>("glyphEvery")->value(), 25);  // it shows what is set
      dialog->findChild<QComboBox*>("glyphField")->setCurrentIndex(0);    // None
      static_cast<QDialog*>(dialog)->accept();
    });
    action("glyphsAction")->trigger();
    QVERIFY(!scene().glyphLayer().shown);
  }

  void theThresholdDialogKeepsARangeAndTurnsOff() {
    QVERIFY(open(VOLPOST_TEST_DATA "/bar/bar_tet4.vtu"));
    const std::size_t cells = scene().session()->model().cellCount();
    whenADialogOpens([](QWidget* dialog) {
      auto* quantity = dialog->findChild<QComboBox*>("thresholdQuantity");
      quantity->setCurrentIndex(quantity->findData(QString("S11")));
      dialog->findChild<QLineEdit*>("thresholdMin")->setText("99");
      dialog->findChild<QLineEdit*>("thresholdMax")->setText("101");
      static_cast<QDialog*>(dialog)->accept();
    });
    action("thresholdAction")->trigger();
    QVERIFY(scene().threshold().shown);
    QCOMPARE(scene().threshold().quantity, std::string("S11"));
    QVERIFY(scene().session()->model().cellCount() < cells);
    QVERIFY(window_->statusBar()->currentMessage().contains(QString("of %1 cells").arg(cells)));
    whenADialogOpens([](QWidget* dialog) {
      QCOMPARE(dialog->findChild<QLineEdit*>("thresholdMin")->text(), QString("99"));  // shows what is set
      dialog->findChild<QPushButton*>("thresholdOff")->click();
    });
    action("thresholdAction")->trigger();
    QVERIFY(!scene().threshold().shown);
    QCOMPARE(scene().session()->model().cellCount(), cells);
  }

  void aNewModelDropsWhatTheOldOneShowed() {
    QVERIFY(open(VOLPOST_TEST_DATA "/bar/bar_tet4.vtu"));
    action("deformAction")->setChecked(true);
    QVERIFY(scene().deformation().shown);
    scene().setSurfaceOpacity(0.3);
    auto* plot = window_->findChild<LinePlotPanel*>("linePlotPanel");
    QVERIFY(plot);
    plot->setEnds({0, 0.5, 0.5}, {10, 0.5, 0.5});
    QVERIFY(plot->plot());
    QVERIFY(plot->samples());
    QVERIFY(scene().plotLine());
    QVERIFY(open(VOLPOST_TEST_DATA "/formats/golden.frd"));
    QVERIFY2(!action("deformAction")->isChecked(), "Deformed Shape stayed checked on a model that is not deformed");
    QVERIFY(!scene().deformation().shown);
    QVERIFY2(!plot->samples(), "the plot kept the previous model's curves");
    QVERIFY(window_->findChild<QLineEdit*>("lineFrom")->text().isEmpty());
    QVERIFY(!scene().plotLine());
    QCOMPARE(scene().state().surfaceOpacity, 1.0);
    // The plotted quantities are the new model's.
    auto* list = window_->findChild<QWidget*>("lineQuantities");
    QVERIFY(list);
  }

  void theStepButtonsFollowTheStepCount() {
    QVERIFY(!action("deformAction")->isChecked());
    QVERIFY(open(VOLPOST_TEST_DATA "/formats/golden.frd"));
    QVERIFY(window_->selectQuantity("T"));
    std::vector<QAction*> stepping;
    for (QAction* a : window_->findChildren<QAction*>()) {
      const QString text = QString(a->text()).remove('&');
      if (text == "Next Step" || text == "Previous Step" || text == "Play Steps") stepping.push_back(a);
    }
    QCOMPARE(stepping.size(), std::size_t(3));
    QCOMPARE(window_->findChild<QComboBox*>("stepBox")->count(), 2);
    for (QAction* a : stepping) QVERIFY2(a->isEnabled(), qPrintable(a->text()));
    QVERIFY(open(VOLPOST_TEST_DATA "/bar/bar_tet4.vtu"));
    for (QAction* a : stepping) QVERIFY2(!a->isEnabled(), qPrintable(a->text() + " stayed enabled for one step"));
  }

  void isoSurfacesStayInTheSurfaceViewAndMayBeOfAnotherQuantity() {
    // Results > Iso-surfaces switched to volume rendering; in the surface view they were
    // hidden inside the opaque surface. Now they stay in the surface view, which becomes
    // see-through, and may be of another quantity than the shown one.
    QVERIFY(open(VOLPOST_TEST_DATA "/bar/bar_tet4.vtu"));
    QVERIFY(window_->selectQuantity("S.mises"));
    whenADialogOpens([](QWidget* dialog) {
      auto* quantity = dialog->findChild<QComboBox*>("isoQuantity");
      quantity->setCurrentIndex(quantity->findData(QString("U.magnitude")));
      dialog->findChild<QLineEdit*>("isoValues")->setText("0.0005:1,0.8,0.2:0.8");
      static_cast<QDialog*>(dialog)->accept();
    });
    action("isoSurfacesAction")->trigger();
    QVERIFY2(!scene().volumeShown(), "the view stays the surface view");
    QCOMPARE(scene().volume().isoQuantity, std::string("U.magnitude"));
    QCOMPARE(scene().volume().isoSurfaces.size(), std::size_t(1));
    QVERIFY2(scene().state().surfaceOpacity < 1.0, "the surface no longer hides them");
    // Drawn by the next frame the view paints (a repaint right away can come before the
    // view is exposed again, and draws nothing).
    QTRY_VERIFY2((window_->viewport()->update(), window_->viewport()->drawing().isoTriangles() > 0),
                 "the iso-surface of U.magnitude is drawn");
    QCOMPARE(scene().view()->quantity.key(), std::string("S.mises"));
  }

  void theSurfaceOpacityHasItsOwnControl() {
    QVERIFY(open(VOLPOST_TEST_DATA "/bar/bar_tet4.vtu"));
    whenADialogOpens([](QWidget* dialog) {
      auto* input = qobject_cast<QInputDialog*>(dialog);
      input->setIntValue(40);
      input->accept();
    });
    action("surfaceOpacityAction")->trigger();
    QCOMPARE(scene().state().surfaceOpacity, 0.4);
  }

  void theClipMenuShowsATypedPlane() {
    QVERIFY(open(VOLPOST_TEST_DATA "/bar/bar_tet4.vtu"));
    action("clip:1")->trigger();  // Normal +Y
    QVERIFY(action("clip:1")->isChecked());
    whenADialogOpens([](QWidget* dialog) {
      auto* input = qobject_cast<QInputDialog*>(dialog);
      input->setTextValue("5,0.5,0.5,0,-1,0");
      input->accept();
    });
    action("typeClipPlane")->trigger();
    QCOMPARE(scene().volume().clipPlanes.front().normal, glm::dvec3(0, -1, 0));
    for (int i = -1; i < 3; ++i)
      QVERIFY2(!action(qPrintable(QString("clip:%1").arg(i)))->isChecked(), "a -Y plane checks no +axis entry");
    // The status bar of a dragged plane: a coordinate that is a rounding of zero reads 0.
    emit window_->viewport()->clipPlaneDragged(ClipPlane{{5.0, 4.737e-15, 0.5}, {0.0, -1.0, 5.921e-16}});
    const QString said = window_->statusBar()->currentMessage();
    QVERIFY2(said.contains("(5, 0, 0.5)") && said.contains("(0, -1, 0)") && !said.contains("e-1"), qPrintable(said));
  }

  void severalTypedPlanesAndInvertTurnsTheOneDragged() {
    QVERIFY(open(VOLPOST_TEST_DATA "/bar/bar_tet4.vtu"));
    whenADialogOpens([](QWidget* dialog) {
      auto* input = qobject_cast<QInputDialog*>(dialog);
      input->setTextValue("5,0.5,0.5,1,0,0\n\n2,0.5,0.5,0,1,0\n");
      input->accept();
    });
    action("typeClipPlane")->trigger();
    QCOMPARE(scene().volume().clipPlanes.size(), std::size_t(2));
    const ClipPlane second = scene().volume().clipPlanes[1];
    emit window_->viewport()->clipPlaneDragged(second);  // its handle moved it
    QVERIFY(window_->statusBar()->currentMessage().startsWith("Clip plane 2 of 2"));
    action("invertClipPlane")->trigger();
    QCOMPARE(scene().volume().clipPlanes[1].normal, glm::dvec3(0, -1, 0));
    QCOMPARE(scene().volume().clipPlanes[0].normal, glm::dvec3(1, 0, 0));  // the other stays
  }

  void probedNumbersAreReadableAndTypedPointsTakeSpaces() {
    QVERIFY(open(VOLPOST_TEST_DATA "/bar/bar_tet4.vtu"));
    scene().setUnits("S", "MPa");  // written after each of S's quantities, as the legend does
    auto* typed = window_->findChild<QLineEdit*>("probeTyped");
    QVERIFY(typed);
    typed->setFocus();
    typed->setText("5 0.5 0.5");  // refused where `probe --points` takes it
    QTest::keyClick(typed, Qt::Key_Return);
    QCOMPARE(scene().probes().size(), std::size_t(1));
    QVERIFY2(!typed->hasFocus(), "the next shortcut letter went into the field");
    auto* details = window_->findChild<QTableWidget*>("probeDetails");
    QVERIFY(details && details->rowCount() > 0);
    for (int row = 0; row < details->rowCount(); ++row) {
      const QString shown = details->item(row, 1)->text();
      QString digits = shown;
      digits.remove(QRegularExpression("e.*")).remove('-').remove('.');
      while (digits.startsWith('0') && digits.size() > 1) digits.remove(0, 1);
      QVERIFY2(digits.size() <= 6, qPrintable(shown));       // 16-17 digits before
      QVERIFY(!details->item(row, 1)->toolTip().isEmpty());  // every digit on hover
    }
    const auto listed = details->findItems("S.mises [MPa]", Qt::MatchExactly);
    QVERIFY(!listed.isEmpty());
    QVERIFY(!details->findItems("S.j2 [(MPa)^2]", Qt::MatchExactly).isEmpty());
    QVERIFY(!details->findItems("S.triaxiality", Qt::MatchExactly).isEmpty());  // a ratio: no units
  }

  void theSampledLineIsDrawnAndKeptInTheState() {
    QVERIFY(open(VOLPOST_TEST_DATA "/bar/bar_tet4.vtu"));
    auto* plot = window_->findChild<LinePlotPanel*>("linePlotPanel");
    plot->setEnds({0, 0.5, 0.5}, {10, 0.5, 0.5});
    window_->findChild<QLineEdit*>("lineFrom")->setText("0 0.5 0.5");  // spaces, as anywhere else
    QVERIFY(plot->plot());
    QVERIFY(scene().plotLine());
    QCOMPARE((*scene().plotLine())[1], glm::dvec3(10, 0.5, 0.5));
    const QString state = QDir::temp().filePath("volpost_plotline.json");
    QVERIFY(window_->saveStateFile(state));
    std::ifstream in(state.toStdString());
    std::stringstream text;
    text << in.rdbuf();
    QVERIFY2(text.str().find("\"plotLine\"") != std::string::npos, text.str().c_str());
    QVERIFY2(text.str().find("\"model\": \"") != std::string::npos, "");
  }

  void aStateBesideItsModelNamesItRelatively() {
    // A state saved in the model's folder names the model relative to it.
    const QString dir = QDir::temp().filePath("volpost_relative_state");
    QDir(dir).removeRecursively();
    QDir().mkpath(dir + "/models");
    QVERIFY(QFile::copy(VOLPOST_TEST_DATA "/bar/bar_tet4.vtu", dir + "/models/bar.vtu"));
    QVERIFY(open(dir + "/models/bar.vtu"));
    QVERIFY(window_->saveStateFile(dir + "/view.json"));
    std::ifstream in((dir + "/view.json").toStdString());
    std::stringstream text;
    text << in.rdbuf();
    QVERIFY2(text.str().find("\"model\": \"models/bar.vtu\"") != std::string::npos, text.str().c_str());
    QDir(dir).removeRecursively();
  }

  void gridSlicesOpenInADock() {
    QVERIFY(open(VOLPOST_TEST_DATA "/seismic/synthetic_12x10x40.sgy"));
    action("gridSlicesAction")->trigger();
    auto* dock = window_->findChild<QDockWidget*>("gridSlicesDock");
    QVERIFY2(dock && dock->isVisible() && !dock->isFloating(), "a floating dialog covered the model");
  }

  void theRendererMenuOffersWhatDrawsTheModel() {
    QVERIFY(open(VOLPOST_TEST_DATA "/bar/bar_tet4.vtu"));
    QAction* grid = action("renderer:texture-raymarch");
    QVERIFY(grid);
    QVERIFY2(!grid->isEnabled(), "a grid renderer was offered for a mesh");
    QVERIFY(action("renderer:cpu")->isEnabled());
    QVERIFY(open(VOLPOST_TEST_DATA "/seismic/synthetic_12x10x40.sgy"));
    QVERIFY(grid->isEnabled());
  }

  void theModelPanelSaysWhatTheProcessHolds() {
    QVERIFY(open(VOLPOST_TEST_DATA "/bar/bar_tet4.vtu"));
    const QString text = window_->findChild<QTextBrowser*>("modelInfo")->toPlainText();
    QVERIFY2(text.contains("volpost holds ") && text.contains("fields read: "), qPrintable(text));
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
  WindowControlsTest test;
  return QTest::qExec(&test, argc, argv);
}

#include "WindowControlsTest.moc"

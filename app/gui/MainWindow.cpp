// SPDX-License-Identifier: MIT
#include "MainWindow.hpp"

#include "../core/Legend.hpp"
#include "../core/PictureFile.hpp"
#include "../core/PluginRenderers.hpp"
#include "../core/ProbeTable.hpp"
#include "../core/StreamlineSeeds.hpp"
#include "../core/VolumeDefaults.hpp"
#include "../core/VolumeSpecs.hpp"
#include "CalculatorDialog.hpp"
#include "ClipActions.hpp"
#include "DeformationActions.hpp"
#include "DisplayActions.hpp"
#include "FrameRateActions.hpp"
#include "GlyphDialog.hpp"
#include "GridSlicesPanel.hpp"
#include "IsoSurfaceDialog.hpp"
#include "LinePlotPanel.hpp"
#include "ModelLoader.hpp"
#include "PluginsDialog.hpp"
#include "ProbeController.hpp"
#include "RecentFiles.hpp"
#include "RendererMenu.hpp"
#include "SaveImageDialog.hpp"
#include "SavedViews.hpp"
#include "SeeThroughSurface.hpp"
#include "SelectionActions.hpp"
#include "SetsPanel.hpp"
#include "StateFiles.hpp"
#include "StepController.hpp"
#include "StreamlineActions.hpp"
#include "ThresholdDialog.hpp"
#include "Viewport.hpp"
#include "VolumeActions.hpp"
#include "WorkWithProgress.hpp"

#include <volpost/core/ResourceLimits.hpp>
#include <volpost/core/Version.hpp>
#include <volpost/render/VolumeRenderer.hpp>

#include <algorithm>

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDockWidget>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFormLayout>
#include <QMimeData>
#include <QPushButton>
#include <QUrl>
#include <QWidget>
#include "host/TextFile.hpp"

#include <QDialog>
#include <QFileDialog>
#include <QFileInfo>
#include <QInputDialog>
#include <QLabel>
#include <QLineEdit>
#include <QMenuBar>
#include <QMessageBox>
#include <QSettings>
#include <QSpinBox>
#include <QStatusBar>
#include <QTextBrowser>
#include <QTimer>
#include <QToolBar>

namespace volpost::app {
namespace {

QString readerFilter(const ReaderRegistry& readers) {
  QStringList all, each;
  for (const MeshReader* r : readers.readers()) {
    QStringList patterns;
    for (const auto& e : r->extensions()) patterns << "*." + QString::fromStdString(e);
    all << patterns;
    each << QString("%1 (%2)").arg(QString::fromStdString(r->formatName()), patterns.join(' '));
  }
  return QString("All models (%1);;%2;;All files (*)").arg(all.join(' '), each.join(";;"));
}

}  // namespace

template <typename Change>
bool MainWindow::changeScene(Change&& change) {
  try {
    change(viewport_->scene());
  } catch (const std::exception& e) {
    statusBar()->showMessage(e.what());
    return false;
  }
  viewport_->update();
  return true;
}

MainWindow::MainWindow(PluginManager& plugins, QWidget* parent) : QMainWindow(parent), plugins_(plugins) {
  setWindowTitle("volpost");
  setAcceptDrops(true);
  viewport_ = new Viewport(volumeRendererFactory(plugins_), this);
  viewport_->scene().setRakesShown(true);
  setCentralWidget(viewport_);
  glLabel_ = new QLabel(this);
  glLabel_->setObjectName("glLabel");
  statusBar()->addPermanentWidget(glLabel_);
  connect(viewport_, &Viewport::glInfo, glLabel_, &QLabel::setText);
  connect(viewport_, &Viewport::glInfo, this, [this](const QString& description) {
    if (rendererMenu_) rendererMenu_->preferCpuOnSoftwareGl(description);
  });
  refiningLabel_ = new QLabel("Refining the picture...", this);
  refiningLabel_->setObjectName("refiningLabel");
  refiningLabel_->setVisible(false);
  statusBar()->addPermanentWidget(refiningLabel_);
  connect(viewport_, &Viewport::refining, refiningLabel_, &QLabel::setVisible);
  connect(viewport_, &Viewport::refiningMessage, refiningLabel_, &QLabel::setText);
  connect(viewport_, &Viewport::renderFailed, this, [this](const QString& m) {
    statusBar()->showMessage("Rendering error: " + m);
  });
  loader_ = new ModelLoader(*this, plugins_.readers());
  buildActions();
  buildToolbar();
  buildPanels();
  QSettings settings("volpost", "volpost");
  setDisplayDigits(settings.value("view/digits", 6).toInt());
  if (const std::size_t budget = parseByteSize(settings.value("limits/memoryBudget").toString().toStdString()))
    setMemoryBudget(budget);
  if (const std::size_t budget = parseByteSize(settings.value("limits/gpuMemoryBudget").toString().toStdString());
      budget && !gpuMemoryBudget())  // the command line's or environment's wins
    setGpuMemoryBudget(budget);
  resize(1280, 800);
  restoreGeometry(settings.value("window/geometry").toByteArray());
  restoreState(settings.value("window/state").toByteArray());
  statusBar()->showMessage("Open a model with File > Open (Ctrl+O)");
}

MainWindow::~MainWindow() = default;

namespace {

QString droppedFile(const QMimeData* mime) {
  if (!mime || !mime->hasUrls() || mime->urls().isEmpty()) return {};
  const QUrl url = mime->urls().first();
  return url.isLocalFile() ? url.toLocalFile() : QString();
}

}  // namespace

void MainWindow::dragEnterEvent(QDragEnterEvent* event) {
  if (!droppedFile(event->mimeData()).isEmpty()) event->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent* event) {
  const QString path = droppedFile(event->mimeData());
  if (path.isEmpty()) return;
  event->acceptProposedAction();
  if (event->mimeData()->urls().size() > 1) statusBar()->showMessage("Opening the first of the dropped files: " + path);
  if (QFileInfo(path).suffix().compare("json", Qt::CaseInsensitive) == 0) openStateFile(path);
  else openFile(path);
}

void MainWindow::closeEvent(QCloseEvent* event) {
  QSettings settings("volpost", "volpost");
  settings.setValue("window/geometry", saveGeometry());
  settings.setValue("window/state", saveState());
  QMainWindow::closeEvent(event);
}

void MainWindow::buildActions() {
  QMenu* file = menuBar()->addMenu("&File");
  fileMenu_ = file;
  file->addAction("&Open...", QKeySequence::Open, this, &MainWindow::chooseFile);
  QMenu* recent = file->addMenu("Open &Recent");
  recent->setObjectName("recentMenu");
  new RecentFiles(*recent, [this](const QString& path) { openFile(path); }, this);
  QAction* readerOptions = file->addAction("Reader &Options...", this, [this] {
    if (const auto options = loader_->askReaderOptions()) reopenWithReaderOptions(*options);
  });
  readerOptions->setObjectName("readerOptionsAction");
  readerOptions->setToolTip("Settings of the file's reader (for example where a SEG-Y file keeps its inline "
                            "numbers, or which offset of a pre-stack file to load), then the file read again");
  file->addAction("Save &Image...", QKeySequence::Save, this, &MainWindow::saveImage)->setObjectName("saveImageAction");
  file->addSeparator();
  stateFiles_ = new StateFiles(
      *this, viewport_->scene(), *file,
      [this](const QString& path, const ReaderOptions& options, std::function<void(bool, const QString&)> then) {
        return readModel(path, options, std::move(then));
      },
      [this] { followAppliedState(); });
  connect(stateFiles_, &StateFiles::applied, this, &MainWindow::stateApplied);
  file->addSeparator();
  file->addAction("&Quit", QKeySequence::Quit, this, &QWidget::close);

  QMenu* view = menuBar()->addMenu("&View");
  viewMenu_ = view;
  view->addAction("&Fit", QKeySequence(Qt::Key_F), viewport_, &Viewport::fit);
  savedViews_ = new SavedViews(
      *this, viewport_->scene(), *view, [this](const std::function<void(Scene&)>& c) { return changeScene(c); },
      [this] { viewport_->update(); });
  const std::pair<const char*, StandardView> views[] = {
      {"From +X", StandardView::PlusX}, {"From -X", StandardView::MinusX}, {"From +Y", StandardView::PlusY},
      {"From -Y", StandardView::MinusY}, {"From +Z", StandardView::PlusZ}, {"From -Z", StandardView::MinusZ},
      {"&Isometric", StandardView::Isometric}};
  int key = Qt::Key_1;
  for (const auto& [label, v] : views) {
    const StandardView sv = v;
    view->addAction(label, QKeySequence(key++), this, [this, sv] { viewport_->setStandardView(sv); });
  }
  view->addSeparator();
  orthoAction_ = view->addAction("&Orthographic");
  orthoAction_->setCheckable(true);
  orthoAction_->setShortcut(QKeySequence(Qt::Key_P));
  connect(orthoAction_, &QAction::toggled, this, [this](bool on) {
    viewport_->setProjection(on ? Camera::Projection::Orthographic : Camera::Projection::Perspective);
  });
  edgesAction_ = view->addAction("Element &Edges");
  edgesAction_->setCheckable(true);
  edgesAction_->setChecked(QSettings("volpost", "volpost").value("view/edges", true).toBool());
  edgesAction_->setShortcut(QKeySequence(Qt::Key_E));
  viewport_->scene().setShowEdges(edgesAction_->isChecked());
  connect(edgesAction_, &QAction::toggled, this, [this](bool on) {
    changeScene([on](Scene& s) { s.setShowEdges(on); });
    QSettings("volpost", "volpost").setValue("view/edges", on);
  });
  auto* trackball = view->addAction("&Trackball Rotation");
  trackball->setObjectName("trackballAction");
  trackball->setCheckable(true);
  trackball->setStatusTip("Off: dragging turns the model like a turntable, upright; on: freely about the screen's axes");
  trackball->setChecked(QSettings("volpost", "volpost").value("view/trackball", false).toBool());
  viewport_->setTrackball(trackball->isChecked());
  connect(trackball, &QAction::toggled, this, [this](bool on) {
    viewport_->setTrackball(on);
    QSettings("volpost", "volpost").setValue("view/trackball", on);
  });
  triadAction_ = view->addAction("Orientation A&xes");
  triadAction_->setObjectName("triadAction");
  triadAction_->setCheckable(true);
  triadAction_->setChecked(true);
  connect(triadAction_, &QAction::toggled, this, [this](bool on) { changeScene([on](Scene& s) { s.setShowTriad(on); }); });
  legendAction_ = view->addAction("&Legend");
  legendAction_->setCheckable(true);
  legendAction_->setChecked(true);
  connect(legendAction_, &QAction::toggled, this, [this](bool on) { changeScene([on](Scene& s) { s.setShowLegend(on); }); });
  view->addAction("Surface &Opacity...", this, &MainWindow::chooseSurfaceOpacity)
      ->setObjectName("surfaceOpacityAction");
  frameRate_ = new FrameRateActions(*this, *viewport_, *view, *statusBar());
  display_ = new DisplayActions(*this, viewport_->scene(), *view, [this](const std::function<void(Scene&)>& c) {
    const bool changed = changeScene(c);
    if (gridSlices_) gridSlices_->followScene();  // its Show the Model's Surface box too
    return changed;
  });
  buildColorActions(view);

  // What is shown of the results (deformation, probes, cuts, contours, lines) and the
  // volume each have a menu: one View menu held all 34 entries.
  QMenu* results = menuBar()->addMenu("&Results");
  resultsMenu_ = results;
  deformation_ = new DeformationActions(
      *this, viewport_->scene(), *results, [this](const std::function<void(Scene&)>& c) { return changeScene(c); },
      [this] {
        if (viewport_->scene().streamlinesNeedTracing()) streamlines_->trace();  // the lines follow the shape
        notifyPanels();
      });
  results->addAction("&Calculator...", this, &MainWindow::openCalculator)->setObjectName("calculatorAction");
  results->addSeparator();
  // Probing follows what is drawn: the deformed model while a deformation is shown.
  probes_ = new ProbeController(*this, *viewport_, *results, [this] { return viewport_->scene().sharedSession(); });
  selection_ = new SelectionActions(
      *this, *viewport_, *results, [this](const std::function<void(Scene&)>& c) { return changeScene(c); },
      [this] { notifyPanels(); });
  results->addSeparator();
  QMenu* volume = menuBar()->addMenu("V&olume");
  volumeMenu_ = volume;
  buildVolumeMenu(volume, results);

  QMenu* tools = menuBar()->addMenu("&Tools");
  tools->addAction("&Plugins...", this, [this] { PluginsDialog(plugins_, this).exec(); });
  tools->addAction("&Memory Budget...", this, [this] {
    askBudget("Memory budget",
              QString("The most memory a model may take (512M, 8G, ...); files that would need more are refused "
                      "with a message.\nNow: %1. Empty: the default (3/4 of this machine's memory).")
                  .arg(QString::fromStdString(byteSizeText(double(memoryBudget())))),
              "limits/memoryBudget", setMemoryBudget);
  });
  tools->addAction("&GPU Memory Budget...", this, [this] {
    const std::size_t now = gpuMemoryBudget();
    askBudget("GPU memory budget",
              QString("The most GPU memory a volume's data may hold at once (256M, 2G, ...); regular grids larger "
                      "than it are drawn in bricks streamed through it.\nNow: %1. Empty: the default (3/4 of what "
                      "an NVIDIA GPU reports, else no limit).")
                  .arg(now ? QString::fromStdString(byteSizeText(double(now))) : QString("the default")),
              "limits/gpuMemoryBudget", setGpuMemoryBudget);
    viewport_->update();  // the volume is laid out again for it
  });
  QMenu* help = menuBar()->addMenu("&Help");
  help->addAction("&About volpost", this, [this] {
    QMessageBox::about(this, "About volpost",
                       "volpost " VOLPOST_VERSION "\nFinite-element post-processing and volume rendering.\n"
                       "Mouse: left drag rotates, right drag or shift+left pans, wheel zooms.");
  });
}

void MainWindow::buildVolumeMenu(QMenu* view, QMenu* results) {
  rendererMenu_ = new RendererMenu(
      *this, viewport_->scene(), volumeRenderers(plugins_), *view,
      [this](const std::function<void(Scene&)>& change) { return changeScene(change); },
      [this] {
        if (viewport_->scene().volumeShown()) viewport_->repaint();
      });
  VolumeActions::Followers followers;
  followers.shown = [this] {
    for (QDockWidget* d : pluginDocks_)
      if (d->isHidden()) {
        d->show();
        d->raise();
      }
  };
  followers.viewChanged = [this] { notifyPanels(); };
  followers.tablesChanged = [this] {
    for (PanelPlugin* panel : plugins_.panelPlugins()) panel->hostChanged();
  };
  volume_ = new VolumeActions(
      *this, viewport_->scene(), *view, !rendererMenu_->renderers().empty(),
      [this](const std::function<void(Scene&)>& c) { return changeScene(c); }, std::move(followers));

  clips_ = new ClipActions(
      *this, viewport_->scene(), *results, [this](const std::function<void(Scene&)>& c) { return changeScene(c); },
      [this] { viewport_->update(); },
      [this] {
        viewport_->repaint();
        return viewport_->uploadedTetCount();
      });
  connect(viewport_, &Viewport::clipBoxDragged, clips_, &ClipActions::applyBox);
  connect(viewport_, &Viewport::clipPlaneDragged, clips_, &ClipActions::planeDragged);
  results->addAction("&Iso-surfaces...", this, &MainWindow::chooseIsoSurfaces)->setObjectName("isoSurfacesAction");
  results->addAction("Gl&yphs...", this, &MainWindow::chooseGlyphs)->setObjectName("glyphsAction");
  results->addAction("&Threshold...", QKeySequence(Qt::Key_T), this, &MainWindow::chooseThreshold)
      ->setObjectName("thresholdAction");
  results->addAction("&Grid Slices...", QKeySequence(Qt::Key_G), this, &MainWindow::showGridSlices)
      ->setObjectName("gridSlicesAction");
  streamlines_ = new StreamlineActions(
      *this, viewport_->scene(), *results, [this](const std::function<void(Scene&)>& c) { return changeScene(c); },
      [this] { viewport_->setRakeMode(true); }, [this] { viewport_->update(); });
  connect(streamlines_, &StreamlineActions::traced, this, &MainWindow::streamlinesTraced);
  connect(viewport_, &Viewport::rakePlaced, streamlines_, &StreamlineActions::placeRake);
}

void MainWindow::showGridSlices() {
  if (!session_ || !session_->model().grid) {
    statusBar()->showMessage(
        "Grid slices are for regular grids (SEG-Y, image data, NRRD); for meshes use View > Clip Plane");
    return;
  }
  Scene& scene = viewport_->scene();
  const auto& slices = scene.state().gridSlices;
  if (!slices[0] && !slices[1] && !slices[2]) {
    // First use: the three middle slices, the surface out of their way.
    const RegularGrid& g = *session_->model().grid;
    std::array<std::optional<double>, 3> middle;
    for (int a = 0; a < 3; ++a)
      middle[std::size_t(a)] = g.label(a, std::round(double(g.dims[std::size_t(a)] - 1) / 2.0));
    changeScene([&](Scene& s) {
      s.setGridSlices(middle);
      s.setSurfaceShown(false);
    });
  }
  if (!gridSlices_) {  // a dock, beside the others: a floating dialog covered the model
    gridSlicesDock_ = new QDockWidget("Grid Slices", this);
    gridSlicesDock_->setObjectName("gridSlicesDock");
    gridSlices_ = new GridSlicesPanel(
        scene,
        [this] {
          display_->syncToScene();  // Show the Model follows the panel's check box
          viewport_->update();
        },
        gridSlicesDock_);
    gridSlices_->setObjectName("gridSlicesPanel");
    gridSlicesDock_->setWidget(gridSlices_);
    addDockWidget(Qt::BottomDockWidgetArea, gridSlicesDock_);
    if (auto* panels = findChild<QMenu*>("panelsMenu")) panels->addAction(gridSlicesDock_->toggleViewAction());
  }
  gridSlices_->followScene();
  gridSlicesDock_->show();
  gridSlicesDock_->raise();
}

void MainWindow::openCalculator() {
  if (!session_) {
    statusBar()->showMessage("Open a model first");
    return;
  }
  Scene& scene = viewport_->scene();
  CalculatorDialog dialog(
      scene.formulas(), formulaNames(session_->model()),
      [this](const std::vector<FormulaSpec>& formulas, const std::string& shown) -> std::string {
        Scene& s = viewport_->scene();
        try {
          s.setFormulas(formulas);
          if (!shown.empty()) s.setResult(s.session()->findQuantity(shown).key(), 0);
        } catch (const std::exception& e) {
          return e.what();
        }
        followAppliedState();
        return {};
      },
      this);
  dialog.exec();
}

void MainWindow::chooseThreshold() {
  if (!session_) {
    statusBar()->showMessage("Open a model first");
    return;
  }
  Scene& scene = viewport_->scene();
  ThresholdDialog dialog(*scene.baseSession(), scene.threshold(), scene.state().quantity, scene.step(), this);
  while (dialog.exec() == QDialog::Accepted) {
    QString bad;
    const auto layer = dialog.layer(&bad);
    if (!layer) {
      QMessageBox::warning(this, "Threshold", bad);
      continue;
    }
    if (changeScene([&](Scene& s) { s.setThreshold(*layer); })) {
      notifyPanels();
      if (layer->shown)
        statusBar()->showMessage(QString("Showing %1 of %2 cells (Results > Threshold > Off shows them all)")
                                     .arg(scene.session()->model().cellCount())
                                     .arg(scene.baseSession()->model().cellCount()));
      return;
    }
  }
}

void MainWindow::chooseGlyphs() {
  if (!session_) {
    statusBar()->showMessage("Open a model first");
    return;
  }
  Scene& scene = viewport_->scene();
  GlyphDialog dialog(*scene.session(), scene.glyphLayer(), this);
  while (dialog.exec() == QDialog::Accepted) {
    QString bad;
    const auto layer = dialog.layer(&bad);
    if (!layer) {
      QMessageBox::warning(this, "Glyphs", bad);
      continue;
    }
    if (changeScene([&](Scene& s) { s.setGlyphs(*layer); })) {
      if (const auto g = scene.glyphs())
        statusBar()->showMessage(QString("%1 glyphs (%2 of %3 nodes)")
                                     .arg(g->glyphs)
                                     .arg(g->every == 1 ? QString("all") : QString("one in %1").arg(g->every))
                                     .arg(g->candidates));
      return;
    }
  }
}

void MainWindow::chooseIsoSurfaces() {
  if (!session_) {
    statusBar()->showMessage("Open a model first");
    return;
  }
  const Scene& scene = viewport_->scene();
  IsoSurfaceDialog dialog(*session_, scene.volume(), scene.view() ? &*scene.view() : nullptr, this);
  for (;;) {
    if (dialog.exec() != QDialog::Accepted) return;
    QString bad;
    const auto surfaces = dialog.surfaces(&bad);
    if (!surfaces) {
      QMessageBox::warning(
          this, "Iso-surfaces",
          QString("'%1' is not VALUE[:r,g,b[:opacity]] (or more than %2)").arg(bad).arg(kMaxIsoSurfaces));
      continue;
    }
    // They stay in the view the user is in (this switched to volume rendering); in the
    // surface view an opaque surface would hide them, so it becomes see-through.
    if (changeScene([&](Scene& s) {
          s.setIsoQuantity(dialog.quantity());
          s.setIsoSurfaces(*surfaces);
          if (!surfaces->empty() && !s.volumeShown()) seeThroughSurface(*this, s, "the iso-surfaces inside");
        }))
      return;
  }
}

void MainWindow::chooseSurfaceOpacity() {
  if (!session_) {
    statusBar()->showMessage("Open a model first");
    return;
  }
  bool ok = false;
  const int percent =
      QInputDialog::getInt(this, "Surface opacity",
                           "Opacity of the model's surface, percent (below 100 it is see-through and "
                           "what is inside shows):",
                           int(std::lround(viewport_->scene().state().surfaceOpacity * 100.0)), 0, 100, 5, &ok);
  if (!ok) return;
  if (changeScene([&](Scene& s) { s.setSurfaceOpacity(percent / 100.0); }))
    statusBar()->showMessage(QString("Surface opacity %1 %").arg(percent));
}

void MainWindow::buildToolbar() {
  QToolBar* bar = addToolBar("Result");
  bar->setObjectName("resultToolbar");
  bar->addWidget(new QLabel(" Result: "));
  quantityBox_ = new QComboBox(this);
  quantityBox_->setObjectName("quantityBox");
  quantityBox_->setMinimumContentsLength(18);
  bar->addWidget(quantityBox_);
  bar->addWidget(new QLabel("  Step: "));
  stepBox_ = new QComboBox(this);
  stepBox_->setObjectName("stepBox");
  stepBox_->setMinimumContentsLength(14);
  bar->addWidget(stepBox_);
  steps_ =
      new StepController(*this, *viewport_, *bar, *stepBox_, *resultsMenu_, *fileMenu_, [this] { notifyPanels(); });
  bar->addWidget(new QLabel("  Colors: "));
  colorMapBox_ = new QComboBox(this);
  colorMapBox_->setObjectName("colorMapBox");
  // Named as the transfer-function editor names them; the item's data is the written name.
  for (const auto& name : ColorMap::names())
    colorMapBox_->addItem(QString::fromStdString(ColorMap::label(name)), QString::fromStdString(name));
  colorMapBox_->setCurrentIndex(std::max(
      0, colorMapBox_->findData(QSettings("volpost", "volpost").value("view/colorMap", "cool-warm").toString())));
  changeScene([this](Scene& s) { s.setColorMap(chosenColorMap()); });
  bar->addWidget(colorMapBox_);
  connect(quantityBox_, &QComboBox::currentIndexChanged, this, [this] {
    fillSteps();
    steps_->quantityChanged();
    refreshScalars();
  });
  connect(stepBox_, &QComboBox::currentIndexChanged, this, &MainWindow::refreshScalars);
  connect(colorMapBox_, &QComboBox::currentIndexChanged, this, [this] {
    const QString name = colorMapBox_->currentData().toString();
    changeScene([&](Scene& s) { s.setColorMap(chosenColorMap()); });
    notifyPanels();
    QSettings("volpost", "volpost").setValue("view/colorMap", name);
  });
}

std::string MainWindow::chosenColorMap() const {
  const std::string base = colorMapBox_ ? colorMapBox_->currentData().toString().toStdString() : "cool-warm";
  return reverseColorsAction_ && reverseColorsAction_->isChecked() ? ColorMap::reversedName(base) : base;
}

// View > Reverse Color Map, Symmetric Color Range, Color Bands...: the colors an analyst
// sets for a report (Abaqus's contour bands, a diverging map centred on zero).
void MainWindow::buildColorActions(QMenu* view) {
  view->addSeparator();
  reverseColorsAction_ = view->addAction("&Reverse Color Map");
  reverseColorsAction_->setObjectName("reverseColorsAction");
  reverseColorsAction_->setCheckable(true);
  connect(reverseColorsAction_, &QAction::toggled, this, [this] {
    changeScene([this](Scene& s) { s.setColorMap(chosenColorMap()); });
    notifyPanels();
  });
  symmetricRangeAction_ = view->addAction("S&ymmetric Color Range");
  symmetricRangeAction_->setObjectName("symmetricRangeAction");
  symmetricRangeAction_->setCheckable(true);
  symmetricRangeAction_->setStatusTip("The colors span -M..M, M the larger of |min| and |max|: zero in the middle");
  connect(symmetricRangeAction_, &QAction::toggled, this, [this](bool on) {
    changeScene([on](Scene& s) { s.setSymmetricRange(on); });
    notifyPanels();
  });
  logScaleAction_ = view->addAction("Lo&g Color Scale");
  logScaleAction_->setObjectName("logScaleAction");
  logScaleAction_->setCheckable(true);
  logScaleAction_->setStatusTip("Colors by the value's logarithm; 0 and below lie below the range");
  connect(logScaleAction_, &QAction::toggled, this, [this](bool on) {
    changeScene([on](Scene& s) { s.setLogScale(on); });  // a typed range not above 0: the status bar says so
    syncColorActions();
    notifyPanels();
  });
  outOfRangeAction_ = view->addAction("Colors &Outside the Range");
  outOfRangeAction_->setObjectName("outOfRangeAction");
  outOfRangeAction_->setCheckable(true);
  outOfRangeAction_->setStatusTip("Values below a typed range in black, above it in white (not the map's end colors)");
  connect(outOfRangeAction_, &QAction::toggled, this, [this](bool on) {
    changeScene([on](Scene& s) {
      s.setOutOfRangeColors(on ? std::optional(glm::dvec3(0.0)) : std::nullopt,
                            on ? std::optional(glm::dvec3(1.0)) : std::nullopt);
    });
    notifyPanels();
  });
  view->addAction("Picture &Title...", this,
                  [this] {
                    bool ok = false;
                    const QString text = QInputDialog::getText(
                        this, "Picture title", "A line at the picture's top left (empty: none):", QLineEdit::Normal,
                        QString::fromStdString(viewport_->scene().state().title), &ok);
                    if (ok) changeScene([&](Scene& s) { s.setTitle(text.trimmed().toStdString()); });
                  })
      ->setObjectName("pictureTitleAction");
  stepTextAction_ = view->addAction("&Step in the Picture");
  stepTextAction_->setObjectName("stepTextAction");
  stepTextAction_->setCheckable(true);
  stepTextAction_->setStatusTip("The shown result and its step or time written under the title (pictures and videos)");
  connect(stepTextAction_, &QAction::toggled, this,
          [this](bool on) { changeScene([on](Scene& s) { s.setStepText(on); }); });
  view->addAction("Legend &Text and Numbers...", this, &MainWindow::chooseLegendText)
      ->setObjectName("legendTextAction");
  colorBandsAction_ = view->addAction("Color &Bands...");
  colorBandsAction_->setObjectName("colorBandsAction");
  connect(colorBandsAction_, &QAction::triggered, this, [this] {
    const int now = viewport_->scene().state().colorBands;
    bool ok = false;
    const int bands = QInputDialog::getInt(
        this, "Color bands", "Discrete bands of equal width (12 as in Abaqus; 0: continuous colors):", now ? now : 12,
        0, kMaxColorBands, 1, &ok);
    if (!ok) return;
    changeScene([bands](Scene& s) { s.setColorBands(bands == 1 ? 2 : bands); });
    syncColorActions();
    notifyPanels();
  });
}

// View > Legend Text and Numbers...: the shown result's title and its field's units, how
// numbers are written and about how many are labelled; the fields show what the legend has.
void MainWindow::chooseLegendText() {
  Scene& scene = viewport_->scene();
  if (!scene.view()) {
    statusBar()->showMessage("Show a result first: the legend belongs to it");
    return;
  }
  const SceneState state = scene.state();
  const Quantity q = scene.view()->quantity;
  QDialog dialog(this);
  dialog.setWindowTitle("Legend text and numbers");
  dialog.setObjectName("legendTextDialog");
  auto* form = new QFormLayout(&dialog);
  auto* title = new QLineEdit(&dialog);
  title->setObjectName("legendTitle");
  title->setPlaceholderText(QString::fromStdString(q.displayName()));
  if (const auto t = state.legendTitles.find(q.key()); t != state.legendTitles.end())
    title->setText(QString::fromStdString(t->second));
  form->addRow(QString("Title of %1:").arg(QString::fromStdString(q.key())), title);
  auto* units = new QLineEdit(&dialog);
  units->setObjectName("legendUnits");
  // The file's own units, where it states them, show until the user types others.
  const Field* field = scene.session() ? scene.session()->model().findField(q.field) : nullptr;
  units->setPlaceholderText(field && !field->units().empty()
                                ? QString::fromStdString(field->units()) + " (as the file states them)"
                                : QString("MPa, mm, K ..."));
  if (const auto u = state.units.find(q.field); u != state.units.end())
    units->setText(QString::fromStdString(u->second));
  form->addRow(QString("Units of %1:").arg(QString::fromStdString(q.field)), units);
  const LegendNumbers numbers = LegendNumbers::parse(state.legendNumbers).value_or(LegendNumbers{});
  auto* style = new QComboBox(&dialog);
  style->setObjectName("legendNumberStyle");
  style->addItem("Significant digits", "auto");
  style->addItem("Digits after the point", "fixed");
  style->addItem("Scientific", "scientific");
  style->setCurrentIndex(int(numbers.style));
  auto* digits = new QSpinBox(&dialog);
  digits->setObjectName("legendDigits");
  digits->setRange(0, 12);
  digits->setValue(numbers.digits);
  form->addRow("Numbers:", style);
  form->addRow("Digits:", digits);
  auto* labels = new QSpinBox(&dialog);
  labels->setObjectName("legendLabels");
  labels->setRange(2, 20);
  labels->setValue(state.legendLabels);
  form->addRow("About how many labels:", labels);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, &dialog);
  form->addRow(buttons);
  connect(buttons, &QDialogButtonBox::accepted, &dialog, &QDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, &dialog, &QDialog::reject);
  if (dialog.exec() != QDialog::Accepted) return;
  const std::string written = style->currentData().toString().toStdString() + ":" +
                              std::to_string(std::max(style->currentIndex() == 0 ? 1 : 0, digits->value()));
  changeScene([&](Scene& s) {
    s.setLegendNumbers(written);  // checked first: nothing changes when it is refused
    s.setLegendTitle(q.key(), title->text().trimmed().toStdString());
    s.setUnits(q.field, units->text().trimmed().toStdString());
    s.setLegendLabels(labels->value());
  });
}

void MainWindow::syncColorActions() {
  if (!reverseColorsAction_) return;
  const SceneState state = viewport_->scene().state();
  const QSignalBlocker a(reverseColorsAction_), b(symmetricRangeAction_), c(outOfRangeAction_), d(logScaleAction_);
  logScaleAction_->setChecked(state.logScale);
  if (stepTextAction_) {
    const QSignalBlocker e(stepTextAction_);
    stepTextAction_->setChecked(state.stepText);
  }
  outOfRangeAction_->setChecked(state.belowColor || state.aboveColor);
  reverseColorsAction_->setChecked(ColorMap::isReversed(state.colorMap));
  symmetricRangeAction_->setChecked(viewport_->scene().symmetricRangeShown());
  colorBandsAction_->setText(state.colorBands ? QString("Color &Bands (%1)...").arg(state.colorBands)
                                              : QString("Color &Bands (continuous)..."));
}

void MainWindow::buildPanels() {
  auto* dock = new QDockWidget("Model", this);
  dock->setObjectName("modelDock");
  modelInfo_ = new QTextBrowser(dock);
  modelInfo_->setObjectName("modelInfo");
  dock->setWidget(modelInfo_);
  addDockWidget(Qt::LeftDockWidgetArea, dock);
  resizeDocks({dock}, {220}, Qt::Horizontal);
  // The file's sets, below the model's description.
  auto* setsDock = new QDockWidget("Sets", this);
  setsDock->setObjectName("setsDock");
  sets_ = new SetsPanel(
      viewport_->scene(), [this](const std::function<void(Scene&)>& c) { return changeScene(c); }, setsDock);
  sets_->setObjectName("setsPanel");
  connect(sets_, &SetsPanel::historyRequested, this,
          [this](const QString& set) { probes_->plotSetHistory(set.toStdString()); });
  setsDock->setWidget(sets_);
  splitDockWidget(dock, setsDock, Qt::Vertical);
  bool tabifiedProbes = false;
  for (PanelPlugin* panel : plugins_.panelPlugins()) {
    auto* d = new QDockWidget(panel->panelTitle(), this);
    d->setObjectName("panel:" + panel->panelTitle());
    d->setWidget(panel->createPanel(*this, d));
    addDockWidget(Qt::RightDockWidgetArea, d);
    resizeDocks({d}, {360}, Qt::Horizontal);  // the view keeps most of the window
    // The volume's panels (the transfer-function editor) open with the volume: in the
    // surface view they took a third of the window. A saved layout restores them as left.
    d->hide();
    pluginDocks_.push_back(d);
    if (probes_ && !tabifiedProbes) {  // the Probe panel shares this place, a tab away
      tabifyDockWidget(d, probes_->dock());
      d->raise();
      tabifiedProbes = true;
    }
  }
  // View > Plot Over Line: a dock beside the Probe panel.
  auto* lineDock = new QDockWidget("Plot Over Line", this);
  lineDock->setObjectName("linePlotDock");
  linePlot_ = new LinePlotPanel(
      [this]() -> const Scene& { return viewport_->scene(); },
      [this](std::optional<std::array<glm::dvec3, 2>> line) { changeScene([&](Scene& s) { s.setPlotLine(line); }); },
      lineDock);
  linePlot_->setObjectName("linePlotPanel");
  lineDock->setWidget(linePlot_);
  addDockWidget(Qt::RightDockWidgetArea, lineDock);
  if (probes_) tabifyDockWidget(probes_->dock(), lineDock);
  lineDock->hide();
  connect(lineDock, &QDockWidget::visibilityChanged, this, [this, lineDock](bool visible) {
    if (!visible && !lineDock->isVisible()) changeScene([](Scene& s) { s.setPlotLine(std::nullopt); });
  });
  connect(linePlot_, &LinePlotPanel::message, this, [this](const QString& m) { statusBar()->showMessage(m); });
  QAction* plotAction = resultsMenu_->addAction("Plot Over &Line...", this, [this, lineDock] {
    lineDock->show();
    lineDock->raise();
    if (linePlot_->useLastProbes()) linePlot_->plot();
  });
  plotAction->setObjectName("linePlotAction");
  // View > Panels brings back a panel that was closed.
  QMenu* panels = viewMenu_->addMenu("P&anels");
  panels->setObjectName("panelsMenu");
  for (QDockWidget* d : findChildren<QDockWidget*>()) panels->addAction(d->toggleViewAction());
}

void MainWindow::chooseFile() {
  QSettings settings("volpost", "volpost");
  const QString path = QFileDialog::getOpenFileName(this, "Open model", settings.value("files/lastDir").toString(),
                                                    readerFilter(plugins_.readers()));
  if (path.isEmpty()) return;
  settings.setValue("files/lastDir", QFileInfo(path).absolutePath());
  openFile(path);
}

void MainWindow::openFile(const QString& path, const ReaderOptions& options) { readModel(path, options, {}); }

bool MainWindow::readModel(const QString& path, const ReaderOptions& options,
                           std::function<void(bool ok, const QString& error)> then) {
  return loader_->open(path, options, [this, path, then = std::move(then)](const ModelRead& read) {
    if (read.session) {
      installSession(read.session);
      emit loadFinished(true, {});
      if (then) then(true, {});
    } else if (read.cancelled) {
      statusBar()->showMessage("Loading cancelled; the previous model is unchanged");
      emit loadFinished(false, "cancelled");
      if (then) then(false, "cancelled");
    } else {
      statusBar()->showMessage("Could not open " + path);
      emit loadFinished(false, read.error);
      if (then) then(false, read.error);
      QMessageBox::critical(this, "Cannot open model", read.error);
    }
  });
}

bool MainWindow::reopenWithReaderOptions(const ReaderOptions& options) {
  if (loader_->lastPath().isEmpty()) {
    statusBar()->showMessage("Open a model first: reader options apply to a file");
    return false;
  }
  openFile(loader_->lastPath(), options);
  return true;
}

void MainWindow::installSession(std::shared_ptr<ModelSession> session) {
  session_ = std::move(session);
  RecentFiles::add(QString::fromStdString(session_->model().sourcePath));
  userTransferFunctions_.clear();  // a new model: its fields get their own defaults
  const Model& m = session_->model();
  setWindowTitle(QString("%1 - volpost").arg(QFileInfo(QString::fromStdString(m.sourcePath)).fileName()));
  viewport_->scene().setSession(session_);
  viewport_->update();
  if (gridSlices_) {
    gridSlices_->followScene();
    if (!session_->model().grid) gridSlicesDock_->hide();
  }
  // What the scene dropped with the old model, the controls drop too (the deformed shape
  // stayed checked; the plot kept the old model's curves).
  volume_->syncToScene();
  deformation_->syncToScene();
  streamlines_->syncToScene();
  clips_->syncToScene();
  savedViews_->syncToScene();
  if (linePlot_) linePlot_->modelChanged();
  if (session_) rendererMenu_->fitToModel(session_->model().grid.has_value());
  fillQuantities();
  showModelInfo();
  std::size_t warnings = 0;
  for (const auto& d : m.diagnostics) warnings += d.severity == Severity::Warning;
  statusBar()->showMessage(QString("%1: %2 nodes, %3 cells%4")
                               .arg(QString::fromStdString(m.sourcePath))
                               .arg(m.nodeCount())
                               .arg(m.cellCount())
                               .arg(warnings ? QString(", %1 defect warning(s): see the Model panel").arg(warnings) : ""));
  notifyPanels();
}

void MainWindow::listQuantities() {
  const QSignalBlocker block(quantityBox_);
  quantityBox_->clear();
  quantityBox_->addItem("(none)", QString());
  for (const Quantity& q : session_->quantities()) {
    const Field& f = session_->fieldOf(q);
    quantityBox_->addItem(QString("%1%2").arg(QString::fromStdString(q.displayName()),
                                              f.location() == FieldLocation::Cell ? " (cell)" : ""),
                          QString::fromStdString(q.key()));
  }
}

void MainWindow::fillQuantities() {
  listQuantities();
  const QSignalBlocker block(quantityBox_);
  const auto preferred = session_->defaultQuantity();
  quantityBox_->setCurrentIndex(preferred ? quantityBox_->findData(QString::fromStdString(preferred->key())) : 0);
  fillSteps();
  refreshScalars();
}

void MainWindow::fillSteps() {
  const QSignalBlocker block(stepBox_);
  stepBox_->clear();
  const auto q = chosenQuantity();
  if (!q) return;
  const Field& f = session_->fieldOf(*q);
  for (std::size_t s = 0; s < f.stepCount(); ++s) {
    const std::string& label = f.steps()[s].label;
    stepBox_->addItem(label.empty() ? QString::number(s + 1) : QString::fromStdString(label));
  }
  stepBox_->setEnabled(f.stepCount() > 1);
}

// What the quantity box asks for; the scene may have refused it (activeQuantity says what
// is shown).
std::optional<Quantity> MainWindow::chosenQuantity() const {
  if (!session_ || quantityBox_->currentIndex() <= 0) return std::nullopt;
  return session_->findQuantity(quantityBox_->currentData().toString().toStdString());
}

// Panels and tests read what is shown from the scene, the one record of it, not from the
// boxes that ask for it.
std::optional<Quantity> MainWindow::activeQuantity() const {
  const auto& view = viewport_->scene().view();
  if (!view) return std::nullopt;
  return view->quantity;
}

std::size_t MainWindow::activeStep() const { return viewport_->scene().step(); }

bool MainWindow::selectQuantity(const QString& key) {
  int index = quantityBox_->findData(key);
  if (index < 0 && session_) {  // a bare field name picks its headline quantity, as on the command line
    try {
      index = quantityBox_->findData(QString::fromStdString(session_->findQuantity(key.toStdString()).key()));
    } catch (const std::invalid_argument&) {
    }
  }
  if (index < 0) return false;
  quantityBox_->setCurrentIndex(index);
  return true;
}

void MainWindow::refreshScalars() {
  if (!session_) return;
  const auto q = chosenQuantity();
  const std::string key = q ? q->key() : std::string();
  const auto tf = userTransferFunctions_.find(key);
  const std::size_t step = std::size_t(std::max(0, stepBox_->currentIndex()));
  const bool ok = changeScene([&](Scene& s) {
    s.setResult(key, step);
    s.setTransferFunction(tf != userTransferFunctions_.end() ? std::optional(tf->second) : std::nullopt);
  });
  if (!ok) {
    changeScene([](Scene& s) { s.setResult({}, 0); });
    QMessageBox::warning(this, "Cannot show result", statusBar()->currentMessage());
  } else if (const auto& view = viewport_->scene().view(); view && view->range.nanCount) {
    statusBar()->showMessage(QString("%1: %2 values are NaN or infinite (drawn gray)")
                                 .arg(QString::fromStdString(view->quantity.displayName()))
                                 .arg(view->range.nanCount));
  }
  if (viewport_->scene().streamlinesNeedTracing()) streamlines_->trace();  // another step: the lines follow
  volume_->syncToScene();                                                  // without a result, no volume
  notifyPanels();
}

void MainWindow::requestRender() { viewport_->update(); }

TransferFunction MainWindow::transferFunction() const { return viewport_->scene().transferFunction(); }

std::optional<TransferFunction2D> MainWindow::transferFunction2D() const {
  return viewport_->scene().state().volume.transferFunction2D;
}

bool MainWindow::setTransferFunction2D(const std::optional<TransferFunction2D>& tf) {
  return volume_->setTransferFunction2D(tf);
}

bool MainWindow::loadTransferFunction2D(const QString& path) { return volume_->loadTransferFunction2D(path); }

void MainWindow::setTransferFunction(const TransferFunction& tf) {
  const auto& view = viewport_->scene().view();
  if (!session_ || !view) return;
  userTransferFunctions_[view->quantity.key()] = tf;
  if (changeScene([&](Scene& s) { s.setTransferFunction(tf); }))
    if (const auto note = transferFunctionRangeNote(tf, *view)) statusBar()->showMessage("Note: " + QString::fromStdString(*note));
}

SampleView MainWindow::activeValues() const {
  const auto& view = viewport_->scene().view();
  return view ? view->values : SampleView();
}

double MainWindow::modelSize() const { return session_ ? session_->model().bounds().diagonal() : 0.0; }

double MainWindow::lastTransferFunctionMs() const { return viewport_->volumeStats().lastTransferFunctionMs; }

void MainWindow::notifyPanels() {
  if (sets_) sets_->followScene();
  if (selection_) selection_->syncToScene();
  if (probes_) probes_->refresh();
  if (steps_) steps_->refresh();
  // One color control at a time: the volume's colors are its transfer function's.
  const bool volume = viewport_->scene().volumeShown();
  colorMapBox_->setEnabled(!volume);
  colorMapBox_->setToolTip(volume ? "The volume's colors are set in the Transfer Function panel (Colors...)"
                                  : "The color map of the surface and of a new volume's transfer function");
  for (PanelPlugin* panel : plugins_.panelPlugins()) panel->hostChanged();
  if (session_) showModelInfo();  // the volume renderer's memory follows the renderer
}

void MainWindow::showModelInfo() {
  const Model& m = session_->model();
  QString html = QString("<b>%1</b><br>%2<br><br>").arg(QFileInfo(QString::fromStdString(m.sourcePath)).fileName().toHtmlEscaped(),
                                                        QString::fromStdString(m.formatName).toHtmlEscaped());
  if (!session_->readerOptions().empty()) {
    QStringList options;
    for (const auto& [name, value] : session_->readerOptions())
      options << QString::fromStdString(name + "=" + value).toHtmlEscaped();
    html += QString("read with %1 (File &gt; Reader Options...)<br><br>").arg(options.join(", "));
  }
  html += QString("%1 nodes<br>%2 cells:<br>").arg(m.nodeCount()).arg(m.cellCount());
  for (const auto& [type, count] : m.countsByType())
    html += QString("&nbsp;&nbsp;%1 %2<br>").arg(count).arg(QString::fromStdString(std::string(cellTypeName(type))));
  const Bounds b = m.bounds();
  if (b.valid)
    html += QString("size %1 x %2 x %3<br>").arg(b.size().x, 0, 'g', 4).arg(b.size().y, 0, 'g', 4).arg(b.size().z, 0, 'g', 4);
  if (const auto& grid = m.grid) {  // a seismic cube or other regular grid: its axes in its own words
    html += "<br><b>Grid</b><br>";
    for (int a = 0; a < 3; ++a)
      html += QString("%1 %2: %3 .. %4 by %5<br>")
                  .arg(grid->dims[std::size_t(a)])
                  .arg(QString::fromStdString(grid->axisNames[std::size_t(a)]).toHtmlEscaped())
                  .arg(grid->label(a, 0.0), 0, 'g', 6)
                  .arg(grid->label(a, double(grid->dims[std::size_t(a)] - 1)), 0, 'g', 6)
                  .arg(grid->labelStep[std::size_t(a)], 0, 'g', 6);
    if (!grid->sampleStorage.empty())
      html += QString("samples stored as %1<br>").arg(QString::fromStdString(grid->sampleStorage).toHtmlEscaped());
    html += "<br>";
  }
  html += QString("%1 boundary faces<br><br><b>Memory</b><br>").arg(session_->surface().boundaryFaceCount);
  // What the process holds, all of it (this model, what is drawn, the program), then parts.
  if (const std::size_t held = processResidentBytes())
    html += QString("volpost holds %1 in all<br>").arg(QString::fromStdString(byteSizeText(double(held))));
  html +=
      QString("fields read: %1<br>").arg(QString::fromStdString(byteSizeText(double(Field::bytesHeldByAllFields()))));
  // Host: the cells, nodes and ids the model holds (fields are read on first use). The
  // volume renderer's figure is its structure's (GPU buffers, or host memory for the CPU
  // ray caster), as of its last frame.
  if (m.meshBuilt()) {
    const double modelBytes = double(m.mesh().cellBytes()) + 24.0 * double(m.mesh().nodeCount()) +
                              8.0 * double(m.mesh().nodeIds.size() + m.mesh().cellIds.size());
    html += QString("model: %1 (%2 bytes per cell)<br>")
                .arg(QString::fromStdString(byteSizeText(modelBytes)))
                .arg(m.mesh().cellCount() ? modelBytes / double(m.mesh().cellCount()) : 0.0, 0, 'f', 0);
  } else {
    html += QString("model: a regular grid (its cells are not stored)<br>");
  }
  const VolumeStats volume = viewport_->volumeStats();
  if (volume.gpuBytes > 0)
    html += QString("volume renderer (%1): %2<br>")
                .arg(QString::fromStdString(viewport_->scene().state().volume.renderer).toHtmlEscaped(),
                     QString::fromStdString(byteSizeText(double(volume.gpuBytes))));
  html += QString("budget: %1<br>").arg(QString::fromStdString(byteSizeText(double(memoryBudget()))));
  const std::size_t gpuBudget = gpuMemoryBudget();
  html += QString("GPU budget: %1<br><br><b>Fields</b><br>")
              .arg(gpuBudget ? QString::fromStdString(byteSizeText(double(gpuBudget))) : QString("the default"));
  for (const auto& f : m.fields)
    html += QString("%1 (%2, per %3, %4 step%5)<br>")
                .arg(QString::fromStdString(f->name()).toHtmlEscaped(), toString(f->kind()), toString(f->location()))
                .arg(f->stepCount())
                .arg(f->stepCount() == 1 ? "" : "s");
  html += "<br><b>Defects</b><br>";
  if (m.diagnostics.empty()) html += "none found<br>";
  for (const auto& d : m.diagnostics)
    html += QString("<span style='color:%1'>%2</span><br>")
                .arg(d.severity == Severity::Warning ? "#a01010" : "#404040", QString::fromStdString(d.message).toHtmlEscaped());
  modelInfo_->setHtml(html);
}

bool MainWindow::saveStateFile(const QString& path) { return stateFiles_->save(path); }

void MainWindow::openStateFile(const QString& path) { stateFiles_->open(path); }

// A state file was applied: the controls, panels and lines follow the scene.
void MainWindow::followAppliedState() {
  const Scene& scene = viewport_->scene();
  if (scene.volume().transferFunction && scene.view())
    userTransferFunctions_[scene.view()->quantity.key()] = *scene.volume().transferFunction;
  syncControlsToScene();
  if (gridSlices_) gridSlices_->followScene();
  if (linePlot_) linePlot_->followScene();
  if (sets_) sets_->followScene();
  viewport_->update();
  notifyPanels();
  if (viewport_->scene().streamlinesNeedTracing()) streamlines_->trace();
}

// The menus and the toolbar show what the scene holds (after a state was applied).
void MainWindow::syncControlsToScene() {
  const Scene& scene = viewport_->scene();
  const SceneState state = scene.state();
  if (scene.sharedBaseSession() != session_ && scene.sharedBaseSession()) {  // formulas came or went
    session_ = scene.sharedBaseSession();
    listQuantities();
    showModelInfo();
  }
  {
    const QSignalBlocker a(quantityBox_), b(stepBox_), c(colorMapBox_);
    quantityBox_->setCurrentIndex(std::max(0, quantityBox_->findData(QString::fromStdString(state.quantity))));
    fillSteps();
    stepBox_->setCurrentIndex(int(state.step));
    const std::string baseMap =
        ColorMap::isReversed(state.colorMap) ? ColorMap::reversedName(state.colorMap) : state.colorMap;
    colorMapBox_->setCurrentIndex(std::max(0, colorMapBox_->findData(QString::fromStdString(baseMap))));
  }
  const auto check = [](QAction* action, bool on) {
    if (!action) return;
    const QSignalBlocker block(action);
    action->setChecked(on);
  };
  check(edgesAction_, state.edges);
  check(legendAction_, state.legend);
  syncColorActions();
  check(triadAction_, state.triad);
  deformation_->syncToScene();
  check(orthoAction_, state.camera && state.camera->orthographic);
  volume_->syncToScene();
  display_->syncToScene();
  streamlines_->syncToScene();
  rendererMenu_->syncToScene();
  clips_->syncToScene();
  savedViews_->syncToScene();
  probes_->syncToScene();
  steps_->syncToScene();
}

void MainWindow::saveImage() {
  QSettings settings("volpost", "volpost");
  const qreal ratio = viewport_->devicePixelRatioF();
  PictureRequest request{settings.value("files/lastImage", "volpost.png").toString(),
                         int(std::lround(viewport_->width() * ratio)), int(std::lround(viewport_->height() * ratio)),
                         viewport_->scene().shown().textScale,
                         settings.value("files/transparentImage", false).toBool()};
  SaveImageDialog dialog(request, this);
  if (dialog.exec() != QDialog::Accepted) return;
  request = dialog.request();
  settings.setValue("files/lastImage", request.path);
  settings.setValue("files/transparentImage", request.transparent);
  try {
    QApplication::setOverrideCursor(Qt::WaitCursor);
    struct Restore {
      ~Restore() { QApplication::restoreOverrideCursor(); }
    } restore;
    savePicture(viewport_->renderPicture(request.width, request.height, request.textScale, request.transparent),
                request.path);
  } catch (const std::exception& e) {
    QMessageBox::critical(this, "Save image", e.what());  // the previous file, if any, is as it was
    return;
  }
  viewport_->update();
  statusBar()->showMessage(QString("Saved %1 (%2 x %3)").arg(request.path).arg(request.width).arg(request.height));
}

// Asks for a size (512M, 8G) for the setting `key`, applies it with `apply` and keeps it;
// empty goes back to the default (0); text that is not a size is refused, the setting kept.
void MainWindow::askBudget(const QString& title, const QString& prompt, const QString& key,
                           void (*apply)(std::size_t)) {
  bool ok = false;
  const QString text = QInputDialog::getText(this, title, prompt, QLineEdit::Normal,
                                             QSettings("volpost", "volpost").value(key).toString(), &ok);
  if (!ok) return;
  if (text.trimmed().isEmpty()) {
    QSettings("volpost", "volpost").remove(key);
    apply(0);  // back to the default
    statusBar()->showMessage(title + ": the default");
    return;
  }
  const std::size_t bytes = parseByteSize(text.trimmed().toStdString());
  if (!bytes) {
    QMessageBox::warning(this, title, QString("'%1' is not a size such as 512M or 8G").arg(text));
    return;
  }
  apply(bytes);
  QSettings("volpost", "volpost").setValue(key, text.trimmed());
  statusBar()->showMessage(QString("%1: %2").arg(title, QString::fromStdString(byteSizeText(double(bytes)))));
}

}  // namespace volpost::app

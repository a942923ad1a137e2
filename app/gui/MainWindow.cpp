// SPDX-License-Identifier: MIT
#include "MainWindow.hpp"

#include "../core/VolumeImage.hpp"
#include "../core/VolumeSpecs.hpp"
#include "PluginsDialog.hpp"
#include "Viewport.hpp"

#include <volpost/core/Version.hpp>
#include <volpost/render/VolumeRenderer.hpp>

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QComboBox>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QFutureWatcher>
#include <QInputDialog>
#include <QLabel>
#include <QLineEdit>
#include <QMenuBar>
#include <QMessageBox>
#include <QProgressDialog>
#include <QSettings>
#include <QStatusBar>
#include <QTextBrowser>
#include <QTimer>
#include <QToolBar>
#include <QtConcurrent/QtConcurrentRun>

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

struct LoadResult {
  std::shared_ptr<ModelSession> session;
  QString error;
  bool cancelled = false;
};

}  // namespace

MainWindow::MainWindow(PluginManager& plugins, QWidget* parent) : QMainWindow(parent), plugins_(plugins) {
  setWindowTitle("volpost");
  viewport_ = new Viewport(this);
  setCentralWidget(viewport_);
  glLabel_ = new QLabel(this);
  statusBar()->addPermanentWidget(glLabel_);
  connect(viewport_, &Viewport::glInfo, glLabel_, &QLabel::setText);
  connect(viewport_, &Viewport::renderFailed, this, [this](const QString& m) {
    statusBar()->showMessage("Rendering error: " + m);
  });
  buildActions();
  buildToolbar();
  buildPanels();
  QSettings settings("volpost", "volpost");
  resize(1280, 800);
  restoreGeometry(settings.value("window/geometry").toByteArray());
  restoreState(settings.value("window/state").toByteArray());
  statusBar()->showMessage("Open a model with File > Open (Ctrl+O)");
}

MainWindow::~MainWindow() = default;

void MainWindow::closeEvent(QCloseEvent* event) {
  QSettings settings("volpost", "volpost");
  settings.setValue("window/geometry", saveGeometry());
  settings.setValue("window/state", saveState());
  QMainWindow::closeEvent(event);
}

void MainWindow::buildActions() {
  QMenu* file = menuBar()->addMenu("&File");
  file->addAction("&Open...", QKeySequence::Open, this, &MainWindow::chooseFile);
  file->addAction("Save &Image...", QKeySequence::Save, this, &MainWindow::saveImage);
  file->addSeparator();
  file->addAction("&Quit", QKeySequence::Quit, this, &QWidget::close);

  QMenu* view = menuBar()->addMenu("&View");
  view->addAction("&Fit", QKeySequence(Qt::Key_F), viewport_, &Viewport::fit);
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
  QAction* ortho = view->addAction("&Orthographic");
  ortho->setCheckable(true);
  ortho->setShortcut(QKeySequence(Qt::Key_P));
  connect(ortho, &QAction::toggled, this, [this](bool on) {
    viewport_->setProjection(on ? Camera::Projection::Orthographic : Camera::Projection::Perspective);
  });
  edgesAction_ = view->addAction("Element &Edges");
  edgesAction_->setCheckable(true);
  edgesAction_->setChecked(QSettings("volpost", "volpost").value("view/edges", true).toBool());
  edgesAction_->setShortcut(QKeySequence(Qt::Key_E));
  viewport_->setShowEdges(edgesAction_->isChecked());
  connect(edgesAction_, &QAction::toggled, this, [this](bool on) {
    viewport_->setShowEdges(on);
    QSettings("volpost", "volpost").setValue("view/edges", on);
  });
  QAction* legend = view->addAction("&Legend");
  legend->setCheckable(true);
  legend->setChecked(true);
  connect(legend, &QAction::toggled, viewport_, &Viewport::setShowLegend);
  buildVolumeMenu(view);

  QMenu* tools = menuBar()->addMenu("&Tools");
  tools->addAction("&Plugins...", this, [this] { PluginsDialog(plugins_, this).exec(); });
  QMenu* help = menuBar()->addMenu("&Help");
  help->addAction("&About volpost", this, [this] {
    QMessageBox::about(this, "About volpost",
                       "volpost " VOLPOST_VERSION "\nFinite-element post-processing and volume rendering.\n"
                       "Mouse: left drag rotates, right drag or shift+left pans, wheel zooms.");
  });
}

std::unique_ptr<VolumeRenderer> MainWindow::createVolumeRenderer(const QString& name) const {
  for (RendererPlugin* plugin : plugins_.rendererPlugins())
    if (plugin->rendererNames().contains(name)) {
      std::unique_ptr<Renderer> r = plugin->createRenderer(name);
      if (auto* v = dynamic_cast<VolumeRenderer*>(r.get())) {
        r.release();
        return std::unique_ptr<VolumeRenderer>(v);
      }
    }
  return nullptr;
}

void MainWindow::buildVolumeMenu(QMenu* view) {
  // Every GPU volume renderer the plugins offer; the first one is used until another is chosen.
  QStringList names;
  for (RendererPlugin* plugin : plugins_.rendererPlugins()) names << plugin->rendererNames();
  view->addSeparator();
  QMenu* renderers = view->addMenu("Volume &Renderer");
  auto* rendererGroup = new QActionGroup(this);
  const std::map<QString, QString> labels = {{"raycast", "Ray casting"},
                                             {"vicp", "Cell projection (MPVONC order)"},
                                             {"vicp-exact", "Cell projection (exact image-space order)"}};
  for (const QString& name : names) {
    auto renderer = createVolumeRenderer(name);
    if (!renderer) continue;
    const auto label = labels.find(name);
    QAction* a = renderers->addAction(label != labels.end() ? label->second : name);
    a->setObjectName("renderer:" + name);
    a->setCheckable(true);
    rendererGroup->addAction(a);
    if (!viewport_->hasVolumeRenderer()) {
      viewport_->setVolumeRenderer(std::move(renderer));
      a->setChecked(true);
    }
    connect(a, &QAction::triggered, this, [this, name] {
      viewport_->setVolumeRenderer(createVolumeRenderer(name));
      statusBar()->showMessage("Volume renderer: " + name);
    });
  }
  volumeAction_ = view->addAction("&Volume Rendering");
  volumeAction_->setObjectName("volumeAction");
  volumeAction_->setCheckable(true);
  volumeAction_->setShortcut(QKeySequence(Qt::Key_V));
  volumeAction_->setEnabled(viewport_->hasVolumeRenderer());
  if (!viewport_->hasVolumeRenderer()) volumeAction_->setToolTip("No volume renderer plugin is loaded");
  connect(volumeAction_, &QAction::toggled, this, &MainWindow::setVolumeShown);

  QMenu* modes = view->addMenu("Volume &Integration");
  auto* modeGroup = new QActionGroup(this);
  const std::pair<const char*, IntegrationMode> modeList[] = {
      {"Linear segments, exact cuts", IntegrationMode::LinearSegments},
      {"Linear segments, iso-detection table (seed)", IntegrationMode::LinearSegmentsIsoTable},
      {"Pre-integrated table", IntegrationMode::PreIntegrated},
      {"Sampling (fixed step)", IntegrationMode::Sampling}};
  for (const auto& [label, mode] : modeList) {
    QAction* a = modes->addAction(label);
    a->setCheckable(true);
    a->setChecked(mode == IntegrationMode::LinearSegments);
    modeGroup->addAction(a);
    const IntegrationMode m = mode;
    connect(a, &QAction::triggered, this, [this, m] { viewport_->setIntegrationMode(m); });
  }
  QMenu* clip = view->addMenu("&Clip Plane");
  auto* clipGroup = new QActionGroup(this);
  const char* axes[] = {"Off", "Normal +X", "Normal +Y", "Normal +Z"};
  for (int i = 0; i < 4; ++i) {
    QAction* a = clip->addAction(axes[i]);
    a->setCheckable(true);
    a->setChecked(i == 0);
    clipGroup->addAction(a);
    connect(a, &QAction::triggered, this, [this, i] {
      viewport_->setClipAxis(i - 1);
      if (i > 0) statusBar()->showMessage("Ctrl+drag in the view moves the clip plane");
    });
  }
  clip->addSeparator();
  clip->addAction("Clip &Box...", this, &MainWindow::chooseClipBox);
  view->addAction("&Iso-surfaces...", this, &MainWindow::chooseIsoSurfaces);
}

void MainWindow::chooseClipBox() {
  if (!session_) return;
  const Bounds b = session_->model().mesh.bounds();
  QString text = QString("%1,%2,%3,%4,%5,%6").arg(b.min.x).arg(b.max.x).arg(b.min.y).arg(b.max.y).arg(b.min.z).arg(b.max.z);
  for (;;) {
    bool ok = false;
    text = QInputDialog::getText(this, "Clip box", "Keep inside xmin,xmax,ymin,ymax,zmin,zmax (empty: no box):",
                                 QLineEdit::Normal, text, &ok);
    if (!ok) return;
    if (text.trimmed().isEmpty()) {
      viewport_->setClipBox({});
      return;
    }
    if (const auto box = parseClipBox(text)) {
      viewport_->setClipBox(*box);
      viewport_->repaint();  // uploads now, so the message below is about this box
      statusBar()->showMessage(QString("Clip box: the GPU holds %1 of the %2 tets")
                                   .arg(viewport_->uploadedTetCount())
                                   .arg(session_->tetrahedra().mesh.cellCount()));
      return;
    }
    QMessageBox::warning(this, "Clip box", QString("'%1' is not six numbers xmin,xmax,ymin,ymax,zmin,zmax with min < max").arg(text));
  }
}

void MainWindow::chooseIsoSurfaces() {
  QString text = isoSurfacesText(viewport_->isoSurfaces());
  if (text.isEmpty()) {
    if (const auto q = activeQuantity(); q && session_) {
      const ScalarView v = session_->evaluate(*q, activeStep());
      if (v.range.valid()) text = QString("%1:1,0.85,0.2:0.6").arg(0.5 * (v.range.min + v.range.max), 0, 'g', 6);
    }
  }
  for (;;) {
    bool ok = false;
    text = QInputDialog::getText(this, "Iso-surfaces",
                                 "VALUE[:r,g,b[:opacity]] separated by ';' (colors and opacity 0..1, up to 8; empty: none):",
                                 QLineEdit::Normal, text, &ok);
    if (!ok) return;
    QString bad;
    if (const auto surfaces = parseIsoSurfaces(text, &bad)) {
      viewport_->setIsoSurfaces(*surfaces);
      if (!surfaces->empty() && !viewport_->volumeShown()) volumeAction_->setChecked(true);
      return;
    }
    QMessageBox::warning(this, "Iso-surfaces", QString("'%1' is not VALUE[:r,g,b[:opacity]] (or more than 8)").arg(bad));
  }
}

void MainWindow::setVolumeShown(bool on) {
  if (!on || !session_) {
    viewport_->showSurface();
    return;
  }
  const auto q = activeQuantity();
  if (!q) {
    statusBar()->showMessage("Choose a result to render as a volume");
    volumeAction_->setChecked(false);
    return;
  }
  try {
    const ScalarView view = session_->evaluate(*q, activeStep());
    viewport_->showVolume(transferFunctionFor(view));
    statusBar()->showMessage(QString("Volume rendering %1 (extinction in 1 / model length unit)")
                                 .arg(QString::fromStdString(q->displayName())));
  } catch (const std::exception& e) {
    const QSignalBlocker block(volumeAction_);
    volumeAction_->setChecked(false);
    viewport_->showSurface();
    statusBar()->showMessage(QString("Volume rendering unavailable: %1").arg(e.what()));
  }
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
  stepBox_->setMinimumContentsLength(8);
  bar->addWidget(stepBox_);
  bar->addWidget(new QLabel("  Colors: "));
  colorMapBox_ = new QComboBox(this);
  colorMapBox_->setObjectName("colorMapBox");
  for (const auto& name : ColorMap::names()) colorMapBox_->addItem(QString::fromStdString(name));
  colorMapBox_->setCurrentText(QSettings("volpost", "volpost").value("view/colorMap", "cool-warm").toString());
  viewport_->setColorMap(ColorMap::named(colorMapBox_->currentText().toStdString()));
  bar->addWidget(colorMapBox_);
  connect(quantityBox_, &QComboBox::currentIndexChanged, this, [this] {
    fillSteps();
    refreshScalars();
  });
  connect(stepBox_, &QComboBox::currentIndexChanged, this, &MainWindow::refreshScalars);
  connect(colorMapBox_, &QComboBox::currentTextChanged, this, [this](const QString& name) {
    viewport_->setColorMap(ColorMap::named(name.toStdString()));
    QSettings("volpost", "volpost").setValue("view/colorMap", name);
  });
}

void MainWindow::buildPanels() {
  auto* dock = new QDockWidget("Model", this);
  dock->setObjectName("modelDock");
  modelInfo_ = new QTextBrowser(dock);
  modelInfo_->setObjectName("modelInfo");
  dock->setWidget(modelInfo_);
  addDockWidget(Qt::LeftDockWidgetArea, dock);
  resizeDocks({dock}, {220}, Qt::Horizontal);
  for (PanelPlugin* panel : plugins_.panelPlugins()) {
    auto* d = new QDockWidget(panel->panelTitle(), this);
    d->setObjectName("panel:" + panel->panelTitle());
    d->setWidget(panel->createPanel(*this, d));
    addDockWidget(Qt::RightDockWidgetArea, d);
    resizeDocks({d}, {360}, Qt::Horizontal);  // the view keeps most of the window
  }
}

void MainWindow::chooseFile() {
  QSettings settings("volpost", "volpost");
  const QString path = QFileDialog::getOpenFileName(this, "Open model", settings.value("files/lastDir").toString(),
                                                    readerFilter(plugins_.readers()));
  if (path.isEmpty()) return;
  settings.setValue("files/lastDir", QFileInfo(path).absolutePath());
  openFile(path);
}

void MainWindow::openFile(const QString& path) {
  if (loading_) {
    statusBar()->showMessage("Still loading the previous file");
    return;
  }
  loading_ = true;
  auto progress = std::make_shared<std::atomic<int>>(0);
  auto cancel = std::make_shared<std::atomic<bool>>(false);
  auto* dialog = new QProgressDialog(QString("Reading %1...").arg(QFileInfo(path).fileName()), "Cancel", 0, 100, this);
  dialog->setWindowModality(Qt::WindowModal);
  dialog->setMinimumDuration(300);
  connect(dialog, &QProgressDialog::canceled, this, [cancel] { *cancel = true; });
  auto* timer = new QTimer(dialog);
  connect(timer, &QTimer::timeout, dialog, [dialog, progress] { dialog->setValue(*progress); });
  timer->start(50);
  statusBar()->showMessage("Reading " + path);

  const ReaderRegistry& readers = plugins_.readers();
  auto* watcher = new QFutureWatcher<LoadResult>(this);
  connect(watcher, &QFutureWatcher<LoadResult>::finished, this, [this, watcher, dialog, path] {
    const LoadResult r = watcher->result();
    watcher->deleteLater();
    dialog->deleteLater();
    loading_ = false;
    if (r.session) {
      installSession(r.session);
      emit loadFinished(true, {});
    } else if (r.cancelled) {
      statusBar()->showMessage("Loading cancelled; the previous model is unchanged");
      emit loadFinished(false, "cancelled");
    } else {
      statusBar()->showMessage("Could not open " + path);
      emit loadFinished(false, r.error);
      QMessageBox::critical(this, "Cannot open model", r.error);
    }
  });
  watcher->setFuture(QtConcurrent::run([&readers, path, progress, cancel]() {
    LoadResult r;
    try {
      Progress p([&](double f, const std::string&) {
        *progress = int(f * 100.0);
        return !*cancel;
      });
      r.session = ModelSession::load(readers, path.toStdString(), p);
    } catch (const Cancelled&) {
      r.cancelled = true;
    } catch (const std::exception& e) {
      r.error = QString::fromStdString(e.what());
    }
    return r;
  }));
}

void MainWindow::installSession(std::shared_ptr<ModelSession> session) {
  session_ = std::move(session);
  userTransferFunctions_.clear();  // a new model: its fields get their own defaults
  const Model& m = session_->model();
  setWindowTitle(QString("%1 - volpost").arg(QFileInfo(QString::fromStdString(m.sourcePath)).fileName()));
  viewport_->setSession(session_);
  if (volumeAction_) {
    const QSignalBlocker block(volumeAction_);
    volumeAction_->setChecked(false);
  }
  fillQuantities();
  showModelInfo();
  std::size_t warnings = 0;
  for (const auto& d : m.diagnostics) warnings += d.severity == Severity::Warning;
  statusBar()->showMessage(QString("%1: %2 nodes, %3 cells%4")
                               .arg(QString::fromStdString(m.sourcePath))
                               .arg(m.mesh.nodeCount())
                               .arg(m.mesh.cellCount())
                               .arg(warnings ? QString(", %1 defect warning(s): see the Model panel").arg(warnings) : ""));
  notifyPanels();
}

void MainWindow::fillQuantities() {
  const QSignalBlocker block(quantityBox_);
  quantityBox_->clear();
  quantityBox_->addItem("(none)", QString());
  for (const Quantity& q : session_->quantities()) {
    const Field& f = session_->fieldOf(q);
    quantityBox_->addItem(QString("%1%2").arg(QString::fromStdString(q.displayName()),
                                              f.location() == FieldLocation::Cell ? " (cell)" : ""),
                          QString::fromStdString(q.key()));
  }
  const auto preferred = session_->defaultQuantity();
  quantityBox_->setCurrentIndex(preferred ? quantityBox_->findData(QString::fromStdString(preferred->key())) : 0);
  fillSteps();
  refreshScalars();
}

void MainWindow::fillSteps() {
  const QSignalBlocker block(stepBox_);
  stepBox_->clear();
  const auto q = activeQuantity();
  if (!q) return;
  const Field& f = session_->fieldOf(*q);
  for (std::size_t s = 0; s < f.stepCount(); ++s) {
    const std::string& label = f.steps()[s].label;
    stepBox_->addItem(label.empty() ? QString::number(s + 1) : QString::fromStdString(label));
  }
  stepBox_->setEnabled(f.stepCount() > 1);
}

std::optional<Quantity> MainWindow::activeQuantity() const {
  if (!session_ || quantityBox_->currentIndex() <= 0) return std::nullopt;
  return session_->findQuantity(quantityBox_->currentData().toString().toStdString());
}

std::size_t MainWindow::activeStep() const { return std::size_t(std::max(0, stepBox_->currentIndex())); }

bool MainWindow::selectQuantity(const QString& key) {
  const int index = quantityBox_->findData(key);
  if (index < 0) return false;
  quantityBox_->setCurrentIndex(index);
  return true;
}

void MainWindow::refreshScalars() {
  if (!session_) return;
  const auto q = activeQuantity();
  if (!q) {
    viewport_->setScalars(std::nullopt, {});
    notifyPanels();
    return;
  }
  try {
    ScalarView view = session_->evaluate(*q, activeStep());
    const DisplayRange range = autoRange(view);
    if (view.range.nanCount)
      statusBar()->showMessage(QString("%1: %2 values are NaN or infinite (drawn gray)")
                                   .arg(QString::fromStdString(q->displayName()))
                                   .arg(view.range.nanCount));
    viewport_->setScalars(std::move(view), range);
    if (volumeAction_ && volumeAction_->isChecked()) setVolumeShown(true);  // new result: new default TF
  } catch (const std::exception& e) {
    viewport_->setScalars(std::nullopt, {});
    QMessageBox::warning(this, "Cannot show result", e.what());
  }
  notifyPanels();
}

void MainWindow::requestRender() { viewport_->update(); }

TransferFunction MainWindow::transferFunctionFor(const ScalarView& view) const {
  const auto it = userTransferFunctions_.find(view.quantity.key());
  if (it != userTransferFunctions_.end()) return it->second;
  return defaultTransferFunction(view, session_->model().mesh.bounds().diagonal());
}

TransferFunction MainWindow::transferFunction() const {
  const auto q = activeQuantity();
  if (!session_ || !q) return {};
  try {
    return transferFunctionFor(session_->evaluate(*q, activeStep()));
  } catch (const std::exception&) {
    return {};
  }
}

void MainWindow::setTransferFunction(const TransferFunction& tf) {
  const auto q = activeQuantity();
  if (!session_ || !q) return;
  userTransferFunctions_[q->key()] = tf;
  if (viewport_->volumeShown()) viewport_->setTransferFunction(tf);
}

std::vector<double> MainWindow::activeValues() const {
  const auto q = activeQuantity();
  if (!session_ || !q) return {};
  try {
    return session_->evaluate(*q, activeStep()).values;
  } catch (const std::exception&) {
    return {};
  }
}

double MainWindow::modelSize() const { return session_ ? session_->model().mesh.bounds().diagonal() : 0.0; }

double MainWindow::lastTransferFunctionMs() const { return viewport_->volumeStats().lastTransferFunctionMs; }

void MainWindow::notifyPanels() {
  for (PanelPlugin* panel : plugins_.panelPlugins()) panel->hostChanged();
}

void MainWindow::showModelInfo() {
  const Model& m = session_->model();
  QString html = QString("<b>%1</b><br>%2<br><br>").arg(QFileInfo(QString::fromStdString(m.sourcePath)).fileName().toHtmlEscaped(),
                                                        QString::fromStdString(m.formatName).toHtmlEscaped());
  html += QString("%1 nodes<br>%2 cells:<br>").arg(m.mesh.nodeCount()).arg(m.mesh.cellCount());
  for (const auto& [type, count] : m.mesh.countsByType())
    html += QString("&nbsp;&nbsp;%1 %2<br>").arg(count).arg(QString::fromStdString(std::string(cellTypeName(type))));
  const Bounds b = m.mesh.bounds();
  if (b.valid)
    html += QString("size %1 x %2 x %3<br>").arg(b.size().x, 0, 'g', 4).arg(b.size().y, 0, 'g', 4).arg(b.size().z, 0, 'g', 4);
  html += QString("%1 boundary faces<br><br><b>Fields</b><br>").arg(session_->surface().boundaryFaceCount);
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

void MainWindow::saveImage() {
  const QString path = QFileDialog::getSaveFileName(this, "Save image", "volpost.png", "PNG image (*.png)");
  if (path.isEmpty()) return;
  if (!viewport_->grabFramebuffer().save(path, "PNG"))
    QMessageBox::critical(this, "Save image", "Cannot write " + path);
  else
    statusBar()->showMessage("Saved " + path);
}

}  // namespace volpost::app

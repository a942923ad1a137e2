// SPDX-License-Identifier: MIT
#include "TfEditorPanel.hpp"

#include <volpost/core/ColorMap.hpp>

#include <QAction>
#include <QCheckBox>
#include <QColorDialog>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QFile>
#include <QFileDialog>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QImage>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>
#include <QTimer>
#include <QToolButton>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>

#include <algorithm>
#include <sstream>
#include <cmath>
#include <set>

namespace volpost::tfeditor {
namespace {

constexpr int kIsoResolution = 256;

QSettings settings() { return QSettings("volpost", "volpost"); }

bool readText(const QString& path, QString& text, QString* error) {
  QFile f(path);
  if (!f.open(QIODevice::ReadOnly)) {
    if (error) *error = path + ": " + f.errorString();
    return false;
  }
  text = QString::fromUtf8(f.readAll());
  return true;
}

}  // namespace

TfEditorPanel::TfEditorPanel(PanelHost& host, QWidget* parent) : QWidget(parent), host_(host) {
  setObjectName("tfEditorPanel");
  buildUi();
  sendTimer_ = new QTimer(this);
  sendTimer_->setSingleShot(true);
  sendTimer_->setInterval(0);  // coalesce: a burst of drag events sends the last state once
  connect(sendTimer_, &QTimer::timeout, this, &TfEditorPanel::sendToHost);
  connect(&model_, &TfEditModel::changed, this, [this] {
    if (!hostUpdating_) sendTimer_->start();
    showSelection();
  });
  connect(&model_, &TfEditModel::selectionChanged, this, &TfEditorPanel::showSelection);
  connect(&isoWatcher_, &QFutureWatcherBase::finished, this, [this] {
    if (!isoFuture_.isFinished()) return;  // a newer build replaced the one that finished
    isoTable_ = isoFuture_.result();
    if (isoPending_) {
      const TransferFunction next = *isoPending_;
      isoPending_.reset();
      startIsoTable(next);
    }
    showSelection();
  });
  hostChanged();
}

TfEditorPanel::~TfEditorPanel() { isoFuture_.waitForFinished(); }

void TfEditorPanel::buildUi() {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(4, 4, 4, 4);

  auto* top = new QHBoxLayout;
  presets_ = new QComboBox(this);
  presets_->setObjectName("tfPreset");
  presets_->setMinimumContentsLength(8);
  presets_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
  presets_->setToolTip("Colors of a preset on the current opacity curve");
  presets_->addItem("Colors...", QString());
  for (const std::string& name : ColorMap::names())  // named as the toolbar names them
    presets_->addItem(QString::fromStdString(ColorMap::label(name)), QString::fromStdString(name));
  connect(presets_, &QComboBox::activated, this, [this](int index) {
    const QString name = presets_->itemData(index).toString();
    if (!name.isEmpty()) applyPreset(name);
    presets_->setCurrentIndex(0);
  });
  top->addWidget(presets_, 1);
  shapes_ = new QComboBox(this);
  shapes_->setObjectName("tfOpacityShape");
  shapes_->setMinimumContentsLength(8);
  shapes_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
  shapes_->setToolTip("Reshape the opacity curve, keeping the colors: which values are dense");
  shapes_->addItem("Opacity...", QString());
  shapes_->addItem("Rising: high values dense", "rising");
  shapes_->addItem("Falling: low values dense", "falling");
  shapes_->addItem("Both ends dense (signed results: clear at zero)", "ends");
  shapes_->addItem("Middle dense", "middle");
  connect(shapes_, &QComboBox::activated, this, [this](int index) {
    const QString shape = shapes_->itemData(index).toString();
    if (!shape.isEmpty()) applyOpacityShape(shape);
    shapes_->setCurrentIndex(0);
  });
  top->addWidget(shapes_, 1);
  const auto button = [&](const QString& text, const QString& tip, auto slot) {
    auto* b = new QToolButton(this);
    b->setText(text);
    b->setToolTip(tip);
    connect(b, &QToolButton::clicked, this, slot);
    top->addWidget(b);
    return b;
  };
  button("ParaView...", "Import the colors of a ParaView color map (.json)", [this] {
    const QString path = QFileDialog::getOpenFileName(this, "Import ParaView color map", {}, "ParaView color maps (*.json)");
    QString error;
    if (!path.isEmpty() && !importParaView(path, &error)) QMessageBox::warning(this, "Import", error);
  });
  button("Open...", "Open a volpost transfer function (.json)", [this] {
    const QString path = QFileDialog::getOpenFileName(this, "Open transfer function", {}, "Transfer functions (*.json)");
    QString error;
    if (!path.isEmpty() && !loadFile(path, &error)) QMessageBox::warning(this, "Open", error);
  });
  button("Save...", "Save this transfer function (.json, volpost-tf)", [this] {
    const QString path = QFileDialog::getSaveFileName(this, "Save transfer function", "transfer_function.json", "Transfer functions (*.json)");
    QString error;
    if (!path.isEmpty() && !saveFile(path, &error)) QMessageBox::warning(this, "Save", error);
  });
  QAction* undo = model_.undoStack()->createUndoAction(this, "Undo");
  QAction* redo = model_.undoStack()->createRedoAction(this, "Redo");
  undo->setShortcuts(QKeySequence::Undo);
  redo->setShortcuts({QKeySequence::Redo, QKeySequence(Qt::CTRL | Qt::Key_Y)});
  // The buttons keep their width (the panel, and so the view, must not resize with every
  // edit): the step's name goes to the tooltip.
  const auto keepText = [](QAction* a, const QString& word) {
    return [a, word](const QString& step) {  // runs after the action's own update
      a->setToolTip(step.isEmpty() ? word : word + " " + step);
      a->setText(word);
    };
  };
  connect(model_.undoStack(), &QUndoStack::undoTextChanged, undo, keepText(undo, "Undo"));
  connect(model_.undoStack(), &QUndoStack::redoTextChanged, redo, keepText(redo, "Redo"));
  for (QAction* a : {undo, redo}) {
    a->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    addAction(a);
    auto* b = new QToolButton(this);
    b->setDefaultAction(a);
    top->addWidget(b);
  }
  layout->addLayout(top);

  curve_ = new TfCurveWidget(model_, this);
  layout->addWidget(curve_, 1);

  auto* grid = new QGridLayout;
  valueEdit_ = new QLineEdit(this);
  valueEdit_->setObjectName("tfValue");
  valueEdit_->setToolTip("Exact value of the selected point (Enter applies)");
  opacityEdit_ = new QLineEdit(this);
  opacityEdit_->setObjectName("tfOpacity");
  opacityEdit_->setToolTip("Opacity of a slab of the reference length, 0 to 1 (Enter applies)");
  colorButton_ = new QPushButton("Color", this);
  colorButton_->setObjectName("tfColor");
  for (QLineEdit* e : {valueEdit_, opacityEdit_}) {
    e->setMinimumWidth(60);
    e->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);  // the dock decides the width
    connect(e, &QLineEdit::returnPressed, this, &TfEditorPanel::applyNumericEntry);
  }
  connect(colorButton_, &QPushButton::clicked, this, &TfEditorPanel::chooseColor);
  grid->addWidget(new QLabel("Value", this), 0, 0);
  grid->addWidget(valueEdit_, 0, 1);
  grid->addWidget(new QLabel("Opacity", this), 0, 2);
  grid->addWidget(opacityEdit_, 0, 3);
  grid->addWidget(colorButton_, 0, 4);

  lengthBox_ = new QDoubleSpinBox(this);
  lengthBox_->setObjectName("tfLength");
  lengthBox_->setDecimals(4);
  lengthBox_->setRange(1e-4, 1e12);
  lengthBox_->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
  lengthBox_->setToolTip("The thickness of material, in model units, whose opacity the curve shows; the function itself is an extinction per unit length");
  connect(lengthBox_, &QDoubleSpinBox::valueChanged, this, [this](double v) { model_.setReferenceLength(v); });
  grid->addWidget(new QLabel("Opacity through", this), 1, 0);
  grid->addWidget(lengthBox_, 1, 1);
  grid->addWidget(new QLabel("model units of thickness", this), 1, 2, 1, 2);
  auto* fit = new QPushButton("Fit", this);
  fit->setToolTip("Show the whole data range (or double-click the curve)");
  connect(fit, &QPushButton::clicked, curve_, &TfCurveWidget::resetView);
  grid->addWidget(fit, 1, 4);
  grid->setColumnStretch(1, 1);
  grid->setColumnStretch(3, 1);
  layout->addLayout(grid);

  auto* options = new QHBoxLayout;
  logBox_ = new QCheckBox("Log histogram", this);
  logBox_->setObjectName("tfLogHistogram");
  fineBox_ = new QCheckBox("Stretch small opacities", this);
  fineBox_->setObjectName("tfFineAxis");
  fineBox_->setToolTip(
      "The opacity axis on a cube-root scale: small opacities, the ones most volumes need, get "
      "most of the height");
  logBox_->setChecked(settings().value("tfeditor/logHistogram", true).toBool());
  fineBox_->setChecked(settings().value("tfeditor/fineAxis", true).toBool());
  curve_->setLogHistogram(logBox_->isChecked());
  curve_->setFineOpacityAxis(fineBox_->isChecked());
  connect(logBox_, &QCheckBox::toggled, this, [this](bool on) {
    curve_->setLogHistogram(on);
    saveState();
  });
  connect(fineBox_, &QCheckBox::toggled, this, [this](bool on) {
    curve_->setFineOpacityAxis(on);
    saveState();
  });
  options->addWidget(logBox_);
  options->addWidget(fineBox_);
  options->addStretch(1);
  layout->addLayout(options);

  auto* bottom = new QHBoxLayout;
  status_ = new QLabel(this);
  status_->setObjectName("tfStatus");
  status_->setWordWrap(true);
  bottom->addWidget(status_, 1);
  layout->addLayout(bottom);
  setToolTip("Click: add a point · drag: move (Shift snaps to data values) · right click / Delete: remove · "
             "wheel: zoom · middle or Alt+drag: window/level · arrows, PageUp/PageDown, Ctrl+Z");
}

std::pair<double, double> TfEditorPanel::dataRange() const { return dataRange_; }

void TfEditorPanel::hostChanged() {
  hostUpdating_ = true;
  const SampleView values = host_.activeValues();  // valid during this call only
  const auto q = host_.activeQuantity();
  const std::string key = q ? q->key() : std::string();
  // The range and the histogram only for other values (another model, result or step):
  // a 512^3 cube's took half a second, and the host calls this on every change it shows.
  const Model* model = host_.model();
  std::ostringstream identity;
  identity << (model ? model->sourcePath : std::string()) << '|' << key << '|' << host_.activeStep() << '|'
           << values.data() << '|' << values.size() << '|' << int(values.type());
  const bool newValues = identity.str() != valuesKey_;
  if (newValues) {
    valuesKey_ = identity.str();
    const ValueRange range = rangeOf(values);
    dataRange_ = range.valid() ? std::pair(range.min, range.max > range.min ? range.max : range.min + 1.0)
                               : std::pair(0.0, 1.0);
  }
  if (host_.modelSize() > 0.0) {
    const QSignalBlocker block(lengthBox_);
    if (key != quantityKey_ || lengthBox_->value() <= 1e-9) {
      lengthBox_->setValue(host_.modelSize() / 10.0);
      model_.setReferenceLength(lengthBox_->value());
    }
  }
  bool restored = false;
  if (key != quantityKey_) {
    quantityKey_ = key;
    TransferFunction tf = host_.transferFunction();
    // The function this panel last made for a result of this name, if it still fits.
    const QString saved = settings().value("tfeditor/functions/" + QString::fromStdString(key)).toString();
    if (!key.empty() && !saved.isEmpty()) {
      try {
        const TransferFunction previous = TransferFunction::fromJson(saved.toStdString());
        const auto [lo, hi] = dataRange();
        if (!previous.empty() && previous.maxValue() >= lo && previous.minValue() <= hi) {
          tf = previous;
          restored = true;
        }
      } catch (const std::exception&) {
      }
    }
    model_.load(tf, {}, true);
    knownHostFunction_ = tf;
  } else if (const TransferFunction hostFunction = host_.transferFunction();
             hostFunction != knownHostFunction_ && !sendTimer_->isActive()) {
    // Set by someone else (a state file, the command line's options in the window): what
    // the picture shows is what the panel edits. (An edit of ours still waiting to be sent
    // goes first.)
    model_.load(hostFunction, {}, true);
    knownHostFunction_ = hostFunction;
  }
  if (newValues) curve_->setData(values);
  hostUpdating_ = false;
  if (restored) sendToHost();
  else startIsoTable(model_.toTransferFunction());  // the preview shows the host's function too
  showSelection();
}

void TfEditorPanel::sendToHost() {
  if (quantityKey_.empty()) return;
  const TransferFunction tf = model_.toTransferFunction();
  knownHostFunction_ = tf;  // before: the host may call hostChanged() from inside
  host_.setTransferFunction(tf);
  knownHostFunction_ = host_.transferFunction();
  startIsoTable(tf);
  saveState();
}

void TfEditorPanel::flush() {
  if (sendTimer_->isActive()) {
    sendTimer_->stop();
    sendToHost();
  }
}

void TfEditorPanel::startIsoTable(const TransferFunction& tf) {
  if (isoFuture_.isValid() && !isoFuture_.isFinished()) {
    isoPending_ = tf;  // only the latest waits; intermediate drag states are skipped
    return;
  }
  auto [lo, hi] = dataRange();
  if (!tf.empty()) lo = std::min(lo, tf.minValue()), hi = std::max(hi, tf.maxValue());
  isoFuture_ = QtConcurrent::run([this, tf, lo = lo, hi = hi] {
    QElapsedTimer timer;
    timer.start();
    auto table = std::make_shared<optics::IsoDetectionTable>(tf, lo, hi, kIsoResolution);
    isoMs_ = double(timer.nsecsElapsed()) * 1e-6;
    return table;
  });
  isoWatcher_.setFuture(isoFuture_);
}

const optics::IsoDetectionTable* TfEditorPanel::isoTable() {
  flush();
  for (;;) {
    if (isoFuture_.isValid()) isoTable_ = isoFuture_.result();  // waits for a build in progress
    if (!isoPending_) break;
    const TransferFunction next = *isoPending_;
    isoPending_.reset();
    startIsoTable(next);
  }
  return isoTable_.get();
}

void TfEditorPanel::showSelection() {
  const auto& sel = model_.selection();
  const int index = sel.empty() ? -1 : model_.indexOf(*sel.begin());
  const bool one = index >= 0;
  for (QWidget* w : {static_cast<QWidget*>(valueEdit_), static_cast<QWidget*>(opacityEdit_), static_cast<QWidget*>(colorButton_)})
    w->setEnabled(one);
  if (one) {
    const EditPoint& p = model_.points()[std::size_t(index)];
    if (!valueEdit_->hasFocus()) valueEdit_->setText(QString::number(p.value, 'g', 10));
    if (!opacityEdit_->hasFocus()) opacityEdit_->setText(QString::number(p.opacity, 'g', 6));
    colorButton_->setStyleSheet(QString("background-color: %1").arg(p.color.name()));
  } else {
    valueEdit_->clear();
    opacityEdit_->clear();
    colorButton_->setStyleSheet({});
  }
  if (host_.transferFunction2D()) {  // edits here change nothing in the picture until it is switched off
    status_->setText("<span style='color:#a60'>The volume is drawn with the 2D function (the Value x gradient "
                     "tab); this one applies again when it is switched off there.</span>");
    return;
  }
  status_->setText(QString("%1 points, %2 selected").arg(model_.points().size()).arg(sel.size()));
  status_->setToolTip(QString("The last change took %1 ms to prepare and %2 ms for the renderer to take up")
                          .arg(isoMs_, 0, 'f', 1)
                          .arg(host_.lastTransferFunctionMs(), 0, 'f', 1));
}

void TfEditorPanel::applyNumericEntry() {
  const auto& sel = model_.selection();
  const int index = sel.empty() ? -1 : model_.indexOf(*sel.begin());
  if (index < 0) return;
  bool okValue = false, okOpacity = false;
  const double value = QLocale::c().toDouble(valueEdit_->text().trimmed(), &okValue);
  const double opacity = QLocale::c().toDouble(opacityEdit_->text().trimmed(), &okOpacity);
  if (!okValue || !std::isfinite(value)) {
    status_->setText(QString("<span style='color:#c00'>value '%1' is not a number</span>").arg(valueEdit_->text().toHtmlEscaped()));
    return;
  }
  if (!okOpacity || !(opacity >= 0.0 && opacity < 1.0)) {
    status_->setText(QString("<span style='color:#c00'>opacity '%1' is not in [0, 1)</span>").arg(opacityEdit_->text().toHtmlEscaped()));
    return;
  }
  EditPoint p = model_.points()[std::size_t(index)];
  p.value = value;
  p.opacity = opacity;
  model_.movePoints({p}, "Edit point", 0);
}

void TfEditorPanel::chooseColor() {
  const auto& sel = model_.selection();
  const int index = sel.empty() ? -1 : model_.indexOf(*sel.begin());
  if (index < 0) return;
  const QColor c = QColorDialog::getColor(model_.points()[std::size_t(index)].color, this, "Point color");
  if (!c.isValid()) return;
  for (int id : std::set<int>(sel)) model_.setColor(id, c);
}

void TfEditorPanel::applyPreset(const QString& name) {
  const ColorMap map = ColorMap::named(name.toStdString());
  auto points = model_.points();
  if (points.size() < 2) {
    const auto [lo, hi] = dataRange();
    model_.load(TransferFunction::ramp(lo, hi, name.toStdString(), 24.0 / std::max(host_.modelSize(), 1e-300)),
                "Preset " + name, false);
    return;
  }
  const double lo = points.front().value, hi = points.back().value;
  for (auto& p : points) {
    const glm::dvec3 c = map.at(hi > lo ? (p.value - lo) / (hi - lo) : 0.5);
    p.color = QColor::fromRgbF(float(c.r), float(c.g), float(c.b));
  }
  model_.replaceAll(points, "Preset " + name);
  settings().setValue("tfeditor/preset", name);
}

void TfEditorPanel::applyOpacityShape(const QString& shape) {
  auto points = model_.points();
  if (points.size() < 2) return;
  const double lo = points.front().value, hi = points.back().value;
  if (!(hi > lo)) return;
  double peak = 0.0;
  for (const auto& p : points) peak = std::max(peak, p.opacity);
  if (!(peak > 0.0)) peak = 0.5;
  const bool signedRange = lo < 0.0 && hi > 0.0;
  for (auto& p : points) {
    const double t = (p.value - lo) / (hi - lo);
    double weight = t;
    if (shape == "falling") weight = 1.0 - t;
    else if (shape == "ends") weight = signedRange ? std::abs(p.value) / std::max(-lo, hi) : std::abs(2.0 * t - 1.0);
    else if (shape == "middle") weight = 1.0 - std::abs(2.0 * t - 1.0);
    p.opacity = std::clamp(peak * (0.1 + 0.9 * weight), 0.0, 1.0);
  }
  model_.replaceAll(points, "Opacity " + shape);
}

bool TfEditorPanel::loadFile(const QString& path, QString* error) {
  QString text;
  if (!readText(path, text, error)) return false;
  try {
    model_.load(TransferFunction::fromJson(text.toStdString()), "Open " + QFileInfo(path).fileName(), false);
    curve_->resetView();
    return true;
  } catch (const std::exception& e) {
    if (error) *error = path + ": " + e.what();
    return false;
  }
}

bool TfEditorPanel::saveFile(const QString& path, QString* error) const {
  QFile f(path);
  if (!f.open(QIODevice::WriteOnly | QIODevice::Truncate)) {
    if (error) *error = path + ": " + f.errorString();
    return false;
  }
  f.write(QByteArray::fromStdString(model_.toTransferFunction().toJson()));
  return true;
}

bool TfEditorPanel::importParaView(const QString& path, QString* error) {
  QString text;
  if (!readText(path, text, error)) return false;
  try {
    model_.load(model_.toTransferFunction().withParaViewColors(text.toStdString(), "", dataRange()),
                "Import " + QFileInfo(path).fileName(), false);
    return true;
  } catch (const std::exception& e) {
    if (error) *error = path + ": " + e.what();
    return false;
  }
}

void TfEditorPanel::saveState() const {
  QSettings s = settings();
  s.setValue("tfeditor/logHistogram", logBox_->isChecked());
  s.setValue("tfeditor/fineAxis", fineBox_->isChecked());
  if (!quantityKey_.empty() && !model_.points().empty())
    s.setValue("tfeditor/functions/" + QString::fromStdString(quantityKey_), QString::fromStdString(model_.toTransferFunction().toJson()));
}

}  // namespace volpost::tfeditor

// SPDX-License-Identifier: MIT
#include "Tf2dEditorPanel.hpp"

#include <QCheckBox>
#include <QColorDialog>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QSignalBlocker>
#include <QTimer>
#include <QVBoxLayout>

#include <cmath>

namespace volpost::tfeditor {

Tf2dEditorPanel::Tf2dEditorPanel(PanelHost& host, QWidget* parent) : QWidget(parent), host_(host) {
  buildUi();
  hostChanged();
}

void Tf2dEditorPanel::buildUi() {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(4, 4, 4, 4);
  use_ = new QCheckBox("Draw the volume with this 2D function", this);
  use_->setObjectName("tf2dUse");
  use_->setToolTip("Color and opacity over the value (across) and its gradient magnitude (up) instead of the value "
                   "alone: boundaries apart from the insides of the same value");
  connect(use_, &QCheckBox::toggled, this, [this] {
    if (!updating_) sendToHost();
  });
  layout->addWidget(use_);

  canvas_ = new Tf2dCanvas(this);
  canvas_->setObjectName("tf2dCanvas");
  layout->addWidget(canvas_, 1);
  connect(canvas_, &Tf2dCanvas::widgetsChanged, this, [this] {
    showSelection();
    if (inUse()) sendTimer_->start();
  });
  connect(canvas_, &Tf2dCanvas::selectionChanged, this, [this] { showSelection(); });

  auto* buttons = new QHBoxLayout;
  const auto button = [&](const QString& text, const char* name, auto&& action) {
    auto* b = new QPushButton(text, this);
    b->setObjectName(name);
    connect(b, &QPushButton::clicked, this, action);
    buttons->addWidget(b);
    return b;
  };
  const auto middle = [this] { return 0.5 * (canvas_->valueLow() + canvas_->valueHigh()); };
  button("Rectangle", "tf2dAddRectangle",
         [this, middle] { canvas_->addWidget(TfWidget2D::Shape::Rectangle, middle(), canvas_->gradientHigh() / 6.0); });
  button("Triangle", "tf2dAddTriangle",
         [this, middle] { canvas_->addWidget(TfWidget2D::Shape::Triangle, middle(), canvas_->gradientHigh() / 3.0); });
  button("Delete", "tf2dDelete", [this] { canvas_->removeSelected(); });
  layout->addLayout(buttons);

  auto* selection = new QHBoxLayout;
  shape_ = new QComboBox(this);
  shape_->setObjectName("tf2dShape");
  shape_->addItems({"Rectangle", "Triangle"});
  connect(shape_, &QComboBox::activated, this, [this] { editSelection(); });
  selection->addWidget(shape_);
  selection->addWidget(new QLabel("Opacity", this));
  opacity_ = new QDoubleSpinBox(this);
  opacity_->setObjectName("tf2dOpacity");
  opacity_->setRange(0.0, 0.999);
  opacity_->setDecimals(3);
  opacity_->setSingleStep(0.05);
  opacity_->setToolTip("The selected widget's opacity over a tenth of the model's size");
  connect(opacity_, &QDoubleSpinBox::valueChanged, this, [this] { editSelection(); });
  selection->addWidget(opacity_);
  color_ = new QPushButton("Color...", this);
  color_->setObjectName("tf2dColor");
  connect(color_, &QPushButton::clicked, this, &Tf2dEditorPanel::chooseColor);
  selection->addWidget(color_);
  layout->addLayout(selection);

  auto* files = new QHBoxLayout;
  auto* load = new QPushButton("Load...", this);
  connect(load, &QPushButton::clicked, this, [this] {
    const QString path = QFileDialog::getOpenFileName(this, "Load a 2D transfer function", QString(), "volpost 2D TF (*.json)");
    QString error;
    if (!path.isEmpty() && !loadFile(path, &error)) QMessageBox::warning(this, "2D transfer function", error);
  });
  auto* save = new QPushButton("Save...", this);
  connect(save, &QPushButton::clicked, this, [this] {
    const QString path = QFileDialog::getSaveFileName(this, "Save the 2D transfer function", QString(), "volpost 2D TF (*.json)");
    QString error;
    if (!path.isEmpty() && !saveFile(path, &error)) QMessageBox::warning(this, "2D transfer function", error);
  });
  files->addWidget(load);
  files->addWidget(save);
  layout->addLayout(files);
  status_ = new QLabel(this);
  status_->setObjectName("tf2dStatus");
  status_->setWordWrap(true);
  layout->addWidget(status_);

  sendTimer_ = new QTimer(this);
  sendTimer_->setSingleShot(true);
  sendTimer_->setInterval(30);
  connect(sendTimer_, &QTimer::timeout, this, &Tf2dEditorPanel::sendToHost);
  showSelection();
}

bool Tf2dEditorPanel::inUse() const { return use_->isChecked(); }

void Tf2dEditorPanel::setInUse(bool on) { use_->setChecked(on); }

double Tf2dEditorPanel::opacityOf(double extinction) const {
  return extinctionToOpacity(extinction, std::max(host_.modelSize() / 10.0, 1e-300));
}

double Tf2dEditorPanel::extinctionOf(double opacity) const {
  return opacityToExtinction(std::clamp(opacity, 0.0, 0.999), std::max(host_.modelSize() / 10.0, 1e-300));
}

void Tf2dEditorPanel::hostChanged() {
  const Model* model = host_.model();
  const auto quantity = host_.activeQuantity();
  const bool grid = model && model->grid && quantity;
  setEnabled(grid);
  status_->setText(grid ? QString() : "For regular grids (SEG-Y, image data) with a result shown.");
  if (!grid) {  // no cube's histogram stays behind another model
    if (!histogramKey_.empty()) canvas_->setHistogram(JointHistogram{});
    histogramKey_.clear();
    return;
  }
  const std::string key = model->sourcePath + "|" + quantity->key() + "|" + std::to_string(host_.activeStep());
  if (key != histogramKey_) {  // the values are copied only for a new result or step
    histogramKey_ = key;
    canvas_->setHistogram(JointHistogram::ofGrid(*model->grid, host_.activeValues()));
  }
  canvas_->setDefaultExtinction(extinctionOf(0.5));
  const QSignalBlocker block(use_);
  updating_ = true;
  if (const auto tf = host_.transferFunction2D()) {
    canvas_->setWidgets(tf->widgets());
    use_->setChecked(true);
  } else {
    use_->setChecked(false);
  }
  updating_ = false;
  showSelection();
}

void Tf2dEditorPanel::showSelection() {
  const int s = canvas_->selected();
  for (QWidget* w : std::initializer_list<QWidget*>{shape_, opacity_, color_}) w->setEnabled(s >= 0);
  if (s < 0) return;
  const TfWidget2D& w = canvas_->widgets()[std::size_t(s)];
  const QSignalBlocker a(shape_), b(opacity_);
  shape_->setCurrentIndex(w.shape == TfWidget2D::Shape::Triangle ? 1 : 0);
  opacity_->setValue(opacityOf(w.extinction));
  const QColor c = QColor::fromRgbF(float(w.color.r), float(w.color.g), float(w.color.b));
  color_->setStyleSheet(QString("background-color: %1").arg(c.name()));
}

void Tf2dEditorPanel::editSelection() {
  const int s = canvas_->selected();
  if (s < 0) return;
  TfWidget2D w = canvas_->widgets()[std::size_t(s)];
  w.shape = shape_->currentIndex() == 1 ? TfWidget2D::Shape::Triangle : TfWidget2D::Shape::Rectangle;
  w.extinction = extinctionOf(opacity_->value());
  canvas_->updateSelected(w);
}

void Tf2dEditorPanel::chooseColor() {
  const int s = canvas_->selected();
  if (s < 0) return;
  TfWidget2D w = canvas_->widgets()[std::size_t(s)];
  const QColor c = QColorDialog::getColor(QColor::fromRgbF(float(w.color.r), float(w.color.g), float(w.color.b)), this);
  if (!c.isValid()) return;
  w.color = {c.redF(), c.greenF(), c.blueF()};
  canvas_->updateSelected(w);
}

void Tf2dEditorPanel::flush() {
  if (sendTimer_->isActive()) {
    sendTimer_->stop();
    sendToHost();
  }
}

void Tf2dEditorPanel::sendToHost() {
  try {
    if (!host_.setTransferFunction2D(inUse() ? std::optional(TransferFunction2D(canvas_->widgets())) : std::nullopt)) {
      const QSignalBlocker block(use_);
      use_->setChecked(false);
      return;
    }
    status_->setText(inUse() ? QString("%1 widgets").arg(canvas_->widgets().size()) : QString());
  } catch (const std::exception& e) {
    status_->setText(QString::fromStdString(e.what()));
  }
}

bool Tf2dEditorPanel::loadFile(const QString& path, QString* error) {
  QFile file(path);
  if (!file.open(QIODevice::ReadOnly)) {
    if (error) *error = path + ": " + file.errorString();
    return false;
  }
  try {
    const TransferFunction2D tf = TransferFunction2D::fromJson(file.read(16 << 20).toStdString());
    canvas_->setWidgets(tf.widgets());
    canvas_->select(-1);
    sendTimer_->start();
    return true;
  } catch (const std::exception& e) {
    if (error) *error = path + ": " + e.what();
    return false;
  }
}

bool Tf2dEditorPanel::saveFile(const QString& path, QString* error) const {
  QFile file(path);
  if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate) ||
      file.write(QByteArray::fromStdString(TransferFunction2D(canvas_->widgets()).toJson())) < 0) {
    if (error) *error = path + ": " + file.errorString();
    return false;
  }
  return true;
}

}  // namespace volpost::tfeditor

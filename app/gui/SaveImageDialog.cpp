// SPDX-License-Identifier: MIT
#include "SaveImageDialog.hpp"

#include "../core/PictureFile.hpp"
#include "../core/SceneImage.hpp"
#include "../core/SceneState.hpp"

#include <QCheckBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>

namespace volpost::app {

namespace {
constexpr int kMaxPicturePixels = 16384;  // as `volpost render --size`
}

SaveImageDialog::SaveImageDialog(const PictureRequest& request, QWidget* parent) : QDialog(parent) {
  setWindowTitle("Save image");
  auto* form = new QFormLayout(this);
  path_ = new QLineEdit(request.path, this);
  path_->setObjectName("imagePath");
  auto* browse = new QPushButton("Browse...", this);
  connect(browse, &QPushButton::clicked, this, [this] {
    const QString chosen = QFileDialog::getSaveFileName(this, "Save image", path_->text(),
                                                        "PNG image (*.png);;JPEG image (*.jpg);;TIFF image (*.tif);;"
                                                        "WebP image (*.webp)");
    if (!chosen.isEmpty()) path_->setText(chosen);
  });
  auto* pathRow = new QHBoxLayout;
  pathRow->addWidget(path_, 1);
  pathRow->addWidget(browse);
  form->addRow("File:", pathRow);
  const auto pixels = [this](int value, const char* name) {
    auto* box = new QSpinBox(this);
    box->setObjectName(name);
    box->setRange(1, kMaxPicturePixels);
    box->setSuffix(" px");
    box->setValue(value);
    return box;
  };
  width_ = pixels(request.width, "imageWidth");
  height_ = pixels(request.height, "imageHeight");
  auto* sizeRow = new QHBoxLayout;
  sizeRow->addWidget(width_);
  sizeRow->addWidget(new QLabel("x", this));
  sizeRow->addWidget(height_);
  auto* twice = new QPushButton("x2", this);
  twice->setToolTip("Twice the width and height (a sharper picture for print)");
  connect(twice, &QPushButton::clicked, this, [this] {
    width_->setValue(width_->value() * 2);
    height_->setValue(height_->value() * 2);
  });
  sizeRow->addWidget(twice);
  form->addRow("Size:", sizeRow);
  textScale_ = new QDoubleSpinBox(this);
  textScale_->setObjectName("imageTextScale");
  textScale_->setRange(kMinTextScale, kMaxTextScale);
  textScale_->setSingleStep(0.25);
  textScale_->setValue(request.textScale);
  textScale_->setToolTip("The legend's, title's and labels' words, times their size in proportion to the picture");
  form->addRow("Text size:", textScale_);
  transparent_ = new QCheckBox("Transparent background (.png, .tif, .webp)", this);
  transparent_->setObjectName("imageTransparent");
  transparent_->setChecked(request.transparent);
  form->addRow(transparent_);
  problem_ = new QLabel(this);
  problem_->setObjectName("imageProblem");
  problem_->setStyleSheet("color: #b00020");
  form->addRow(problem_);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Save | QDialogButtonBox::Cancel, this);
  connect(buttons, &QDialogButtonBox::accepted, this, &SaveImageDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  form->addRow(buttons);
}

PictureRequest SaveImageDialog::request() const {
  return {path_->text().trimmed(), width_->value(), height_->value(), textScale_->value(), transparent_->isChecked()};
}

QString SaveImageDialog::problemWith(const PictureRequest& r) {
  if (r.path.isEmpty()) return "Choose a file to save the picture to.";
  try {
    pictureFormatOf(r.path);
  } catch (const std::invalid_argument& e) {
    return QString::fromStdString(e.what());
  }
  if (r.transparent && !formatKeepsTransparency(r.path))
    return "A transparent background needs a .png, .tif or .webp file: " + r.path + " keeps none.";
  return {};
}

void SaveImageDialog::accept() {
  const QString problem = problemWith(request());
  problem_->setText(problem);
  if (problem.isEmpty()) QDialog::accept();
}

}  // namespace volpost::app

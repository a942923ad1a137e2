// SPDX-License-Identifier: MIT
#include "GridSlicesPanel.hpp"

#include "../core/Scene.hpp"

#include <QCheckBox>
#include <QGridLayout>
#include <QLabel>
#include <QSlider>

#include <cmath>

namespace volpost::app {

GridSlicesPanel::GridSlicesPanel(Scene& scene, std::function<void()> changed, QWidget* parent)
    : QWidget(parent), scene_(scene), changed_(std::move(changed)) {
  auto* grid = new QGridLayout(this);
  for (int a = 0; a < 3; ++a) {
    shown_[std::size_t(a)] = new QCheckBox(this);
    shown_[std::size_t(a)]->setObjectName(QString("gridSliceShown%1").arg(a));
    sliders_[std::size_t(a)] = new QSlider(Qt::Horizontal, this);
    sliders_[std::size_t(a)]->setObjectName(QString("gridSlice%1").arg(a));
    sliders_[std::size_t(a)]->setMinimumWidth(240);
    labels_[std::size_t(a)] = new QLabel(this);
    labels_[std::size_t(a)]->setMinimumWidth(70);
    grid->addWidget(shown_[std::size_t(a)], a, 0);
    grid->addWidget(sliders_[std::size_t(a)], a, 1);
    grid->addWidget(labels_[std::size_t(a)], a, 2);
    connect(shown_[std::size_t(a)], &QCheckBox::toggled, this, [this] { apply(); });
    connect(sliders_[std::size_t(a)], &QSlider::valueChanged, this, [this] { apply(); });
  }
  surface_ = new QCheckBox("Show the model's surface (it hides the slices inside)", this);
  surface_->setObjectName("gridSlicesSurface");
  grid->addWidget(surface_, 3, 0, 1, 3);
  connect(surface_, &QCheckBox::toggled, this, [this](bool on) {
    if (following_) return;
    scene_.setSurfaceShown(on);
    changed_();
  });
  followScene();
}

void GridSlicesPanel::followScene() {
  following_ = true;
  const auto session = scene_.session();
  const bool hasGrid = session && session->model().grid;
  for (int a = 0; a < 3; ++a) {
    QCheckBox* box = shown_[std::size_t(a)];
    QSlider* slider = sliders_[std::size_t(a)];
    box->setEnabled(hasGrid);
    slider->setEnabled(hasGrid);
    if (!hasGrid) {
      box->setText(QString("axis %1").arg(a + 1));
      box->setChecked(false);
      labels_[std::size_t(a)]->clear();
      continue;
    }
    const RegularGrid& g = *session->model().grid;
    box->setText(QString::fromStdString(g.axisNames[std::size_t(a)]));
    slider->setRange(0, int(g.dims[std::size_t(a)]) - 1);
    slider->setPageStep(std::max(1, int(g.dims[std::size_t(a)]) / 10));
    const auto& label = scene_.state().gridSlices[std::size_t(a)];
    box->setChecked(label.has_value());
    const double index = label ? (*label - g.firstLabel[std::size_t(a)]) / g.labelStep[std::size_t(a)]
                               : double(g.dims[std::size_t(a)] - 1) / 2.0;
    slider->setValue(int(std::lround(index)));
    labels_[std::size_t(a)]->setText(QString::number(g.label(a, double(slider->value())), 'g', 8));
  }
  surface_->setChecked(scene_.state().surfaceShown);
  following_ = false;
}

void GridSlicesPanel::apply() {
  if (following_) return;
  const auto session = scene_.session();
  if (!session || !session->model().grid) return;
  const RegularGrid& g = *session->model().grid;
  std::array<std::optional<double>, 3> labels;
  for (int a = 0; a < 3; ++a) {
    const double label = g.label(a, double(sliders_[std::size_t(a)]->value()));
    labels_[std::size_t(a)]->setText(QString::number(label, 'g', 8));
    if (shown_[std::size_t(a)]->isChecked()) labels[std::size_t(a)] = label;
  }
  scene_.setGridSlices(labels);
  changed_();
}

}  // namespace volpost::app

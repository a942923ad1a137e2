// SPDX-License-Identifier: MIT
#include "DeformationActions.hpp"

#include "../core/Scene.hpp"

#include <QAction>
#include <QInputDialog>
#include <QLineEdit>
#include <QMainWindow>
#include <QMenu>
#include <QSignalBlocker>
#include <QStatusBar>

#include <cmath>

namespace volpost::app {

DeformationActions::DeformationActions(QMainWindow& window, Scene& scene, QMenu& menu, ChangeScene changeScene,
                                       std::function<void()> changed)
    : QObject(&window),
      window_(window),
      scene_(scene),
      changeScene_(std::move(changeScene)),
      changed_(std::move(changed)) {
  shown_ = menu.addAction("&Deformed Shape");
  shown_->setObjectName("deformAction");
  shown_->setCheckable(true);
  shown_->setShortcut(QKeySequence(Qt::Key_D));
  connect(shown_, &QAction::toggled, this, [this](bool on) { show(on, scene_.deformation().scale); });
  outline_ = menu.addAction("&Undeformed Outline");
  outline_->setObjectName("undeformedAction");
  outline_->setCheckable(true);
  outline_->setToolTip("With the deformed shape: the undeformed model's element edges in gray");
  connect(outline_, &QAction::toggled, this, [this](bool on) {
    DeformationLayer d = scene_.deformation();
    d.undeformedOutline = on;
    changeScene_([&](Scene& s) { s.setDeformation(d); });
    syncToScene();
  });
  menu.addAction("Deformation &Scale...", this, &DeformationActions::typeScale)->setObjectName("deformScaleAction");
}

void DeformationActions::syncToScene() {
  const DeformationLayer& d = scene_.deformation();
  const QSignalBlocker a(shown_), b(outline_);
  shown_->setChecked(d.shown);
  outline_->setChecked(d.undeformedOutline);
}

void DeformationActions::typeScale() {
  bool ok = false;
  const auto current = scene_.deformation().scale;
  const QString text =
      QInputDialog::getText(&window_, "Deformation scale",
                            "Displacement x this factor (empty: automatic, the largest displacement "
                            "10 % of the model's size):",
                            QLineEdit::Normal, current ? QString::number(*current, 'g', 10) : QString(), &ok);
  if (!ok) return;
  std::optional<double> scale;
  if (!text.trimmed().isEmpty()) {
    bool number = false;
    scale = text.trimmed().toDouble(&number);
    if (!number || !std::isfinite(*scale)) {
      window_.statusBar()->showMessage(QString("'%1' is not a scale factor").arg(text));
      return;
    }
  }
  show(true, scale);
}

void DeformationActions::show(bool on, std::optional<double> scale) {
  const ModelSession* model = scene_.baseSession();
  if (!model) {
    syncToScene();
    return;
  }
  DeformationLayer d = scene_.deformation();
  if (on && !model->model().findField(d.field)) {
    const auto field = chooseDisplacementField();
    if (!field) {
      syncToScene();
      return;
    }
    d.field = *field;
  }
  d.shown = on;
  d.scale = scale;
  const bool ok = changeScene_([&](Scene& s) { s.setDeformation(d); });
  syncToScene();
  if (ok && on)
    window_.statusBar()->showMessage(QString("Deformed: %1 x %2%3; probing uses the deformed coordinates")
                                         .arg(QString::fromStdString(d.field))
                                         .arg(scene_.deformationScale(), 0, 'g', 4)
                                         .arg(scale ? "" : " (automatic: largest displacement = 10 % of the model)"));
  changed_();
}

// The field to deform by: one named as a displacement (U, DISP, displacement ...) when the
// model has it; otherwise the user picks among the nodal vectors (a velocity is no
// displacement, and was taken without asking). nullopt: none, or cancelled (said why).
std::optional<std::string> DeformationActions::chooseDisplacementField() {
  QStringList vectors;
  for (const auto& f : scene_.baseSession()->model().fields)
    if (f->location() == FieldLocation::Node && f->components() == 3) {
      const QString name = QString::fromStdString(f->name());
      const QString lower = name.toLower();
      if (lower == "u" || lower == "disp" || lower.startsWith("displacement")) return f->name();
      vectors << name;
    }
  if (vectors.isEmpty()) {
    window_.statusBar()->showMessage("This model has no nodal vector field to deform it by");
    return std::nullopt;
  }
  bool ok = false;
  const QString chosen = QInputDialog::getItem(&window_, "Deformed shape",
                                               "No field is named as a displacement (U, DISP, displacement).\n"
                                               "Deform the model by:",
                                               vectors, 0, false, &ok);
  if (!ok) return std::nullopt;
  return chosen.toStdString();
}

}  // namespace volpost::app

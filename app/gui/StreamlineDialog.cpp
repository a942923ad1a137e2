// SPDX-License-Identifier: MIT
#include "StreamlineDialog.hpp"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QPlainTextEdit>

#include <cmath>

namespace volpost::app {

StreamlineDialog::StreamlineDialog(const ModelSession& session, const StreamlineLayer& layer, QWidget* parent)
    : QDialog(parent), original_(layer) {
  setWindowTitle("Streamlines");
  auto* form = new QFormLayout(this);
  field_ = new QComboBox(this);
  field_->setObjectName("streamlineField");
  for (const auto& f : session.model().fields)
    if (f->components() == 3)
      field_->addItem(QString("%1%2").arg(QString::fromStdString(f->name()), f->location() == FieldLocation::Cell ? " (per element)" : ""),
                      QString::fromStdString(f->name()));
  const int current = field_->findData(QString::fromStdString(layer.field));
  if (current >= 0) field_->setCurrentIndex(current);
  form->addRow("Vector field:", field_);
  seeds_ = new QPlainTextEdit(this);
  seeds_->setObjectName("streamlineSeeds");
  QStringList specs;
  for (const auto& s : layer.seeds) specs << QString::fromStdString(s);
  if (specs.isEmpty()) {  // a first rake across the model's middle
    const Bounds b = session.model().bounds();
    const glm::dvec3 c = b.center(), half = 0.4 * b.size();
    specs << QString("line:%1,%2,%3:%4,%5,%6:20")
                 .arg(c.x - half.x, 0, 'g', 6).arg(c.y - half.y, 0, 'g', 6).arg(c.z, 0, 'g', 6)
                 .arg(c.x - half.x, 0, 'g', 6).arg(c.y + half.y, 0, 'g', 6).arg(c.z, 0, 'g', 6);
  }
  seeds_->setPlainText(specs.join('\n'));
  seeds_->setToolTip("One per line: point:X,Y,Z | line:X0,Y0,Z0:X1,Y1,Z1:N | disk:CX,CY,CZ:NX,NY,NZ:R:N | "
                     "box:XMIN,XMAX,YMIN,YMAX,ZMIN,ZMAX:N | boundary:CX,CY,CZ:R:N. View > Streamlines > Place Rake "
                     "draws one with the mouse.");
  form->addRow("Seeds:", seeds_);
  integrator_ = new QComboBox(this);
  integrator_->addItem("Adaptive Runge-Kutta 2 (error-controlled)", int(StreamlineMethod::RK2));
  integrator_->addItem("Runge-Kutta 4 (step doubling)", int(StreamlineMethod::RK4));
  integrator_->addItem("Dormand-Prince 5(4)", int(StreamlineMethod::RK45));
  integrator_->setCurrentIndex(integrator_->findData(int(layer.settings.method)));
  form->addRow("Integration:", integrator_);
  direction_ = new QComboBox(this);
  direction_->addItem("Both ways from the seeds", int(StreamlineDirection::Both));
  direction_->addItem("Downstream", int(StreamlineDirection::Forward));
  direction_->addItem("Upstream", int(StreamlineDirection::Backward));
  direction_->setCurrentIndex(direction_->findData(int(layer.settings.direction)));
  form->addRow("Direction:", direction_);
  // The accuracy as a user reads it: the error a step may make, a fraction of the model.
  tolerance_ = new QComboBox(this);
  tolerance_->setObjectName("streamlineTolerance");
  for (int e = 2; e <= 10; ++e)
    tolerance_->addItem(QString("1e-%1 of the model's size%2").arg(e).arg(e == 5 ? " (default)" : ""),
                        std::pow(10.0, -e));
  if (tolerance_->findData(layer.settings.tolerance) < 0)
    tolerance_->addItem(QString("%1 of the model's size").arg(layer.settings.tolerance, 0, 'g', 3),
                        layer.settings.tolerance);
  tolerance_->setCurrentIndex(tolerance_->findData(layer.settings.tolerance));
  tolerance_->setToolTip(
      "The largest error a step may make in the line's position, as a fraction of the model's "
      "size: smaller is more accurate and slower");
  form->addRow("Accuracy per step:", tolerance_);
  colorBy_ = new QComboBox(this);
  colorBy_->addItem("Speed", QString());
  for (const Quantity& q : session.quantities()) colorBy_->addItem(QString::fromStdString(q.displayName()), QString::fromStdString(q.key()));
  colorBy_->setCurrentIndex(std::max(0, colorBy_->findData(QString::fromStdString(layer.colorBy))));
  form->addRow("Color by:", colorBy_);
  width_ = new QDoubleSpinBox(this);
  width_->setRange(1.0, 16.0);
  width_->setValue(layer.style.width);
  width_->setSuffix(" px");
  form->addRow("Line width:", width_);
  tubes_ = new QCheckBox("Shaded tubes instead of lit lines", this);
  tubes_->setChecked(layer.style.tubes);
  form->addRow(tubes_);
  arrows_ = new QCheckBox("Arrows along the lines, pointing downstream", this);
  arrows_->setChecked(layer.style.arrows);
  form->addRow(arrows_);
  average_ = new QCheckBox("Average a per-element field at the nodes (an approximation)", this);
  average_->setChecked(layer.averageCellVectors);
  form->addRow(average_);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
  connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  form->addRow(buttons);
}

StreamlineLayer StreamlineDialog::layer() const {
  StreamlineLayer l = original_;
  l.shown = true;
  l.field = field_->currentData().toString().toStdString();
  l.seeds.clear();
  for (const QString& line : seeds_->toPlainText().split('\n', Qt::SkipEmptyParts))
    if (!line.trimmed().isEmpty()) l.seeds.push_back(line.trimmed().toStdString());
  l.settings.method = StreamlineMethod(integrator_->currentData().toInt());
  l.settings.direction = StreamlineDirection(direction_->currentData().toInt());
  l.settings.tolerance = tolerance_->currentData().toDouble();
  l.colorBy = colorBy_->currentData().toString().toStdString();
  l.style.width = float(width_->value());
  l.style.tubes = tubes_->isChecked();
  l.style.arrows = arrows_->isChecked();
  l.averageCellVectors = average_->isChecked();
  return l;
}

}  // namespace volpost::app

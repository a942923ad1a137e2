// SPDX-License-Identifier: MIT
#include "IsoSurfaceDialog.hpp"

#include "../core/VolumeSpecs.hpp"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>

#include <algorithm>

namespace volpost::app {

IsoSurfaceDialog::IsoSurfaceDialog(const ModelSession& session, const VolumeLayer& volume, const ScalarView* shown,
                                   QWidget* parent)
    : QDialog(parent) {
  setWindowTitle("Iso-surfaces");
  auto* form = new QFormLayout(this);
  quantity_ = new QComboBox(this);
  quantity_->setObjectName("isoQuantity");
  quantity_->addItem("The shown result", QString());
  for (const Quantity& q : session.quantities())
    if (session.fieldOf(q).location() == FieldLocation::Node)  // contours need values at the nodes
      quantity_->addItem(QString::fromStdString(q.displayName()), QString::fromStdString(q.key()));
  quantity_->setCurrentIndex(std::max(0, quantity_->findData(QString::fromStdString(volume.isoQuantity))));
  form->addRow("Of:", quantity_);
  values_ = new QLineEdit(this);
  values_->setObjectName("isoValues");
  values_->setMinimumWidth(360);
  values_->setToolTip(QString("VALUE[:r,g,b[:opacity]] separated by ';' (colors and opacity 0..1, up to %1; empty: "
                              "none)")
                          .arg(kMaxIsoSurfaces));
  QString text = isoSurfacesText(volume.isoSurfaces);
  if (text.isEmpty() && shown && shown->range.valid())
    text = QString("%1:1,0.85,0.2:0.6").arg(0.5 * (shown->range.min + shown->range.max), 0, 'g', 6);
  values_->setText(text);
  form->addRow("Values:", values_);
  form->addRow(
      new QLabel(QString("VALUE[:r,g,b[:opacity]] separated by ';', up to %1; empty: none").arg(kMaxIsoSurfaces)));
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
  connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  form->addRow(buttons);
}

std::string IsoSurfaceDialog::quantity() const { return quantity_->currentData().toString().toStdString(); }

std::optional<std::vector<optics::IsoSurface>> IsoSurfaceDialog::surfaces(QString* bad) const {
  return parseIsoSurfaces(values_->text(), bad);
}

}  // namespace volpost::app

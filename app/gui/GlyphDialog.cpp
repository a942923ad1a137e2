// SPDX-License-Identifier: MIT
#include "GlyphDialog.hpp"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLineEdit>
#include <QSpinBox>

#include <cmath>

namespace volpost::app {

GlyphDialog::GlyphDialog(const ModelSession& session, const GlyphLayer& layer, QWidget* parent) : QDialog(parent) {
  setWindowTitle("Glyphs");
  auto* form = new QFormLayout(this);
  field_ = new QComboBox(this);
  field_->setObjectName("glyphField");
  field_->addItem("None", QString());
  for (const auto& f : session.model().fields)
    if (f->location() == FieldLocation::Node && f->kind() == FieldKind::Vector)
      field_->addItem(QString::fromStdString(f->name()) + " (arrows)", QString::fromStdString(f->name()));
    else if (f->location() == FieldLocation::Node && f->kind() == FieldKind::SymTensor)
      field_->addItem(QString::fromStdString(f->name()) + " (principal bars)", QString::fromStdString(f->name()));
  field_->setCurrentIndex(layer.shown ? std::max(0, field_->findData(QString::fromStdString(layer.field))) : 0);
  form->addRow("Field:", field_);
  colorBy_ = new QComboBox(this);
  colorBy_->setObjectName("glyphColor");
  colorBy_->addItem("Their length (principal values)", QString());
  for (const Quantity& q : session.quantities())
    if (session.fieldOf(q).location() == FieldLocation::Node)
      colorBy_->addItem(QString::fromStdString(q.displayName()), QString::fromStdString(q.key()));
  colorBy_->setCurrentIndex(std::max(0, colorBy_->findData(QString::fromStdString(layer.colorBy))));
  form->addRow("Colored by:", colorBy_);
  nodes_ = new QComboBox(this);
  nodes_->setObjectName("glyphNodes");
  nodes_->addItem("The surface's nodes", false);
  nodes_->addItem("All nodes (for a see-through surface or a clip)", true);
  nodes_->setCurrentIndex(layer.allNodes ? 1 : 0);
  form->addRow("At:", nodes_);
  every_ = new QSpinBox(this);
  every_->setObjectName("glyphEvery");
  every_->setRange(0, 1000000);
  every_->setSpecialValueText("Automatic (at most 20,000)");
  every_->setPrefix("one node in ");
  every_->setValue(layer.every);
  form->addRow("How many:", every_);
  fixedLength_ = new QCheckBox("All the same length (arrows: the direction only)", this);
  fixedLength_->setObjectName("glyphFixed");
  fixedLength_->setChecked(layer.fixedLength);
  form->addRow(fixedLength_);
  scale_ = new QLineEdit(layer.scale ? QString::number(*layer.scale, 'g', 10) : QString(), this);
  scale_->setObjectName("glyphScale");
  scale_->setPlaceholderText("automatic: the longest is 6% of the model");
  scale_->setToolTip("Model units per unit of the field (all the same length: the arrows' length)");
  form->addRow("Scale:", scale_);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
  connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  form->addRow(buttons);
}

std::optional<GlyphLayer> GlyphDialog::layer(QString* bad) const {
  GlyphLayer g;
  g.field = field_->currentData().toString().toStdString();
  g.shown = !g.field.empty();
  g.colorBy = colorBy_->currentData().toString().toStdString();
  g.allNodes = nodes_->currentData().toBool();
  g.every = every_->value();
  g.fixedLength = fixedLength_->isChecked();
  const QString scale = scale_->text().trimmed();
  if (!scale.isEmpty()) {
    bool ok = false;
    const double s = scale.toDouble(&ok);
    if (!ok || !(s > 0.0) || !std::isfinite(s)) {
      if (bad) *bad = "the scale '" + scale + "' is not a positive number (empty: automatic)";
      return std::nullopt;
    }
    g.scale = s;
  }
  return g;
}

}  // namespace volpost::app

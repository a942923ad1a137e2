// SPDX-License-Identifier: MIT
#include "ThresholdDialog.hpp"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>

#include <cmath>

namespace volpost::app {

ThresholdDialog::ThresholdDialog(const ModelSession& session, const ThresholdLayer& layer, const std::string& shown,
                                 std::size_t step, QWidget* parent)
    : QDialog(parent), session_(session), step_(step) {
  setWindowTitle("Threshold");
  auto* form = new QFormLayout(this);
  quantity_ = new QComboBox(this);
  quantity_->setObjectName("thresholdQuantity");
  for (const Quantity& q : session.quantities())
    quantity_->addItem(QString::fromStdString(q.displayName()), QString::fromStdString(q.key()));
  const std::string start = layer.shown ? layer.quantity : shown;
  quantity_->setCurrentIndex(std::max(0, quantity_->findData(QString::fromStdString(start))));
  form->addRow("Show the cells where:", quantity_);
  range_ = new QLabel(this);
  range_->setObjectName("thresholdValues");
  form->addRow(range_);
  min_ = new QLineEdit(this);
  min_->setObjectName("thresholdMin");
  max_ = new QLineEdit(this);
  max_->setObjectName("thresholdMax");
  form->addRow("is at least:", min_);
  form->addRow("and at most:", max_);
  nodes_ = new QComboBox(this);
  nodes_->setObjectName("thresholdNodes");
  nodes_->addItem("at all of its nodes", true);
  nodes_->addItem("at any of its nodes", false);
  nodes_->setCurrentIndex(layer.allNodes ? 0 : 1);
  nodes_->setToolTip("For a result at the nodes; an element result uses the element's own value");
  form->addRow("A nodal value counts:", nodes_);
  showRangeOf(quantity_->currentData().toString().toStdString());
  if (layer.shown) {
    min_->setText(QString::number(layer.min, 'g', 10));
    max_->setText(QString::number(layer.max, 'g', 10));
  }
  connect(quantity_, &QComboBox::currentIndexChanged, this,
          [this] { showRangeOf(quantity_->currentData().toString().toStdString()); });
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
  QPushButton* off = buttons->addButton("Off", QDialogButtonBox::AcceptRole);
  off->setObjectName("thresholdOff");
  connect(off, &QPushButton::clicked, this, [this] { off_ = true; });
  connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  form->addRow(buttons);
}

// The quantity's values at the step, and its upper half as the range to start from.
void ThresholdDialog::showRangeOf(const std::string& key) {
  if (key.empty()) return;
  try {
    const Quantity q = session_.findQuantity(key);
    const ScalarView v = session_.evaluate(q, std::min(step_, session_.fieldOf(q).stepCount() - 1));
    range_->setText(
        QString("Its values at this step: %1 .. %2").arg(v.range.min, 0, 'g', 6).arg(v.range.max, 0, 'g', 6));
    min_->setText(QString::number(0.5 * (v.range.min + v.range.max), 'g', 6));
    max_->setText(QString::number(v.range.max, 'g', 10));
  } catch (const std::exception& e) {
    range_->setText(QString::fromStdString(e.what()));
  }
}

std::optional<ThresholdLayer> ThresholdDialog::layer(QString* bad) const {
  ThresholdLayer t;
  if (off_) return t;
  t.shown = true;
  t.quantity = quantity_->currentData().toString().toStdString();
  t.allNodes = nodes_->currentData().toBool();
  bool okMin = false, okMax = false;
  t.min = min_->text().trimmed().toDouble(&okMin);
  t.max = max_->text().trimmed().toDouble(&okMax);
  if (!okMin || !okMax || !std::isfinite(t.min) || !std::isfinite(t.max) || t.min > t.max) {
    if (bad)
      *bad = QString("'%1' to '%2' is not a range of two numbers, the first not above the second")
                 .arg(min_->text(), max_->text());
    return std::nullopt;
  }
  return t;
}

}  // namespace volpost::app

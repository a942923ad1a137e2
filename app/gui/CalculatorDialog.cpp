// SPDX-License-Identifier: MIT
#include "CalculatorDialog.hpp"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QRegularExpression>
#include <QVBoxLayout>

#include <algorithm>

namespace volpost::app {

CalculatorDialog::CalculatorDialog(std::vector<FormulaSpec> formulas, std::vector<std::string> names, Apply apply,
                                   QWidget* parent)
    : QDialog(parent), formulas_(std::move(formulas)), apply_(std::move(apply)) {
  setWindowTitle("Calculator");
  setObjectName("calculatorDialog");
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(new QLabel("Formulas (each a result of its own, kept in the state file):", this));
  list_ = new QListWidget(this);
  list_->setObjectName("formulaList");
  layout->addWidget(list_);

  auto* form = new QFormLayout;
  name_ = new QLineEdit(this);
  name_->setObjectName("formulaName");
  name_->setPlaceholderText("ratio");
  form->addRow("&Name:", name_);
  expression_ = new QLineEdit(this);
  expression_->setObjectName("formulaExpression");
  expression_->setPlaceholderText("S.mises / 250      1.35*S@1 + 1.5*S@2      x > 0 ? T : 0");
  form->addRow("&Expression:", expression_);
  auto* insertRow = new QHBoxLayout;
  names_ = new QComboBox(this);
  names_->setObjectName("formulaNames");
  for (const std::string& n : names) names_->addItem(QString::fromStdString(n));
  for (const char* f : {"sqrt()", "abs()", "min(,)", "max(,)", "sin()", "cos()", "exp()", "ln()", "log10()", "_pi"})
    names_->addItem(f);
  auto* insert = new QPushButton("&Insert", this);
  insertRow->addWidget(names_, 1);
  insertRow->addWidget(insert);
  form->addRow("Names:", insertRow);
  layout->addLayout(form);
  layout->addWidget(
      new QLabel("@N reads step N (@last, @max, @min: the envelope over the steps); a whole vector or "
                 "tensor (U, S) is combined component by component; a, b, c makes a vector.",
                 this));
  layout->itemAt(layout->count() - 1)->widget()->setProperty("wordWrap", true);
  problem_ = new QLabel(this);
  problem_->setObjectName("formulaProblem");
  problem_->setWordWrap(true);
  problem_->setStyleSheet("color: #a01010");
  layout->addWidget(problem_);

  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
  auto* add = buttons->addButton("&Add or Replace", QDialogButtonBox::ActionRole);
  add->setObjectName("addFormula");
  remove_ = buttons->addButton("&Remove", QDialogButtonBox::ActionRole);
  remove_->setObjectName("removeFormula");
  layout->addWidget(buttons);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  connect(add, &QPushButton::clicked, this, [this] { addFromEditors(); });
  connect(remove_, &QPushButton::clicked, this, [this] { removeSelected(); });
  connect(insert, &QPushButton::clicked, this, [this] {
    QString text = names_->currentText();
    expression_->insert(text);
    if (text.endsWith(')')) expression_->cursorBackward(false, text.endsWith(",)") ? 2 : 1);
    expression_->setFocus();
  });
  connect(list_, &QListWidget::currentRowChanged, this, [this] { showSelected(); });
  listFormulas();
}

QString CalculatorDialog::problem() const { return problem_->text(); }

void CalculatorDialog::listFormulas() {
  const QSignalBlocker block(list_);
  list_->clear();
  for (const FormulaSpec& f : formulas_) list_->addItem(QString::fromStdString(f.name + " = " + f.expression));
  remove_->setEnabled(!formulas_.empty());
}

void CalculatorDialog::showSelected() {
  const int row = list_->currentRow();
  if (row < 0 || row >= int(formulas_.size())) return;
  name_->setText(QString::fromStdString(formulas_[std::size_t(row)].name));
  expression_->setText(QString::fromStdString(formulas_[std::size_t(row)].expression));
}

bool CalculatorDialog::apply(std::vector<FormulaSpec> next, const std::string& shown) {
  const std::string why = apply_(next, shown);
  problem_->setText(QString::fromStdString(why));
  if (!why.empty()) {
    // "at character N of": the place in the expression, selected for the user to fix.
    const QRegularExpressionMatch at = QRegularExpression("at character (\\d+) of").match(problem_->text());
    if (at.hasMatch()) {
      expression_->setFocus();
      expression_->setSelection(at.captured(1).toInt() - 1, 1);
    }
    return false;
  }
  formulas_ = std::move(next);
  listFormulas();
  return true;
}

bool CalculatorDialog::addFromEditors() {
  const FormulaSpec f{name_->text().trimmed().toStdString(), expression_->text().trimmed().toStdString()};
  std::vector<FormulaSpec> next = formulas_;
  auto same = std::find_if(next.begin(), next.end(), [&](const FormulaSpec& g) { return g.name == f.name; });
  if (same != next.end()) *same = f;
  else next.push_back(f);
  if (!apply(std::move(next), f.name)) return false;
  list_->setCurrentRow(int(std::find(formulas_.begin(), formulas_.end(), f) - formulas_.begin()));
  return true;
}

bool CalculatorDialog::removeSelected() {
  const int row = list_->currentRow();
  if (row < 0 || row >= int(formulas_.size())) {
    problem_->setText("Select the formula to remove in the list.");
    return false;
  }
  std::vector<FormulaSpec> next = formulas_;
  next.erase(next.begin() + row);
  return apply(std::move(next), "");
}

}  // namespace volpost::app

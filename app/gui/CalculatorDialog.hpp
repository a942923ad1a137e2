// SPDX-License-Identifier: MIT
// Results > Calculator...: the scene's formulas, listed as "name = expression"; a formula
// is added (or replaced, by its name) and removed here, each change applied at once. A
// formula the scene refuses keeps the dialog open with the reason, the character at fault
// selected in the expression.
#pragma once

#include "../core/Formula.hpp"

#include <QDialog>

#include <functional>
#include <string>
#include <vector>

class QComboBox;
class QLabel;
class QLineEdit;
class QListWidget;
class QPushButton;

namespace volpost::app {

class CalculatorDialog : public QDialog {
  Q_OBJECT

 public:
  /// Applies a new list of formulas (`shown`: the formula to show, empty for none) and
  /// returns why it was refused, or an empty text when it was applied.
  using Apply = std::function<std::string(const std::vector<FormulaSpec>& formulas, const std::string& shown)>;

  /// `names`: what a formula may read (formulaNames of the model as read).
  CalculatorDialog(std::vector<FormulaSpec> formulas, std::vector<std::string> names, Apply apply, QWidget* parent);

  const std::vector<FormulaSpec>& formulas() const { return formulas_; }
  /// The text of the last refusal (empty when the last change was applied).
  QString problem() const;

  /// What the buttons do, for a test: Add with the editors' name and expression.
  bool addFromEditors();
  bool removeSelected();

 private:
  void listFormulas();
  void showSelected();
  bool apply(std::vector<FormulaSpec> next, const std::string& shown);

  std::vector<FormulaSpec> formulas_;
  Apply apply_;
  QListWidget* list_ = nullptr;
  QLineEdit* name_ = nullptr;
  QLineEdit* expression_ = nullptr;
  QComboBox* names_ = nullptr;
  QLabel* problem_ = nullptr;
  QPushButton* remove_ = nullptr;
};

}  // namespace volpost::app

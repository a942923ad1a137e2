// SPDX-License-Identifier: MIT
// User formulas (the calculator): a new field computed from the model's quantities and
// coordinates, such as "ratio = S.mises / 250", "combo = 1.35*S@1 + 1.5*S@2" or
// "peak = S.mises@max". The expression is read by muParser; docs/user/calculator.md has the
// rules.
#pragma once

#include <volpost/core/Field.hpp>
#include <volpost/core/Model.hpp>

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace volpost::app {

/// A named formula, kept as text (in state files too).
struct FormulaSpec {
  std::string name;
  std::string expression;
  bool operator==(const FormulaSpec&) const = default;
};

/// A formula that cannot be used: the message names the formula, and where the expression
/// is at fault, the character (1-based) and what is wrong there.
struct FormulaError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

/// "NAME=EXPRESSION" (as --formula takes it) split at the first "="; FormulaError when
/// there is no "=" or either side is empty.
FormulaSpec parseFormulaText(const std::string& text);

/// How a quantity or field is written inside a formula: its written form with every
/// character other than a letter, a digit, "_" or "." replaced by "_" ("element set" is
/// element_set).
std::string formulaName(const std::string& writtenForm);

/// The names a formula over this model can use, for help texts: every quantity, the
/// vector and tensor fields themselves, and x, y, z, time.
std::vector<std::string> formulaNames(const Model& model);

/// The formula's field: values per node (per cell when it reads a per-cell field; node
/// values are then averaged over each cell's nodes), one step per step of the fields it
/// reads without a pinned step, computed when a step is first asked for. Checks everything
/// it can before returning (names, steps, the number of values); FormulaError otherwise.
std::shared_ptr<Field> formulaField(const Model& model, const FormulaSpec& formula);

/// Appends the formulas' fields to the model, in order (each may read the ones before it).
/// Throws FormulaError naming the formula at fault (the model then holds the ones before it).
void appendFormulaFields(Model& model, const std::vector<FormulaSpec>& formulas);

}  // namespace volpost::app

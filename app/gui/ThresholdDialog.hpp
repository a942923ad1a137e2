// SPDX-License-Identifier: MIT
// Results > Threshold...: only the cells whose value lies in a range are drawn (as
// `volpost render --threshold Q:MIN:MAX`); "Off" shows the whole model again.
#pragma once

#include "../core/Threshold.hpp"

#include <QDialog>

#include <optional>

class QComboBox;
class QLabel;
class QLineEdit;

namespace volpost::app {

class ThresholdDialog : public QDialog {
  Q_OBJECT

 public:
  /// Starts from `layer`, or the shown quantity (`shown`, may be empty) over its upper half.
  ThresholdDialog(const ModelSession& session, const ThresholdLayer& layer, const std::string& shown, std::size_t step,
                  QWidget* parent);
  /// The layer chosen; nullopt, with what is wrong in `bad`, when a bound is not a number.
  std::optional<ThresholdLayer> layer(QString* bad) const;

 private:
  void showRangeOf(const std::string& quantity);
  const ModelSession& session_;
  std::size_t step_;
  bool off_ = false;
  QComboBox* quantity_;
  QLineEdit* min_;
  QLineEdit* max_;
  QComboBox* nodes_;
  QLabel* range_;
};

}  // namespace volpost::app

// SPDX-License-Identifier: MIT
// View > Streamlines: which vector field, where the lines start (one seed description per
// line, or a rake placed with the mouse), how they are integrated and drawn.
#pragma once

#include "../core/ModelSession.hpp"
#include "../core/SceneState.hpp"

#include <QDialog>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QPlainTextEdit;
class QSpinBox;

namespace volpost::app {

class StreamlineDialog : public QDialog {
  Q_OBJECT

 public:
  StreamlineDialog(const ModelSession& session, const StreamlineLayer& layer, QWidget* parent);
  /// The layer as the dialog shows it (shown = true).
  StreamlineLayer layer() const;

 private:
  QComboBox* field_ = nullptr;
  QPlainTextEdit* seeds_ = nullptr;
  QComboBox* integrator_ = nullptr;
  QComboBox* direction_ = nullptr;
  QComboBox* tolerance_ = nullptr;
  QComboBox* colorBy_ = nullptr;
  QDoubleSpinBox* width_ = nullptr;
  QCheckBox* tubes_ = nullptr;
  QCheckBox* arrows_ = nullptr;
  QCheckBox* average_ = nullptr;
  StreamlineLayer original_;
};

}  // namespace volpost::app

// SPDX-License-Identifier: MIT
// Results > Glyphs...: arrows of a vector field or principal bars of a tensor field at the
// nodes, what colors them, how long they are, and at which nodes (as `volpost render
// --glyphs FIELD --glyph-*`). "None" turns them off.
#pragma once

#include "../core/Glyphs.hpp"

#include <QDialog>

class QCheckBox;
class QComboBox;
class QLineEdit;
class QSpinBox;

namespace volpost::app {

class GlyphDialog : public QDialog {
  Q_OBJECT

 public:
  GlyphDialog(const ModelSession& session, const GlyphLayer& layer, QWidget* parent);
  /// The layer chosen; nullopt, with what is wrong in `bad`, when the scale is not a
  /// positive number.
  std::optional<GlyphLayer> layer(QString* bad) const;

 private:
  QComboBox* field_;
  QComboBox* colorBy_;
  QComboBox* nodes_;
  QSpinBox* every_;
  QCheckBox* fixedLength_;
  QLineEdit* scale_;
};

}  // namespace volpost::app

// SPDX-License-Identifier: MIT
// Results > Iso-surfaces...: of which quantity (the shown result, or another given at the
// nodes) and at which values, each with its color and opacity, as one line of text
// ("VALUE[:r,g,b[:opacity]]" separated by ';').
#pragma once

#include "../core/ModelSession.hpp"
#include "../core/SceneState.hpp"

#include <QDialog>

#include <optional>
#include <string>
#include <vector>

class QComboBox;
class QLineEdit;

namespace volpost::app {

class IsoSurfaceDialog : public QDialog {
  Q_OBJECT

 public:
  /// Shows the volume layer's iso-surfaces, or one at the middle of `shown` (the values of
  /// the result shown, if any) when there are none.
  IsoSurfaceDialog(const ModelSession& session, const VolumeLayer& volume, const ScalarView* shown, QWidget* parent);
  /// The quantity chosen (empty: the shown result).
  std::string quantity() const;
  /// The surfaces typed; nullopt, with the part that is wrong in `bad`, when the text is
  /// not VALUE[:r,g,b[:opacity]] or names more than the renderers draw.
  std::optional<std::vector<optics::IsoSurface>> surfaces(QString* bad) const;

 private:
  QComboBox* quantity_ = nullptr;
  QLineEdit* values_ = nullptr;
};

}  // namespace volpost::app

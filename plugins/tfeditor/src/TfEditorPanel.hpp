// SPDX-License-Identifier: MIT
// The transfer-function editor dock: the curve, exact numeric entry for the selected
// point, presets, ParaView import, volpost TF files, undo/redo, and the live link to the
// host (coalesced: a drag sends the latest function once the event loop is free). The 2D
// iso-detection table of the current function is rebuilt off the GUI thread and shown.
#pragma once

#include "TfCurveWidget.hpp"
#include "TfEditModel.hpp"

#include <volpost/core/optics/IsoTables.hpp>
#include <volpost/plugin/PluginInterfaces.hpp>

#include <QFutureWatcher>
#include <QWidget>

#include <memory>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QTimer;

namespace volpost::tfeditor {

class TfEditorPanel : public QWidget {
  Q_OBJECT

 public:
  TfEditorPanel(PanelHost& host, QWidget* parent = nullptr);
  ~TfEditorPanel() override;

  /// The host's model, result or step changed: new histogram, and the function the host
  /// holds for this result (a new result starts a new undo history).
  void hostChanged();
  QSize sizeHint() const override { return {380, 440}; }

  TfEditModel& model() { return model_; }
  TfCurveWidget& curve() { return *curve_; }
  /// The iso-detection table of the function last sent to the host (waits for a build in
  /// progress). For tests and the preview.
  const optics::IsoDetectionTable* isoTable();
  /// Sends pending edits to the host now (the coalescing timer would do it shortly).
  void flush();
  void applyPreset(const QString& name);
  /// Reshapes the opacity curve over the points' values, keeping their colors and the
  /// curve's peak: "rising" (high values dense), "falling" (low values dense), "ends"
  /// (both ends dense, clear at zero for a signed range, else at the middle), "middle".
  void applyOpacityShape(const QString& shape);
  bool loadFile(const QString& path, QString* error = nullptr);
  bool saveFile(const QString& path, QString* error = nullptr) const;
  bool importParaView(const QString& path, QString* error = nullptr);

 private:
  void buildUi();
  void sendToHost();
  void startIsoTable(const TransferFunction& tf);
  void showSelection();
  void applyNumericEntry();
  void chooseColor();
  void saveState() const;
  std::pair<double, double> dataRange() const;

  PanelHost& host_;
  TfEditModel model_;
  TfCurveWidget* curve_ = nullptr;
  QComboBox* presets_ = nullptr;
  QComboBox* shapes_ = nullptr;
  QLineEdit* valueEdit_ = nullptr;
  QLineEdit* opacityEdit_ = nullptr;
  QPushButton* colorButton_ = nullptr;
  QDoubleSpinBox* lengthBox_ = nullptr;
  QCheckBox* logBox_ = nullptr;
  QCheckBox* fineBox_ = nullptr;
  QLabel* status_ = nullptr;
  QTimer* sendTimer_ = nullptr;
  std::string quantityKey_;
  /// The host's function as this panel last loaded or sent it: a different one in the host
  /// (a state file opened, a function set elsewhere) is loaded into the panel.
  std::optional<TransferFunction> knownHostFunction_;
  std::pair<double, double> dataRange_{0.0, 1.0};  ///< of the active values (they are not kept)
  std::string valuesKey_;  ///< which values dataRange_ and the histogram are of
  bool hostUpdating_ = false;

  QFuture<std::shared_ptr<optics::IsoDetectionTable>> isoFuture_;
  QFutureWatcher<std::shared_ptr<optics::IsoDetectionTable>> isoWatcher_;
  std::shared_ptr<optics::IsoDetectionTable> isoTable_;
  std::optional<TransferFunction> isoPending_;  // a newer function waits for the running build
  double isoMs_ = 0.0;
};

}  // namespace volpost::tfeditor

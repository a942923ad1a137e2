// SPDX-License-Identifier: MIT
// The 2D transfer function's editor (regular grids): the canvas over the joint histogram of
// the active result, buttons to add rectangles and triangles and to delete, the selected
// widget's color, opacity and shape, volpost-tf2d files, and the switch that draws the
// volume with it. Live: edits reach the host coalesced, as the 1D editor's do.
#pragma once

#include "Tf2dCanvas.hpp"

#include <volpost/plugin/PluginInterfaces.hpp>

#include <QWidget>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QTimer;

namespace volpost::tfeditor {

class Tf2dEditorPanel : public QWidget {
  Q_OBJECT

 public:
  explicit Tf2dEditorPanel(PanelHost& host, QWidget* parent = nullptr);

  /// The host's model, result or step changed: the histogram again, the host's function.
  void hostChanged();
  Tf2dCanvas& canvas() { return *canvas_; }
  /// Whether the volume is drawn with this function (the switch).
  bool inUse() const;
  void setInUse(bool on);
  /// Sends pending edits to the host now (the coalescing timer would do it shortly).
  void flush();
  bool loadFile(const QString& path, QString* error = nullptr);
  bool saveFile(const QString& path, QString* error = nullptr) const;
  /// The opacity of `extinction` over the reference length (a tenth of the model), and back.
  double opacityOf(double extinction) const;
  double extinctionOf(double opacity) const;

 private:
  void buildUi();
  void showSelection();
  void editSelection();
  void chooseColor();
  void sendToHost();

  PanelHost& host_;
  Tf2dCanvas* canvas_ = nullptr;
  QCheckBox* use_ = nullptr;
  QComboBox* shape_ = nullptr;
  QDoubleSpinBox* opacity_ = nullptr;
  QPushButton* color_ = nullptr;
  QLabel* status_ = nullptr;
  QTimer* sendTimer_ = nullptr;
  std::string histogramKey_;
  bool updating_ = false;
};

}  // namespace volpost::tfeditor

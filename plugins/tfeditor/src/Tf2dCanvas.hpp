// SPDX-License-Identifier: MIT
// The 2D transfer function's canvas: the joint histogram of value (across) and gradient
// magnitude (up) in gray, log-scaled, and the widgets over it in their colors. Click a
// widget to select it, drag it to move it; drag the selected one's handles to widen it (the
// square on its right edge) or to raise its top (the square on its top edge); double-click
// the empty histogram to add a rectangle there; Delete removes the selected widget.
#pragma once

#include "JointHistogram.hpp"

#include <volpost/core/TransferFunction2D.hpp>

#include <QImage>
#include <QWidget>

#include <vector>

namespace volpost::tfeditor {

class Tf2dCanvas : public QWidget {
  Q_OBJECT

 public:
  explicit Tf2dCanvas(QWidget* parent = nullptr);

  /// The histogram behind the widgets; its ranges are the canvas's axes.
  void setHistogram(const JointHistogram& histogram);
  /// Whether a histogram with any count is behind the widgets.
  bool hasHistogram() const { return hasHistogram_; }
  double valueLow() const { return valueLow_; }
  double valueHigh() const { return valueHigh_; }
  double gradientHigh() const { return gradientHigh_; }

  void setWidgets(std::vector<TfWidget2D> widgets);
  const std::vector<TfWidget2D>& widgets() const { return widgets_; }
  int selected() const { return selected_; }
  void select(int index);
  /// Adds a widget (a tenth of the values wide, the lower third of the gradients) and
  /// selects it.
  void addWidget(TfWidget2D::Shape shape, double value, double gradient);
  void removeSelected();
  /// Replaces the selected widget (its color, extinction, shape).
  void updateSelected(const TfWidget2D& widget);
  /// The extinction new widgets get.
  void setDefaultExtinction(double extinction) { defaultExtinction_ = extinction; }

  /// Where (value, gradient) is drawn, and the other way.
  QPointF toScreen(double value, double gradient) const;
  QPointF fromScreen(const QPointF& p) const;  ///< x: value, y: gradient
  /// The selected widget's handles on screen (width: right edge; top: top edge).
  QPointF widthHandle(const TfWidget2D& w) const;
  QPointF topHandle(const TfWidget2D& w) const;

  QSize sizeHint() const override { return {360, 220}; }
  QSize minimumSizeHint() const override { return {160, 100}; }

 signals:
  void widgetsChanged();
  void selectionChanged(int index);

 protected:
  void paintEvent(QPaintEvent*) override;
  void mousePressEvent(QMouseEvent* e) override;
  void mouseMoveEvent(QMouseEvent* e) override;
  void mouseReleaseEvent(QMouseEvent* e) override;
  void mouseDoubleClickEvent(QMouseEvent* e) override;
  void keyPressEvent(QKeyEvent* e) override;

 private:
  enum class Drag { None, Move, Width, Top };
  QRectF plotRect() const;
  QPolygonF outline(const TfWidget2D& w) const;
  int widgetAt(const QPointF& p) const;

  QImage histogramImage_;
  bool hasHistogram_ = false;
  double valueLow_ = 0.0, valueHigh_ = 1.0, gradientHigh_ = 1.0;
  std::vector<TfWidget2D> widgets_;
  int selected_ = -1;
  double defaultExtinction_ = 1.0;
  Drag drag_ = Drag::None;
  QPointF dragStart_;           ///< in (value, gradient)
  TfWidget2D dragOriginal_;
};

}  // namespace volpost::tfeditor

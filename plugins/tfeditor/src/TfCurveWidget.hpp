// SPDX-License-Identifier: MIT
// The opacity curve over the scalar range: control points to add (click), drag, select
// (Ctrl/Shift+click), delete (right click, Delete), a color bar below, the histogram of
// the active result behind (optionally log), zoom (wheel), a cube-root opacity axis for the
// small opacities that matter, and window/level (middle or Alt+drag). Keyboard: arrows
// move the selection (Shift: finer), PageDown/PageUp select the next/previous point,
// Insert adds, Delete removes, Ctrl+A selects all (Tab stays focus navigation).
#pragma once

#include "TfEditModel.hpp"

#include <volpost/core/SampleView.hpp>

#include <QWidget>

#include <optional>
#include <vector>

namespace volpost::tfeditor {

class TfCurveWidget : public QWidget {
  Q_OBJECT

 public:
  /// The histogram is built from at most this many of the values (evenly spaced in the
  /// model's order, plus the smallest and largest).
  static constexpr std::size_t kMaxHistogramValues = std::size_t(1) << 22;

  explicit TfCurveWidget(TfEditModel& model, QWidget* parent = nullptr);

  /// Values of the active result: the histogram and the Shift-drag snap targets.
  void setData(SampleView values);
  void setLogHistogram(bool on);
  void setFineOpacityAxis(bool on);
  bool fineOpacityAxis() const { return fineAxis_; }
  /// Visible value range; resetView() shows the data and all points.
  void setView(double lo, double hi);
  void resetView();
  std::pair<double, double> view() const { return {viewLo_, viewHi_}; }

  // The mapping between widget pixels and (value, opacity), for the tests too.
  QRectF plotRect() const;
  QPointF toPixel(double value, double opacity) const;
  double valueAt(double x) const;
  double opacityAt(double y) const;
  /// The data value nearest to v (v itself when there is no data).
  double snapped(double v) const;

  QSize sizeHint() const override { return {360, 200}; }
  QSize minimumSizeHint() const override { return {180, 110}; }

 protected:
  void paintEvent(QPaintEvent*) override;
  void mousePressEvent(QMouseEvent* e) override;
  void mouseMoveEvent(QMouseEvent* e) override;
  void mouseReleaseEvent(QMouseEvent* e) override;
  void mouseDoubleClickEvent(QMouseEvent* e) override;
  void wheelEvent(QWheelEvent* e) override;
  void keyPressEvent(QKeyEvent* e) override;

 private:
  std::optional<int> pointAt(const QPointF& pos) const;  // id
  void moveSelection(double dValue, double dOpacityDisplay, const QString& what);
  double displayOf(double opacity) const;
  double opacityOfDisplay(double d) const;
  void rebuildHistogram();

  TfEditModel& model_;
  std::vector<double> sortedData_;
  std::vector<double> histogram_;
  bool logHistogram_ = false, fineAxis_ = true;
  double viewLo_ = 0.0, viewHi_ = 1.0;
  enum class Drag { None, Points, WindowLevel } drag_ = Drag::None;
  QPointF pressPos_;
  std::vector<EditPoint> pressPoints_;  // the points when the drag began
  int dragKey_ = 1000;                  // merge key of the current gesture
  int grabbed_ = 0;                     // id of the point under the mouse at press
};

}  // namespace volpost::tfeditor

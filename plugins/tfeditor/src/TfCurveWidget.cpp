// SPDX-License-Identifier: MIT
#include "TfCurveWidget.hpp"

#include <QKeyEvent>
#include <QLinearGradient>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>

namespace volpost::tfeditor {
namespace {
constexpr int kColorBar = 16;   // px below the plot
constexpr int kMargin = 6;
constexpr double kPickRadius = 7.0;
constexpr int kHistogramBins = 96;
}  // namespace

TfCurveWidget::TfCurveWidget(TfEditModel& model, QWidget* parent) : QWidget(parent), model_(model) {
  setObjectName("tfCurve");
  setFocusPolicy(Qt::StrongFocus);
  setMouseTracking(true);
  setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
  setAccessibleName("Transfer function curve");
  connect(&model_, &TfEditModel::changed, this, qOverload<>(&QWidget::update));
  connect(&model_, &TfEditModel::selectionChanged, this, qOverload<>(&QWidget::update));
}

// At most kMaxHistogramValues values are kept (every n-th, and the two extremes): a 512^3
// cube's histogram is the same picture from a 32nd of its values, without a 1 GB sorted
// copy and seconds of sorting on the GUI thread.
void TfCurveWidget::setData(SampleView values) {
  sortedData_.clear();
  const std::size_t stride = values.size() / kMaxHistogramValues + 1;
  double lo = INFINITY, hi = -INFINITY;
  for (std::size_t i = 0; i < values.size(); ++i) {
    const double v = values[i];
    if (!std::isfinite(v)) continue;
    lo = std::min(lo, v), hi = std::max(hi, v);
    if (i % stride == 0) sortedData_.push_back(v);
  }
  if (stride > 1 && hi >= lo) sortedData_.insert(sortedData_.end(), {lo, hi});
  std::sort(sortedData_.begin(), sortedData_.end());  // duplicates kept: the histogram counts them
  resetView();
}

void TfCurveWidget::setLogHistogram(bool on) {
  logHistogram_ = on;
  update();
}

void TfCurveWidget::setFineOpacityAxis(bool on) {
  fineAxis_ = on;
  update();
}

void TfCurveWidget::setView(double lo, double hi) {
  if (!(hi > lo) || !std::isfinite(lo) || !std::isfinite(hi)) return;
  viewLo_ = lo;
  viewHi_ = hi;
  rebuildHistogram();
  update();
}

void TfCurveWidget::resetView() {
  double lo = INFINITY, hi = -INFINITY;
  if (!sortedData_.empty()) lo = sortedData_.front(), hi = sortedData_.back();
  for (const auto& p : model_.points()) lo = std::min(lo, p.value), hi = std::max(hi, p.value);
  if (!std::isfinite(lo)) lo = 0.0, hi = 1.0;
  if (!(hi > lo)) hi = lo + std::max(1.0, std::abs(lo)) * 1e-3;
  setView(lo, hi);  // the data's own range, as the legend shows it (no padding)
}

void TfCurveWidget::rebuildHistogram() {
  histogram_.assign(kHistogramBins, 0.0);
  const auto first = std::lower_bound(sortedData_.begin(), sortedData_.end(), viewLo_);
  const auto last = std::upper_bound(sortedData_.begin(), sortedData_.end(), viewHi_);
  for (auto it = first; it != last; ++it) {
    const int b = std::clamp(int((*it - viewLo_) / (viewHi_ - viewLo_) * kHistogramBins), 0, kHistogramBins - 1);
    histogram_[std::size_t(b)] += 1.0;
  }
}

QRectF TfCurveWidget::plotRect() const {
  return QRectF(kMargin, kMargin, std::max(10, width() - 2 * kMargin), std::max(10, height() - 2 * kMargin - kColorBar - 4));
}

// Cube-root axis: opacities of 0.001 and 0.01 land at 10% and 22% of the height.
double TfCurveWidget::displayOf(double opacity) const { return fineAxis_ ? std::cbrt(std::max(opacity, 0.0)) : opacity; }
double TfCurveWidget::opacityOfDisplay(double d) const {
  d = std::clamp(d, 0.0, 1.0);
  return fineAxis_ ? d * d * d : d;
}

QPointF TfCurveWidget::toPixel(double value, double opacity) const {
  const QRectF r = plotRect();
  return {r.left() + (value - viewLo_) / (viewHi_ - viewLo_) * r.width(), r.bottom() - displayOf(opacity) * r.height()};
}

double TfCurveWidget::valueAt(double x) const {
  const QRectF r = plotRect();
  return viewLo_ + (x - r.left()) / r.width() * (viewHi_ - viewLo_);
}

double TfCurveWidget::opacityAt(double y) const {
  const QRectF r = plotRect();
  return opacityOfDisplay((r.bottom() - y) / r.height());
}

double TfCurveWidget::snapped(double v) const {
  if (sortedData_.empty()) return v;
  const auto it = std::lower_bound(sortedData_.begin(), sortedData_.end(), v);
  if (it == sortedData_.begin()) return *it;
  if (it == sortedData_.end()) return sortedData_.back();
  return (v - *(it - 1) < *it - v) ? *(it - 1) : *it;
}

std::optional<int> TfCurveWidget::pointAt(const QPointF& pos) const {
  std::optional<int> best;
  double bestDistance = kPickRadius;
  for (const auto& p : model_.points()) {
    const QPointF q = toPixel(p.value, p.opacity);
    const double d = std::hypot(q.x() - pos.x(), q.y() - pos.y());
    if (d <= bestDistance) bestDistance = d, best = p.id;
  }
  return best;
}

void TfCurveWidget::paintEvent(QPaintEvent*) {
  QPainter painter(this);
  painter.setRenderHint(QPainter::Antialiasing);
  const QRectF r = plotRect();
  painter.fillRect(rect(), palette().window());
  painter.fillRect(r, palette().base());
  // Histogram behind everything.
  const double peak = histogram_.empty() ? 0.0 : *std::max_element(histogram_.begin(), histogram_.end());
  if (peak > 0.0) {
    const double barWidth = r.width() / kHistogramBins;
    for (int b = 0; b < kHistogramBins; ++b) {
      const double h = logHistogram_ ? std::log1p(histogram_[std::size_t(b)]) / std::log1p(peak) : histogram_[std::size_t(b)] / peak;
      painter.fillRect(QRectF(r.left() + b * barWidth, r.bottom() - h * r.height(), barWidth, h * r.height()),
                       QColor(128, 128, 128, 70));
    }
  }
  // Opacity grid lines at 0.001, 0.01, 0.1, 0.5.
  painter.setPen(QPen(QColor(128, 128, 128, 90), 0, Qt::DotLine));
  for (double o : {0.001, 0.01, 0.1, 0.5}) {
    const double y = toPixel(viewLo_, o).y();
    painter.drawLine(QPointF(r.left(), y), QPointF(r.right(), y));
    painter.drawText(QPointF(r.left() + 2, y - 2), QString::number(o));
  }
  const auto& pts = model_.points();
  // The function once per paint (the curve samples it at every pixel column).
  const TransferFunction tf = model_.toTransferFunction();
  const double length = model_.referenceLength();
  const auto colorAt = [&](double v) {
    if (tf.empty()) return QColor(Qt::white);
    const glm::dvec3 c = tf.color(v);
    return QColor::fromRgbF(float(c.r), float(c.g), float(c.b));
  };
  const auto opacityAt = [&](double v) { return tf.empty() ? 0.0 : extinctionToOpacity(tf.extinction(v), length); };
  // The curve, filled with the function's colors, sampled so the cube-root axis bends it.
  if (!pts.empty()) {
    QPainterPath path;
    const int samples = std::max(2, int(r.width()));
    path.moveTo(r.left(), r.bottom());
    for (int i = 0; i <= samples; ++i) {
      const double v = viewLo_ + (viewHi_ - viewLo_) * i / samples;
      path.lineTo(toPixel(v, opacityAt(v)));
    }
    path.lineTo(r.right(), r.bottom());
    path.closeSubpath();
    QLinearGradient fill(r.left(), 0, r.right(), 0);
    for (int i = 0; i <= 32; ++i) {
      QColor c = colorAt(viewLo_ + (viewHi_ - viewLo_) * i / 32.0);
      c.setAlpha(150);
      fill.setColorAt(i / 32.0, c);
    }
    painter.fillPath(path, fill);
    painter.setPen(QPen(palette().text().color(), 1.5));
    painter.drawPath(path);
  }
  // Control points.
  for (const auto& p : pts) {
    const QPointF q = toPixel(p.value, p.opacity);
    const bool selected = model_.selection().count(p.id) > 0;
    painter.setBrush(p.color);
    painter.setPen(QPen(selected ? palette().highlight().color() : palette().text().color(), selected ? 3 : 1));
    painter.drawEllipse(q, selected ? 6.0 : 4.5, selected ? 6.0 : 4.5);
  }
  // Color bar.
  const QRectF bar(r.left(), r.bottom() + 4, r.width(), kColorBar);
  QLinearGradient colors(bar.left(), 0, bar.right(), 0);
  for (int i = 0; i <= 64; ++i) colors.setColorAt(i / 64.0, colorAt(viewLo_ + (viewHi_ - viewLo_) * i / 64.0));
  painter.fillRect(bar, colors);
  painter.setPen(palette().text().color());
  painter.setBrush(Qt::NoBrush);
  painter.drawRect(bar);
  // The end labels in black or white, whichever stands out from the bar's color under them.
  const auto readableOn = [](const QColor& c) {
    return 0.299 * c.redF() + 0.587 * c.greenF() + 0.114 * c.blueF() < 0.5 ? QColor(Qt::white) : QColor(Qt::black);
  };
  painter.setPen(readableOn(colorAt(viewLo_)));
  painter.drawText(bar.adjusted(3, 0, -3, 0), Qt::AlignLeft | Qt::AlignVCenter, QString::number(viewLo_, 'g', 4));
  painter.setPen(readableOn(colorAt(viewHi_)));
  painter.drawText(bar.adjusted(3, 0, -3, 0), Qt::AlignRight | Qt::AlignVCenter, QString::number(viewHi_, 'g', 4));
  if (hasFocus()) {
    painter.setPen(QPen(palette().highlight().color(), 1, Qt::DashLine));
    painter.drawRect(rect().adjusted(1, 1, -2, -2));
  }
}

void TfCurveWidget::mousePressEvent(QMouseEvent* e) {
  setFocus(Qt::MouseFocusReason);
  pressPos_ = e->position();
  ++dragKey_;
  const auto hit = pointAt(e->position());
  if (e->button() == Qt::RightButton) {
    if (hit) model_.removePoints({*hit});
    return;
  }
  if (e->button() == Qt::MiddleButton || (e->button() == Qt::LeftButton && (e->modifiers() & Qt::AltModifier))) {
    drag_ = Drag::WindowLevel;
    pressPoints_ = model_.points();
    return;
  }
  if (e->button() != Qt::LeftButton) return;
  if (hit) {
    std::set<int> sel = model_.selection();
    if (e->modifiers() & Qt::ControlModifier) {
      if (!sel.erase(*hit)) sel.insert(*hit);
    } else if (e->modifiers() & Qt::ShiftModifier) {
      sel.insert(*hit);
    } else if (!sel.count(*hit)) {
      sel = {*hit};
    }
    model_.setSelection(sel);
    grabbed_ = *hit;
  } else {
    // A click on empty space adds a point there, ready to drag.
    if (!plotRect().contains(e->position())) return;
    grabbed_ = model_.addPoint(valueAt(e->position().x()), opacityAt(e->position().y()));
  }
  drag_ = Drag::Points;
  pressPoints_ = model_.points();
}

void TfCurveWidget::mouseMoveEvent(QMouseEvent* e) {
  if (drag_ == Drag::None) {
    setCursor(pointAt(e->position()) ? Qt::PointingHandCursor : Qt::CrossCursor);
    return;
  }
  const QRectF r = plotRect();
  const QPointF d = e->position() - pressPos_;
  if (drag_ == Drag::WindowLevel) {
    // Horizontal: move the whole function; vertical: widen (up) or narrow (down) it
    // around its center.
    if (pressPoints_.empty()) return;
    const double shift = d.x() / r.width() * (viewHi_ - viewLo_);
    const double scale = std::exp(-d.y() / r.height() * 2.0);
    const double center = 0.5 * (pressPoints_.front().value + pressPoints_.back().value);
    std::vector<EditPoint> moved = pressPoints_;
    for (auto& p : moved) p.value = center + (p.value - center) * scale + shift;
    model_.replaceAll(moved, "Window/level", dragKey_);
    return;
  }
  // Points: the grabbed one follows the mouse (snapped to data with Shift); the rest of
  // the selection moves by the same amounts.
  const EditPoint* grabbed = nullptr;
  for (const auto& p : pressPoints_)
    if (p.id == grabbed_) grabbed = &p;
  if (!grabbed) return;
  double value = valueAt(toPixel(grabbed->value, 0).x() + d.x());
  if (e->modifiers() & Qt::ShiftModifier) value = snapped(value);
  const double display = displayOf(grabbed->opacity) - d.y() / r.height();
  const double dValue = value - grabbed->value, dDisplay = display - displayOf(grabbed->opacity);
  std::vector<EditPoint> moved;
  for (const auto& p : pressPoints_)
    if (model_.selection().count(p.id) || p.id == grabbed_) {
      EditPoint m = p;
      m.value = p.value + dValue;
      m.opacity = opacityOfDisplay(displayOf(p.opacity) + dDisplay);
      moved.push_back(m);
    }
  model_.movePoints(moved, "Move point", dragKey_);
}

void TfCurveWidget::mouseReleaseEvent(QMouseEvent*) { drag_ = Drag::None; }

void TfCurveWidget::mouseDoubleClickEvent(QMouseEvent* e) {
  // Double-click on empty space: back to the whole range.
  if (!pointAt(e->position())) resetView();
}

void TfCurveWidget::wheelEvent(QWheelEvent* e) {
  const double factor = std::pow(1.25, -e->angleDelta().y() / 120.0);
  const double at = valueAt(e->position().x());
  setView(at + (viewLo_ - at) * factor, at + (viewHi_ - at) * factor);
  e->accept();
}

void TfCurveWidget::moveSelection(double dValue, double dDisplay, const QString& what) {
  std::vector<EditPoint> moved;
  for (const auto& p : model_.points())
    if (model_.selection().count(p.id)) {
      EditPoint m = p;
      m.value += dValue;
      m.opacity = opacityOfDisplay(displayOf(p.opacity) + dDisplay);
      moved.push_back(m);
    }
  if (!moved.empty()) model_.movePoints(moved, what, 0);
}

void TfCurveWidget::keyPressEvent(QKeyEvent* e) {
  const bool fine = e->modifiers() & Qt::ShiftModifier;
  const double step = (viewHi_ - viewLo_) * (fine ? 0.001 : 0.01), up = fine ? 0.002 : 0.02;
  const auto& pts = model_.points();
  // Undo/redo also work from here when the panel's shortcuts do not see the key (a window
  // that is not active, e.g. a floating dock).
  if (e->matches(QKeySequence::Undo)) {
    model_.undoStack()->undo();
    return e->accept();
  }
  if (e->matches(QKeySequence::Redo) || (e->key() == Qt::Key_Y && e->modifiers() == Qt::ControlModifier)) {
    model_.undoStack()->redo();
    return e->accept();
  }
  switch (e->key()) {
    case Qt::Key_Left: moveSelection(-step, 0.0, "Move point"); break;
    case Qt::Key_Right: moveSelection(step, 0.0, "Move point"); break;
    case Qt::Key_Up: moveSelection(0.0, up, "Change opacity"); break;
    case Qt::Key_Down: moveSelection(0.0, -up, "Change opacity"); break;
    case Qt::Key_Delete:
    case Qt::Key_Backspace:
      if (!model_.selection().empty()) model_.removePoints(model_.selection());
      break;
    case Qt::Key_Insert:
    case Qt::Key_Plus: {
      const double v = 0.5 * (viewLo_ + viewHi_);
      model_.addPoint(v, model_.opacityAt(v));
      break;
    }
    case Qt::Key_PageDown:
    case Qt::Key_PageUp: {
      if (pts.empty()) break;
      int index = model_.selection().empty() ? -1 : model_.indexOf(*model_.selection().begin());
      index = e->key() == Qt::Key_PageDown ? index + 1 : index - 1;
      index = (index + int(pts.size())) % int(pts.size());
      model_.setSelection({pts[std::size_t(index)].id});
      break;
    }
    case Qt::Key_A:
      if (e->modifiers() & Qt::ControlModifier) {
        std::set<int> all;
        for (const auto& p : pts) all.insert(p.id);
        model_.setSelection(all);
        break;
      }
      [[fallthrough]];
    default: QWidget::keyPressEvent(e); return;
  }
  e->accept();
}

}  // namespace volpost::tfeditor

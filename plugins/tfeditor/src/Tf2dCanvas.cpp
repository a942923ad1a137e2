// SPDX-License-Identifier: MIT
#include "Tf2dCanvas.hpp"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>

namespace volpost::tfeditor {

namespace {
constexpr double kHandle = 4.0;  // half the side of a handle's square, pixels
}

Tf2dCanvas::Tf2dCanvas(QWidget* parent) : QWidget(parent) {
  setFocusPolicy(Qt::StrongFocus);
  setMouseTracking(false);
  setToolTip("Value across, gradient magnitude up. Drag a widget to move it, its squares to widen or raise it; "
             "double-click to add one; Delete removes the selected one");
}

void Tf2dCanvas::setHistogram(const JointHistogram& h) {
  valueLow_ = h.valueLow;
  valueHigh_ = h.valueHigh;
  gradientHigh_ = h.gradientHigh;
  histogramImage_ = QImage(std::max(h.valueBins, 1), std::max(h.gradientBins, 1), QImage::Format_RGB32);
  histogramImage_.fill(Qt::black);
  const double top = std::log1p(double(h.largest()));
  hasHistogram_ = h.largest() > 0;
  for (int g = 0; g < h.gradientBins; ++g)
    for (int v = 0; v < h.valueBins; ++v) {
      const int gray = top > 0.0 ? int(235.0 * std::log1p(double(h.count(v, g))) / top) : 0;
      histogramImage_.setPixel(v, h.gradientBins - 1 - g, qRgb(gray, gray, gray));  // low gradients at the bottom
    }
  update();
}

void Tf2dCanvas::setWidgets(std::vector<TfWidget2D> widgets) {
  widgets_ = std::move(widgets);
  if (selected_ >= int(widgets_.size())) selected_ = -1;
  update();
}

void Tf2dCanvas::select(int index) {
  selected_ = index >= 0 && index < int(widgets_.size()) ? index : -1;
  update();
  emit selectionChanged(selected_);
}

void Tf2dCanvas::addWidget(TfWidget2D::Shape shape, double value, double gradient) {
  TfWidget2D w;
  w.shape = shape;
  w.value = value;
  w.width = 0.1 * (valueHigh_ - valueLow_);
  w.gradientLow = shape == TfWidget2D::Shape::Triangle ? 0.0 : std::max(0.0, gradient - gradientHigh_ / 6.0);
  w.gradientHigh = std::max(w.gradientLow + gradientHigh_ / 3.0, gradient);
  w.color = {0.9, 0.6, 0.2};
  w.extinction = defaultExtinction_;
  widgets_.push_back(w);
  select(int(widgets_.size()) - 1);
  emit widgetsChanged();
}

void Tf2dCanvas::removeSelected() {
  if (selected_ < 0) return;
  widgets_.erase(widgets_.begin() + selected_);
  select(-1);
  emit widgetsChanged();
}

void Tf2dCanvas::updateSelected(const TfWidget2D& widget) {
  if (selected_ < 0) return;
  widgets_[std::size_t(selected_)] = widget;
  update();
  emit widgetsChanged();
}

QRectF Tf2dCanvas::plotRect() const { return QRectF(6.0, 6.0, std::max(width() - 12.0, 1.0), std::max(height() - 12.0, 1.0)); }

QPointF Tf2dCanvas::toScreen(double value, double gradient) const {
  const QRectF r = plotRect();
  return {r.left() + (value - valueLow_) / (valueHigh_ - valueLow_) * r.width(),
          r.bottom() - gradient / gradientHigh_ * r.height()};
}

QPointF Tf2dCanvas::fromScreen(const QPointF& p) const {
  const QRectF r = plotRect();
  return {valueLow_ + (p.x() - r.left()) / r.width() * (valueHigh_ - valueLow_),
          (r.bottom() - p.y()) / r.height() * gradientHigh_};
}

QPolygonF Tf2dCanvas::outline(const TfWidget2D& w) const {
  const double half = 0.5 * w.width;
  if (w.shape == TfWidget2D::Shape::Triangle)
    return QPolygonF({toScreen(w.value, w.gradientLow), toScreen(w.value + half, w.gradientHigh),
                      toScreen(w.value - half, w.gradientHigh)});
  return QPolygonF({toScreen(w.value - half, w.gradientLow), toScreen(w.value + half, w.gradientLow),
                    toScreen(w.value + half, w.gradientHigh), toScreen(w.value - half, w.gradientHigh)});
}

QPointF Tf2dCanvas::widthHandle(const TfWidget2D& w) const {
  return toScreen(w.value + 0.5 * w.width, w.shape == TfWidget2D::Shape::Triangle ? w.gradientHigh
                                                                                 : 0.5 * (w.gradientLow + w.gradientHigh));
}

QPointF Tf2dCanvas::topHandle(const TfWidget2D& w) const { return toScreen(w.value, w.gradientHigh); }

int Tf2dCanvas::widgetAt(const QPointF& p) const {
  for (int i = int(widgets_.size()) - 1; i >= 0; --i)  // the last drawn is on top
    if (outline(widgets_[std::size_t(i)]).containsPoint(p, Qt::OddEvenFill)) return i;
  return -1;
}

void Tf2dCanvas::paintEvent(QPaintEvent*) {
  QPainter painter(this);
  painter.fillRect(rect(), palette().window());
  const QRectF r = plotRect();
  if (!histogramImage_.isNull()) painter.drawImage(r, histogramImage_);
  painter.setRenderHint(QPainter::Antialiasing);
  for (std::size_t i = 0; i < widgets_.size(); ++i) {
    const TfWidget2D& w = widgets_[i];
    const QColor c = QColor::fromRgbF(float(w.color.r), float(w.color.g), float(w.color.b));
    QColor fill = c;
    fill.setAlphaF(0.45f);
    painter.setBrush(fill);
    painter.setPen(QPen(int(i) == selected_ ? Qt::white : c.darker(150), int(i) == selected_ ? 2.0 : 1.0));
    painter.drawPolygon(outline(w));
  }
  if (selected_ >= 0) {
    const TfWidget2D& w = widgets_[std::size_t(selected_)];
    painter.setBrush(Qt::white);
    painter.setPen(QPen(Qt::black, 1.0));
    for (const QPointF& h : {widthHandle(w), topHandle(w)})
      painter.drawRect(QRectF(h.x() - kHandle, h.y() - kHandle, 2 * kHandle, 2 * kHandle));
  }
  painter.setPen(palette().text().color());
  painter.setBrush(Qt::NoBrush);
  painter.drawRect(r);
  // The axes' ends, inside the corners.
  painter.setPen(Qt::white);
  const QRectF inner = r.adjusted(3, 2, -3, -2);
  painter.drawText(inner, Qt::AlignLeft | Qt::AlignBottom, QString::number(valueLow_, 'g', 4));
  painter.drawText(inner, Qt::AlignRight | Qt::AlignBottom, QString::number(valueHigh_, 'g', 4));
  painter.drawText(inner, Qt::AlignLeft | Qt::AlignTop, QString("gradient %1").arg(gradientHigh_, 0, 'g', 3));
}

void Tf2dCanvas::mousePressEvent(QMouseEvent* e) {
  const QPointF p = e->position();
  drag_ = Drag::None;
  const auto near = [&](const QPointF& h) { return std::abs(p.x() - h.x()) <= kHandle + 2 && std::abs(p.y() - h.y()) <= kHandle + 2; };
  if (selected_ >= 0) {
    const TfWidget2D& w = widgets_[std::size_t(selected_)];
    if (near(widthHandle(w))) drag_ = Drag::Width;
    else if (near(topHandle(w))) drag_ = Drag::Top;
  }
  if (drag_ == Drag::None) {
    const int hit = widgetAt(p);
    if (hit != selected_) select(hit);
    if (hit >= 0) drag_ = Drag::Move;
  }
  if (drag_ != Drag::None) {
    dragStart_ = fromScreen(p);
    dragOriginal_ = widgets_[std::size_t(selected_)];
  }
}

void Tf2dCanvas::mouseMoveEvent(QMouseEvent* e) {
  if (drag_ == Drag::None || selected_ < 0) return;
  const QPointF at = fromScreen(e->position());
  TfWidget2D w = dragOriginal_;
  const double minimumWidth = 1e-3 * (valueHigh_ - valueLow_), minimumHeight = 1e-3 * gradientHigh_;
  switch (drag_) {
    case Drag::Move: {
      w.value += at.x() - dragStart_.x();
      const double shift = std::max(at.y() - dragStart_.y(), -w.gradientLow);  // gradients stay >= 0
      w.gradientLow += shift;
      w.gradientHigh += shift;
      break;
    }
    case Drag::Width: w.width = std::max(2.0 * std::abs(at.x() - w.value), minimumWidth); break;
    case Drag::Top: w.gradientHigh = std::max(at.y(), w.gradientLow + minimumHeight); break;
    case Drag::None: break;
  }
  widgets_[std::size_t(selected_)] = w;
  update();
  emit widgetsChanged();
}

void Tf2dCanvas::mouseReleaseEvent(QMouseEvent*) { drag_ = Drag::None; }

void Tf2dCanvas::mouseDoubleClickEvent(QMouseEvent* e) {
  if (widgetAt(e->position()) >= 0) return;
  const QPointF at = fromScreen(e->position());
  addWidget(TfWidget2D::Shape::Rectangle, at.x(), std::max(at.y(), 0.0));
}

void Tf2dCanvas::keyPressEvent(QKeyEvent* e) {
  if ((e->key() == Qt::Key_Delete || e->key() == Qt::Key_Backspace) && selected_ >= 0) removeSelected();
  else QWidget::keyPressEvent(e);
}

}  // namespace volpost::tfeditor

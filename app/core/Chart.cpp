// SPDX-License-Identifier: MIT
#include "Chart.hpp"

#include "Legend.hpp"

#include <QPainterPath>

#include <algorithm>
#include <cmath>

namespace volpost::app {
namespace {

const QColor kCurveColors[] = {QColor(31, 119, 180),  QColor(214, 39, 40), QColor(44, 160, 44),   QColor(255, 127, 14),
                               QColor(148, 103, 189), QColor(140, 86, 75), QColor(227, 119, 194), QColor(23, 190, 207)};

QString tickText(double v) { return QString::number(v, 'g', 4); }

}  // namespace

void paintChart(QPainter& painter, const QRect& area, const Chart& chart) {
  painter.save();
  painter.setRenderHint(QPainter::Antialiasing);
  QFont font = painter.font();
  font.setPixelSize(std::clamp(area.height() / 30, 9, 40));
  painter.setFont(font);
  const QFontMetrics fm(font);
  double lo = INFINITY, hi = -INFINITY, left = INFINITY, right = -INFINITY;
  for (const ChartCurve& c : chart.curves)
    for (std::size_t i = 0; i < c.x.size() && i < c.y.size(); ++i) {
      if (std::isfinite(c.x[i])) left = std::min(left, c.x[i]), right = std::max(right, c.x[i]);
      if (std::isfinite(c.y[i])) lo = std::min(lo, c.y[i]), hi = std::max(hi, c.y[i]);
    }
  if (!(hi >= lo)) lo = 0.0, hi = 1.0;  // no value: empty axes
  if (hi == lo) lo -= std::max(1.0, std::abs(lo)) * 0.5, hi += std::max(1.0, std::abs(hi)) * 0.5;
  if (!(right >= left)) left = 0.0, right = 1.0;
  if (right == left) left -= 0.5, right += 0.5;
  const auto yTicks = niceTicks(lo, hi, 6);
  const auto xTicks = niceTicks(left, right, 6);
  int labelWidth = 0;
  for (double t : yTicks) labelWidth = std::max(labelWidth, fm.horizontalAdvance(tickText(t)));
  // The key: as many columns (up to 3) as its longest name leaves room for; names are cut
  // with an ellipsis only when one column cannot hold them.
  int nameWidth = 0;
  for (const ChartCurve& c : chart.curves)
    nameWidth = std::max(nameWidth, fm.horizontalAdvance(QString::fromStdString(c.name)));
  const int keyEntry = nameWidth + 40;
  const int columns =
      std::clamp(area.width() / std::max(keyEntry, 1), 1, std::max(1, std::min(3, int(chart.curves.size()))));
  const int keyRows = int((chart.curves.size() + std::size_t(columns) - 1) / std::size_t(columns));
  const int keyHeight = fm.height() * keyRows;
  // Room at the right for half of the last x label, at the left for the y axis's title.
  const int rightMargin = std::max(16, fm.horizontalAdvance(tickText(xTicks.empty() ? right : xTicks.back())) / 2 + 6);
  const QRect plot =
      area.adjusted(labelWidth + 14 + fm.height(), fm.height() + keyHeight + 8, -rightMargin, -2 * fm.height() - 10);
  const auto px = [&](double a) { return plot.left() + (a - left) / (right - left) * plot.width(); };
  const auto py = [&](double v) { return plot.bottom() - (v - lo) / (hi - lo) * plot.height(); };
  painter.setPen(QPen(QColor(225, 225, 225), 1.0));
  for (double t : yTicks) painter.drawLine(QPointF(plot.left(), py(t)), QPointF(plot.right(), py(t)));
  for (double t : xTicks) painter.drawLine(QPointF(px(t), plot.top()), QPointF(px(t), plot.bottom()));
  painter.setPen(QPen(QColor(60, 60, 60), 1.0));
  painter.drawRect(plot);
  for (double t : yTicks)
    painter.drawText(QRectF(area.left(), py(t) - fm.height() / 2.0, labelWidth + 8, fm.height()),
                     Qt::AlignRight | Qt::AlignVCenter, tickText(t));
  for (double t : xTicks)
    painter.drawText(QRectF(px(t) - 50, plot.bottom() + 4, 100, fm.height()), Qt::AlignHCenter | Qt::AlignTop,
                     tickText(t));
  painter.drawText(QRectF(plot.left(), plot.bottom() + 6 + fm.height(), plot.width(), fm.height()), Qt::AlignHCenter,
                   QString::fromStdString(chart.xTitle));
  {  // the y axis's title: the given one, the curve's name, or "value" for several
    painter.save();
    painter.translate(area.left() + 2, plot.center().y());
    painter.rotate(-90.0);
    const QString title = !chart.yTitle.empty()      ? QString::fromStdString(chart.yTitle)
                          : chart.curves.size() == 1 ? QString::fromStdString(chart.curves.front().name)
                                                     : QString("value");
    painter.drawText(QRectF(-plot.height() / 2.0, 0, plot.height(), fm.height()), Qt::AlignHCenter | Qt::AlignTop,
                     fm.elidedText(title, Qt::ElideRight, plot.height()));
    painter.restore();
  }
  // One curve per series; a missing value breaks it; a curve of few points shows them.
  for (std::size_t k = 0; k < chart.curves.size(); ++k) {
    const ChartCurve& c = chart.curves[k];
    const QColor color = kCurveColors[k % std::size(kCurveColors)];
    QPainterPath path;
    std::vector<QPointF> dots;
    bool open = false;
    for (std::size_t i = 0; i < c.x.size() && i < c.y.size(); ++i) {
      if (!std::isfinite(c.y[i]) || !std::isfinite(c.x[i])) {
        open = false;
        continue;
      }
      const QPointF p(px(c.x[i]), py(c.y[i]));
      if (open) path.lineTo(p);
      else path.moveTo(p);
      open = true;
      dots.push_back(p);
    }
    painter.setPen(QPen(color, std::max(1.5, font.pixelSize() / 7.0)));
    painter.drawPath(path);
    if (dots.size() <= 60) {
      painter.setBrush(color);
      const double r = std::max(2.0, font.pixelSize() / 4.0);
      for (const QPointF& d : dots) painter.drawEllipse(d, r, r);
      painter.setBrush(Qt::NoBrush);
    }
    const int column = int(k % std::size_t(columns)), row = int(k / std::size_t(columns));
    const double columnWidth = double(area.width() - 8) / columns;
    const QRectF key(area.left() + 8 + column * columnWidth, area.top() + 4 + row * fm.height(), columnWidth - 8,
                     fm.height());
    painter.drawLine(QPointF(key.left(), key.center().y()), QPointF(key.left() + 18, key.center().y()));
    painter.setPen(QColor(30, 30, 30));
    const QRectF text = key.adjusted(24, 0, 0, 0);
    painter.drawText(text, Qt::AlignLeft | Qt::AlignVCenter,
                     fm.elidedText(QString::fromStdString(c.name), Qt::ElideRight, int(text.width())));
  }
  painter.restore();
}

QImage chartImage(const Chart& chart, int width, int height) {
  QImage image(width, height, QImage::Format_RGB32);
  image.fill(Qt::white);
  QPainter painter(&image);
  paintChart(painter, image.rect(), chart);
  return image;
}

}  // namespace volpost::app

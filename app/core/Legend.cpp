// SPDX-License-Identifier: MIT
#include "Legend.hpp"

#include <QFontMetrics>
#include <QLinearGradient>
#include <QPainter>

#include <algorithm>
#include <cmath>

namespace volpost::app {

std::vector<double> niceTicks(double min, double max, int target) {
  std::vector<double> ticks;
  if (!(max > min) || !std::isfinite(min) || !std::isfinite(max)) {
    ticks.push_back(min);
    return ticks;
  }
  const double rough = (max - min) / std::max(1, target - 1);
  const double mag = std::pow(10.0, std::floor(std::log10(rough)));
  double step = mag;
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * mag >= rough) {
      step = m * mag;
      break;
    }
  // Counted, not accumulated: far from zero (1e17 + a range of 10) adding the step to a
  // tick would not move it, and the loop would never end.
  const double first = std::ceil(min / step - 1e-9), last = std::floor(max / step + 1e-9);
  if (!(step > 0.0) || !std::isfinite(first) || !std::isfinite(last) || last - first > 4.0 * target + 10.0) {
    ticks = {min, max};
    return ticks;
  }
  const auto count = static_cast<long long>(last - first);
  for (long long i = 0; i <= count; ++i) {
    const double t = (first + double(i)) * step;
    if (ticks.empty() || t != ticks.back()) ticks.push_back(std::abs(t) < step * 1e-9 ? 0.0 : t);
  }
  if (ticks.empty()) ticks = {min, max};
  return ticks;
}

std::vector<double> logTicks(double min, double max, int target) {
  if (!(min > 0.0) || !(max > min)) return {min, max};
  const int first = int(std::ceil(std::log10(min) - 1e-9)), last = int(std::floor(std::log10(max) + 1e-9));
  std::vector<double> ticks;
  const int decades = last - first + 1;
  // Every power while there are at most twice as many as asked for, else every k-th.
  const int stride = decades <= 2 * target ? 1 : (decades + target - 1) / std::max(1, target);
  for (int k = first; k <= last; k += stride) ticks.push_back(std::pow(10.0, k));
  if (stride == 1 && int(ticks.size()) < target) {  // few decades: 2 and 5 times each power too
    std::vector<double> more;
    for (int k = first - 1; k <= last; ++k)
      for (const double m : {1.0, 2.0, 5.0}) {
        const double v = m * std::pow(10.0, k);
        if (v >= min * (1.0 - 1e-9) && v <= max * (1.0 + 1e-9)) more.push_back(v);
      }
    if (more.size() >= ticks.size()) ticks = more;
  }
  if (ticks.size() < 2) ticks = {min, max};
  return ticks;
}

QString LegendNumbers::text(double value) const {
  switch (style) {
    case Style::Fixed:
      return QString::number(value, 'f', digits);
    case Style::Scientific:
      return QString::number(value, 'e', digits);
    case Style::Automatic:
      break;
  }
  return QString::number(value, 'g', digits);
}

QString LegendNumbers::widest() const {
  switch (style) {
    case Style::Fixed:
      return "-8888888." + QString(digits, '8');
    case Style::Scientific:
      return "-8." + QString(digits, '8') + "e+888";
    case Style::Automatic:
      break;
  }
  return "-8." + QString(std::max(0, digits - 1), '8') + "e+88";
}

std::optional<LegendNumbers> LegendNumbers::parse(const std::string& text) {
  const auto colon = text.find(':');
  const std::string name = text.substr(0, colon);
  LegendNumbers n;
  if (name == "auto") n.style = Style::Automatic;
  else if (name == "fixed") n.style = Style::Fixed, n.digits = 2;
  else if (name == "scientific") n.style = Style::Scientific, n.digits = 3;
  else return std::nullopt;
  if (colon != std::string::npos) {
    const std::string digits = text.substr(colon + 1);
    if (digits.empty() || digits.size() > 2 || !std::all_of(digits.begin(), digits.end(), ::isdigit))
      return std::nullopt;
    n.digits = std::stoi(digits);
  }
  if (n.digits > 12 || (n.style == Style::Automatic && n.digits < 1)) return std::nullopt;
  return n;
}

std::string LegendNumbers::written() const {
  const char* name = style == Style::Fixed ? "fixed" : style == Style::Scientific ? "scientific" : "auto";
  return std::string(name) + ":" + std::to_string(digits);
}

namespace {

QFont legendFont(QFont font, const QRect& area, double textScale) {
  // In proportion to the picture, readable when small; then as much larger as asked.
  const int size = std::clamp(area.height() / 48, 9, 96);
  font.setPixelSize(std::max(6, int(std::lround(size * textScale))));
  return font;
}

int labelWidthOf(const QFontMetrics& fm, const std::vector<double>& ticks, const LegendNumbers& numbers) {
  int width = 0;
  for (double t : ticks) width = std::max(width, fm.horizontalAdvance(numbers.text(t)));
  return width;
}

// The data's extremes get a digit more than the ticks in the automatic style: they are
// values, not round marks.
QString footerNumber(const LegendNumbers& numbers, double v) {
  if (numbers.style != LegendNumbers::Style::Automatic) return numbers.text(v);
  return QString::number(v, 'g', numbers.digits + 1);
}

int barWidthOf(const QRect& area) { return std::max(8, area.width() / 40); }

// Where a value sits along the bar, 0 at its bottom and 1 at its top.
double barFraction(const LegendContent& c, double v) {
  if (c.logScale && c.min > 0.0 && c.max > c.min)
    return (std::log(v) - std::log(c.min)) / (std::log(c.max) - std::log(c.min));
  return c.max > c.min ? (v - c.min) / (c.max - c.min) : 0.0;
}

// The value at a fraction of the bar (the inverse of barFraction).
double valueAtFraction(const LegendContent& c, double f) {
  if (c.logScale && c.min > 0.0 && c.max > c.min) return c.min * std::pow(c.max / c.min, f);
  return c.min + (c.max - c.min) * f;
}

// The bands' bounds, every one when they fit the bar's height (Abaqus labels all 13 of 12
// bands), else every k-th, the ends always.
std::vector<double> bandBounds(const LegendContent& c, int barHeight, int lineHeight) {
  const int fit = std::max(2, barHeight / std::max(1, lineHeight));
  const int stride = std::max(1, (c.bands + fit - 1) / (fit - 1));
  std::vector<double> bounds;
  for (int b = 0; b <= c.bands; b += stride) bounds.push_back(valueAtFraction(c, double(b) / c.bands));
  if (c.bands % stride != 0) bounds.push_back(c.max);
  return bounds;
}

}  // namespace

QString quantityUnits(const Quantity& q, const QString& fieldUnits) {
  switch (q.op) {
    case ScalarOp::AngleX:
    case ScalarOp::AngleY:
    case ScalarOp::AngleZ:
    case ScalarOp::LodeAngle:
      return "deg";
    case ScalarOp::Triaxiality:
      return {};
    case ScalarOp::DeviatoricJ2:
      return fieldUnits.isEmpty() ? QString() : "(" + fieldUnits + ")^2";
    case ScalarOp::DeviatoricJ3:
      return fieldUnits.isEmpty() ? QString() : "(" + fieldUnits + ")^3";
    default:
      return fieldUnits;
  }
}

QColor textColorOver(bool dark) { return dark ? QColor(235, 235, 235) : QColor(40, 40, 40); }

bool isDarkBackground(const glm::dvec3& rgb) { return 0.2126 * rgb.r + 0.7152 * rgb.g + 0.0722 * rgb.b < 0.5; }

int legendWidth(const QRect& area, const LegendNumbers& numbers, double textScale) {
  // The widest label the number style can give: the strip does not change with the
  // numbers, so the model keeps its place and size when the quantity or step changes.
  const QFontMetrics fm(legendFont(QFont(), area, textScale));
  return fm.horizontalAdvance(numbers.widest()) + 12 + barWidthOf(area) + 8;
}

namespace {

constexpr int kLongestSwatchName = 40;  ///< characters; longer names are cut with an ellipsis

QString swatchName(const QString& name) {
  return name.size() > kLongestSwatchName ? name.left(kLongestSwatchName - 1) + QChar(0x2026) : name;
}

// A key of named colors: the title lines, then one row per color (a box and its name, the
// boxes in a column at the strip's right), as many as fit and a last row saying how many
// more there are.
void paintSwatches(QPainter& painter, const QRect& area, const LegendContent& c, const QFontMetrics& fm) {
  const int textRight = area.right() - 4;
  const QRect titleRect(area.left(), area.top() + 4, textRight - area.left(), fm.height());
  painter.drawText(titleRect, Qt::AlignRight | Qt::AlignVCenter, c.title);
  painter.drawText(titleRect.translated(0, fm.height()), Qt::AlignRight | Qt::AlignVCenter, c.subtitle);
  const int row = fm.height() + 4, box = fm.height();
  const int top = area.top() + 4 + 2 * fm.height() + 8;
  const int fit = std::max(1, (area.bottom() - top) / row);
  const std::size_t shown = c.swatches.size() <= std::size_t(fit) ? c.swatches.size() : std::size_t(fit - 1);
  for (std::size_t i = 0; i < shown; ++i) {
    const int y = top + int(i) * row;
    const QRect r(textRight - box, y, box, box);
    const glm::dvec3& rgb = c.swatches[i].rgb;
    painter.fillRect(r, QColor::fromRgbF(float(rgb.r), float(rgb.g), float(rgb.b)));
    painter.drawRect(r);
    painter.drawText(QRect(area.left(), y, r.left() - 6 - area.left(), box), Qt::AlignRight | Qt::AlignVCenter,
                     swatchName(c.swatches[i].name));
  }
  if (shown < c.swatches.size())
    painter.drawText(QRect(area.left(), top + int(shown) * row, textRight - area.left(), box),
                     Qt::AlignRight | Qt::AlignVCenter, QString("and %1 more").arg(c.swatches.size() - shown));
}

}  // namespace

int legendWidth(const QRect& area, const LegendContent& content) {
  const int bar = legendWidth(area, content.numbers, content.textScale);
  if (content.swatches.empty()) return bar;
  const QFontMetrics fm(legendFont(QFont(), area, content.textScale));
  int widest = 0;
  for (const LegendContent::Swatch& s : content.swatches)
    widest = std::max(widest, fm.horizontalAdvance(swatchName(s.name)));
  return std::max(bar, widest + fm.height() + 6 + 4 + 8);
}

void paintLegend(QPainter& painter, const QRect& area, const ColorMap& map, const LegendContent& c) {
  painter.save();
  painter.setRenderHint(QPainter::Antialiasing, true);
  const QFont font = legendFont(painter.font(), area, c.textScale);
  painter.setFont(font);
  painter.setPen(textColorOver(c.onDark));
  const QFontMetrics fm(font);
  const int barWidth = barWidthOf(area);
  const int top = area.top() + fm.height() * 3, bottom = area.bottom() - fm.height() * 2;
  if (bottom - top < 20) {
    painter.restore();
    return;
  }
  if (!c.swatches.empty()) {
    paintSwatches(painter, area, c, fm);
    painter.restore();
    return;
  }
  const auto footer = [&](int y) {
    // The data's own extremes, whatever range the colors span.
    const double lo = c.dataMin.value_or(c.min), hi = c.dataMax.value_or(c.max);
    const bool differs = c.dataMin && c.dataMax && (lo != c.min || hi != c.max);
    const QString rangeText =
        QString("%1min %2  max %3")
            .arg(differs ? "data " : "", footerNumber(c.numbers, lo), footerNumber(c.numbers, hi));
    painter.drawText(QRect(area.left(), y, area.right() - 4 - area.left(), fm.height()),
                     Qt::AlignRight | Qt::AlignVCenter, rangeText);
    if (c.noValueCount)
      painter.drawText(QRect(area.left(), y + fm.height(), area.right() - 4 - area.left(), fm.height()),
                       Qt::AlignRight | Qt::AlignVCenter,
                       QString("%1 without value (%2)").arg(c.noValueCount).arg(c.noValueShown));
  };
  if (!c.noBarNote.isEmpty()) {
    const QRect titleRect(area.left(), area.top() + 4, area.right() - 4 - area.left(), fm.height());
    painter.setPen(textColorOver(c.onDark));
    painter.drawText(titleRect, Qt::AlignRight | Qt::AlignVCenter, c.title);
    painter.drawText(titleRect.translated(0, fm.height()), Qt::AlignRight | Qt::AlignVCenter, c.subtitle);
    painter.drawText(titleRect.translated(0, 2 * fm.height()), Qt::AlignRight | Qt::AlignVCenter, c.noBarNote);
    footer(area.top() + 4 + 3 * fm.height());
    painter.restore();
    return;
  }
  std::vector<double> ticks = c.bands > 0 ? bandBounds(c, bottom - top, fm.height())
                              : c.logScale && c.min > 0.0 && c.max > c.min
                                  ? logTicks(c.min, c.max, std::clamp(c.labels, 2, 20))
                                  : niceTicks(c.min, c.max, std::clamp(c.labels, 2, 20));
  int labelWidth = labelWidthOf(fm, ticks, c.numbers);
  if (c.aboveColor || c.belowColor) labelWidth = std::max(labelWidth, fm.horizontalAdvance(QStringLiteral("above")));
  const int barRight = area.right() - labelWidth - 12;
  // A box at each end for the colors outside the range, the bar between them.
  const int box = fm.height();
  const QRect bar(barRight - barWidth, top + (c.aboveColor ? box + 3 : 0), barWidth,
                  bottom - top - (c.aboveColor ? box + 3 : 0) - (c.belowColor ? box + 3 : 0));
  const auto endBox = [&](const glm::dvec3& rgb, int y, const QString& label) {
    const QRect r(bar.left(), y, bar.width(), box);
    painter.fillRect(r, QColor::fromRgbF(float(rgb.r), float(rgb.g), float(rgb.b)));
    painter.setPen(textColorOver(c.onDark));
    painter.drawRect(r);
    painter.drawText(QPoint(bar.right() + 7, r.center().y() + fm.ascent() / 2 - 1), label);
  };
  if (c.aboveColor) endBox(*c.aboveColor, top, "above");
  if (c.belowColor) endBox(*c.belowColor, bar.bottom() + 3, "below");

  if (c.bands > 0) {  // each band in the color of its middle, as the surface draws it
    for (int b = 0; b < c.bands; ++b) {
      const auto rgb = map.at((b + 0.5) / c.bands);
      const int y0 = bar.bottom() - int(std::lround(double(b) / c.bands * bar.height()));
      const int y1 = bar.bottom() - int(std::lround(double(b + 1) / c.bands * bar.height()));
      painter.fillRect(QRect(bar.left(), y1, bar.width(), y0 - y1 + 1),
                       QColor::fromRgbF(float(rgb.r), float(rgb.g), float(rgb.b)));
    }
  } else {
    QLinearGradient gradient(bar.bottomLeft(), bar.topLeft());
    for (int i = 0; i <= 32; ++i) {
      const auto rgb = map.at(i / 32.0);
      gradient.setColorAt(i / 32.0, QColor::fromRgbF(float(rgb.r), float(rgb.g), float(rgb.b)));
    }
    painter.fillRect(bar, gradient);
  }
  painter.setPen(textColorOver(c.onDark));
  painter.drawRect(bar);

  for (double t : ticks) {
    const int y = bar.bottom() - int(std::lround(barFraction(c, t) * bar.height()));
    painter.drawLine(bar.right(), y, bar.right() + 4, y);
    painter.drawText(QPoint(bar.right() + 7, y + fm.ascent() / 2 - 1), c.numbers.text(t));
  }
  const int textRight = area.right() - 4;
  const QRect titleRect(area.left(), area.top() + 4, textRight - area.left(), fm.height());
  painter.drawText(titleRect, Qt::AlignRight | Qt::AlignVCenter, c.title);
  painter.drawText(titleRect.translated(0, fm.height()), Qt::AlignRight | Qt::AlignVCenter, c.subtitle);
  footer(bar.bottom() + 4 + (c.belowColor ? box + 3 : 0));
  painter.restore();
}

}  // namespace volpost::app

// SPDX-License-Identifier: MIT
// A chart of curves y(x): axes with "nice" ticks, one colored curve per series with a key,
// gaps where a value is missing (NaN), dots on curves of few points. Painted with
// QPainter, so the window's docks and `volpost plot -o` draw the same chart.
#pragma once

#include <QImage>
#include <QPainter>

#include <string>
#include <vector>

namespace volpost::app {

struct ChartCurve {
  std::string name;       ///< in the key
  std::vector<double> x;  ///< ascending
  std::vector<double> y;  ///< NaN: no value there (the curve breaks)
};

struct Chart {
  std::string xTitle;
  std::string yTitle;  ///< empty: the curve's name when there is one, else "value"
  std::vector<ChartCurve> curves;
};

void paintChart(QPainter& painter, const QRect& area, const Chart& chart);

/// The chart as a picture of this size (white background).
QImage chartImage(const Chart& chart, int width, int height);

}  // namespace volpost::app

// SPDX-License-Identifier: MIT
#include "LinePlot.hpp"

#include "Chart.hpp"

namespace volpost::app {
namespace {

Chart chartOf(const LineSamples& s) {
  Chart chart;
  chart.xTitle = "distance along the line (model units)";
  for (std::size_t k = 0; k < s.keys.size(); ++k) {
    ChartCurve curve;
    curve.name = s.names[k];
    curve.x = s.arcLength;
    for (std::size_t i = 0; i < s.points.size(); ++i) curve.y.push_back(s.value(i, k));
    chart.curves.push_back(std::move(curve));
  }
  return chart;
}

}  // namespace

void paintLinePlot(QPainter& painter, const QRect& area, const LineSamples& samples) {
  paintChart(painter, area, chartOf(samples));
}

QImage linePlotImage(const LineSamples& samples, int width, int height) {
  return chartImage(chartOf(samples), width, height);
}

}  // namespace volpost::app

// SPDX-License-Identifier: MIT
// A chart of sampled quantities against arc length (plot over line): axes with "nice"
// ticks, one colored curve per quantity with a key, gaps where the line leaves the mesh.
// Painted with QPainter, so the window's dock and `volpost plot -o` draw the same chart.
#pragma once

#include "LineSampling.hpp"

#include <QImage>
#include <QPainter>

namespace volpost::app {

void paintLinePlot(QPainter& painter, const QRect& area, const LineSamples& samples);

/// The chart as a picture of this size (white background).
QImage linePlotImage(const LineSamples& samples, int width, int height);

}  // namespace volpost::app

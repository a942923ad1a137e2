// SPDX-License-Identifier: MIT
#include "StreamlineOptions.hpp"

#include <cmath>
#include <stdexcept>

namespace volpost::app {
namespace {

double number(const QCommandLineParser& p, const QCommandLineOption& o, double min) {
  bool ok = false;
  const double v = p.value(o).toDouble(&ok);
  if (!ok || !std::isfinite(v) || v < min)
    throw std::invalid_argument(QString("--%1 %2 is not a number of at least %3")
                                    .arg(o.names().constLast(), p.value(o)).arg(min).toStdString());
  return v;
}

}  // namespace

void StreamlineOptions::apply(const QCommandLineParser& p, StreamlineLayer& layer) const {
  if (p.isSet(seeds)) {
    layer.seeds.clear();
    for (const QString& s : p.values(seeds)) layer.seeds.push_back(s.toStdString());
  }
  if (p.isSet(integrator)) {
    const QString v = p.value(integrator);
    if (v == "rk2") layer.settings.method = StreamlineMethod::RK2;
    else if (v == "rk4") layer.settings.method = StreamlineMethod::RK4;
    else if (v == "rk45") layer.settings.method = StreamlineMethod::RK45;
    else throw std::invalid_argument(QString("--integrator %1 is not one of: rk2, rk4, rk45").arg(v).toStdString());
  }
  if (p.isSet(direction)) {
    const QString v = p.value(direction);
    if (v == "forward") layer.settings.direction = StreamlineDirection::Forward;
    else if (v == "backward") layer.settings.direction = StreamlineDirection::Backward;
    else if (v == "both") layer.settings.direction = StreamlineDirection::Both;
    else throw std::invalid_argument(QString("--direction %1 is not one of: forward, backward, both").arg(v).toStdString());
  }
  if (p.isSet(tolerance)) {
    layer.settings.tolerance = number(p, tolerance, 0.0);
    if (!(layer.settings.tolerance > 0.0)) throw std::invalid_argument("--tolerance must be positive");
  }
  if (p.isSet(maxSteps)) layer.settings.maxSteps = std::size_t(std::min(number(p, maxSteps, 1.0), 1e8));
  if (p.isSet(maxLength)) layer.settings.maxLength = number(p, maxLength, 0.0);
  if (p.isSet(pointSpacing)) layer.settings.pointSpacing = number(p, pointSpacing, 0.0);
  if (p.isSet(colorBy)) layer.colorBy = p.value(colorBy).toStdString();
  if (p.isSet(averageCells)) layer.averageCellVectors = true;
}

}  // namespace volpost::app

// SPDX-License-Identifier: MIT
#include "LineSampling.hpp"

#include "ProbeTable.hpp"

#include <glm/geometric.hpp>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace volpost::app {

double LineSamples::value(std::size_t sample, std::size_t key) const {
  const auto v = points.at(sample).value(keys.at(key));
  return v && points[sample].inside() ? *v : std::numeric_limits<double>::quiet_NaN();
}

LineSamples sampleLine(const ModelSession& session, const glm::dvec3& from, const glm::dvec3& to, std::size_t samples,
                       const std::vector<std::string>& keys, std::size_t step, const Progress& progress) {
  if (samples < 2 || samples > kMaxLineSamples)
    throw std::invalid_argument("a line needs 2 to " + std::to_string(kMaxLineSamples) + " samples, not " +
                                std::to_string(samples));
  const double length = glm::length(to - from);
  if (!(length > 0.0) || !std::isfinite(length)) throw std::invalid_argument("the line's two ends must differ (and be finite)");
  LineSamples out;
  out.from = from;
  out.to = to;
  for (const std::string& key : keys) {
    const Quantity q = session.findQuantity(key);  // throws, naming the valid ones
    out.keys.push_back(q.key());
    out.names.push_back(q.displayName());
  }
  out.points.reserve(samples);
  for (std::size_t i = 0; i < samples; ++i) {
    const double t = double(i) / double(samples - 1);
    out.points.push_back(probeAt(session, from + t * (to - from), step));
    out.arcLength.push_back(t * length);
    if (i % 256 == 0) progress.report(t);
  }
  return out;
}

std::string lineTable(const LineSamples& s) {
  std::string out = "arc_length,x,y,z,element";
  for (const std::string& key : s.keys) out += "," + key;
  out += "\n";
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    const ProbeResult& r = s.points[i];
    out += exactNumber(s.arcLength[i]) + "," + exactNumber(r.point.x) + "," + exactNumber(r.point.y) + "," +
           exactNumber(r.point.z) + "," + (r.inside() ? std::to_string(r.cellId) : std::string());
    for (std::size_t k = 0; k < s.keys.size(); ++k) out += "," + exactNumber(s.value(i, k));
    out += "\n";
  }
  return out;
}

}  // namespace volpost::app

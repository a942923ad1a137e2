// SPDX-License-Identifier: MIT
#include "History.hpp"

#include "Probe.hpp"
#include "ProbeTable.hpp"

#include <cmath>
#include <limits>

namespace volpost::app {
namespace {

ProbeResult probePlace(const ModelSession& session, const HistoryPlace& place, std::size_t step) {
  switch (place.kind) {
    case HistoryPlace::Kind::Node:
      return probeNode(session, place.id, step);
    case HistoryPlace::Kind::Element:
      return probeElement(session, place.id, step);
    case HistoryPlace::Kind::Point:
      break;
  }
  return probeAt(session, place.point, step);
}

// A CSV field: quoted when it holds a comma, a quote or a line break (step labels may).
std::string csvField(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string out = "\"";
  for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

bool increasing(const std::vector<double>& v) {
  for (std::size_t i = 1; i < v.size(); ++i)
    if (!(v[i] > v[i - 1])) return false;
  return v.size() > 1;
}

}  // namespace

std::string HistoryPlace::label() const {
  switch (kind) {
    case Kind::Node:
      return "node " + std::to_string(id);
    case Kind::Element:
      return "element " + std::to_string(id);
    case Kind::Point:
      break;
  }
  return "(" + exactNumber(point.x) + ", " + exactNumber(point.y) + ", " + exactNumber(point.z) + ")";
}

History sampleHistory(const ModelSession& session, const std::vector<HistoryPlace>& places,
                      const std::vector<std::string>& keys, const Progress& progress) {
  if (places.empty()) throw std::invalid_argument("a history needs a node, an element or a point");
  if (keys.empty()) throw std::invalid_argument("a history needs a quantity");
  if (places.size() * keys.size() > kMaxHistoryCurves)
    throw std::invalid_argument(std::to_string(places.size() * keys.size()) +
                                " curves (places x quantities); at most " + std::to_string(kMaxHistoryCurves));
  History h;
  const Field* longest = nullptr;
  std::vector<const Field*> fields;
  for (const std::string& key : keys) {
    const Field& f = session.fieldOf(session.findQuantity(key));  // throws naming the valid ones
    fields.push_back(&f);
    if (!longest || f.stepCount() > longest->stepCount()) longest = &f;
  }
  for (const Step& s : longest->steps()) {
    h.stepLabels.push_back(s.label);
    h.times.push_back(s.time);
  }
  h.byTime = increasing(h.times);
  for (const HistoryPlace& place : places)
    for (const std::string& key : keys) {
      const Quantity q = session.findQuantity(key);
      h.curves.push_back({q.key(), place.label(), q.displayName(), q.displayName() + " at " + place.label(), {}});
    }
  const std::size_t steps = h.times.size();
  for (std::size_t p = 0; p < places.size(); ++p) {
    (void)probePlace(session, places[p], 0);  // an unknown id throws before the long part
    for (std::size_t s = 0; s < steps; ++s) {
      const ProbeResult r = probePlace(session, places[p], s);
      for (std::size_t k = 0; k < keys.size(); ++k) {
        const bool has = s < fields[k]->stepCount() && r.inside();
        const auto v = has ? r.value(h.curves[p * keys.size() + k].key) : std::nullopt;
        h.curves[p * keys.size() + k].values.push_back(v ? *v : std::numeric_limits<double>::quiet_NaN());
      }
      progress.report(double(p * steps + s + 1) / double(places.size() * steps));
    }
  }
  return h;
}

std::string historyTable(const History& h) {
  std::string out = "step,label,time";
  for (const History::Curve& c : h.curves) out += "," + csvField(c.key + " at " + c.place);
  out += "\n";
  for (std::size_t s = 0; s < h.times.size(); ++s) {
    out += std::to_string(s + 1) + "," + csvField(h.stepLabels[s]) + "," + exactNumber(h.times[s]);
    for (const History::Curve& c : h.curves) out += "," + exactNumber(c.values[s]);
    out += "\n";
  }
  return out;
}

Chart historyChart(const History& h) {
  Chart chart;
  chart.xTitle = h.byTime ? "time" : "step";
  // One quantity at several places: it names the y axis.
  bool oneQuantity = !h.curves.empty();
  for (const History::Curve& c : h.curves) oneQuantity = oneQuantity && c.key == h.curves.front().key;
  if (oneQuantity) chart.yTitle = h.curves.front().quantityName;
  for (const History::Curve& c : h.curves) {
    ChartCurve curve;
    curve.name = c.name;
    for (std::size_t s = 0; s < c.values.size(); ++s) curve.x.push_back(h.byTime ? h.times[s] : double(s + 1));
    curve.y = c.values;
    chart.curves.push_back(std::move(curve));
  }
  return chart;
}

}  // namespace volpost::app

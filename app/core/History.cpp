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
    case HistoryPlace::Kind::SetMax:
    case HistoryPlace::Kind::SetMin:
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

bool isSetExtreme(const HistoryPlace& place) {
  return place.kind == HistoryPlace::Kind::SetMax || place.kind == HistoryPlace::Kind::SetMin;
}

// Which values of a quantity the set holds: per node (a node set's nodes, an element set's
// elements' nodes) or per element (an element set's elements). Throws std::invalid_argument
// for an unknown set (naming the sets there are) or a node set of a per-element quantity.
std::vector<std::uint32_t> setValueIndices(const ModelSession& session, const std::string& name, FieldLocation location,
                                           const std::string& key) {
  const std::vector<EntitySet> sets = modelSets(session.model());
  const EntitySet* s = findSet(sets, name);
  if (!s) {
    std::string all;
    for (const EntitySet& e : sets) all += (all.empty() ? "" : ", ") + e.name;
    throw std::invalid_argument("no set is named '" + name + "' (" +
                                (all.empty() ? std::string("this model has no sets") : "its sets: " + all) + ")");
  }
  if (location == FieldLocation::Cell) {
    if (s->kind == SetKind::Nodes)
      throw std::invalid_argument(key + " is given per element; its extreme over the node set " + s->name +
                                  " needs an element set");
    return s->members;
  }
  if (s->kind == SetKind::Nodes) return s->members;
  const Mesh& mesh = session.model().mesh();
  std::vector<std::uint32_t> nodes;
  for (const std::uint32_t c : s->members)
    if (c < mesh.cellCount())
      for (const NodeIndex n : mesh.cellNodes(c)) nodes.push_back(n);
  normalizeMembers(nodes);
  return nodes;
}

// The set's largest (smallest) finite value of `view`; NaN when it has none.
double extremeOver(const ScalarView& view, const std::vector<std::uint32_t>& indices, bool largest) {
  double best = std::numeric_limits<double>::quiet_NaN();
  for (const std::uint32_t i : indices) {
    if (i >= view.values.size()) continue;
    const double v = view.values[i];
    if (std::isfinite(v) && (std::isnan(best) || (largest ? v > best : v < best))) best = v;
  }
  return best;
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
    case Kind::SetMax:
      return "max over " + set;
    case Kind::SetMin:
      return "min over " + set;
    case Kind::Point:
      break;
  }
  return "(" + exactNumber(point.x) + ", " + exactNumber(point.y) + ", " + exactNumber(point.z) + ")";
}

History sampleHistory(const ModelSession& session, const std::vector<HistoryPlace>& places,
                      const std::vector<std::string>& keys, const Progress& progress) {
  if (places.empty()) throw std::invalid_argument("a history needs a node, an element, a point or a set");
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
  // The sets' members first: an unknown set throws before the long part.
  std::vector<std::vector<std::vector<std::uint32_t>>> members(places.size());
  for (std::size_t p = 0; p < places.size(); ++p)
    if (isSetExtreme(places[p]))
      for (std::size_t k = 0; k < keys.size(); ++k)
        members[p].push_back(setValueIndices(session, places[p].set, fields[k]->location(), keys[k]));
  for (std::size_t p = 0; p < places.size(); ++p) {
    if (isSetExtreme(places[p])) {
      for (std::size_t s = 0; s < steps; ++s) {
        for (std::size_t k = 0; k < keys.size(); ++k) {
          History::Curve& curve = h.curves[p * keys.size() + k];
          curve.values.push_back(s < fields[k]->stepCount()
                                     ? extremeOver(session.evaluate(session.findQuantity(keys[k]), s), members[p][k],
                                                   places[p].kind == HistoryPlace::Kind::SetMax)
                                     : std::numeric_limits<double>::quiet_NaN());
        }
        progress.report(double(p * steps + s + 1) / double(places.size() * steps));
      }
      continue;
    }
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

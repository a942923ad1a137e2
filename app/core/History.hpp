// SPDX-License-Identifier: MIT
// History plots: quantities against the step (or the time, where the file gives steps
// increasing times) at nodes, elements or points, one curve per place and quantity, as a
// chart and a table. The window's probe panel and `volpost plot --history` ask here.
#pragma once

#include "Chart.hpp"
#include "ModelSession.hpp"

#include <glm/vec3.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace volpost::app {

/// Where a history is taken: a node or an element by the file's id, a point, or the
/// largest (smallest) value over a set at each step: over a node set's nodes or an element
/// set's elements (a nodal quantity: their nodes).
struct HistoryPlace {
  enum class Kind { Node, Element, Point, SetMax, SetMin };
  Kind kind = Kind::Point;
  std::int64_t id = 0;
  glm::dvec3 point{0.0};
  std::string set{};  ///< SetMax, SetMin: the set's name
  /// "node 5484", "element 15600", "(5, 0.5, 0.5)", "max over E_TET", "min over FIXED"
  std::string label() const;
};

struct History {
  std::vector<std::string> stepLabels;  ///< of the longest field read
  std::vector<double> times;
  /// The x axis: the steps' times when they increase (a transient), else step numbers.
  bool byTime = false;
  struct Curve {
    std::string key;             ///< the quantity's written form
    std::string place;           ///< HistoryPlace::label
    std::string quantityName;    ///< "S von Mises"
    std::string name;            ///< "S von Mises at node 5484"
    std::vector<double> values;  ///< one per step; NaN where the field has no such step or the point is outside
  };
  std::vector<Curve> curves;
};

/// The most places times quantities one history holds.
inline constexpr std::size_t kMaxHistoryCurves = 64;

/// Every quantity at every place, at every step. Throws std::invalid_argument for an
/// unknown quantity or id, no places or quantities, or more than kMaxHistoryCurves curves.
History sampleHistory(const ModelSession& session, const std::vector<HistoryPlace>& places,
                      const std::vector<std::string>& keys, const Progress& progress = {});

/// Comma-separated: step, label, time, then one column per curve, full precision.
std::string historyTable(const History& history);
Chart historyChart(const History& history);

}  // namespace volpost::app

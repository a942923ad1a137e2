// SPDX-License-Identifier: MIT
// Threshold: only the cells whose value lies in a range are drawn: a per-element result
// by the element's own value, a nodal one by the values at all of its nodes or at any of
// them. The kept cells make a model of their own (the nodes and their fields shared, the
// element results cut to the kept cells, each cell keeping the file's number), so the
// surface, the sections, iso-surfaces, the volume, probing and the extremes all follow it.
#pragma once

#include "ModelSession.hpp"

#include <memory>
#include <string>

namespace volpost::app {

struct ThresholdLayer {
  bool shown = false;
  std::string quantity;  ///< written form ("S.mises", "region")
  double min = 0.0, max = 0.0;
  /// A nodal quantity: a cell is kept when all its nodes' values lie in the range (off:
  /// when any does). Per-element quantities use the element's value.
  bool allNodes = true;
  bool operator==(const ThresholdLayer&) const = default;
};

/// Throws std::invalid_argument for an unknown quantity (naming the choices), or a range
/// that is not finite with min <= max.
void checkThreshold(const ModelSession& session, const ThresholdLayer& layer);
/// The model of the kept cells at `step` (the quantity's last when it has fewer). Keeps
/// every node (their indices, so nodal fields are shared as they are). Cells with no value
/// (NaN) are dropped. May keep no cell at all.
std::shared_ptr<ModelSession> thresholdedSession(const ModelSession& session, const ThresholdLayer& layer,
                                                 std::size_t step);

}  // namespace volpost::app

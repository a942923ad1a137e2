// SPDX-License-Identifier: MIT
#include "Threshold.hpp"

#include "CellSubset.hpp"

#include <cmath>
#include <stdexcept>

namespace volpost::app {
namespace {

std::vector<char> keptCells(const ModelSession& session, const ThresholdLayer& t, std::size_t step) {
  const Quantity q = session.findQuantity(t.quantity);
  const ScalarView view = session.evaluate(q, std::min(step, session.fieldOf(q).stepCount() - 1));
  const Mesh& mesh = session.model().mesh();
  const auto inside = [&](double v) { return v >= t.min && v <= t.max; };  // NaN: never
  std::vector<char> kept(mesh.cellCount(), 0);
  for (std::size_t c = 0; c < mesh.cellCount(); ++c) {
    if (view.location == FieldLocation::Cell) {
      kept[c] = c < view.values.size() && inside(view.values[c]);
      continue;
    }
    bool all = true, any = false;
    for (const NodeIndex n : mesh.cellNodes(c)) {
      const bool in = n < view.values.size() && inside(view.values[n]);
      all = all && in;
      any = any || in;
    }
    kept[c] = t.allNodes ? all : any;
  }
  return kept;
}

}  // namespace

void checkThreshold(const ModelSession& session, const ThresholdLayer& layer) {
  if (!layer.shown) return;
  (void)session.findQuantity(layer.quantity);  // throws naming the quantities
  if (!std::isfinite(layer.min) || !std::isfinite(layer.max) || !(layer.min <= layer.max))
    throw std::invalid_argument("a threshold needs a finite range MIN:MAX with MIN <= MAX");
}

std::shared_ptr<ModelSession> thresholdedSession(const ModelSession& session, const ThresholdLayer& layer,
                                                 std::size_t step) {
  checkThreshold(session, layer);
  const std::vector<char> kept = keptCells(session, layer, step);
  return cellSubsetSession(session, kept);
}

}  // namespace volpost::app

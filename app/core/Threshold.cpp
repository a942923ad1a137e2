// SPDX-License-Identifier: MIT
#include "Threshold.hpp"

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

// A per-element field cut to the kept cells, read from the whole one step by step.
std::shared_ptr<Field> keptPart(const std::shared_ptr<Field>& whole,
                                std::shared_ptr<const std::vector<std::size_t>> cells) {
  const int width = whole->components();
  auto loader = [whole, cells, width](std::size_t step) {
    const std::vector<double>& all = whole->values(step);
    std::vector<double> out;
    out.reserve(cells->size() * std::size_t(width));
    for (const std::size_t c : *cells)
      for (int k = 0; k < width; ++k) {
        const std::size_t i = c * std::size_t(width) + std::size_t(k);
        out.push_back(i < all.size() ? all[i] : std::numeric_limits<double>::quiet_NaN());
      }
    return out;
  };
  return std::make_shared<Field>(whole->name(), FieldLocation::Cell, width, cells->size(), whole->steps(),
                                 std::move(loader));
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
  const Model& whole = session.model();
  const Mesh& from = whole.mesh();
  auto cells = std::make_shared<std::vector<std::size_t>>();
  for (std::size_t c = 0; c < kept.size(); ++c)
    if (kept[c]) cells->push_back(c);
  auto model = std::make_shared<Model>();
  model->sourcePath = whole.sourcePath;
  model->formatName = whole.formatName;
  model->title = whole.title;
  model->diagnostics = whole.diagnostics;
  Mesh mesh;
  mesh.nodes = from.nodes;
  mesh.nodeIds = from.nodeIds;
  std::size_t entries = 0;
  for (const std::size_t c : *cells) entries += from.cellNodes(c).size();
  mesh.reserveCells(cells->size(), entries);
  mesh.cellIds.reserve(cells->size());
  for (const std::size_t c : *cells) {
    mesh.addCell(from.cellType(c), from.cellNodes(c));
    mesh.cellIds.push_back(from.cellId(c));  // the file's numbers, not the positions in the part
  }
  model->setMesh(std::move(mesh));
  const std::shared_ptr<const std::vector<std::size_t>> shared = cells;
  for (const auto& f : whole.fields)
    model->fields.push_back(f->location() == FieldLocation::Cell ? keptPart(f, shared) : f);
  return ModelSession::fromModel(std::move(model));
}

}  // namespace volpost::app

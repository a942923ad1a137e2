// SPDX-License-Identifier: MIT
#include "CellSubset.hpp"

#include <limits>

namespace volpost::app {
namespace {

constexpr std::uint32_t kNotKept = 0xffffffffu;

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

std::shared_ptr<ModelSession> cellSubsetSession(const ModelSession& session, const std::vector<char>& kept) {
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
  // The sets name the part's cells: each element set keeps its members that are kept.
  std::vector<std::uint32_t> newIndex(from.cellCount(), kNotKept);
  for (std::size_t i = 0; i < cells->size(); ++i) newIndex[(*cells)[i]] = std::uint32_t(i);
  for (EntitySet set : whole.sets) {
    if (set.kind == SetKind::Cells) {
      std::vector<std::uint32_t> members;
      for (const std::uint32_t c : set.members)
        if (c < newIndex.size() && newIndex[c] != kNotKept) members.push_back(newIndex[c]);
      set.members = std::move(members);
    }
    model->sets.push_back(std::move(set));
  }
  const std::shared_ptr<const std::vector<std::size_t>> shared = cells;
  for (const auto& f : whole.fields)
    model->fields.push_back(f->location() == FieldLocation::Cell ? keptPart(f, shared) : f);
  return ModelSession::fromModel(std::move(model));
}

}  // namespace volpost::app

// SPDX-License-Identifier: MIT
#include "SetVisibility.hpp"

#include "CellSubset.hpp"

#include <algorithm>
#include <stdexcept>

namespace volpost::app {
namespace {

std::string choices(const std::vector<EntitySet>& sets) {
  std::string out;
  for (const EntitySet& s : sets)
    if (s.kind == SetKind::Cells) out += (out.empty() ? "" : ", ") + s.name;
  return out.empty() ? "this model has no element sets" : "its element sets: " + out;
}

const EntitySet& elementSet(const std::vector<EntitySet>& sets, const std::string& name) {
  const EntitySet* s = findSet(sets, name);
  if (!s) throw std::invalid_argument("no set is named '" + name + "' (" + choices(sets) + ")");
  if (s->kind != SetKind::Cells)
    throw std::invalid_argument("'" + name + "' is a set of " + std::to_string(s->members.size()) +
                                " nodes; only element sets can be shown or hidden (" + choices(sets) + ")");
  return *s;
}

// The set to mark, of either kind (a copy: the sets are made on each call); throws naming
// the sets there are.
EntitySet markedSet(const ModelSession& session, const std::string& name) {
  const std::vector<EntitySet> sets = modelSets(session.model());
  if (const EntitySet* s = findSet(sets, name)) return *s;
  std::string all;
  for (const EntitySet& e : sets) all += (all.empty() ? "" : ", ") + e.name;
  throw std::invalid_argument("no set is named '" + name + "' (" +
                              (all.empty() ? std::string("this model has no sets") : "its sets: " + all) + ")");
}

}  // namespace

std::vector<char> cellsOfSets(const ModelSession& session, const SetVisibility& v) {
  const std::vector<EntitySet> sets = modelSets(session.model());
  const std::size_t cells = session.model().cellCount();
  std::vector<char> kept(cells, v.shown.empty() ? 1 : 0);
  const auto mark = [&](const std::string& name, char value) {
    for (const std::uint32_t c : elementSet(sets, name).members)
      if (c < cells) kept[c] = value;
  };
  for (const std::string& name : v.shown) mark(name, 1);
  for (const std::string& name : v.hidden) mark(name, 0);
  return kept;
}

MarkedMembers markedMembers(const ModelSession& session, const std::string& name) {
  const EntitySet set = markedSet(session, name);
  const EntitySet* s = &set;
  MarkedMembers out;
  out.kind = s->kind;
  const Model& model = session.model();
  if (!model.meshBuilt()) return out;
  const Mesh& mesh = model.mesh();
  std::vector<char> marked(mesh.nodeCount(), 0);
  if (s->kind == SetKind::Cells) {
    for (const std::uint32_t c : s->members)
      if (c < mesh.cellCount()) {
        out.cells.push_back(c);
        for (const NodeIndex n : mesh.cellNodes(c)) marked[n] = 1;
      }
  } else {
    std::vector<char> used(mesh.nodeCount(), 0);  // a node of a hidden part is not there to mark
    for (const NodeIndex n : mesh.connectivity()) used[n] = 1;
    for (const std::uint32_t n : s->members)
      if (n < used.size() && used[n]) marked[n] = 1;
  }
  for (std::size_t n = 0; n < marked.size(); ++n)
    if (marked[n]) out.nodes.push_back(std::uint32_t(n));
  return out;
}

void checkSetVisibility(const ModelSession& session, const SetVisibility& v) {
  if (!v.marked.empty()) (void)markedSet(session, v.marked);
  if (v.colors) {
    const std::vector<EntitySet> sets = modelSets(session.model());
    if (std::none_of(sets.begin(), sets.end(), [](const EntitySet& s) { return s.kind == SetKind::Cells; }))
      throw std::invalid_argument("this model has no element sets to color by (volpost info lists its sets)");
  }
  if (!v.active()) return;
  const std::vector<char> kept = cellsOfSets(session, v);  // throws for unknown names
  if (std::find(kept.begin(), kept.end(), 1) == kept.end())
    throw std::invalid_argument(v.shown.empty() ? "hiding these sets leaves no element to draw"
                                                : "the shown sets less the hidden ones leave no element to draw");
}

std::shared_ptr<const ModelSession> setVisibleSession(std::shared_ptr<const ModelSession> session,
                                                      const SetVisibility& v) {
  if (!v.active()) return session;
  return cellSubsetSession(*session, cellsOfSets(*session, v));
}

}  // namespace volpost::app

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

void checkSetVisibility(const ModelSession& session, const SetVisibility& v) {
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

// SPDX-License-Identifier: MIT
#include "Selection.hpp"

#include <algorithm>
#include <charconv>
#include <stdexcept>
#include <unordered_map>

namespace volpost::app {
namespace {

// Index of each id, for `count` entities whose id `idOf` gives.
template <class IdOf>
std::unordered_map<std::int64_t, std::uint32_t> indexOfIds(std::size_t count, IdOf idOf) {
  std::unordered_map<std::int64_t, std::uint32_t> out;
  out.reserve(count);
  for (std::size_t i = 0; i < count; ++i) out.emplace(idOf(i), std::uint32_t(i));
  return out;
}

template <class IdOf>
EntitySet setOf(const char* name, SetKind kind, const std::vector<std::int64_t>& ids, std::size_t count, IdOf idOf) {
  EntitySet set{name, kind, kSelectionOrigin, {}};
  const auto index = indexOfIds(count, idOf);
  for (const std::int64_t id : ids) {
    const auto at = index.find(id);
    if (at == index.end())
      throw std::invalid_argument("the model has no " + std::string(kind == SetKind::Cells ? "element" : "node") + " " +
                                  std::to_string(id) + " to select");
    set.members.push_back(at->second);
  }
  normalizeMembers(set.members);
  return set;
}

std::int64_t idIn(std::string_view text, const std::string& whole) {
  std::int64_t v = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (error != std::errc() || end != text.data() + text.size())
    throw std::invalid_argument("'" + std::string(text) + "' in '" + whole + "' is not an id");
  return v;
}

}  // namespace

void normalizeIds(std::vector<std::int64_t>& ids) {
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
}

std::vector<EntitySet> selectionSets(const ModelSession& session, const Selection& selection) {
  if (selection.elements.size() > kMaxSelected || selection.nodes.size() > kMaxSelected)
    throw std::invalid_argument("at most " + std::to_string(kMaxSelected) + " elements and nodes can be selected");
  std::vector<EntitySet> out;
  const Model& model = session.model();
  if (selection.empty()) return out;
  if (!model.meshBuilt()) throw std::invalid_argument("a regular grid has no elements or nodes to select");
  const Mesh& mesh = model.mesh();
  if (!selection.elements.empty())
    out.push_back(setOf(kSelectedElements, SetKind::Cells, selection.elements, mesh.cellCount(),
                        [&](std::size_t c) { return mesh.cellId(c); }));
  if (!selection.nodes.empty())
    out.push_back(setOf(kSelectedNodes, SetKind::Nodes, selection.nodes, mesh.nodeCount(),
                        [&](std::size_t n) { return mesh.nodeId(n); }));
  return out;
}

namespace {

// The ids and ranges of "101,105-110" as [first, last] pairs, in the order written.
std::vector<std::pair<std::int64_t, std::int64_t>> idRanges(const std::string& text) {
  std::vector<std::pair<std::int64_t, std::int64_t>> out;
  std::size_t start = 0, total = 0;
  while (start <= text.size()) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    std::string_view part(text.data() + start, comma - start);
    while (!part.empty() && part.front() == ' ') part.remove_prefix(1);
    while (!part.empty() && part.back() == ' ') part.remove_suffix(1);
    if (part.empty()) throw std::invalid_argument("'" + text + "' has an empty id between commas");
    const std::size_t dash = part.find('-', 1);  // a leading '-' is a negative id's sign
    if (dash == std::string_view::npos) {
      const std::int64_t id = idIn(part, text);
      out.emplace_back(id, id);
    } else {
      const std::int64_t first = idIn(part.substr(0, dash), text), last = idIn(part.substr(dash + 1), text);
      if (last < first) throw std::invalid_argument("the range " + std::string(part) + " runs backwards");
      out.emplace_back(first, last);
    }
    const std::uint64_t span = std::uint64_t(out.back().second) - std::uint64_t(out.back().first);
    if (span >= kMaxSelected || (total += span + 1) > kMaxSelected)
      throw std::invalid_argument("'" + (text.size() > 40 ? text.substr(0, 40) + "..." : text) + "' names more than " +
                                  std::to_string(kMaxSelected) + " ids");
    start = comma + 1;
  }
  return out;
}

}  // namespace

std::vector<std::int64_t> parseIdList(const std::string& text) {
  std::vector<std::int64_t> ids;
  for (const auto& [first, last] : idRanges(text))
    for (std::int64_t id = first;; ++id) {
      ids.push_back(id);
      if (id == last) break;
    }
  normalizeIds(ids);
  return ids;
}

std::vector<std::int64_t> idsInModel(const std::string& text, const ModelSession& session, SetKind kind) {
  const Model& model = session.model();
  if (!model.meshBuilt()) throw std::invalid_argument("a regular grid has no elements or nodes to select");
  const Mesh& mesh = model.mesh();
  const bool cells = kind == SetKind::Cells;
  std::vector<std::int64_t> present;
  const std::size_t count = cells ? mesh.cellCount() : mesh.nodeCount();
  for (std::size_t i = 0; i < count; ++i) present.push_back(cells ? mesh.cellId(i) : mesh.nodeId(i));
  normalizeIds(present);
  const char* what = cells ? "element" : "node";
  std::vector<std::int64_t> ids;
  for (const auto& [first, last] : idRanges(text)) {
    const auto from = std::lower_bound(present.begin(), present.end(), first);
    const auto to = std::upper_bound(from, present.end(), last);
    if (from == to)
      throw std::invalid_argument(first == last ? "the model has no " + std::string(what) + " " + std::to_string(first)
                                                : "the model has no " + std::string(what) + " numbered " +
                                                      std::to_string(first) + " to " + std::to_string(last));
    ids.insert(ids.end(), from, to);
  }
  normalizeIds(ids);
  return ids;
}

std::string idListText(const std::vector<std::int64_t>& ids) {
  std::string out;
  for (std::size_t i = 0; i < ids.size();) {
    std::size_t j = i;
    while (j + 1 < ids.size() && ids[j + 1] == ids[j] + 1) ++j;
    if (!out.empty()) out += ',';
    out += std::to_string(ids[i]);
    if (j > i) out += '-' + std::to_string(ids[j]);
    i = j + 1;
  }
  return out;
}

}  // namespace volpost::app

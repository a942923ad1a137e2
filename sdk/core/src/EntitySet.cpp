// SPDX-License-Identifier: MIT
#include <volpost/core/EntitySet.hpp>
#include <volpost/core/Model.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>

namespace volpost {
namespace {

constexpr std::size_t kMaxOfferedGroups = 64;

std::string lower(std::string s) {
  for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::string valueName(double v) { return std::to_string(static_cast<long long>(v)); }

// The groups an integer cell field offers: one per value, or none where it is not a
// small set of integers.
std::vector<EntitySet> groupsOfField(const Field& field) {
  if (field.location() != FieldLocation::Cell || field.components() != 1 || field.stepCount() != 1) return {};
  const std::vector<double>* read = nullptr;
  try {
    read = &field.values(0);
  } catch (const std::exception&) {
    return {};  // a step that cannot be read offers no groups (info says why)
  }
  const std::vector<double>& values = *read;
  std::map<double, std::vector<std::uint32_t>> byValue;
  for (std::size_t c = 0; c < values.size(); ++c) {
    const double v = values[c];
    if (!std::isfinite(v) || v != std::floor(v) || std::fabs(v) > 1e15) return {};
    auto& members = byValue[v];
    members.push_back(std::uint32_t(c));
    if (byValue.size() > kMaxOfferedGroups) return {};
  }
  if (byValue.size() < 2) return {};
  std::vector<EntitySet> out;
  for (auto& [value, members] : byValue)
    out.push_back({field.name() + " " + valueName(value), SetKind::Cells, "cell field", std::move(members)});
  return out;
}

}  // namespace

const char* setKindName(SetKind kind) { return kind == SetKind::Cells ? "elements" : "nodes"; }

void normalizeMembers(std::vector<std::uint32_t>& members) {
  std::sort(members.begin(), members.end());
  members.erase(std::unique(members.begin(), members.end()), members.end());
}

std::vector<EntitySet> modelSets(const Model& model) {
  // The user's selection (sets of origin "selection", which the window and `render
  // --select-elements` add) is no set of the file's: it comes last and leaves the groups
  // a region field offers where the file defines no element set.
  std::vector<EntitySet> out, selected;
  for (const EntitySet& s : model.sets) (s.origin == "selection" ? selected : out).push_back(s);
  const bool fileHasElementSets =
      std::any_of(out.begin(), out.end(), [](const EntitySet& s) { return s.kind == SetKind::Cells; });
  if (!fileHasElementSets && !model.grid)
    for (const auto& f : model.fields)
      for (EntitySet& g : groupsOfField(*f)) out.push_back(std::move(g));
  out.insert(out.end(), std::make_move_iterator(selected.begin()), std::make_move_iterator(selected.end()));
  return out;
}

const EntitySet* findSet(const std::vector<EntitySet>& sets, const std::string& name) {
  for (const EntitySet& s : sets)
    if (s.name == name) return &s;
  const std::string wanted = lower(name);
  for (const EntitySet& s : sets)
    if (lower(s.name) == wanted) return &s;
  return nullptr;
}

}  // namespace volpost

// SPDX-License-Identifier: MIT
#include "DeckSets.hpp"

#include <cctype>

namespace volpost::meshio {
namespace {

// A GENERATE line may not produce more ids than this (a typo such as "1, 2000000000, 1"
// would otherwise ask for gigabytes).
constexpr std::int64_t kMaxGenerated = 100'000'000;

bool isNumber(std::string_view f) {
  return !f.empty() && (std::isdigit(static_cast<unsigned char>(f.front())) || f.front() == '-' || f.front() == '+');
}

}  // namespace

DeckSets::Written& DeckSets::set(SetKind kind, const std::string& name) {
  const auto [it, added] = index_.emplace(std::make_pair(kind, name), sets_.size());
  if (added) sets_.push_back({name, kind, {}, {}});
  return sets_[it->second];
}

void DeckSets::begin(SetKind kind, const std::string& name, bool generate) {
  (void)set(kind, name);
  current_ = index_.at({kind, name});
  generate_ = generate;
}

void DeckSets::addId(SetKind kind, const std::string& name, std::int64_t id) {
  if (!name.empty()) set(kind, name).ids.push_back(id);
}

void DeckSets::readLine(TextScanner& s, std::string_view line) {
  if (!current_) return;
  Written& target = sets_[*current_];
  std::vector<std::string_view> fields;
  for (auto f : splitFields(line, true))
    if (!trim(f).empty()) fields.push_back(trim(f));
  const char* what = target.kind == SetKind::Cells ? "an element id" : "a node id";
  if (generate_) {
    if (fields.size() < 2 || fields.size() > 3) s.fail("a GENERATE line of a set reads 'first, last[, step]'");
    const std::int64_t first = parseInteger(s, fields[0], what), last = parseInteger(s, fields[1], what);
    const std::int64_t step = fields.size() == 3 ? parseInteger(s, fields[2], "a GENERATE step") : 1;
    if (step <= 0 || last < first) s.fail("a GENERATE line needs first <= last and a positive step");
    // Counted in floating point and stepped by index: ids near the integer limits must
    // neither overflow the count nor the last step.
    const double count = (double(last) - double(first)) / double(step);
    if (count >= double(kMaxGenerated))
      s.fail("this GENERATE line makes more than " + std::to_string(kMaxGenerated) + " ids");
    for (std::int64_t k = 0; k <= std::int64_t(count); ++k) target.ids.push_back(first + k * step);
    return;
  }
  for (const auto f : fields) {
    if (isNumber(f)) target.ids.push_back(parseInteger(s, f, what));
    else target.references.push_back(toUpper(f));
  }
}

void DeckSets::moveInto(Model& model, const IdIndex& nodes, const IdIndex& elements) const {
  std::map<std::pair<SetKind, std::string>, std::size_t> resolved;  // into model.sets
  for (const Written& w : sets_) {
    const IdIndex& index = w.kind == SetKind::Cells ? elements : nodes;
    EntitySet out{w.name, w.kind, w.kind == SetKind::Cells ? "ELSET" : "NSET", {}};
    std::size_t unknown = 0;
    std::int64_t firstUnknown = 0;
    for (const std::int64_t id : w.ids) {
      if (const auto i = index.find(id)) out.members.push_back(*i);
      else if (w.kind == SetKind::Cells && skippedElements_.count(id)) continue;
      else if (unknown++ == 0) firstUnknown = id;
    }
    std::vector<std::string> missingSets;
    for (const std::string& r : w.references) {
      const auto it = resolved.find({w.kind, r});
      if (it == resolved.end()) {
        missingSets.push_back(r);
        continue;
      }
      const auto& from = model.sets[it->second].members;
      out.members.insert(out.members.end(), from.begin(), from.end());
    }
    normalizeMembers(out.members);
    const std::string label = std::string(w.kind == SetKind::Cells ? "*ELSET " : "*NSET ") + w.name;
    if (unknown > 0)
      model.diagnostics.push_back({Severity::Warning,
                                   "set-unknown-ids",
                                   label + " names " + std::to_string(unknown) + " " +
                                       (w.kind == SetKind::Cells ? "element" : "node") + " id" +
                                       (unknown == 1 ? "" : "s") +
                                       " the deck does not define (the first: " + std::to_string(firstUnknown) + ")",
                                   {}});
    if (!missingSets.empty())
      model.diagnostics.push_back({Severity::Warning,
                                   "set-unknown-names",
                                   label + " names " + missingSets.front() +
                                       ", which is no set defined before it (a set may name earlier sets of its kind)",
                                   {}});
    if (out.members.empty()) {
      model.diagnostics.push_back(
          {Severity::Info,
           "set-empty",
           label + " holds no " + setKindName(w.kind) + " volpost loaded (elements that are not solids are not loaded)",
           {}});
      continue;
    }
    resolved[{w.kind, w.name}] = model.sets.size();
    model.sets.push_back(std::move(out));
  }
}

}  // namespace volpost::meshio

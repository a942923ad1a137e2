// SPDX-License-Identifier: MIT
#include "DeckSets.hpp"

#include <algorithm>
#include <cctype>
#include <limits>

namespace volpost::meshio {
namespace {

// A GENERATE line may not produce more ids than this (a typo such as "1, 2000000000, 1"
// would otherwise ask for gigabytes).
constexpr std::int64_t kMaxGenerated = 100'000'000;

// b - a for a <= b, exact over the whole range of the ids.
std::uint64_t distance(std::int64_t a, std::int64_t b) { return std::uint64_t(b) - std::uint64_t(a); }

bool isNumber(std::string_view f) {
  return !f.empty() && (std::isdigit(static_cast<unsigned char>(f.front())) || f.front() == '-' || f.front() == '+');
}

}  // namespace

DeckSets::Written& DeckSets::set(SetKind kind, const std::string& name) {
  const auto [it, added] = index_.emplace(std::make_pair(kind, name), sets_.size());
  if (added) sets_.push_back({name, kind, {}, {}, {}});
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
    target.ranges.push_back({first, last, step});
    return;
  }
  for (const auto f : fields) {
    if (isNumber(f)) target.ids.push_back(parseInteger(s, f, what));
    else target.references.push_back(toUpper(f));
  }
}

void DeckSets::moveInto(Model& model, const IdIndex& nodes, const IdIndex& elements) const {
  std::map<std::pair<SetKind, std::string>, std::size_t> resolved;  // into model.sets
  // The smallest and largest id of the elements (loaded or not) and of the nodes.
  const auto span = [](const std::vector<std::int64_t>& ids, std::size_t count) {
    std::pair<std::int64_t, std::int64_t> s{std::numeric_limits<std::int64_t>::max(),
                                            std::numeric_limits<std::int64_t>::min()};
    for (std::size_t i = 0; i < count; ++i) {
      const std::int64_t id = ids.empty() ? std::int64_t(i) + 1 : ids[i];
      s = {std::min(s.first, id), std::max(s.second, id)};
    }
    return s;
  };
  auto elementSpan = span(model.mesh().cellIds, model.mesh().cellCount());
  for (const std::int64_t id : skippedElements_)
    elementSpan = {std::min(elementSpan.first, id), std::max(elementSpan.second, id)};
  const auto nodeSpan = span(model.mesh().nodeIds, model.mesh().nodeCount());
  for (const Written& w : sets_) {
    const IdIndex& index = w.kind == SetKind::Cells ? elements : nodes;
    EntitySet out{w.name, w.kind, w.kind == SetKind::Cells ? "ELSET" : "NSET", {}};
    std::size_t unknown = 0;
    std::int64_t firstUnknown = 0;
    const auto look = [&](std::int64_t id) {
      if (const auto i = index.find(id)) out.members.push_back(*i);
      else if (w.kind == SetKind::Cells && skippedElements_.count(id)) return;
      else if (unknown++ == 0) firstUnknown = id;
    };
    for (const std::int64_t id : w.ids) look(id);
    const auto [low, high] = w.kind == SetKind::Cells ? elementSpan : nodeSpan;
    for (const Written::Range& r : w.ranges) {
      // Only the ids within the deck's span are looked up; the others are counted.
      const std::uint64_t total = distance(r.first, r.last) / std::uint64_t(r.step) + 1;
      std::uint64_t looked = 0;
      if (low <= high && r.last >= low && r.first <= high) {
        const std::uint64_t step = std::uint64_t(r.step);
        std::uint64_t skip = 0;  // steps before the span
        if (r.first < low) skip = distance(r.first, low) / step + (distance(r.first, low) % step != 0 ? 1 : 0);
        const std::int64_t top = std::min(r.last, high);
        if (skip <= distance(r.first, top) / step) {
          const std::int64_t from = std::int64_t(std::uint64_t(r.first) + skip * step);
          const std::uint64_t n = distance(from, top) / step;
          for (std::uint64_t k = 0; k <= n; ++k, ++looked) look(std::int64_t(std::uint64_t(from) + k * step));
        }
      }
      if (total > looked) {
        if (unknown == 0) firstUnknown = r.first < low ? r.first : r.last;
        unknown += std::size_t(total - looked);
      }
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

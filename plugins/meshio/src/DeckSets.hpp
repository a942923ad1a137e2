// SPDX-License-Identifier: MIT
// The element and node sets of an Abaqus/CalculiX deck: *ELSET and *NSET blocks (ids,
// GENERATE ranges, names of earlier sets), ELSET= on *ELEMENT and NSET= on *NODE. Kept as
// written while the deck is read, turned into the model's sets of cell and node indices at
// the end, when every element is known.
#pragma once

#include "NodeTable.hpp"
#include "TextScanner.hpp"

#include <volpost/core/EntitySet.hpp>
#include <volpost/core/Model.hpp>

#include <map>
#include <optional>
#include <string>
#include <unordered_set>
#include <vector>

namespace volpost::meshio {

class DeckSets {
 public:
  /// Starts (or goes on with: a set may be given in several blocks) the set `name`.
  void begin(SetKind kind, const std::string& name, bool generate);
  /// A data line of the current *ELSET / *NSET block.
  void readLine(TextScanner& s, std::string_view line);
  /// An element of *ELEMENT, ELSET=name, or a node of *NODE, NSET=name.
  void addId(SetKind kind, const std::string& name, std::int64_t id);
  /// An element the reader did not load (a shell, a beam): sets may name it.
  void noteSkippedElement(std::int64_t id) { skippedElements_.insert(id); }
  const std::unordered_set<std::int64_t>& skippedElements() const { return skippedElements_; }
  /// The sets as cell and node indices; ids no element or node has and names of unknown
  /// sets are reported in one warning each, sets left empty (of shells, say) in an info.
  void moveInto(Model& model, const IdIndex& nodes, const IdIndex& elements) const;

 private:
  struct Written {
    std::string name;
    SetKind kind = SetKind::Cells;
    std::vector<std::int64_t> ids;
    /// GENERATE lines as written: expanded at the end only over the ids the deck has, so
    /// "1, 99999999" costs what the model's ids cost, not 800 MB.
    struct Range {
      std::int64_t first = 0, last = 0, step = 1;
    };
    std::vector<Range> ranges;
    std::vector<std::string> references;  ///< earlier sets named on a data line
  };
  Written& set(SetKind kind, const std::string& name);
  std::vector<Written> sets_;
  std::map<std::pair<SetKind, std::string>, std::size_t> index_;
  std::optional<std::size_t> current_;
  std::unordered_set<std::int64_t> skippedElements_;
  bool generate_ = false;
};

}  // namespace volpost::meshio

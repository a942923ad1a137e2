// SPDX-License-Identifier: MIT
// The *SURFACE blocks of an Abaqus/CalculiX deck (where loads and contacts are applied):
// TYPE=ELEMENT lines name an element or an element set and a face (S1..S6; none: the free
// faces of those elements), TYPE=NODE lines a node or a node set. volpost keeps each as the
// node set of its faces' nodes, so it can be listed and marked like the deck's NSETs.
#pragma once

#include "NodeTable.hpp"
#include "TextScanner.hpp"

#include <volpost/core/Model.hpp>

#include <string>
#include <unordered_set>
#include <vector>

namespace volpost::meshio {

class DeckSurfaces {
 public:
  void begin(const std::string& name, bool ofNodes);
  /// A data line of the current *SURFACE block.
  void readLine(TextScanner& s, std::string_view line);
  /// A C3D8 with repeated nodes read as a pyramid or a wedge: its hexahedron's face
  /// numbers no longer name its faces.
  void noteCollapsed(std::int64_t elementId) { collapsed_.insert(elementId); }
  /// The surfaces as node sets, after the deck's sets are in `model` (a surface may name
  /// them). `skipped`: the ids of elements not loaded (shells...).
  void moveInto(Model& model, const IdIndex& nodes, const IdIndex& elements,
                const std::unordered_set<std::int64_t>& skipped) const;

 private:
  struct Entry {
    std::int64_t id = 0;  ///< an element or node id, when `set` is empty
    std::string set;      ///< an ELSET or NSET name
    int face = 0;         ///< 1..6 (S1..S6), 0 for the free faces, -1 for a shell's side
  };
  struct Written {
    std::string name;
    bool ofNodes = false;
    std::vector<Entry> entries;
  };
  std::vector<Written> surfaces_;
  std::unordered_set<std::int64_t> collapsed_;
};

}  // namespace volpost::meshio

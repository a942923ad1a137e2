// SPDX-License-Identifier: MIT
// A named set of elements or of nodes that a file defines: an Abaqus/CalculiX ELSET or
// NSET, a Gmsh physical group, an Exodus element block or node set. Analysts show, hide and
// restrict results by them, so readers keep them as the file names them.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace volpost {

class Model;

enum class SetKind { Cells, Nodes };

struct EntitySet {
  std::string name;
  SetKind kind = SetKind::Cells;
  /// How the file defines it, in the file's words: "ELSET", "NSET", "physical group",
  /// "element block", "node set", or "cell field" for groups offered by a region field.
  std::string origin;
  /// Indices (not the file's ids) of the model's cells or nodes, sorted, each once.
  std::vector<std::uint32_t> members;
};

/// "elements" or "nodes".
const char* setKindName(SetKind kind);

/// Sorts the members and drops repeats.
void normalizeMembers(std::vector<std::uint32_t>& members);

/// The model's sets, and where the file defines no element set, groups offered by each
/// integer cell field of one step with 2 to 64 distinct values (VTK region ids, Gmsh's
/// "region" without names): one group per value, named "FIELD VALUE".
std::vector<EntitySet> modelSets(const Model& model);

/// The set named `name` (case-sensitive, then case-insensitive), or nullptr.
const EntitySet* findSet(const std::vector<EntitySet>& sets, const std::string& name);

}  // namespace volpost

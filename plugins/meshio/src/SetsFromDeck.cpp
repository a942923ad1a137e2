// SPDX-License-Identifier: MIT
#include "SetsFromDeck.hpp"

#include "AbaqusInputReader.hpp"
#include "NodeTable.hpp"

#include <volpost/core/EntitySet.hpp>
#include <volpost/core/Error.hpp>

#include <filesystem>
#include <system_error>

namespace volpost::meshio {
namespace {

// The deck beside the results: results.frd -> results.inp (or .INP).
std::filesystem::path deckBeside(const std::string& resultsPath) {
  for (const char* ext : {".inp", ".INP"}) {
    std::filesystem::path deck = resultsPath;
    deck.replace_extension(ext);
    std::error_code error;
    if (std::filesystem::is_regular_file(deck, error)) return deck;
  }
  return {};
}

IdIndex indexOf(const std::vector<std::int64_t>& ids, std::size_t count) {
  IdIndex index;
  for (std::size_t i = 0; i < count; ++i) index.add(ids.empty() ? std::int64_t(i + 1) : ids[i], std::uint32_t(i));
  return index;
}

std::int64_t idAt(const std::vector<std::int64_t>& ids, std::uint32_t i) {
  return ids.empty() ? std::int64_t(i) + 1 : ids.at(i);
}

}  // namespace

void addSetsFromDeckBeside(const std::string& resultsPath, Model& model) {
  const std::filesystem::path deckPath = deckBeside(resultsPath);
  if (deckPath.empty() || !model.meshBuilt()) return;
  const std::string deckName = deckPath.filename().string();
  std::unique_ptr<Model> deck;
  try {
    deck = AbaqusInputReader().read(deckPath.string(), Progress{});
  } catch (const std::exception& e) {
    model.diagnostics.push_back({Severity::Info,
                                 "deck-sets-not-read",
                                 "the sets of " + deckName + " beside this file were not read: " + e.what(),
                                 {}});
    return;
  }
  for (const Diagnostic& d : deck->diagnostics)  // what is wrong with its sets is said here too
    if (d.code.rfind("set-", 0) == 0)
      model.diagnostics.push_back({d.severity, d.code, deckName + ": " + d.message, {}});
  if (deck->sets.empty()) return;
  const Mesh& mesh = model.mesh();
  const IdIndex nodes = indexOf(mesh.nodeIds, mesh.nodeCount());
  const IdIndex cells = indexOf(mesh.cellIds, mesh.cellCount());
  std::size_t missing = 0;
  std::string firstMissing;
  for (const EntitySet& from : deck->sets) {
    const bool isCells = from.kind == SetKind::Cells;
    const auto& deckIds = isCells ? deck->mesh().cellIds : deck->mesh().nodeIds;
    EntitySet to{from.name, from.kind, std::string(isCells ? "ELSET" : "NSET") + " of " + deckName, {}};
    std::size_t lacking = 0;
    for (const std::uint32_t m : from.members) {
      if (const auto i = (isCells ? cells : nodes).find(idAt(deckIds, m))) to.members.push_back(*i);
      else ++lacking;
    }
    if (lacking > 0 && missing++ == 0)
      firstMissing =
          from.name + " (" + std::to_string(lacking) + " of its " + std::to_string(from.members.size()) + ")";
    normalizeMembers(to.members);
    if (!to.members.empty()) model.sets.push_back(std::move(to));
  }
  model.diagnostics.push_back(
      {Severity::Info, "deck-sets", "the element and node sets were read from " + deckName + " beside this file", {}});
  if (missing > 0)
    model.diagnostics.push_back({Severity::Warning,
                                 "deck-sets-mismatch",
                                 std::to_string(missing) + " set" + (missing == 1 ? "" : "s") + " of " + deckName +
                                     " name ids this file does not have, the first: " + firstMissing +
                                     " (the deck and the results may not be of the same mesh)",
                                 {}});
}

}  // namespace volpost::meshio

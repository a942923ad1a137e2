// SPDX-License-Identifier: MIT
// The user's selection: elements and nodes picked in the window (a click, a box) or named
// on the command line, kept by the file's own ids (so a state file names the same ones
// after the model is read again). The selection joins the model's sets as "selected
// elements" and "selected nodes", so everything sets do (show only, hide, mark, number,
// color, restrict the range, probe) applies to it.
#pragma once

#include "ModelSession.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace volpost::app {

inline constexpr const char* kSelectionOrigin = "selection";  ///< EntitySet::origin of the selection's sets
inline constexpr const char* kSelectedElements = "selected elements";
inline constexpr const char* kSelectedNodes = "selected nodes";
/// More would be no selection an analyst reads (and a state file of megabytes).
inline constexpr std::size_t kMaxSelected = 1'000'000;

struct Selection {
  std::vector<std::int64_t> elements;  ///< the file's element ids, sorted, each once
  std::vector<std::int64_t> nodes;     ///< the file's node ids, sorted, each once
  bool empty() const { return elements.empty() && nodes.empty(); }
  bool operator==(const Selection&) const = default;
};

/// Sorts the ids and drops repeats.
void normalizeIds(std::vector<std::int64_t>& ids);

/// The selection as sets of `session`'s cells and nodes (none for an empty part). Throws
/// std::invalid_argument naming the first id no element (node) of the model has, or past
/// kMaxSelected.
std::vector<EntitySet> selectionSets(const ModelSession& session, const Selection& selection);

/// Ids written as "101,105-110,200" (ranges inclusive). Throws std::invalid_argument
/// naming the part that is not an id or a range, or a range past kMaxSelected.
std::vector<std::int64_t> parseIdList(const std::string& text);
/// The ids `text` names that `session`'s model has (elements for SetKind::Cells, else
/// nodes): an id alone must be there, a range takes those of its ids that are (numbering
/// has gaps) and must hold one. Throws std::invalid_argument naming what is missing.
std::vector<std::int64_t> idsInModel(const std::string& text, const ModelSession& session, SetKind kind);
/// The ids written back the same way, runs as ranges: "101,105-110".
std::string idListText(const std::vector<std::int64_t>& ids);

}  // namespace volpost::app

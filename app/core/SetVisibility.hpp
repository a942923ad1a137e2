// SPDX-License-Identifier: MIT
// Which of the model's element sets are drawn: only the shown ones (none named: every
// cell), less the hidden ones. The kept cells make a part of the model (CellSubset), so
// the surface, sections, the volume, probing, plots and the extremes are those of the part.
#pragma once

#include "ModelSession.hpp"

#include <memory>
#include <string>
#include <vector>

namespace volpost::app {

struct SetVisibility {
  std::vector<std::string> shown;   ///< element sets drawn alone (empty: every cell)
  std::vector<std::string> hidden;  ///< element sets not drawn
  /// A set whose nodes (a node set's, or those of an element set's drawn elements) are
  /// marked in the picture; empty: none. Marking draws no other cells.
  std::string marked;
  /// The marked set's numbers written beside it: its nodes' (a node set) or its elements'
  /// at their centres (an element set), the file's own ids.
  bool numbers = false;
  /// Each drawn element set in a plain color of its own (SetColors.hpp) instead of the
  /// result's colors on the surface, the sections and the slices.
  bool colors = false;
  bool active() const { return !shown.empty() || !hidden.empty(); }
  bool drawsTheSame(const SetVisibility& o) const { return shown == o.shown && hidden == o.hidden; }
  bool operator==(const SetVisibility&) const = default;
};

/// Throws std::invalid_argument for a name no element set has (naming the sets there are),
/// a node set (which has no cells to show), or a choice that leaves no cell.
void checkSetVisibility(const ModelSession& session, const SetVisibility& v);
struct MarkedMembers {
  SetKind kind = SetKind::Nodes;
  std::vector<std::uint32_t> nodes;  ///< among those the session's cells use, sorted
  std::vector<std::uint32_t> cells;  ///< an element set's cells in the session
};
/// What of set `name` the session draws: a node set's nodes that its cells use, or an
/// element set's cells and their nodes; throws std::invalid_argument for an unknown name.
MarkedMembers markedMembers(const ModelSession& session, const std::string& name);
/// Per cell of the model: drawn or not.
std::vector<char> cellsOfSets(const ModelSession& session, const SetVisibility& v);
/// The part of the model the sets leave (the session itself when nothing is chosen).
std::shared_ptr<const ModelSession> setVisibleSession(std::shared_ptr<const ModelSession> session,
                                                      const SetVisibility& v);

}  // namespace volpost::app

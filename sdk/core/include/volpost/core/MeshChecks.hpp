// SPDX-License-Identifier: MIT
// Checks run on every loaded model; each defect found becomes a Diagnostic.
#pragma once

#include <volpost/core/Model.hpp>

namespace volpost {

/// Flags non-finite coordinates, inverted and degenerate cells, repeated nodes in a cell,
/// coincident unmerged nodes (merged), unused nodes and duplicated cells. Field values are
/// not touched (they stay lazy); rangeOf() counts their NaNs when they are first used.
void checkModel(Model& model);

}  // namespace volpost

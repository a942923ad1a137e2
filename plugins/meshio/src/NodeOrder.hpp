// SPDX-License-Identifier: MIT
// Node orders of FE formats, converted to volpost's (VTK's) order. A format's order is
// described the way its documentation does: which of its corners is VTK corner k, and which
// corner pair each of its midside nodes sits on. The permutation follows from VTK's edge
// table, so no hand-typed 20-entry permutation can be subtly wrong.
#pragma once

#include <volpost/core/CellType.hpp>

#include <array>
#include <span>
#include <utility>
#include <vector>

namespace volpost::meshio {

using CornerPair = std::pair<int, int>;

/// vtk[k] = index into the format's node list of VTK node k. `corners[k]` is the format
/// corner that is VTK corner k; `midsides[j]` is the corner pair (format numbering) of the
/// format's node cornerCount + j. Throws std::logic_error on an inconsistent description.
std::vector<int> vtkOrderFrom(CellType type, std::span<const int> corners,
                              std::span<const CornerPair> midsides);

}  // namespace volpost::meshio

// SPDX-License-Identifier: MIT
// How the host's grid algorithms (sections, iso-surfaces) split a regular grid's cell into
// tetrahedra without building it: the six tets around the diagonal from corner (0,0,0) to
// (1,1,1), each a path 0 -> one axis -> two axes -> 7 (Freudenthal's split). The same split
// in every cell puts matching diagonals on the faces neighbours share.
#pragma once

#include <array>

namespace volpost {

/// Corner c of a cell is (c & 1, c >> 1 & 1, c >> 2 & 1) in index steps from its first point.
inline constexpr std::array<std::array<int, 4>, 6> kGridCellTets = {{
    {0, 1, 3, 7}, {0, 3, 2, 7}, {0, 2, 6, 7}, {0, 6, 4, 7}, {0, 4, 5, 7}, {0, 5, 1, 7}}};

}  // namespace volpost

// SPDX-License-Identifier: MIT
// Steiner-free splits of hexahedra, wedges and pyramids into tetrahedra, one per diagonal
// configuration of their quadrilateral faces, computed once by TetGen on the reference
// cell. Internal to Tetrahedralize.cpp.
#pragma once

#include <volpost/core/CellType.hpp>

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

namespace volpost::detail {

using LocalTet = std::array<std::uint8_t, 4>;

/// Bit k of `diagonals` says which diagonal splits the k-th quadrilateral face of the
/// cell (in topology(type).faces order): 0 the one through corners[0] and corners[2],
/// 1 the one through corners[1] and corners[3]. Returns the tets in local corner indices
/// whose boundary triangles are exactly those faces, or nullopt when the configuration has
/// no tetrahedralization without an interior Steiner point. Thread-safe; cached.
const std::optional<std::vector<LocalTet>>& splitTemplate(CellType type, unsigned diagonals);

}  // namespace volpost::detail

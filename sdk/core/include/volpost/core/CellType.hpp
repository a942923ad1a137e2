// SPDX-License-Identifier: MIT
// Finite-element cell types and their local topology, in VTK's node order.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

namespace volpost {

enum class CellType : std::uint8_t { Tet4, Tet10, Hex8, Hex20, Wedge6, Wedge15, Pyramid5 };

inline constexpr std::array<CellType, 7> kAllCellTypes = {
    CellType::Tet4,   CellType::Tet10,   CellType::Hex8,    CellType::Hex20,
    CellType::Wedge6, CellType::Wedge15, CellType::Pyramid5};

/// A face of a cell: its corner nodes as local indices, ordered so the right-hand normal
/// points out of the cell (3 or 4 corners; `size` says which).
struct CellFace {
  std::array<std::uint8_t, 4> corners{};
  std::uint8_t size = 0;
};

/// An edge between two corners and, for quadratic cells, the local index of its midside node.
struct CellEdge {
  std::uint8_t a = 0, b = 0;
  std::int8_t mid = -1;
};

struct CellTopology {
  CellType type;
  std::string_view name;   ///< "tet4", "hex20", ...
  int nodeCount;           ///< all nodes, midside ones included
  int cornerCount;         ///< vertices of the geometric shape
  bool quadratic;
  std::span<const CellFace> faces;
  std::span<const CellEdge> edges;
};

const CellTopology& topology(CellType type);
inline std::string_view cellTypeName(CellType type) { return topology(type).name; }
std::optional<CellType> cellTypeFromName(std::string_view name);

/// VTK cell type numbers (vtkCellType.h) for the types volpost knows.
std::optional<CellType> cellTypeFromVtk(int vtkType);
int vtkCellType(CellType type);

}  // namespace volpost

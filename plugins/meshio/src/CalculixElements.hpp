// SPDX-License-Identifier: MIT
// Abaqus/CalculiX solid elements: the types a deck names (C3D8R, DC3D10, ...) and the .frd
// element codes, with their node orders in volpost's (VTK's). Shared by the .inp and .frd
// readers, which must build the same cells from the same model.
#pragma once

#include <volpost/core/CellType.hpp>

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace volpost::meshio {

struct SolidElement {
  CellType cell;
  int fileNodes;               // nodes per element in the file
  std::vector<int> vtkOrder;   // file node of each VTK node
};

/// "C3D4", "C3D10M", "C3D8R", "DC3D20", ...: the solid element, nullopt for a type that is
/// not a 3-D continuum element. Throws std::invalid_argument for a C3D-family name volpost
/// does not know (e.g. "C3D99"), so that a typo is not read as "skip this block".
std::optional<SolidElement> abaqusSolid(std::string_view type);

/// .frd element codes: 1 he8, 2 pe6, 3 te4, 4 he20, 5 pe15, 6 te10 (others: nullopt).
std::optional<SolidElement> frdSolid(int code);

/// CalculiX has no pyramid and writes one as a C3D8 with its apex repeated (1,2,3,4,5,5,5,5),
/// and a wedge as a C3D8 with 3=4 and 7=8. Given a hex8 in VTK order, returns the cell it
/// really is and its nodes; a hex with other repeated nodes stays a (degenerate) hex.
CellType collapseDegenerateHex(std::span<std::uint32_t> nodes, int& nodeCount);

}  // namespace volpost::meshio

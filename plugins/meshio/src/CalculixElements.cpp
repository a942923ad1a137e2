// SPDX-License-Identifier: MIT
// Node orders: the Abaqus and CalculiX manuals' element figures. Corners are VTK's except
// the wedge, whose first triangle VTK wants facing away from the second (Abaqus lists it
// the other way). Midside nodes of .inp follow edge lists below; ccx writes .frd he20
// and pe15 with their last two groups of edge nodes swapped (ccx frd.c), so those two
// have their own lists.
#include "CalculixElements.hpp"

#include "NodeOrder.hpp"

#include <array>
#include <cctype>
#include <stdexcept>

namespace volpost::meshio {
namespace {

constexpr std::array<int, 4> kTet{0, 1, 2, 3};
constexpr std::array<int, 5> kPyramid{0, 1, 2, 3, 4};
constexpr std::array<int, 8> kHex{0, 1, 2, 3, 4, 5, 6, 7};
constexpr std::array<int, 6> kWedge{0, 2, 1, 3, 5, 4};
constexpr std::array<CornerPair, 6> kTetEdges{{{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}}};
constexpr std::array<CornerPair, 12> kHexEdges{{{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                                {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}}};
constexpr std::array<CornerPair, 12> kFrdHexEdges{{{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 4}, {1, 5},
                                                   {2, 6}, {3, 7}, {4, 5}, {5, 6}, {6, 7}, {7, 4}}};
constexpr std::array<CornerPair, 9> kWedgeEdges{{{0, 1}, {1, 2}, {2, 0}, {3, 4}, {4, 5}, {5, 3},
                                                 {0, 3}, {1, 4}, {2, 5}}};
constexpr std::array<CornerPair, 9> kFrdWedgeEdges{{{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 4}, {2, 5},
                                                    {3, 4}, {4, 5}, {5, 3}}};

SolidElement make(CellType cell, std::span<const int> corners, std::span<const CornerPair> edges) {
  const int n = topology(cell).nodeCount;
  return {cell, n, vtkOrderFrom(cell, corners, edges)};
}

}  // namespace

std::optional<SolidElement> abaqusSolid(std::string_view type) {
  std::string t;
  for (char c : type) t += char(std::toupper(static_cast<unsigned char>(c)));
  std::size_t at = t.rfind("C3D", 0) == 0 ? 3 : t.rfind("DC3D", 0) == 0 ? 4 : std::string::npos;
  if (at == std::string::npos) return std::nullopt;
  std::size_t end = at;
  while (end < t.size() && std::isdigit(static_cast<unsigned char>(t[end]))) ++end;
  const std::string digits = t.substr(at, end - at);
  if (digits == "4") return make(CellType::Tet4, kTet, {});
  if (digits == "10") return make(CellType::Tet10, kTet, kTetEdges);
  if (digits == "8") return make(CellType::Hex8, kHex, {});
  if (digits == "20") return make(CellType::Hex20, kHex, kHexEdges);
  if (digits == "6") return make(CellType::Wedge6, kWedge, {});
  if (digits == "15") return make(CellType::Wedge15, kWedge, kWedgeEdges);
  if (digits == "5") return make(CellType::Pyramid5, kPyramid, {});
  throw std::invalid_argument("element type " + std::string(type) +
                              " is not a solid element volpost knows (C3D4, C3D10, C3D8, C3D20, C3D6, C3D15, C3D5 and their variants)");
}

std::optional<SolidElement> frdSolid(int code) {
  switch (code) {
    case 1: return make(CellType::Hex8, kHex, {});
    case 2: return make(CellType::Wedge6, kWedge, {});
    case 3: return make(CellType::Tet4, kTet, {});
    case 4: return make(CellType::Hex20, kHex, kFrdHexEdges);
    case 5: return make(CellType::Wedge15, kWedge, kFrdWedgeEdges);
    case 6: return make(CellType::Tet10, kTet, kTetEdges);
    default: return std::nullopt;
  }
}

CellType collapseDegenerateHex(std::span<std::uint32_t> n, int& nodeCount) {
  nodeCount = 8;
  if (n.size() < 8) return CellType::Hex8;
  const bool apex = n[4] == n[5] && n[5] == n[6] && n[6] == n[7];
  const bool baseDistinct = n[0] != n[1] && n[0] != n[2] && n[0] != n[3] && n[1] != n[2] && n[1] != n[3] && n[2] != n[3];
  if (apex && baseDistinct && n[4] != n[0] && n[4] != n[1] && n[4] != n[2] && n[4] != n[3]) {
    nodeCount = 5;  // (0,1,2,3,4) already
    return CellType::Pyramid5;
  }
  if (n[2] == n[3] && n[6] == n[7]) {
    // Triangle (0,1,2) under (4,5,6), Abaqus orientation: VTK wedge (0,2,1,4,6,5).
    const std::array<std::uint32_t, 6> w{n[0], n[2], n[1], n[4], n[6], n[5]};
    bool distinct = true;
    for (std::size_t i = 0; i < 6; ++i)
      for (std::size_t j = i + 1; j < 6; ++j) distinct = distinct && w[i] != w[j];
    if (distinct) {
      std::copy(w.begin(), w.end(), n.begin());
      nodeCount = 6;
      return CellType::Wedge6;
    }
  }
  return CellType::Hex8;
}

}  // namespace volpost::meshio

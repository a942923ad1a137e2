// SPDX-License-Identifier: MIT
#include <volpost/core/CellType.hpp>

namespace volpost {
namespace {

// Faces list corners so the right-hand normal points outward for a cell of positive
// volume in VTK's node order (the same tables as vtkTetra/vtkHexahedron/vtkWedge/vtkPyramid).
constexpr CellFace kTetFaces[] = {{{0, 1, 3}, 3}, {{1, 2, 3}, 3}, {{2, 0, 3}, 3}, {{0, 2, 1}, 3}};
constexpr CellFace kHexFaces[] = {{{0, 4, 7, 3}, 4}, {{1, 2, 6, 5}, 4}, {{0, 1, 5, 4}, 4},
                                  {{3, 7, 6, 2}, 4}, {{0, 3, 2, 1}, 4}, {{4, 5, 6, 7}, 4}};
constexpr CellFace kWedgeFaces[] = {{{0, 1, 2}, 3}, {{3, 5, 4}, 3}, {{0, 3, 4, 1}, 4},
                                    {{1, 4, 5, 2}, 4}, {{2, 5, 3, 0}, 4}};
constexpr CellFace kPyramidFaces[] = {{{0, 3, 2, 1}, 4}, {{0, 1, 4}, 3}, {{1, 2, 4}, 3},
                                      {{2, 3, 4}, 3}, {{3, 0, 4}, 3}};

constexpr CellEdge kTet4Edges[] = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};
constexpr CellEdge kTet10Edges[] = {{0, 1, 4}, {1, 2, 5}, {2, 0, 6},
                                    {0, 3, 7}, {1, 3, 8}, {2, 3, 9}};
constexpr CellEdge kHex8Edges[] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                   {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
constexpr CellEdge kHex20Edges[] = {{0, 1, 8},   {1, 2, 9},   {2, 3, 10},  {3, 0, 11},
                                    {4, 5, 12},  {5, 6, 13},  {6, 7, 14},  {7, 4, 15},
                                    {0, 4, 16},  {1, 5, 17},  {2, 6, 18},  {3, 7, 19}};
constexpr CellEdge kWedge6Edges[] = {{0, 1}, {1, 2}, {2, 0}, {3, 4}, {4, 5}, {5, 3},
                                     {0, 3}, {1, 4}, {2, 5}};
constexpr CellEdge kWedge15Edges[] = {{0, 1, 6},  {1, 2, 7},  {2, 0, 8},
                                      {3, 4, 9},  {4, 5, 10}, {5, 3, 11},
                                      {0, 3, 12}, {1, 4, 13}, {2, 5, 14}};
constexpr CellEdge kPyramidEdges[] = {{0, 1}, {1, 2}, {2, 3}, {3, 0},
                                      {0, 4}, {1, 4}, {2, 4}, {3, 4}};

const CellTopology kTopologies[] = {
    {CellType::Tet4, "tet4", 4, 4, false, kTetFaces, kTet4Edges},
    {CellType::Tet10, "tet10", 10, 4, true, kTetFaces, kTet10Edges},
    {CellType::Hex8, "hex8", 8, 8, false, kHexFaces, kHex8Edges},
    {CellType::Hex20, "hex20", 20, 8, true, kHexFaces, kHex20Edges},
    {CellType::Wedge6, "wedge6", 6, 6, false, kWedgeFaces, kWedge6Edges},
    {CellType::Wedge15, "wedge15", 15, 6, true, kWedgeFaces, kWedge15Edges},
    {CellType::Pyramid5, "pyramid5", 5, 5, false, kPyramidFaces, kPyramidEdges},
};

struct VtkPair {
  int vtk;
  CellType type;
};
constexpr VtkPair kVtkTypes[] = {{10, CellType::Tet4},   {24, CellType::Tet10},
                                 {12, CellType::Hex8},   {25, CellType::Hex20},
                                 {13, CellType::Wedge6}, {26, CellType::Wedge15},
                                 {14, CellType::Pyramid5}};

}  // namespace

const CellTopology& topology(CellType type) { return kTopologies[static_cast<int>(type)]; }

std::optional<CellType> cellTypeFromName(std::string_view name) {
  for (const auto& t : kTopologies)
    if (t.name == name) return t.type;
  return std::nullopt;
}

std::optional<CellType> cellTypeFromVtk(int vtkType) {
  for (const auto& p : kVtkTypes)
    if (p.vtk == vtkType) return p.type;
  return std::nullopt;
}

int vtkCellType(CellType type) {
  for (const auto& p : kVtkTypes)
    if (p.type == type) return p.vtk;
  return 0;
}

}  // namespace volpost

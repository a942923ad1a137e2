// SPDX-License-Identifier: MIT
#include "VtkCells.hpp"

#include <array>

namespace volpost::meshio {
namespace {

// VTK types of points, lines and faces: boundary or marker cells in FE files, skipped.
bool isLowerDimensional(std::int64_t t) {
  constexpr std::array<int, 17> kTypes = {1, 2, 3, 4, 5, 6, 7, 8, 9, 21, 22, 23, 28, 30, 34, 35, 36};
  for (int k : kTypes)
    if (t == k) return true;
  return false;
}

bool isKnownVtkType(std::int64_t t) {
  return (t >= 1 && t <= 16) || (t >= 21 && t <= 37) || t == 42 || (t >= 60 && t <= 81);
}

}  // namespace

VtkCellMapping addVtkCells(const VtkCellArrays& cells, std::size_t pointCount, Mesh& mesh,
                           const std::function<void(const std::string&)>& fail) {
  VtkCellMapping mapping;
  const std::size_t n = cells.types.size();
  mapping.modelCell.assign(n, -1);
  mesh.reserveCells(n, cells.connectivity.size());
  std::vector<NodeIndex> nodes;
  for (std::size_t c = 0; c < n; ++c) {
    const std::int64_t vtkType = cells.types[c];
    const auto type = cellTypeFromVtk(int(vtkType));
    const std::string which = "cell " + std::to_string(c);
    if (!type) {
      if (isLowerDimensional(vtkType)) {
        ++mapping.skipped;
        continue;
      }
      if (!isKnownVtkType(vtkType)) fail(which + " has type " + std::to_string(vtkType) + ", which is not a VTK cell type");
      fail(which + " has VTK cell type " + std::to_string(vtkType) +
           ", which volpost does not support (supported: tet4, tet10, hex8, hex20, wedge6, wedge15, pyramid5)");
    }
    const std::int64_t begin = cells.offsets[c], end = cells.offsets[c + 1];
    const int expected = topology(*type).nodeCount;
    if (end - begin != expected)
      fail(which + " (" + std::string(cellTypeName(*type)) + ") has " + std::to_string(end - begin) +
           " nodes, expected " + std::to_string(expected));
    nodes.resize(std::size_t(expected));
    for (int k = 0; k < expected; ++k) {
      const std::int64_t p = cells.connectivity[std::size_t(begin + k)];
      if (p < 0 || std::uint64_t(p) >= pointCount)
        fail(which + " uses point " + std::to_string(p) + ", but the file has " + std::to_string(pointCount) +
             " points (0.." + std::to_string(std::int64_t(pointCount) - 1) + ")");
      nodes[std::size_t(k)] = NodeIndex(p);
    }
    mapping.modelCell[c] = std::int64_t(mesh.cellCount());
    mesh.addCell(*type, nodes);
  }
  return mapping;
}

std::vector<double> selectModelCells(const std::vector<double>& values, int components,
                                     const VtkCellMapping& mapping) {
  if (mapping.skipped == 0) return values;
  std::vector<double> out;
  out.reserve(values.size());
  for (std::size_t c = 0; c < mapping.modelCell.size(); ++c)
    if (mapping.modelCell[c] >= 0)
      out.insert(out.end(), values.begin() + std::ptrdiff_t(c * std::size_t(components)),
                 values.begin() + std::ptrdiff_t((c + 1) * std::size_t(components)));
  return out;
}

}  // namespace volpost::meshio

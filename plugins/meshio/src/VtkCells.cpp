// SPDX-License-Identifier: MIT
#include "VtkCells.hpp"

#include <algorithm>
#include <array>
#include <optional>

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

// Cells all of one volume type, each with its node count in order: the connectivity can
// become the mesh's as it is.
std::optional<CellType> uniformCells(const VtkCellArrays& cells, std::size_t pointCount) {
  if (cells.types.empty()) return std::nullopt;
  const auto type = cellTypeFromVtk(int(cells.types.front()));
  if (!type) return std::nullopt;
  const auto size = std::int64_t(topology(*type).nodeCount);
  if (cells.offsets.size() != cells.types.size() + 1 || cells.connectivity.size() != cells.types.size() * std::size_t(size))
    return std::nullopt;
  for (std::size_t c = 0; c < cells.types.size(); ++c)
    if (cells.types[c] != cells.types.front() || cells.offsets[c + 1] != std::int64_t(c + 1) * size) return std::nullopt;
  for (NodeIndex p : cells.connectivity)
    if (p >= pointCount) return std::nullopt;  // the general path says which cell
  return type;
}

}  // namespace

VtkCellMapping addVtkCells(VtkCellArrays& cells, std::size_t pointCount, Mesh& mesh,
                           const std::function<void(const std::string&)>& fail) {
  VtkCellMapping mapping;
  const std::size_t n = cells.types.size();
  mapping.fileCells = n;
  if (mesh.cellCount() == 0)
    if (const auto type = uniformCells(cells, pointCount)) {
      mesh.takeCells(*type, std::move(cells.connectivity));
      cells.connectivity.clear();
      return mapping;
    }
  const std::int64_t firstModelCell = std::int64_t(mesh.cellCount());
  mesh.reserveCells(mesh.cellCount() + n, mesh.connectivity().size() + cells.connectivity.size());
  std::vector<NodeIndex> nodes;
  for (std::size_t c = 0; c < n; ++c) {
    const std::int64_t vtkType = cells.types[c];
    const auto type = cellTypeFromVtk(int(vtkType));
    const auto which = [c] { return "cell " + std::to_string(c); };  // only for messages
    if (!type) {
      if (isLowerDimensional(vtkType)) {
        if (mapping.modelCell.empty()) {  // the first skipped cell: the cells before it map one to one
          mapping.modelCell.assign(n, -1);
          for (std::size_t k = 0; k < c; ++k) mapping.modelCell[k] = firstModelCell + std::int64_t(k);
        }
        ++mapping.skipped;
        continue;
      }
      if (!isKnownVtkType(vtkType)) fail(which() + " has type " + std::to_string(vtkType) + ", which is not a VTK cell type");
      fail(which() + " has VTK cell type " + std::to_string(vtkType) +
           ", which volpost does not support (supported: tet4, tet10, hex8, hex20, wedge6, wedge15, pyramid5)");
    }
    const std::int64_t begin = cells.offsets[c], end = cells.offsets[c + 1];
    const int expected = topology(*type).nodeCount;
    if (end - begin != expected)
      fail(which() + " (" + std::string(cellTypeName(*type)) + ") has " + std::to_string(end - begin) +
           " nodes, expected " + std::to_string(expected));
    nodes.resize(std::size_t(expected));
    for (int k = 0; k < expected; ++k) {
      const NodeIndex p = cells.connectivity[std::size_t(begin + k)];
      if (p >= pointCount) fail(pointOutsideMessage(c, p, pointCount));
      nodes[std::size_t(k)] = p;
    }
    if (!mapping.modelCell.empty()) mapping.modelCell[c] = std::int64_t(mesh.cellCount());
    mesh.addCell(*type, nodes);
  }
  return mapping;
}

std::string pointOutsideMessage(std::size_t cell, std::int64_t point, std::size_t pointCount) {
  return "cell " + std::to_string(cell) + " uses point " + std::to_string(point) + ", but the file has " +
         std::to_string(pointCount) + " points (0.." + std::to_string(std::int64_t(pointCount) - 1) + ")";
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

// SPDX-License-Identifier: MIT
// Cell assembly shared by the VTK legacy and XML readers.
#pragma once

#include <volpost/core/Mesh.hpp>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace volpost::meshio {

struct VtkCellArrays {
  std::vector<std::int64_t> types;         ///< one VTK type per cell
  std::vector<std::int64_t> offsets;       ///< cells + 1 entries, offsets[0] == 0
  std::vector<std::int64_t> connectivity;
};

struct VtkCellMapping {
  /// Model cell of each file cell, -1 for cells that are not volume cells (skipped).
  std::vector<std::int64_t> modelCell;
  std::size_t skipped = 0;  ///< vertices, lines, triangles, quads... (boundary markers)
};

/// Adds the volume cells to `mesh`. Calls `fail(message)` (which must throw) on a cell
/// type that is not a VTK type or not supported, a wrong node count, or a node index
/// outside [0, pointCount).
VtkCellMapping addVtkCells(const VtkCellArrays& cells, std::size_t pointCount, Mesh& mesh,
                           const std::function<void(const std::string&)>& fail);

/// Keeps the values of the file cells that became model cells.
std::vector<double> selectModelCells(const std::vector<double>& values, int components,
                                     const VtkCellMapping& mapping);

}  // namespace volpost::meshio

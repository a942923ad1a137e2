// SPDX-License-Identifier: MIT
// The finite-element mesh: nodes in double precision and cells of mixed types.
#pragma once

#include <volpost/core/CellType.hpp>

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <span>
#include <vector>

namespace volpost {

using NodeIndex = std::uint32_t;

struct Bounds {
  glm::dvec3 min{0.0};
  glm::dvec3 max{0.0};
  bool valid = false;
  glm::dvec3 center() const { return (min + max) * 0.5; }
  glm::dvec3 size() const { return max - min; }
  double diagonal() const;
  void extend(const glm::dvec3& p);
};

class Mesh {
 public:
  /// Node positions, model units. Index = 0-based node index used by the cells.
  std::vector<glm::dvec3> nodes;
  /// Node ids as the source file numbered them (empty when the file has none).
  std::vector<std::int64_t> nodeIds;
  /// Element ids as the source file numbered them (empty when the file has none).
  std::vector<std::int64_t> cellIds;

  /// The id a user knows a node or an element by: the file's own, or for files that have
  /// none (VTK) the position counted from 1, as FE programs number.
  std::int64_t nodeId(std::size_t node) const { return nodeIds.empty() ? std::int64_t(node) + 1 : nodeIds[node]; }
  std::int64_t cellId(std::size_t cell) const { return cellIds.empty() ? std::int64_t(cell) + 1 : cellIds[cell]; }

  void reserveCells(std::size_t cells, std::size_t connectivityEntries);
  /// Appends a cell; `cellNodes` has topology(type).nodeCount entries.
  void addCell(CellType type, std::span<const NodeIndex> cellNodes);

  std::size_t nodeCount() const { return nodes.size(); }
  std::size_t cellCount() const { return cells_->types.size(); }
  CellType cellType(std::size_t cell) const { return cells_->types[cell]; }
  std::span<const NodeIndex> cellNodes(std::size_t cell) const {
    const CellArrays& c = *cells_;
    if (c.uniformSize) return {c.connectivity.data() + cell * c.uniformSize, c.uniformSize};
    return {c.connectivity.data() + c.offsets[cell], c.offsets[cell + 1] - c.offsets[cell]};
  }
  std::span<const CellType> cellTypes() const { return cells_->types; }
  std::span<const NodeIndex> connectivity() const { return cells_->connectivity; }
  /// Cells of one type for a mesh that has none yet, taking `connectivity` (nodeCount of
  /// the type per cell) without a copy: how readers hand over a large uniform mesh.
  /// Throws std::invalid_argument when the mesh has cells or the count does not divide.
  void takeCells(CellType type, std::vector<NodeIndex>&& connectivity);
  /// Replaces every node index n in the cells by map[n] (used to merge coincident nodes).
  void remapNodes(const std::vector<NodeIndex>& map);
  /// Bytes the cells take (types, connectivity and, for meshes of mixed cell sizes, offsets).
  std::size_t cellBytes() const;
  /// Takes `other`'s cells as they are, shared (see below): nodes and ids stay this mesh's own.
  void shareCellsOf(const Mesh& other) { cells_ = other.cells_; }
  /// Whether this mesh and `other` share one copy of their cells (see below).
  bool sharesCellsWith(const Mesh& other) const { return cells_ == other.cells_ && cellCount() > 0; }

  std::map<CellType, std::size_t> countsByType() const;
  /// Bounds of the nodes that cells use (unused and non-finite points are ignored).
  Bounds bounds() const;
  /// Bounds of every node, used or not.
  Bounds allNodeBounds() const;

  Mesh();
  Mesh(const Mesh&) = default;
  Mesh& operator=(const Mesh&) = default;
  Mesh(Mesh&& other) noexcept;
  Mesh& operator=(Mesh&& other) noexcept;

 private:
  // A copy of a mesh shares its cells until one of the two changes them (copy on write):
  // the tetrahedra of an all-tet mesh are the mesh itself, not a second copy of 17 bytes
  // per tet. Meshes whose cells all have one node count (all-tet, all-hex) keep no offsets.
  struct CellArrays {
    std::vector<CellType> types;
    std::vector<std::size_t> offsets;  ///< cells + 1 entries; empty while uniformSize is set
    std::vector<NodeIndex> connectivity;
    std::uint32_t uniformSize = 0;     ///< nodes of every cell, or 0 (mixed sizes, or no cell yet)
  };
  CellArrays& cellsToChange();
  static const std::shared_ptr<CellArrays>& noCells();
  std::shared_ptr<CellArrays> cells_;
};

/// Signed volume of a cell from its corner faces (negative = inverted or mirrored).
double signedCellVolume(const Mesh& mesh, std::size_t cell);

/// True when a cell uses one node twice: such a cell (flagged by the model checks as
/// "repeated-node-cells") has no proper faces or volume, and every consumer (boundary,
/// tetrahedralization, point location, rendering) leaves it out.
bool cellRepeatsANode(const Mesh& mesh, std::size_t cell);

}  // namespace volpost

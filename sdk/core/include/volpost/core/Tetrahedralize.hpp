// SPDX-License-Identifier: MIT
// Conforming tetrahedra for volume rendering. Quadrilateral faces are split by the
// diagonal through their smallest global node index (Dompierre et al. 1999), so two cells
// sharing a face split it the same way. Each hexahedron, wedge and pyramid then takes the
// Steiner-free split of its diagonal configuration (TetGen computes one per configuration
// on the reference cell, once) when all its pieces are positive by CGAL's exact
// orientation predicate; otherwise (a configuration with no such split, or a distorted
// cell) it gets a Steiner point at its centroid joined to its face triangles. tet10 is
// split into 8 tets through its midside nodes; hex20 and wedge15 use their corners (their
// midside values are not used).
#pragma once

#include <volpost/core/Mesh.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace volpost {

struct TetMesh {
  Mesh mesh;  ///< tet4 only; nodes are the original ones, then one Steiner point per cell that needs it
  /// The source cell of every tet; empty when every tet is its own source cell (an
  /// all-tet mesh, its own tetrahedralization: 4 bytes per tet saved). Read it through
  /// sourceCell().
  std::vector<std::uint32_t> cellOfTet;
  std::size_t originalNodes = 0;
  /// Steiner point i (node originalNodes + i) is the mean of these source nodes.
  std::vector<std::uint32_t> steinerCell;
  /// Source cells whose split has a tet that is not positively oriented even with the
  /// centroid point (inverted or badly folded cells): their pieces overlap.
  std::vector<std::uint32_t> foldedCells;
  /// Source cells left out: they use one node twice (no volume).
  std::vector<std::uint32_t> skippedCells;

  std::uint32_t sourceCell(std::size_t tet) const {
    return cellOfTet.empty() ? std::uint32_t(tet) : cellOfTet[tet];
  }

  /// Node values for `mesh`: the originals, then each Steiner point's mean of its cell's corners.
  std::vector<double> nodeValues(const Mesh& source, std::span<const double> values) const;
  /// Cell values for `mesh`: each tet takes its source cell's.
  std::vector<double> cellValues(std::span<const double> values) const;
};

/// A mesh of tet4 (and tet10) only comes back with the same nodes and one tet per tet4.
TetMesh tetrahedralize(const Mesh& mesh);

/// Throws std::invalid_argument unless the mesh has only tetrahedra (tet4, tet10) and one
/// value per node or per cell: what the volume renderers take (after tetrahedralize()).
void requireTetrahedraAndValues(const Mesh& mesh, bool perNode, std::size_t valueCount);

}  // namespace volpost

// SPDX-License-Identifier: MIT
// The part of a tetrahedral mesh that clip planes can show: tets with all four vertices on
// the clipped side of one plane are dropped, nodes renumbered. The renderers still cut
// exactly at the planes, so the picture is the same while the GPU holds only this part.
#pragma once

#include <volpost/core/ClipPlane.hpp>
#include <volpost/core/Field.hpp>
#include <volpost/core/Mesh.hpp>

#include <span>
#include <vector>

namespace volpost {

struct CulledMesh {
  Mesh mesh;                           ///< the kept tets, nodes renumbered
  std::vector<std::uint32_t> nodeOf;   ///< source node of each kept node
  std::vector<std::uint32_t> cellOf;   ///< source cell of each kept tet
  /// Values of the source (one per node or per cell) for this mesh.
  std::vector<double> values(FieldLocation location, std::span<const double> sourceValues) const;
};

/// `tets` must hold tet4 cells only (TetMesh::mesh). No planes: everything is kept.
CulledMesh cullToClipPlanes(const Mesh& tets, const std::vector<ClipPlane>& planes);

}  // namespace volpost

// SPDX-License-Identifier: MIT
// Which tet lies across each face of each tet: what walks through a tetrahedral mesh (rays,
// streamlines, visibility sorts) step along.
#pragma once

#include <volpost/core/Mesh.hpp>

#include <glm/vec4.hpp>

#include <span>
#include <vector>

namespace volpost {

/// For every tet (4 vertex ids), the tet across the face opposite vertex k, or -1 (the
/// boundary, or a face shared by more than two tets). Built on all cores by sorting faces.
std::vector<glm::ivec4> faceNeighbors(std::span<const glm::uvec4> tets);
/// The same for a mesh of tet4 cells (a TetMesh's mesh).
std::vector<glm::ivec4> faceNeighbors(const Mesh& tets);

}  // namespace volpost

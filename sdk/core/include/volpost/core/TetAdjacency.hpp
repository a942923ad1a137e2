// SPDX-License-Identifier: MIT
// Which tet lies across each face of each tet: what walks through a tetrahedral mesh (rays,
// streamlines, visibility sorts) step along.
#pragma once

#include <volpost/core/Mesh.hpp>

#include <glm/vec4.hpp>

#include <cstddef>
#include <functional>
#include <span>
#include <vector>

namespace volpost {

/// The most tets face adjacency can take: a face is numbered tet x 4 + face in 32 bits
/// here and in the GPU renderers' shaders (2^30 - 1 = 1.07G tets).
inline constexpr std::size_t kMaxTetsForFaceIndex = (std::size_t(1) << 30) - 1;
/// Throws std::length_error (naming both counts) for more tets than that.
void requireFaceIndexable(std::size_t tets);

/// For every tet (4 vertex ids), the tet across the face opposite vertex k, or -1 (the
/// boundary, or a face shared by more than two tets). Built on all cores by grouping faces
/// under their smallest vertex, with about 4 bytes per tet (and 12 per vertex) besides the
/// result. Throws std::length_error beyond
/// kMaxTetsForFaceIndex tets.
std::vector<glm::ivec4> faceNeighbors(std::span<const glm::uvec4> tets);
/// The same, reading each tet's vertex ids through nodesOf(t) and writing each interior
/// face's neighbour through setNeighbor(tet, face, across) (called from several threads,
/// never twice for one tet face; faces left unset are boundary): for structures that hold
/// the neighbours next to the vertices, with no list of either on the side.
void faceNeighborsInto(std::size_t tetCount, const std::function<glm::uvec4(std::size_t)>& nodesOf,
                       const std::function<void(std::size_t tet, int face, int across)>& setNeighbor);
/// The same for a mesh of tet4 cells (a TetMesh's mesh).
std::vector<glm::ivec4> faceNeighbors(const Mesh& tets);

}  // namespace volpost

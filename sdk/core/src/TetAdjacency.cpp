// SPDX-License-Identifier: MIT
#include <volpost/core/TetAdjacency.hpp>

#include <volpost/core/WorkerThreads.hpp>

#include <volpost/core/FaceGroups.hpp>

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>

namespace volpost {
namespace {

constexpr int kFaces[4][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};

}  // namespace

void requireFaceIndexable(std::size_t tets) {
  if (tets > kMaxTetsForFaceIndex)
    throw std::length_error(std::to_string(tets) + " tetrahedra: more than face adjacency can number (" +
                            std::to_string(kMaxTetsForFaceIndex) + ", tet x 4 + face in 32 bits); clip the model "
                            "or split it into parts");
}

// Face adjacency by grouping the 4 faces of every tet under their smallest vertex id (both
// copies of a shared face land in one group), then sorting each group, which is small, by
// the face's two other vertex ids. A face is listed as tet x 4 + face only (4 bytes; its
// other vertices are read again from the tet when its group is sorted), and large meshes
// go in passes over shares of the vertex ids (FaceGroups.hpp): the lists hold about 4
// bytes per tet at once, plus 12 per vertex, besides the result. Every step is on all cores.
std::vector<glm::ivec4> faceNeighbors(std::span<const glm::uvec4> tets) {
  std::vector<glm::ivec4> neighbors(tets.size(), glm::ivec4(-1));
  faceNeighborsInto(
      tets.size(), [&tets](std::size_t t) { return tets[t]; },
      [&neighbors](std::size_t t, int face, int across) { neighbors[t][face] = across; });
  return neighbors;
}

namespace {

// The face of `nodes` opposite vertex f, its vertex ids ascending.
std::array<std::uint32_t, 3> sortedFace(const glm::uvec4& nodes, int f) {
  std::array<std::uint32_t, 3> v = {nodes[kFaces[f][0]], nodes[kFaces[f][1]], nodes[kFaces[f][2]]};
  if (v[0] > v[1]) std::swap(v[0], v[1]);
  if (v[1] > v[2]) std::swap(v[1], v[2]);
  if (v[0] > v[1]) std::swap(v[0], v[1]);
  return v;
}

constexpr std::size_t kTetsPerChunk = std::size_t(1) << 14;

}  // namespace

void faceNeighborsInto(std::size_t tetCount, const std::function<glm::uvec4(std::size_t)>& nodesOf,
                       const std::function<void(std::size_t tet, int face, int across)>& setNeighbor) {
  requireFaceIndexable(tetCount);
  if (tetCount == 0) return;
  std::vector<std::uint32_t> chunkMax((tetCount + kTetsPerChunk - 1) / kTetsPerChunk, 0);
  forEachChunk(tetCount, kTetsPerChunk, [&](std::size_t begin, std::size_t end) {
    std::uint32_t top = 0;
    for (std::size_t t = begin; t < end; ++t) {
      const glm::uvec4 n = nodesOf(t);
      top = std::max({top, n[0], n[1], n[2], n[3]});
    }
    chunkMax[begin / kTetsPerChunk] = top;
  });
  const std::size_t vertices = std::size_t(*std::max_element(chunkMax.begin(), chunkMax.end())) + 1;
  std::vector<std::uint32_t>().swap(chunkMax);
  const auto listFaces = [&](auto visit) {  // each face as tet x 4 + face, under its smallest vertex
    forEachChunk(tetCount, kTetsPerChunk, [&](std::size_t begin, std::size_t end) {
      for (std::size_t t = begin; t < end; ++t) {
        const glm::uvec4 n = nodesOf(t);
        for (int f = 0; f < 4; ++f)
          visit(std::size_t(std::min({n[kFaces[f][0]], n[kFaces[f][1]], n[kFaces[f][2]]})), std::uint32_t(t) * 4 + std::uint32_t(f));
      }
    });
  };
  // Each group sorted by the faces' two larger vertex ids: pairs are neighbours.
  const auto matchGroup = [&](std::span<const std::uint32_t> faces) {
    struct Keyed {
      std::uint64_t key;
      std::uint32_t tetFace;
      bool operator<(const Keyed& o) const { return key != o.key ? key < o.key : tetFace < o.tetFace; }
    };
    thread_local std::vector<Keyed> group;
    group.clear();
    for (const std::uint32_t tetFace : faces) {
      const auto face = sortedFace(nodesOf(tetFace / 4), int(tetFace % 4));
      group.push_back({std::uint64_t(face[1]) << 32 | face[2], tetFace});
    }
    std::sort(group.begin(), group.end());
    for (std::size_t i = 0; i < group.size();) {
      std::size_t j = i + 1;
      while (j < group.size() && group[j].key == group[i].key) ++j;
      if (j - i == 2) {  // an interior face; 3+ (non-manifold) are left as boundary
        const std::uint32_t a = group[i].tetFace, b = group[i + 1].tetFace;
        setNeighbor(a / 4, int(a % 4), int(b / 4));
        setNeighbor(b / 4, int(b % 4), int(a / 4));
      }
      i = j;
    }
  };
  forEachFaceGroup<std::uint32_t>(vertices, std::clamp<std::size_t>(tetCount >> 20, 1, 4), listFaces, matchGroup);
}

std::vector<glm::ivec4> faceNeighbors(const Mesh& tets) {
  std::vector<glm::uvec4> v(tets.cellCount());
  for (std::size_t c = 0; c < tets.cellCount(); ++c) {
    const auto n = tets.cellNodes(c);
    v[c] = glm::uvec4(n[0], n[1], n[2], n[3]);
  }
  return faceNeighbors(v);
}

}  // namespace volpost

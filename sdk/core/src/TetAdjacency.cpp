// SPDX-License-Identifier: MIT
#include <volpost/core/TetAdjacency.hpp>

#include <volpost/core/WorkerThreads.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <stdexcept>
#include <string>
#include <thread>

namespace volpost {
namespace {

constexpr int kFaces[4][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};

// Runs body(range, begin, end) over [0, n) in `ranges` ranges on the threads the system gives.
template <typename Body>
void parallelRanges(std::size_t n, unsigned ranges, Body body) {
  std::atomic<unsigned> next{0};
  runOnThreads(ranges, [&](unsigned) {
    for (unsigned w; (w = next++) < ranges;) body(w, n * w / ranges, n * (w + 1) / ranges);
  });
}

}  // namespace

void requireFaceIndexable(std::size_t tets) {
  if (tets > kMaxTetsForFaceIndex)
    throw std::length_error(std::to_string(tets) + " tetrahedra: more than face adjacency can number (" +
                            std::to_string(kMaxTetsForFaceIndex) + ", tet x 4 + face in 32 bits); clip the model "
                            "or split it into parts");
}

// Face adjacency by sorting the 4 faces of every tet. In parallel: faces are bucketed by
// their smallest vertex id (both copies of a shared face land in the same bucket), each
// worker lists the faces of a range of tets, then each bucket is sorted and matched on
// its own. Every tet face is written by exactly one bucket. Large meshes go in passes over
// a share of the buckets each, so the face list (16 bytes per face) never holds more than
// about 16 bytes per tet at once, besides the result.
std::vector<glm::ivec4> faceNeighbors(std::span<const glm::uvec4> tets) {
  std::vector<glm::ivec4> neighbors(tets.size(), glm::ivec4(-1));
  faceNeighborsInto(
      tets.size(), [&tets](std::size_t t) { return tets[t]; },
      [&neighbors](std::size_t t, int face, int across) { neighbors[t][face] = across; });
  return neighbors;
}

void faceNeighborsInto(std::size_t tetCount, const std::function<glm::uvec4(std::size_t)>& nodesOf,
                       const std::function<void(std::size_t tet, int face, int across)>& setNeighbor) {
  requireFaceIndexable(tetCount);
  struct FaceKey {
    std::uint64_t high;  ///< the face's two smallest vertex ids
    std::uint32_t low;   ///< its largest
    std::uint32_t tetFace;
    bool operator<(const FaceKey& o) const { return high != o.high ? high < o.high : low < o.low; }
    bool sameFace(const FaceKey& o) const { return high == o.high && low == o.low; }
  };
  const unsigned workers = std::clamp(std::thread::hardware_concurrency(), 1u, 16u);
  const std::size_t passes = std::clamp<std::size_t>(tetCount >> 20, 1, 4);
  const std::size_t buckets = std::size_t(workers) * 8 * passes;
  for (std::size_t pass = 0; pass < passes; ++pass) {
    const std::size_t firstBucket = buckets * pass / passes, endBucket = buckets * (pass + 1) / passes;
    std::vector<std::vector<std::vector<FaceKey>>> listed(workers, std::vector<std::vector<FaceKey>>(endBucket - firstBucket));
    parallelRanges(tetCount, workers, [&](unsigned w, std::size_t begin, std::size_t end) {
      for (auto& bucket : listed[w]) bucket.reserve((end - begin) * 4 / buckets + (end - begin) / buckets / 2 + 16);
      for (std::size_t t = begin; t < end; ++t) {
        const glm::uvec4 nodes = nodesOf(t);
        for (int f = 0; f < 4; ++f) {
          std::array<std::uint32_t, 3> v = {nodes[kFaces[f][0]], nodes[kFaces[f][1]], nodes[kFaces[f][2]]};
          if (v[0] > v[1]) std::swap(v[0], v[1]);
          if (v[1] > v[2]) std::swap(v[1], v[2]);
          if (v[0] > v[1]) std::swap(v[0], v[1]);
          const std::size_t bucket = v[0] % buckets;
          if (bucket >= firstBucket && bucket < endBucket)
            listed[w][bucket - firstBucket].push_back(
                {std::uint64_t(v[0]) << 32 | v[1], v[2], std::uint32_t(t) * 4 + std::uint32_t(f)});
        }
      }
    });
    parallelRanges(endBucket - firstBucket, workers, [&](unsigned, std::size_t first, std::size_t last) {
      std::vector<FaceKey> faces;
      for (std::size_t b = first; b < last; ++b) {
        faces.clear();
        std::size_t total = 0;
        for (unsigned w = 0; w < workers; ++w) total += listed[w][b].size();
        faces.reserve(total);
        for (unsigned w = 0; w < workers; ++w) {
          faces.insert(faces.end(), listed[w][b].begin(), listed[w][b].end());
          std::vector<FaceKey>().swap(listed[w][b]);  // freed as it is taken
        }
        std::sort(faces.begin(), faces.end());
        for (std::size_t i = 0; i < faces.size();) {
          std::size_t j = i + 1;
          while (j < faces.size() && faces[j].sameFace(faces[i])) ++j;
          if (j - i == 2) {  // an interior face; 3+ (non-manifold) are left as boundary
            const std::uint32_t a = faces[i].tetFace, b2 = faces[i + 1].tetFace;
            setNeighbor(a / 4, int(a % 4), int(b2 / 4));
            setNeighbor(b2 / 4, int(b2 % 4), int(a / 4));
          }
          i = j;
        }
      }
    });
  }
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

// SPDX-License-Identifier: MIT
#include "TetMeshGpu.hpp"

#include <volpost/core/Quantity.hpp>
#include <volpost/core/Tetrahedralize.hpp>
#include <volpost/core/WorkerThreads.hpp>

#include <glm/geometric.hpp>

#include <algorithm>
#include <atomic>
#include <cstring>
#include <array>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>
#include <thread>

namespace volpost::volume {
namespace {

constexpr int kFaces[4][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};

constexpr std::size_t kChunk = std::size_t(1) << 14;

double orientation(const glm::dvec3* p) { return glm::dot(p[1] - p[0], glm::cross(p[2] - p[0], p[3] - p[0])); }


constexpr std::uint32_t kNone = 0xffffffffu, kFar = 1u, kTetBits = 0x3fffffffu;

// The tet across each face (4 words per tet, then packed in place), with its boundary faces.
void findNeighbors(TetMeshGpu& g) {
  std::vector<std::uint32_t> words(g.tetCount * 4, kNone);
  faceNeighborsInto(
      g.tetCount, [&g](std::size_t t) { return g.tetNodes(t); },
      [&words](std::size_t t, int face, int across) { words[t * 4 + std::size_t(face)] = std::uint32_t(across); });
  packNeighbors(words, g.tetCount, g.farNeighbors, g.boundaryFaces);
  g.neighbors = std::move(words);
}

}  // namespace

std::vector<glm::vec4> buildFaceBvh(std::vector<std::uint32_t>& faces, std::span<const glm::uvec3> faceNodes,
                                    std::span<const glm::vec4> nodes) {
  const std::size_t n = faces.size();
  std::vector<glm::vec4> bvh;
  if (n == 0) return bvh;
  std::vector<std::array<glm::vec3, 2>> boxes(n);
  for (std::size_t i = 0; i < n; ++i) {
    glm::vec3 lo(INFINITY), hi(-INFINITY);
    for (int k = 0; k < 3; ++k) {
      const glm::vec3 p(nodes[faceNodes[i][k]]);
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
    const glm::vec3 pad = (hi - lo) * 1e-5f + 1e-6f * glm::length(hi) + 1e-30f;  // float boxes: be generous
    boxes[i] = {lo - pad, hi + pad};
  }
  std::vector<std::uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  struct Task {
    std::uint32_t node, first, count;
  };
  std::vector<Task> tasks = {{0, 0, std::uint32_t(n)}};
  bvh.assign(2, glm::vec4(0.0f));
  while (!tasks.empty()) {
    const Task t = tasks.back();
    tasks.pop_back();
    glm::vec3 lo(INFINITY), hi(-INFINITY), clo(INFINITY), chi(-INFINITY);
    for (std::uint32_t i = t.first; i < t.first + t.count; ++i) {
      lo = glm::min(lo, boxes[order[i]][0]);
      hi = glm::max(hi, boxes[order[i]][1]);
      const glm::vec3 c = 0.5f * (boxes[order[i]][0] + boxes[order[i]][1]);
      clo = glm::min(clo, c);
      chi = glm::max(chi, c);
    }
    const glm::vec3 e = chi - clo;
    const bool leaf = t.count <= 4 || (e.x == 0.0f && e.y == 0.0f && e.z == 0.0f);
    std::uint32_t first = t.first, count = t.count;
    if (!leaf) {
      const int axis = e.x >= e.y && e.x >= e.z ? 0 : e.y >= e.z ? 1 : 2;
      const auto b = order.begin() + t.first;
      std::nth_element(b, b + t.count / 2, b + t.count, [&](std::uint32_t x, std::uint32_t y) {
        return boxes[x][0][axis] + boxes[x][1][axis] < boxes[y][0][axis] + boxes[y][1][axis];
      });
      first = std::uint32_t(bvh.size() / 2);
      count = 0;
      bvh.resize(bvh.size() + 4, glm::vec4(0.0f));
      tasks.push_back({first, t.first, t.count / 2});
      tasks.push_back({first + 1, t.first + t.count / 2, t.count - t.count / 2});
    }
    std::uint32_t bits[2] = {first, count};
    float asFloat[2];
    std::memcpy(asFloat, bits, sizeof bits);
    bvh[2 * t.node] = glm::vec4(lo, asFloat[0]);
    bvh[2 * t.node + 1] = glm::vec4(hi, asFloat[1]);
  }
  std::vector<std::uint32_t> ordered(n);
  for (std::size_t i = 0; i < n; ++i) ordered[i] = faces[order[i]];
  faces = std::move(ordered);
  return bvh;
}

namespace {

void buildBvh(TetMeshGpu& g) {
  std::vector<glm::uvec3> faceNodes(g.boundaryFaces.size());
  for (std::size_t i = 0; i < faceNodes.size(); ++i) {
    const std::uint32_t t = g.boundaryFaces[i] / 4, f = g.boundaryFaces[i] % 4;
    const glm::uvec4 v = g.tetNodes(t);
    faceNodes[i] = {v[kFaces[f][0]], v[kFaces[f][1]], v[kFaces[f][2]]};
  }
  g.bvh = buildFaceBvh(g.boundaryFaces, faceNodes, g.nodes);
}

}  // namespace

void packNeighbors(std::vector<std::uint32_t>& words, std::size_t tetCount, std::size_t& farCount,
                   std::vector<std::uint32_t>& boundaryFaces) {
  // First, on all cores: the face of the tet across that points back, in the two bits tet
  // numbers leave free (tets < 2^30). Others read a word while its owner sets those bits:
  // atomic, and read through the mask.
  forEachChunk(tetCount, kChunk, [&](std::size_t begin, std::size_t end) {
    for (std::size_t t = begin; t < end; ++t)
      for (std::size_t k = 0; k < 4; ++k) {
        std::atomic_ref<std::uint32_t> mine(words[t * 4 + k]);
        const std::uint32_t across = mine.load(std::memory_order_relaxed);
        if (across == kNone) continue;
        std::uint32_t back = 0;
        for (std::uint32_t j = 0; j < 4; ++j)
          if ((std::atomic_ref<std::uint32_t>(words[std::size_t(across) * 4 + j]).load(std::memory_order_relaxed) &
               kTetBits) == t)
            back = j;
        mine.fetch_or(back << 30, std::memory_order_relaxed);
      }
  });
  // Then in place, in tet order: the three words of tet t lie at or before its four.
  std::vector<std::uint32_t> far;
  for (std::size_t t = 0; t < tetCount; ++t) {
    std::uint32_t field[4];
    for (std::size_t k = 0; k < 4; ++k) {
      const std::uint32_t w = words[t * 4 + k];
      if (w == kNone) {
        field[k] = 0;
        boundaryFaces.push_back(std::uint32_t(t * 4 + k));
        continue;
      }
      const std::int64_t step = std::int64_t(w & kTetBits) - std::int64_t(t);
      if (step >= -kNearNeighborStep && step <= kNearNeighborStep) {
        field[k] = (std::uint32_t(step) & 0x3fffffu) << 2 | w >> 30;
      } else {
        field[k] = kFar;
        far.insert(far.end(), {std::uint32_t(t * 4 + k), (w & kTetBits) * 4 + (w >> 30)});
      }
    }
    words[t * 3] = field[0] | field[1] << 24;
    words[t * 3 + 1] = field[1] >> 8 | field[2] << 16;
    words[t * 3 + 2] = field[2] >> 16 | field[3] << 8;
  }
  farCount = far.size() / 2;  // in tet order: ascending keys already
  words.resize(tetCount * 3);
  words.insert(words.end(), far.begin(), far.end());
}

glm::ivec4 TetMeshGpu::neighborsOf(std::size_t tet) const {
  const std::uint32_t* w = neighbors.data() + tet * 3;
  const std::uint32_t field[4] = {w[0] & 0xffffffu, (w[0] >> 24 | w[1] << 8) & 0xffffffu,
                                  (w[1] >> 16 | w[2] << 16) & 0xffffffu, w[2] >> 8};
  glm::ivec4 across(-1);
  for (int k = 0; k < 4; ++k) {
    if (field[k] == 0) continue;
    if (field[k] == kFar) {
      const std::uint32_t key = std::uint32_t(tet * 4 + std::size_t(k));
      const std::uint32_t* pairs = neighbors.data() + tetCount * 3;
      std::size_t lo = 0, hi = farNeighbors;
      while (lo < hi) {
        const std::size_t mid = (lo + hi) / 2;
        if (pairs[2 * mid] < key) lo = mid + 1;
        else hi = mid;
      }
      across[k] = int(pairs[2 * lo + 1] / 4);
      continue;
    }
    const std::int32_t step = std::int32_t(field[k] << 8) >> 10;  // bits 2..23, sign-extended
    across[k] = int(std::int64_t(tet) + step);
  }
  return across;
}

// The range of the finite values (see TetMeshGpu::valueOffset).
void setValueFrame(TetMeshGpu& g, SampleView values) { setValueFrame(g, rangeOf(values)); }

void setValueFrame(TetMeshGpu& g, const ValueRange& range) {
  const double lo = range.min, hi = range.max;  // 0, 0 without a finite value
  g.valueMin = lo;
  g.valueMax = hi;
  g.valueOffset = lo;
  const double scale = 1.0 / (hi - lo);
  // A constant field (or one whose spread is below double's normal range) maps to 0; a
  // spread beyond double's range is halved first.
  g.valueScale = std::isfinite(scale) ? scale : std::isfinite(hi - lo) ? 1.0 : 0.5 / (0.5 * hi - 0.5 * lo);
}

std::size_t TetMeshGpu::bytes() const {  // what goes to the GPU (cellOfTet stays on the CPU)
  const std::size_t neighborBytes = (tetCount * 3 + farNeighbors * 2) * sizeof(std::uint32_t);
  return nodes.size() * sizeof(glm::vec4) + tetCount * sizeof(glm::uvec4) + neighborBytes +
         cellValues.size() * sizeof(float) + boundaryFaces.size() * sizeof(std::uint32_t) + bvh.size() * sizeof(glm::vec4);
}

TetMeshGpu buildTetMeshGpu(const Mesh& mesh, FieldLocation location, std::span<const double> values) {
  requireTetrahedraAndValues(mesh, location == FieldLocation::Node, values.size());
  TetMeshGpu g;
  const Bounds b = mesh.bounds();
  g.origin = b.valid ? b.center() : glm::dvec3(0.0);
  g.diagonal = b.valid ? b.diagonal() : 0.0;
  setValueFrame(g, values);
  g.nodes.resize(mesh.nodeCount());
  forEachChunk(mesh.nodeCount(), kChunk, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      const glm::dvec3 p = mesh.nodes[i] - g.origin;
      const double v = location == FieldLocation::Node ? values[i] : g.valueOffset;
      g.nodes[i] = glm::vec4(float(p.x), float(p.y), float(p.z), std::isfinite(v) ? g.gpuValue(v) : 0.0f);
    }
  });
  // Each cell's orientation (0: left out for zero volume or a value that is not finite) and
  // longest edge, on all cores; then the kept ones in order.
  std::vector<std::int8_t> sign(mesh.cellCount());
  std::vector<double> chunkMaxEdge((mesh.cellCount() + kChunk - 1) / kChunk, 0.0);
  forEachChunk(mesh.cellCount(), kChunk, [&](std::size_t begin, std::size_t end) {
    double longest = 0.0;
    for (std::size_t c = begin; c < end; ++c) {
      const auto n = mesh.cellNodes(c);
      glm::dvec3 p[4];
      bool finite = location == FieldLocation::Cell ? std::isfinite(values[c]) : true;
      for (int k = 0; k < 4; ++k) {
        p[k] = mesh.nodes[n[k]];
        finite = finite && std::isfinite(p[k].x) && std::isfinite(p[k].y) && std::isfinite(p[k].z) &&
                 (location == FieldLocation::Cell || std::isfinite(values[n[k]]));
      }
      const double o = finite ? orientation(p) : 0.0;
      sign[c] = std::int8_t(o > 0.0 ? 1 : o < 0.0 ? -1 : 0);
      if (sign[c] != 0)
        for (int i = 0; i < 4; ++i)
          for (int j = i + 1; j < 4; ++j) longest = std::max(longest, glm::length(p[i] - p[j]));
    }
    chunkMaxEdge[begin / kChunk] = longest;
  });
  for (double e : chunkMaxEdge) g.maxEdge = std::max(g.maxEdge, e);
  g.skippedTets = std::size_t(std::count(sign.begin(), sign.end(), std::int8_t(0)));
  g.tetCount = mesh.cellCount() - g.skippedTets;
  const bool asGiven = g.skippedTets == 0 && mesh.connectivity().size() == mesh.cellCount() * 4 &&
                       std::all_of(sign.begin(), sign.end(), [](std::int8_t x) { return x > 0; }) &&
                       std::all_of(mesh.cellTypes().begin(), mesh.cellTypes().end(), [](CellType t) { return t == CellType::Tet4; });
  if (asGiven) {  // the mesh's cells are the list: shared, not copied
    auto sharing = std::make_shared<Mesh>();
    sharing->shareCellsOf(mesh);
    g.sharedCells = std::move(sharing);
  } else {
    g.tets.resize(g.tetCount);
  }
  if (g.skippedTets > 0) g.cellOfTet.resize(g.tetCount);
  if (location == FieldLocation::Cell) g.cellValues.resize(g.tetCount);
  for (std::size_t c = 0, t = 0; c < mesh.cellCount(); ++c) {
    if (sign[c] == 0) continue;
    const auto n = mesh.cellNodes(c);
    if (!asGiven)  // inverted cells drawn, oriented
      g.tets[t] = sign[c] > 0 ? glm::uvec4(n[0], n[1], n[2], n[3]) : glm::uvec4(n[0], n[2], n[1], n[3]);
    if (g.skippedTets > 0) g.cellOfTet[t] = std::uint32_t(c);
    if (location == FieldLocation::Cell) g.cellValues[t] = g.gpuValue(values[c]);
    ++t;
  }
  std::vector<std::int8_t>().swap(sign);
  findNeighbors(g);
  buildBvh(g);
  return g;
}

bool replaceValues(TetMeshGpu& g, const Mesh& mesh, FieldLocation location, std::span<const double> values) {
  const std::size_t expected = location == FieldLocation::Node ? mesh.nodeCount() : mesh.cellCount();
  if (values.size() != expected || (location == FieldLocation::Cell) != !g.cellValues.empty() ||
      (location == FieldLocation::Cell && g.cellValues.size() != g.tetCount))
    return false;
  // Every kept tet must stay finite, and no left-out tet may have become renderable.
  std::vector<char> kept(mesh.cellCount(), 0);
  for (std::size_t t = 0; t < g.tetCount; ++t) kept[g.sourceCell(t)] = 1;
  for (std::size_t c = 0; c < mesh.cellCount(); ++c) {
    bool finite = true;
    if (location == FieldLocation::Cell) finite = std::isfinite(values[c]);
    else
      for (NodeIndex n : mesh.cellNodes(c).first(4)) finite = finite && std::isfinite(values[n]);
    if (kept[c] && !finite) return false;
    if (!kept[c] && finite && g.skippedTets > 0) {
      // It may have been left out for zero volume instead: only those may stay out.
      const auto n = mesh.cellNodes(c);
      const glm::dvec3 p[4] = {mesh.nodes[n[0]], mesh.nodes[n[1]], mesh.nodes[n[2]], mesh.nodes[n[3]]};
      if (orientation(p) != 0.0) return false;
    }
  }
  setValueFrame(g, values);
  if (location == FieldLocation::Node)
    for (std::size_t i = 0; i < mesh.nodeCount(); ++i) g.nodes[i].w = std::isfinite(values[i]) ? g.gpuValue(values[i]) : 0.0f;
  else
    for (std::size_t t = 0; t < g.tetCount; ++t) g.cellValues[t] = g.gpuValue(values[g.sourceCell(t)]);
  return true;
}

}  // namespace volpost::volume

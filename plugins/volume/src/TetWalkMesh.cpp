// SPDX-License-Identifier: MIT
#include "TetWalkMesh.hpp"

#include <volpost/core/TetAdjacency.hpp>
#include <volpost/core/Tetrahedralize.hpp>
#include <volpost/core/WorkerThreads.hpp>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace volpost::volume {
namespace {
constexpr int kFaces[4][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};  // face k is opposite vertex k

// The connectivity entries per cell when every cell is a tet of one kind (tet4: 4, tet10:
// 10, corners first) stored without offsets; 0 otherwise.
std::size_t uniformTetStride(const Mesh& mesh) {
  const auto types = mesh.cellTypes();
  if (types.empty() || (types.front() != CellType::Tet4 && types.front() != CellType::Tet10)) return 0;
  if (std::any_of(types.begin(), types.end(), [&](CellType t) { return t != types.front(); })) return 0;
  const std::size_t stride = types.front() == CellType::Tet4 ? 4 : 10;
  return mesh.connectivity().size() == types.size() * stride ? stride : 0;
}

// body(i) for i in [0, n), on all cores.
template <typename Body>
void parallelChunks(std::size_t n, Body body) {
  forEachChunk(n, std::size_t(1) << 14, [&body](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) body(i);
  });
}
}

TetWalkMesh::TetWalkMesh(const Mesh& mesh, FieldLocation location, std::span<const double> values)
    : location_(location) {
  requireTetrahedraAndValues(mesh, location == FieldLocation::Node, values.size());
  const Bounds b = mesh.bounds();
  origin_ = b.valid ? b.center() : glm::dvec3(0.0);
  diagonal_ = b.valid ? b.diagonal() : 0.0;
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (double v : values)
    if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
  valueOffset_ = lo <= hi ? 0.5 * (lo + hi) : 0.0;

  // On all cores: the nodes, then which tets are kept, then their neighbours in place.
  nodes_.resize(mesh.nodeCount());
  exactPositions_.resize(mesh.nodeCount());
  parallelChunks(mesh.nodeCount(), [&](std::size_t i) {
    const glm::dvec3 p = mesh.nodes[i] - origin_;
    const double v = location == FieldLocation::Node && std::isfinite(values[i]) ? values[i] - valueOffset_ : 0.0;
    exactPositions_[i] = p;
    nodes_[i] = glm::vec4(glm::vec3(p), float(v));
  });
  std::vector<std::uint8_t> kept(mesh.cellCount());
  parallelChunks(mesh.cellCount(), [&](std::size_t c) {
    const auto nodes = mesh.cellNodes(c);
    glm::dvec3 p[4];
    bool finite = true;
    for (int k = 0; k < 4; ++k) {
      p[k] = mesh.nodes[nodes[k]] - origin_;
      const double s = location == FieldLocation::Node ? values[nodes[k]] : values[c];
      finite = finite && std::isfinite(s) && std::isfinite(p[k].x) && std::isfinite(p[k].y) && std::isfinite(p[k].z);
    }
    kept[c] = finite && glm::determinant(glm::dmat3(p[1] - p[0], p[2] - p[0], p[3] - p[0])) != 0.0;
  });
  const auto count = std::size_t(std::count(kept.begin(), kept.end(), std::uint8_t(1)));
  skipped_ = mesh.cellCount() - count;
  if (location == FieldLocation::Cell) cellValues_.resize(count);
  const std::size_t stride = uniformTetStride(mesh);
  if (skipped_ == 0 && stride != 0) {  // every cell kept, all of one type: its cells are the list
    auto sharing = std::make_shared<Mesh>();
    sharing->shareCellsOf(mesh);
    tetNodes_ = sharing->connectivity().data();
    stride_ = stride;
    sharedCells_ = true;
    tetNodeOwner_ = std::move(sharing);
    if (location == FieldLocation::Cell)
      parallelChunks(count, [&](std::size_t c) { cellValues_[c] = float(values[c] - valueOffset_); });
  } else {
    auto own = std::make_shared<std::vector<std::uint32_t>>(count * 4);
    auto keptTets = std::make_shared<std::vector<std::uint32_t>>();
    if (skipped_ > 0) keptTets->reserve(count);
    for (std::size_t c = 0, t = 0; c < mesh.cellCount(); ++c) {
      if (!kept[c]) continue;
      if (skipped_ > 0) keptTets->push_back(std::uint32_t(c));
      const auto nodes = mesh.cellNodes(c);
      std::copy(nodes.begin(), nodes.begin() + 4, own->begin() + std::ptrdiff_t(4 * t));
      if (location == FieldLocation::Cell) cellValues_[t] = float(values[c] - valueOffset_);
      ++t;
    }
    tetNodes_ = own->data();
    if (skipped_ > 0) keptTets_ = std::move(keptTets);
    stride_ = 4;
    tetNodeOwner_ = std::move(own);
  }
  std::vector<std::uint8_t>().swap(kept);
  auto neighbors = std::make_shared<std::vector<glm::ivec4>>(count, glm::ivec4(-1));
  std::vector<glm::ivec4>& across = *neighbors;
  faceNeighborsInto(
      count, [this](std::size_t t) { return tetNodes(t); },
      [&across](std::size_t t, int face, int other) { across[t][face] = other; });
  neighbors_ = std::move(neighbors);
}

std::shared_ptr<const TetWalkMesh> TetWalkMesh::withValues(const std::shared_ptr<const TetWalkMesh>& previous,
                                                           const Mesh& mesh, std::span<const double> values) {
  const bool sameTets = previous && previous->skipped_ == 0 && previous->tetCount() == mesh.cellCount() &&
                        values.size() == (previous->cellValues() ? mesh.cellCount() : mesh.nodeCount()) &&
                        std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); });
  if (!sameTets) return std::make_shared<const TetWalkMesh>(mesh, previous ? previous->location_ : FieldLocation::Node, values);
  auto next = std::make_shared<TetWalkMesh>(*previous);  // shares the tets' nodes and neighbours
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (double v : values) lo = std::min(lo, v), hi = std::max(hi, v);
  next->valueOffset_ = lo <= hi ? 0.5 * (lo + hi) : 0.0;
  if (next->cellValues())
    parallelChunks(values.size(), [&](std::size_t c) { next->cellValues_[c] = float(values[c] - next->valueOffset_); });
  else
    parallelChunks(values.size(), [&](std::size_t i) { next->nodes_[i].w = float(values[i] - next->valueOffset_); });
  return next;
}

std::vector<BoundaryFace> TetWalkMesh::boundaryOf(const std::vector<std::uint8_t>& visible) const {
  std::vector<BoundaryFace> faces;
  for (std::size_t t = 0; t < tetCount(); ++t) {
    if (!visible[t]) continue;
    const glm::uvec4 nodes = tetNodes(t);
    for (int f = 0; f < 4; ++f) {
      const int across = tetNeighbors(t)[f];
      if (across >= 0 && visible[std::size_t(across)]) continue;
      std::uint32_t v[3] = {nodes[kFaces[f][0]], nodes[kFaces[f][1]], nodes[kFaces[f][2]]};
      const glm::dvec3 a = exactPositions_[v[0]], b = exactPositions_[v[1]], c = exactPositions_[v[2]];
      const glm::dvec3 inside = exactPositions_[nodes[f]];
      if (glm::dot(glm::cross(b - a, c - a), inside - a) > 0.0) std::swap(v[1], v[2]);  // normal outward
      faces.push_back({std::uint32_t(t), {v[0], v[1], v[2]}});
    }
  }
  return faces;
}

std::size_t TetWalkMesh::bytes() const {
  const std::size_t ownNodes = sharedCells_ ? 0 : tetCount() * 4 * sizeof(std::uint32_t);
  return nodes_.size() * (sizeof(glm::vec4) + sizeof(glm::dvec3)) + ownNodes + tetCount() * sizeof(glm::ivec4) +
         cellValues_.size() * sizeof(float) + (keptTets_ ? keptTets_->size() * sizeof(std::uint32_t) : 0);
}

}  // namespace volpost::volume

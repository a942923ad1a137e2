// SPDX-License-Identifier: MIT
#include <volpost/core/Mesh.hpp>

#include <glm/geometric.hpp>

#include <cassert>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace volpost {
namespace {

bool isFinite(const glm::dvec3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

}  // namespace

double Bounds::diagonal() const { return valid ? glm::length(max - min) : 0.0; }

void Bounds::extend(const glm::dvec3& p) {
  if (!valid) {
    min = max = p;
    valid = true;
    return;
  }
  min = glm::min(min, p);
  max = glm::max(max, p);
}

// Every mesh without cells shares one empty set: the first change copies it (it is always
// shared), and a move can leave an empty mesh behind without allocating, as noexcept
// promises. Made by the first Mesh ever constructed, so no move can be the first to ask.
const std::shared_ptr<Mesh::CellArrays>& Mesh::noCells() {
  static const std::shared_ptr<CellArrays> empty = std::make_shared<CellArrays>();
  return empty;
}

Mesh::Mesh() : cells_(noCells()) {}

// A moved-from mesh stays a valid empty mesh.
Mesh::Mesh(Mesh&& other) noexcept
    : nodes(std::move(other.nodes)), nodeIds(std::move(other.nodeIds)), cellIds(std::move(other.cellIds)),
      cells_(std::exchange(other.cells_, noCells())) {}

Mesh& Mesh::operator=(Mesh&& other) noexcept {
  if (this != &other) {
    nodes = std::move(other.nodes);
    nodeIds = std::move(other.nodeIds);
    cellIds = std::move(other.cellIds);
    cells_ = std::exchange(other.cells_, noCells());
  }
  return *this;
}

Mesh::CellArrays& Mesh::cellsToChange() {
  if (cells_.use_count() > 1) cells_ = std::make_shared<CellArrays>(*cells_);
  return *cells_;
}

void Mesh::reserveCells(std::size_t cells, std::size_t connectivityEntries) {
  CellArrays& c = cellsToChange();
  c.types.reserve(cells);
  c.connectivity.reserve(connectivityEntries);
}

void Mesh::addCell(CellType type, std::span<const NodeIndex> cellNodes) {
  assert(static_cast<int>(cellNodes.size()) == topology(type).nodeCount);
  CellArrays& c = cellsToChange();
  const auto size = std::uint32_t(cellNodes.size());
  if (c.types.empty() && c.offsets.empty()) {
    c.uniformSize = size;
  } else if (c.uniformSize && size != c.uniformSize) {  // the first cell of another size: offsets from now on
    c.offsets.reserve(c.types.capacity() + 1);
    for (std::size_t i = 0; i <= c.types.size(); ++i) c.offsets.push_back(i * c.uniformSize);
    c.uniformSize = 0;
  }
  c.types.push_back(type);
  c.connectivity.insert(c.connectivity.end(), cellNodes.begin(), cellNodes.end());
  if (!c.uniformSize) c.offsets.push_back(c.connectivity.size());
}

void Mesh::takeCells(CellType type, std::vector<NodeIndex>&& connectivity) {
  const auto size = std::size_t(topology(type).nodeCount);
  if (cellCount() != 0 || connectivity.size() % size != 0)
    throw std::invalid_argument("takeCells: the mesh has cells already, or " + std::to_string(connectivity.size()) +
                                " node indices are not whole cells of " + std::to_string(size));
  CellArrays& c = cellsToChange();
  c.types.assign(connectivity.size() / size, type);
  c.offsets.clear();
  c.connectivity = std::move(connectivity);
  c.uniformSize = c.types.empty() ? 0 : std::uint32_t(size);
}

void Mesh::remapNodes(const std::vector<NodeIndex>& map) {
  for (NodeIndex& n : cellsToChange().connectivity) n = map[n];
}

std::size_t Mesh::cellBytes() const {
  return cells_->types.size() * sizeof(CellType) + cells_->offsets.size() * sizeof(std::size_t) +
         cells_->connectivity.size() * sizeof(NodeIndex);
}

std::map<CellType, std::size_t> Mesh::countsByType() const {
  std::map<CellType, std::size_t> counts;
  for (CellType t : cells_->types) ++counts[t];
  return counts;
}

Bounds Mesh::bounds() const {
  std::vector<char> used(nodes.size(), 0);
  for (NodeIndex n : cells_->connectivity)
    if (n < used.size()) used[n] = 1;
  Bounds b;
  for (std::size_t i = 0; i < nodes.size(); ++i)
    if (used[i] && isFinite(nodes[i])) b.extend(nodes[i]);
  return b;
}

Bounds Mesh::allNodeBounds() const {
  Bounds b;
  for (const auto& p : nodes)
    if (isFinite(p)) b.extend(p);
  return b;
}

double signedCellVolume(const Mesh& mesh, std::size_t cell) {
  const auto& topo = topology(mesh.cellType(cell));
  const auto nodes = mesh.cellNodes(cell);
  glm::dvec3 centroid(0.0);
  for (int i = 0; i < topo.cornerCount; ++i) centroid += mesh.nodes[nodes[i]];
  centroid /= double(topo.cornerCount);
  // Sum of tets (centroid, face triangle); quads are fanned from their first corner,
  // so warped faces contribute consistently and mirrored cells come out negative.
  double volume = 0.0;
  for (const CellFace& face : topo.faces) {
    const glm::dvec3 a = mesh.nodes[nodes[face.corners[0]]] - centroid;
    for (int k = 1; k + 1 < face.size; ++k) {
      const glm::dvec3 b = mesh.nodes[nodes[face.corners[k]]] - centroid;
      const glm::dvec3 c = mesh.nodes[nodes[face.corners[k + 1]]] - centroid;
      volume += glm::dot(a, glm::cross(b, c)) / 6.0;
    }
  }
  return volume;
}

bool cellRepeatsANode(const Mesh& mesh, std::size_t cell) {
  const auto nodes = mesh.cellNodes(cell);
  for (std::size_t i = 1; i < nodes.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (nodes[i] == nodes[j]) return true;
  return false;
}

}  // namespace volpost

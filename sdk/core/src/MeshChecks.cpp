// SPDX-License-Identifier: MIT
#include <volpost/core/MeshChecks.hpp>

#include <volpost/core/WorkerThreads.hpp>

#include <glm/geometric.hpp>

#include <algorithm>
#include <limits>
#include <array>
#include <cmath>
#include <cstring>
#include <sstream>
#include <numeric>

namespace volpost {
namespace {

constexpr std::size_t kMaxItems = 1000;  // a diagnostic lists at most this many entities

void add(Model& model, std::string code, std::size_t count, const std::string& what,
         std::vector<std::size_t> items, Severity severity = Severity::Warning) {
  if (count == 0) return;
  if (items.size() > kMaxItems) items.resize(kMaxItems);
  std::ostringstream msg;
  msg << count << ' ' << what;
  if (!items.empty()) {
    msg << " (first: ";
    for (std::size_t i = 0; i < std::min<std::size_t>(items.size(), 5); ++i)
      msg << (i ? ", " : "") << items[i];
    msg << ")";
  }
  model.diagnostics.push_back({severity, std::move(code), msg.str(), std::move(items)});
}

bool finite(const glm::dvec3& p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

void checkNodes(Model& model) {
  const Mesh& mesh = model.mesh();
  std::vector<char> used(mesh.nodeCount(), 0);
  for (NodeIndex n : mesh.connectivity()) used[n] = 1;
  std::vector<std::size_t> nonFinite, unused;
  for (std::size_t i = 0; i < mesh.nodeCount(); ++i) {
    if (!finite(mesh.nodes[i])) nonFinite.push_back(i);
    if (!used[i]) unused.push_back(i);
  }
  add(model, "nonfinite-coordinates", nonFinite.size(), "nodes with NaN or infinite coordinates",
      nonFinite);
  add(model, "unused-nodes", unused.size(), "nodes used by no cell (ignored for bounds)", unused,
      Severity::Info);
}

// Sorts entries (each with a well-mixed 64-bit `hash`) by hash, then by `tie`: first in
// place into 256 runs by the hash's top byte (one pass of swaps: an American flag sort),
// then each run, small enough for the caches, sorted on its own, on all cores.
template <typename Entry, typename Tie>
void sortByHashOnAllCores(std::vector<Entry>& entries, Tie tie) {
  const auto digit = [](const Entry& e) { return std::size_t(e.hash >> 56); };
  std::array<std::size_t, 257> start{};
  for (const Entry& e : entries) ++start[digit(e) + 1];
  for (std::size_t d = 0; d < 256; ++d) start[d + 1] += start[d];
  std::array<std::size_t, 256> next;
  std::copy(start.begin(), start.end() - 1, next.begin());
  for (std::size_t d = 0; d < 256; ++d)
    while (next[d] < start[d + 1]) {
      Entry e = entries[next[d]];
      for (std::size_t home = digit(e); home != d; home = digit(e)) std::swap(e, entries[next[home]++]);
      entries[next[d]++] = e;
    }
  forEachChunk(256, 1, [&](std::size_t d, std::size_t) {
    std::sort(entries.begin() + std::ptrdiff_t(start[d]), entries.begin() + std::ptrdiff_t(start[d + 1]),
              [&tie](const Entry& a, const Entry& b) { return a.hash != b.hash ? a.hash < b.hash : tie(a, b); });
  });
}

std::uint64_t mixed(std::uint64_t h) {  // splitmix64's finalizer: every input bit moves the top bits
  h = (h ^ (h >> 30)) * 0xbf58476d1ce4e5b9ull;
  h = (h ^ (h >> 27)) * 0x94d049bb133111ebull;
  return h ^ (h >> 31);
}

// Coincident nodes that cells do not share make every face look like boundary; they are
// merged (cells re-pointed to the first node at that position) and reported. Found by
// sorting node indices by position (8 bytes per node, no hash map).
void mergeCoincidentNodes(Model& model) {
  Mesh& mesh = model.mesh();
  struct Entry {
    std::uint64_t hash;
    NodeIndex node;
  };
  const auto bitsOf = [](double v) {
    if (v == 0.0) v = 0.0;  // -0 and +0 are one position
    std::uint64_t b;
    std::memcpy(&b, &v, sizeof b);
    return b;
  };
  std::vector<Entry> entries;
  entries.reserve(mesh.nodeCount());
  for (std::size_t i = 0; i < mesh.nodeCount(); ++i) {
    const glm::dvec3& p = mesh.nodes[i];
    if (finite(p)) entries.push_back({mixed(bitsOf(p.x) ^ mixed(bitsOf(p.y) ^ mixed(bitsOf(p.z)))), NodeIndex(i)});
  }
  // The first node of a position comes first among its equals.
  sortByHashOnAllCores(entries, [](const Entry& a, const Entry& b) { return a.node < b.node; });
  std::vector<NodeIndex> map;
  std::vector<std::size_t> merged;
  for (std::size_t i = 1; i < entries.size(); ++i) {
    if (entries[i].hash != entries[i - 1].hash) continue;
    const glm::dvec3& p = mesh.nodes[entries[i].node];
    for (std::size_t j = i; j-- > 0 && entries[j].hash == entries[i].hash;) {  // the first equal one before it
      if (mesh.nodes[entries[j].node] != p) continue;
      if (map.empty()) {
        map.resize(mesh.nodeCount());
        std::iota(map.begin(), map.end(), NodeIndex(0));
      }
      map[entries[i].node] = map[entries[j].node];
      merged.push_back(entries[i].node);
      break;
    }
  }
  if (merged.empty()) return;
  std::sort(merged.begin(), merged.end());
  mesh.remapNodes(map);
  add(model, "duplicate-nodes", merged.size(),
      "nodes at the same position as an earlier node, merged so cells share faces", merged);
}

double faceWarp(const Mesh& mesh, std::span<const NodeIndex> nodes, const CellFace& f) {
  const glm::dvec3 a = mesh.nodes[nodes[f.corners[0]]], b = mesh.nodes[nodes[f.corners[1]]],
                   c = mesh.nodes[nodes[f.corners[2]]], d = mesh.nodes[nodes[f.corners[3]]];
  const glm::dvec3 n = glm::cross(c - a, d - b);  // normal of the quad's mean plane
  const double len = glm::length(n);
  const double size = std::max(glm::length(c - a), glm::length(d - b));
  if (len == 0.0 || size == 0.0) return 0.0;
  // Distance of the diagonals from each other relative to the face size.
  return std::abs(glm::dot(b - a, n) / len) / size;
}

// A quad is self-intersecting (bow-tie) or non-convex when the two triangles of one of
// its diagonal splits face opposite ways. Warped but convex quads pass.
bool faceTwisted(const Mesh& mesh, std::span<const NodeIndex> nodes, const CellFace& f) {
  glm::dvec3 p[4];
  for (int k = 0; k < 4; ++k) p[k] = mesh.nodes[nodes[f.corners[k]]];
  for (int d = 0; d < 2; ++d) {
    const glm::dvec3 a = p[d], b = p[d + 1], c = p[d + 2], e = p[(d + 3) % 4];
    if (glm::dot(glm::cross(b - a, c - a), glm::cross(c - a, e - a)) < 0.0) return true;
  }
  return false;
}

double longestEdge(const Mesh& mesh, std::span<const NodeIndex> nodes, const CellTopology& topo) {
  double longest = 0.0;
  for (const CellEdge& e : topo.edges)
    longest = std::max(longest, glm::length(mesh.nodes[nodes[e.a]] - mesh.nodes[nodes[e.b]]));
  return longest;
}

template <typename Found>
void checkCell(const Mesh& mesh, std::size_t c, Found& found) {
  const auto nodes = mesh.cellNodes(c);
  const auto& topo = topology(mesh.cellType(c));
  if (cellRepeatsANode(mesh, c)) {
    found.repeated.push_back(c);
    return;
  }
  for (NodeIndex n : nodes)
    if (!finite(mesh.nodes[n])) return;
  const double v = signedCellVolume(mesh, c);
  // Relative to the cell's own size, so slivers are caught in tiny and huge models alike.
  const double edge = longestEdge(mesh, nodes, topo);
  if (std::abs(v) <= 1e-6 * edge * edge * edge) found.degenerate.push_back(c);
  else if (v < 0.0) found.inverted.push_back(c);
  bool isWarped = false, isTwisted = false;
  for (const CellFace& f : topo.faces) {
    if (f.size != 4) continue;
    isTwisted = isTwisted || faceTwisted(mesh, nodes, f);
    isWarped = isWarped || faceWarp(mesh, nodes, f) > 1e-3;
  }
  if (isTwisted) found.twisted.push_back(c);
  else if (isWarped) found.warped.push_back(c);
}

// Each cell's defects, on all cores in chunks; the lists come out in cell order.
void checkCells(Model& model) {
  const Mesh& mesh = model.mesh();
  struct Found {
    std::vector<std::size_t> inverted, degenerate, repeated, warped, twisted;
  };
  constexpr std::size_t kChunk = 1 << 15;
  const std::size_t chunks = (mesh.cellCount() + kChunk - 1) / kChunk;
  std::vector<Found> found(chunks);
  forEachChunk(mesh.cellCount(), kChunk, [&](std::size_t begin, std::size_t end) {
    for (std::size_t c = begin; c < end; ++c) checkCell(mesh, c, found[begin / kChunk]);
  });
  Found all;
  for (Found& f : found)
    for (auto [to, from] : {std::pair{&all.inverted, &f.inverted}, {&all.degenerate, &f.degenerate},
                            {&all.repeated, &f.repeated}, {&all.warped, &f.warped}, {&all.twisted, &f.twisted}})
      to->insert(to->end(), from->begin(), from->end());
  add(model, "inverted-cells", all.inverted.size(), "inverted cells (negative volume)", all.inverted);
  add(model, "degenerate-cells", all.degenerate.size(), "cells with zero or near-zero volume", all.degenerate);
  add(model, "repeated-node-cells", all.repeated.size(),
      "cells that use one node twice (degenerate: left out of the surface, probing and rendering)", all.repeated);
  add(model, "twisted-faces", all.twisted.size(), "cells with self-intersecting (bow-tie) faces", all.twisted);
  add(model, "warped-faces", all.warped.size(), "cells with non-planar quadrilateral faces", all.warped);
}

// Cells with the same corner nodes, found through a hash of their sorted corners (12
// bytes per cell while checking) and confirmed by comparing the corners themselves.
void checkDuplicateCells(Model& model) {
  const Mesh& mesh = model.mesh();
  const auto sortedCorners = [&](std::size_t c) {
    const auto nodes = mesh.cellNodes(c);
    const int corners = topology(mesh.cellType(c)).cornerCount;
    std::array<NodeIndex, 8> key;
    key.fill(std::numeric_limits<NodeIndex>::max());
    std::copy(nodes.begin(), nodes.begin() + std::min(corners, 8), key.begin());
    std::sort(key.begin(), key.end());
    return key;
  };
  struct Entry {
    std::uint64_t hash;
    std::uint32_t cell;
  };
  std::vector<Entry> entries(mesh.cellCount());
  forEachChunk(entries.size(), std::size_t(1) << 15, [&](std::size_t begin, std::size_t end) {
    for (std::size_t c = begin; c < end; ++c) {
      std::uint64_t h = 1469598103934665603ull;  // FNV-1a over the sorted corners
      for (NodeIndex n : sortedCorners(c)) h = (h ^ n) * 1099511628211ull;
      entries[c] = {h, std::uint32_t(c)};
    }
  });
  sortByHashOnAllCores(entries, [](const Entry& a, const Entry& b) { return a.cell < b.cell; });
  std::vector<std::size_t> dup;
  for (std::size_t i = 1; i < entries.size(); ++i) {
    if (entries[i].hash != entries[i - 1].hash) continue;
    const auto key = sortedCorners(entries[i].cell);
    for (std::size_t j = i; j-- > 0 && entries[j].hash == entries[i].hash;)
      if (sortedCorners(entries[j].cell) == key) {
        dup.push_back(entries[i].cell);
        break;
      }
  }
  std::sort(dup.begin(), dup.end());
  add(model, "duplicate-cells", dup.size(), "cells that repeat another cell's nodes", dup);
}

// Two entities under one id make "element 7" ambiguous in every message and probe.
void checkDuplicateIds(Model& model) {
  const auto duplicates = [](const std::vector<std::int64_t>& ids) {
    std::vector<std::pair<std::int64_t, std::size_t>> sorted(ids.size());
    for (std::size_t i = 0; i < ids.size(); ++i) sorted[i] = {ids[i], i};
    std::sort(sorted.begin(), sorted.end());
    std::vector<std::size_t> dup;
    for (std::size_t i = 1; i < sorted.size(); ++i)
      if (sorted[i].first == sorted[i - 1].first) dup.push_back(sorted[i].second);
    std::sort(dup.begin(), dup.end());
    return dup;
  };
  const auto cells = duplicates(model.mesh().cellIds);
  if (!cells.empty())
    add(model, "duplicate-element-ids", cells.size(),
        "elements whose id another element has too, e.g. id " + std::to_string(model.mesh().cellIds[cells[0]]) +
            " (their values and probes are ambiguous)",
        cells);
  const auto nodes = duplicates(model.mesh().nodeIds);
  if (!nodes.empty())
    add(model, "duplicate-node-ids", nodes.size(),
        "nodes whose id another node has too, e.g. id " + std::to_string(model.mesh().nodeIds[nodes[0]]), nodes);
}

}  // namespace

void checkModel(Model& model) {
  // A regular grid whose cells are not built yet has none of these defects: its points are
  // distinct and its hexahedra positive by construction, and readers refuse a grid with a
  // RegularGrid::defect(). Checking would build the 57 bytes per point it saves.
  if (!model.meshBuilt()) return;
  checkNodes(model);
  mergeCoincidentNodes(model);
  checkCells(model);
  checkDuplicateCells(model);
  checkDuplicateIds(model);
}

}  // namespace volpost

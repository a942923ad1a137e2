// SPDX-License-Identifier: MIT
#include "host/BoundarySurface.hpp"

// GCC 12 reports a false -Warray-bounds inside std::sort's insertion sort at -O2.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Warray-bounds"
#endif

#include <volpost/core/WorkerThreads.hpp>

#include <volpost/core/FaceGroups.hpp>

#include <algorithm>
#include <mutex>
#include <span>
#include <unordered_map>
#include <limits>

namespace volpost {
namespace {

using FaceKey = std::array<NodeIndex, 4>;  // sorted corner nodes, padded with the largest index

FaceKey faceKey(std::span<const NodeIndex> nodes, const CellFace& face) {
  FaceKey key;
  key.fill(std::numeric_limits<NodeIndex>::max());
  for (int k = 0; k < face.size; ++k) key[std::size_t(k)] = nodes[face.corners[k]];
  std::sort(key.begin(), key.begin() + face.size);
  return key;
}

// The cell faces no other cell shares, as cell x 8 + face, ascending. Each face is listed
// under its smallest corner as 8 bytes (FaceGroups.hpp), and each group sorted by the
// face's corners read again from its cell: about 8 bytes per tet at once (a list of every
// face with its corners was 96). On all cores.
std::vector<std::uint64_t> unsharedFaces(const Mesh& mesh, const Progress& progress) {
  constexpr std::size_t kChunk = std::size_t(1) << 14;
  const auto listFaces = [&](auto visit) {
    forEachChunk(mesh.cellCount(), kChunk, [&](std::size_t begin, std::size_t end) {
      for (std::size_t c = begin; c < end; ++c) {
        if (cellRepeatsANode(mesh, c)) continue;  // flagged by the checks; no proper faces
        const auto n = mesh.cellNodes(c);
        const auto& topo = topology(mesh.cellType(c));
        for (std::size_t f = 0; f < topo.faces.size(); ++f) {
          const CellFace& face = topo.faces[f];
          NodeIndex smallest = n[face.corners[0]];
          for (int k = 1; k < face.size; ++k) smallest = std::min(smallest, n[face.corners[k]]);
          visit(std::size_t(smallest), std::uint64_t(c) * 8 + f);
        }
      }
    });
  };
  std::vector<std::uint64_t> unshared;
  std::mutex unsharedMutex;
  const auto matchGroup = [&](std::span<const std::uint64_t> faces) {
    thread_local std::vector<std::pair<FaceKey, std::uint64_t>> group;
    group.clear();
    for (const std::uint64_t id : faces) {
      const std::size_t c = std::size_t(id / 8);
      group.push_back({faceKey(mesh.cellNodes(c), topology(mesh.cellType(c)).faces[id % 8]), id});
    }
    std::sort(group.begin(), group.end());
    for (std::size_t i = 0; i < group.size();) {
      std::size_t j = i + 1;
      while (j < group.size() && group[j].first == group[i].first) ++j;
      if (j - i == 1) {
        const std::lock_guard lock(unsharedMutex);
        unshared.push_back(group[i].second);
      }
      i = j;
    }
  };
  forEachFaceGroup<std::uint64_t>(mesh.nodeCount(), std::clamp<std::size_t>(mesh.cellCount() >> 20, 1, 4), listFaces,
                                  matchGroup);
  progress.report(0.5);
  std::sort(unshared.begin(), unshared.end());  // cell order, whatever the threads did
  return unshared;
}

int midsideNode(const CellTopology& topo, int a, int b) {
  for (const CellEdge& e : topo.edges)
    if ((e.a == a && e.b == b) || (e.a == b && e.b == a)) return e.mid;
  return -1;
}

// The cells of a mesh, as the builder reads them.
struct MeshCells {
  const Mesh& mesh;
  std::span<const NodeIndex> nodes(std::size_t cell) const { return mesh.cellNodes(cell); }
  CellType type(std::size_t cell) const { return mesh.cellType(cell); }
  glm::dvec3 position(NodeIndex node) const { return mesh.nodes[node]; }
  std::size_t nodeCount() const { return mesh.nodeCount(); }
};

// The hexahedra of a regular grid, made when asked (the grid holds no cells).
struct GridCells {
  const RegularGrid& grid;
  mutable std::array<NodeIndex, 8> corners{};
  std::span<const NodeIndex> nodes(std::size_t cell) const {
    const std::size_t cx = grid.dims[0] - 1, cy = grid.dims[1] - 1;
    corners = gridHexahedron(grid, cell % cx, (cell / cx) % cy, cell / (cx * cy));
    return corners;
  }
  CellType type(std::size_t) const { return CellType::Hex8; }
  glm::dvec3 position(NodeIndex node) const { return grid.pointPosition(node); }
  std::size_t nodeCount() const { return grid.pointCount(); }
};

template <typename Cells>
class SurfaceBuilder {
 public:
  SurfaceBuilder(const Cells& cells, BoundarySurface& out) : cells_(cells), out_(out) {
    out_.mesh.add_property(out_.nodeOfVertex, "volpost:node");
    out_.mesh.add_property(out_.cellOfFace, "volpost:cell");
  }

  void addCellFace(std::uint32_t cell, const CellFace& face) {
    const auto nodes = cells_.nodes(cell);
    const auto& topo = topology(cells_.type(cell));
    NodeIndex corner[4], mid[4];
    bool quadratic = topo.quadratic;
    for (int k = 0; k < face.size; ++k) {
      corner[k] = nodes[face.corners[k]];
      if (quadratic) {
        const int m = midsideNode(topo, face.corners[k], face.corners[(k + 1) % face.size]);
        quadratic = m >= 0;
        mid[k] = quadratic ? nodes[m] : 0;
      }
    }
    for (int k = 0; k < face.size; ++k) {
      if (quadratic) {
        addEdge(corner[k], mid[k]);
        addEdge(mid[k], corner[(k + 1) % face.size]);
      } else {
        addEdge(corner[k], corner[(k + 1) % face.size]);
      }
    }
    if (!quadratic && face.size == 3) {
      addTriangle(cell, corner[0], corner[1], corner[2]);
    } else if (!quadratic) {
      addTriangle(cell, corner[0], corner[1], corner[2]);
      addTriangle(cell, corner[0], corner[2], corner[3]);
    } else if (face.size == 3) {
      addTriangle(cell, corner[0], mid[0], mid[2]);
      addTriangle(cell, mid[0], corner[1], mid[1]);
      addTriangle(cell, mid[2], mid[1], corner[2]);
      addTriangle(cell, mid[0], mid[1], mid[2]);
    } else {
      for (int k = 0; k < 4; ++k) addTriangle(cell, mid[(k + 3) % 4], corner[k], mid[k]);
      addTriangle(cell, mid[0], mid[1], mid[3]);
      addTriangle(cell, mid[1], mid[2], mid[3]);
    }
  }

  void finish() {
    auto& e = out_.edges;
    std::sort(e.begin(), e.end());
    e.erase(std::unique(e.begin(), e.end()), e.end());
  }

 private:
  SurfaceMesh::VertexHandle newVertex(NodeIndex node) {
    const glm::dvec3 p = cells_.position(node) - out_.origin;
    auto v = out_.mesh.add_vertex(SurfaceMesh::Point(float(p.x), float(p.y), float(p.z)));
    out_.mesh.property(out_.nodeOfVertex, v) = node;
    return v;
  }

  // A map, not a vector over every node: a grid's boundary touches few of its points.
  SurfaceMesh::VertexHandle vertexOf(NodeIndex node) {
    auto [at, inserted] = vertexOfNode_.try_emplace(node);
    if (inserted) at->second = newVertex(node);
    return at->second;
  }

  void addTriangle(std::uint32_t cell, NodeIndex a, NodeIndex b, NodeIndex c) {
    if (a == b || b == c || a == c) return;  // no area to draw, and OpenMesh asserts on it
    auto f = out_.mesh.add_face(vertexOf(a), vertexOf(b), vertexOf(c));
    if (!f.is_valid()) {
      // Non-manifold configuration (e.g. a fin of faces on one edge): keep the triangle
      // with vertices of its own so it is still drawn.
      f = out_.mesh.add_face(newVertex(a), newVertex(b), newVertex(c));
      ++out_.nonManifoldFaceCount;
    }
    if (f.is_valid()) out_.mesh.property(out_.cellOfFace, f) = cell;
  }

  void addEdge(NodeIndex a, NodeIndex b) { out_.edges.push_back({std::min(a, b), std::max(a, b)}); }

  const Cells& cells_;
  BoundarySurface& out_;
  std::unordered_map<NodeIndex, SurfaceMesh::VertexHandle> vertexOfNode_;
};

}  // namespace

BoundarySurface extractBoundary(const Mesh& mesh, const Progress& progress) {
  BoundarySurface out;
  const Bounds b = mesh.bounds();
  out.origin = b.valid ? b.center() : glm::dvec3(0.0);
  const std::vector<std::uint64_t> unshared = unsharedFaces(mesh, progress);
  const MeshCells cells{mesh};
  SurfaceBuilder builder(cells, out);
  for (std::size_t i = 0; i < unshared.size(); ++i) {
    const std::size_t cell = std::size_t(unshared[i] / 8);
    builder.addCellFace(std::uint32_t(cell), topology(mesh.cellType(cell)).faces[unshared[i] % 8]);
    ++out.boundaryFaceCount;
    if ((i & 0xffff) == 0) progress.report(0.5 + 0.45 * double(i) / double(unshared.size()));
  }
  builder.finish();
  out.mesh.request_face_normals();
  out.mesh.update_face_normals();
  progress.report(1.0);
  return out;
}

// The faces on the grid's six sides, straight from the index ranges: no face sorting and no
// hexahedra, so a cube of 16M points gives its boundary in a fraction of a second.
BoundarySurface extractBoundary(const RegularGrid& grid, const Progress& progress) {
  BoundarySurface out;
  const Bounds b = grid.bounds();
  out.origin = b.valid ? b.center() : glm::dvec3(0.0);
  if (!grid.defect().empty()) return out;
  const GridCells cells{grid};
  SurfaceBuilder builder(cells, out);
  const std::array<std::size_t, 3> n = {grid.dims[0] - 1, grid.dims[1] - 1, grid.dims[2] - 1};
  const CellTopology& hex = topology(CellType::Hex8);
  for (std::size_t k = 0; k < n[2]; ++k) {
    for (std::size_t j = 0; j < n[1]; ++j)
      for (std::size_t i = 0; i < n[0]; ++i) {
        const std::array<std::size_t, 3> at = {i, j, k};
        if (i != 0 && j != 0 && k != 0 && i + 1 != n[0] && j + 1 != n[1] && k + 1 != n[2]) {
          i = n[0] - 2;  // skip the interior of this row (the loop's ++i lands on its last cell)
          continue;
        }
        const std::uint32_t cell = std::uint32_t(i + n[0] * (j + n[1] * k));
        const auto corners = cells.nodes(cell);
        const std::array<NodeIndex, 8> hexCorners{corners[0], corners[1], corners[2], corners[3],
                                                  corners[4], corners[5], corners[6], corners[7]};
        for (const CellFace& face : hex.faces) {
          // On a side when every corner has its index at 0 or at the end along one axis.
          bool onSide = false;
          for (int a = 0; a < 3 && !onSide; ++a)
            for (const std::size_t end : {std::size_t(0), grid.dims[std::size_t(a)] - 1}) {
              bool all = at[std::size_t(a)] == (end == 0 ? 0 : n[std::size_t(a)] - 1);
              for (int c = 0; c < face.size && all; ++c)
                all = grid.pointIndices(hexCorners[std::size_t(face.corners[c])])[std::size_t(a)] == end;
              onSide = onSide || all;
            }
          if (!onSide) continue;
          builder.addCellFace(cell, face);
          ++out.boundaryFaceCount;
        }
      }
    progress.report(double(k + 1) / double(n[2]));
  }
  builder.finish();
  out.mesh.request_face_normals();
  out.mesh.update_face_normals();
  return out;
}

}  // namespace volpost

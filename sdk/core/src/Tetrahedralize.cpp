// SPDX-License-Identifier: MIT
#include <volpost/core/Tetrahedralize.hpp>
#include <volpost/core/WorkerThreads.hpp>

#include "CellSplitTemplates.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <numeric>
#include <stdexcept>
#include <string>

namespace volpost {
namespace {

double tetVolume6(const Mesh& m, const std::array<NodeIndex, 4>& t) {
  const glm::dvec3 a = m.nodes[t[1]] - m.nodes[t[0]], b = m.nodes[t[2]] - m.nodes[t[0]], c = m.nodes[t[3]] - m.nodes[t[0]];
  return glm::dot(a, glm::cross(b, c));
}

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

// Exact sign of the tet's volume (CGAL's filtered predicate): a split is accepted only when
// every piece is truly non-degenerate, however thin.
CGAL::Orientation orientationOf(const std::vector<glm::dvec3>& nodes, const std::array<NodeIndex, 4>& t) {
  const auto p = [&](int k) {
    const glm::dvec3& v = nodes[t[std::size_t(k)]];
    return Kernel::Point_3(v.x, v.y, v.z);
  };
  return CGAL::orientation(p(0), p(1), p(2), p(3));
}

class Builder {
 public:
  explicit Builder(TetMesh& out) : out_(out) {}

  // Hexahedra, wedges and pyramids: the Steiner-free split of their diagonal configuration
  // (diagonal through the smallest node index of each quad, so neighbours agree) when every
  // piece is positive; else a star from the centroid; cells where even that folds are listed.
  void splitCell(const Mesh& src, std::uint32_t cell) {
    const auto nodes = src.cellNodes(cell);
    const CellType type = src.cellType(cell);
    const CellType linear = type == CellType::Hex20 ? CellType::Hex8 : type == CellType::Wedge15 ? CellType::Wedge6 : type;
    unsigned diagonals = 0, quad = 0;
    for (const CellFace& f : topology(linear).faces) {
      if (f.size != 4) continue;
      const NodeIndex a = nodes[f.corners[0]], b = nodes[f.corners[1]], c = nodes[f.corners[2]], d = nodes[f.corners[3]];
      const NodeIndex lowest = std::min({a, b, c, d});
      if (lowest == b || lowest == d) diagonals |= 1u << quad;
      ++quad;
    }
    const auto& pieces = detail::splitTemplate(linear, diagonals);
    if (pieces) {
      // All pieces positive: a valid split. All negative: a mirrored cell (inverted node
      // order, flagged by the model checks), whose pieces are valid once flipped.
      std::array<std::array<NodeIndex, 4>, 8> tets{};
      std::size_t positive = 0, negative = 0;
      for (std::size_t i = 0; i < pieces->size() && i < tets.size(); ++i) {
        for (int k = 0; k < 4; ++k) tets[i][std::size_t(k)] = nodes[(*pieces)[i][std::size_t(k)]];
        const auto o = orientationOf(out_.mesh.nodes, tets[i]);
        positive += o == CGAL::POSITIVE;
        negative += o == CGAL::NEGATIVE;
      }
      if (positive == pieces->size() || negative == pieces->size()) {
        for (std::size_t i = 0; i < pieces->size(); ++i) {
          if (negative) std::swap(tets[i][1], tets[i][2]);
          out_.mesh.addCell(CellType::Tet4, tets[i]);
          out_.cellOfTet.push_back(cell);
        }
        return;
      }
    }
    if (!starFromCentroid(src, cell)) out_.foldedCells.push_back(cell);
  }

  // Adds a tet in VTK's (positive) orientation; returns the orientation it came in.
  CGAL::Orientation addTet(std::array<NodeIndex, 4> t, std::uint32_t cell) {
    const CGAL::Orientation o = orientationOf(out_.mesh.nodes, t);
    if (o == CGAL::NEGATIVE || (o == CGAL::ZERO && tetVolume6(out_.mesh, t) < 0.0)) std::swap(t[1], t[2]);
    out_.mesh.addCell(CellType::Tet4, t);
    out_.cellOfTet.push_back(cell);
    return o;
  }

  // Centroid Steiner point joined to every face triangle (quads by the global diagonal
  // rule). Returns false when the pieces came in with mixed or zero orientations: the
  // centroid does not see every face from inside (a folded cell), so they overlap.
  bool starFromCentroid(const Mesh& src, std::uint32_t cell) {
    std::size_t positive = 0, negative = 0, pieces = 0;
    const auto add = [&](std::array<NodeIndex, 4> t) {
      const auto o = addTet(t, cell);
      positive += o == CGAL::POSITIVE;
      negative += o == CGAL::NEGATIVE;
      ++pieces;
    };
    const auto nodes = src.cellNodes(cell);
    const auto& topo = topology(src.cellType(cell));
    glm::dvec3 c(0.0);
    for (int i = 0; i < topo.cornerCount; ++i) c += src.nodes[nodes[i]];
    const NodeIndex s = NodeIndex(out_.mesh.nodes.size());
    out_.mesh.nodes.push_back(c / double(topo.cornerCount));
    out_.steinerCell.push_back(cell);
    for (const CellFace& f : topo.faces) {
      const NodeIndex a = nodes[f.corners[0]], b = nodes[f.corners[1]], d = nodes[f.corners[2]];
      if (f.size == 3) {
        add({a, b, d, s});
        continue;
      }
      const NodeIndex e = nodes[f.corners[3]];
      const NodeIndex lowest = std::min({a, b, d, e});
      if (lowest == a || lowest == d) {  // diagonal a-d
        add({a, b, d, s});
        add({a, d, e, s});
      } else {  // diagonal b-e
        add({b, d, e, s});
        add({b, e, a, s});
      }
    }
    return positive == pieces || negative == pieces;
  }

  void tet10(const Mesh& src, std::uint32_t cell) {
    const auto n = src.cellNodes(cell);
    const auto t = [&](int a, int b, int c, int d) { addTet({n[a], n[b], n[c], n[d]}, cell); };
    t(0, 4, 6, 7), t(4, 1, 5, 8), t(6, 5, 2, 9), t(7, 8, 9, 3);  // corner tets
    t(4, 9, 5, 8), t(4, 9, 8, 7), t(4, 9, 7, 6), t(4, 9, 6, 5);  // inner octahedron around 4-9
  }

 private:
  TetMesh& out_;
};

}  // namespace

namespace {

// A mesh of positively oriented tet4 only (the usual tet mesh) is its own tetrahedra: its
// cells are shared, not copied. Checked on all cores with the exact predicate.
bool allPositiveTet4(const Mesh& mesh) {
  const std::size_t n = mesh.cellCount();
  if (n == 0) return false;
  const auto types = mesh.cellTypes();
  if (std::any_of(types.begin(), types.end(), [](CellType t) { return t != CellType::Tet4; })) return false;
  std::atomic<bool> allGood{true};
  forEachChunk(n, std::size_t(1) << 14, [&](std::size_t begin, std::size_t end) {
    for (std::size_t c = begin; c < end && allGood; ++c) {
      const auto v = mesh.cellNodes(c);
      if (cellRepeatsANode(mesh, c) || orientationOf(mesh.nodes, {v[0], v[1], v[2], v[3]}) != CGAL::POSITIVE)
        allGood = false;
    }
  });
  return allGood;
}

}  // namespace

TetMesh tetrahedralize(const Mesh& mesh) {
  TetMesh out;
  if (allPositiveTet4(mesh)) {
    out.mesh.nodes = mesh.nodes;
    out.mesh.shareCellsOf(mesh);
    out.originalNodes = mesh.nodeCount();
    return out;  // cellOfTet empty: each tet is its source cell
  }
  out.mesh.nodes = mesh.nodes;
  out.originalNodes = mesh.nodeCount();
  Builder b(out);
  for (std::uint32_t c = 0; c < mesh.cellCount(); ++c) {
    if (cellRepeatsANode(mesh, c)) {  // flagged by the checks; no volume to split
      out.skippedCells.push_back(c);
      continue;
    }
    const auto n = mesh.cellNodes(c);
    switch (mesh.cellType(c)) {
      case CellType::Tet4: b.addTet({n[0], n[1], n[2], n[3]}, c); break;
      case CellType::Tet10: b.tet10(mesh, c); break;
      default: b.splitCell(mesh, c); break;
    }
  }
  return out;
}

void requireTetrahedraAndValues(const Mesh& mesh, bool perNode, std::size_t valueCount) {
  const std::size_t expected = perNode ? mesh.nodeCount() : mesh.cellCount();
  if (valueCount != expected)
    throw std::invalid_argument("volume rendering: " + std::to_string(valueCount) + " values for " +
                                std::to_string(expected) + (perNode ? " nodes" : " cells"));
  for (const auto& [type, count] : mesh.countsByType())
    if (type != CellType::Tet4 && type != CellType::Tet10)
      throw std::invalid_argument("volume rendering needs tetrahedra; this mesh has " + std::to_string(count) + " " +
                                  std::string(cellTypeName(type)) + " cells (split them with tetrahedralize() first)");
}

std::vector<double> TetMesh::nodeValues(const Mesh& source, std::span<const double> values) const {
  std::vector<double> out(values.begin(), values.end());
  out.reserve(mesh.nodeCount());
  for (std::uint32_t cell : steinerCell) {
    const auto nodes = source.cellNodes(cell);
    const int corners = topology(source.cellType(cell)).cornerCount;
    double sum = 0.0;
    for (int i = 0; i < corners; ++i) sum += values[nodes[i]];
    out.push_back(sum / corners);
  }
  return out;
}

std::vector<double> TetMesh::cellValues(std::span<const double> values) const {
  std::vector<double> out(mesh.cellCount());
  for (std::size_t t = 0; t < out.size(); ++t) out[t] = values[sourceCell(t)];
  return out;
}

}  // namespace volpost

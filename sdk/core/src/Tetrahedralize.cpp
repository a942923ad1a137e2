// SPDX-License-Identifier: MIT
#include <volpost/core/Tetrahedralize.hpp>

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>

namespace volpost {
namespace {

double tetVolume6(const Mesh& m, const std::array<NodeIndex, 4>& t) {
  const glm::dvec3 a = m.nodes[t[1]] - m.nodes[t[0]], b = m.nodes[t[2]] - m.nodes[t[0]], c = m.nodes[t[3]] - m.nodes[t[0]];
  return glm::dot(a, glm::cross(b, c));
}

class Builder {
 public:
  explicit Builder(TetMesh& out) : out_(out) {}

  void addTet(std::array<NodeIndex, 4> t, std::uint32_t cell) {
    if (tetVolume6(out_.mesh, t) < 0.0) std::swap(t[1], t[2]);  // VTK orientation
    out_.mesh.addCell(CellType::Tet4, t);
    out_.cellOfTet.push_back(cell);
  }

  // Centroid Steiner point joined to every face triangle (quads by the global diagonal rule).
  void starFromCentroid(const Mesh& src, std::uint32_t cell) {
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
        addTet({a, b, d, s}, cell);
        continue;
      }
      const NodeIndex e = nodes[f.corners[3]];
      const NodeIndex lowest = std::min({a, b, d, e});
      if (lowest == a || lowest == d) {  // diagonal a-d
        addTet({a, b, d, s}, cell);
        addTet({a, d, e, s}, cell);
      } else {  // diagonal b-e
        addTet({b, d, e, s}, cell);
        addTet({b, e, a, s}, cell);
      }
    }
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

TetMesh tetrahedralize(const Mesh& mesh) {
  TetMesh out;
  out.mesh.nodes = mesh.nodes;
  out.originalNodes = mesh.nodeCount();
  Builder b(out);
  for (std::uint32_t c = 0; c < mesh.cellCount(); ++c) {
    const auto n = mesh.cellNodes(c);
    switch (mesh.cellType(c)) {
      case CellType::Tet4: b.addTet({n[0], n[1], n[2], n[3]}, c); break;
      case CellType::Tet10: b.tet10(mesh, c); break;
      default: b.starFromCentroid(mesh, c); break;
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
  std::vector<double> out(cellOfTet.size());
  for (std::size_t t = 0; t < cellOfTet.size(); ++t) out[t] = values[cellOfTet[t]];
  return out;
}

}  // namespace volpost

// SPDX-License-Identifier: MIT
#include "host/IsoSurfaceExtraction.hpp"
#include "host/GridCellTets.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <unordered_map>

namespace volpost {
namespace {

std::uint64_t edgeKey(NodeIndex a, NodeIndex b) {
  if (a > b) std::swap(a, b);
  return (std::uint64_t(a) << 32) | b;
}

// Marching tetrahedra over tets given by their node indices; `positionOf(node)` places a
// node (a mesh's node array, or a grid point from its indices).
template <typename PositionOf>
class IsoBuilder {
 public:
  IsoBuilder(ExtractedSurface& out, SampleView values, double iso, PositionOf positionOf)
      : out_(out), values_(values), iso_(iso), positionOf_(positionOf) {}

  void addTet(const std::array<NodeIndex, 4>& n) {
    std::array<int, 4> inside{}, outside{};  // corners 0..3 of the tet, in its order
    int ni = 0, no = 0;
    for (int k = 0; k < 4; ++k) {
      if (!std::isfinite(values_[n[std::size_t(k)]])) return;
      (values_[n[std::size_t(k)]] >= iso_ ? inside[std::size_t(ni++)] : outside[std::size_t(no++)]) = k;
    }
    if (ni == 0 || no == 0) return;
    const glm::dvec3 p0 = positionOf_(n[0]);
    const double det = glm::dot(positionOf_(n[1]) - p0, glm::cross(positionOf_(n[2]) - p0, positionOf_(n[3]) - p0));
    if (det == 0.0) return;
    // Orientation from the tet's corners, not from the triangle's own normal: a nearly
    // degenerate triangle (the value crossing close to a node) has a normal whose sign
    // rounding decides, and one wrongly turned triangle tears the surface open. For a
    // positively oriented tet (a, b, c, d), the triangle on edges a-b, a-c, a-d faces away
    // from a, and the quadrilateral on a-c, a-d, b-d, b-c faces toward c and d.
    const auto vertex = [&](int a, int b) { return vertexOn(n[std::size_t(a)], n[std::size_t(b)]); };
    if (ni == 1 || no == 1) {
      const int apex = ni == 1 ? inside[0] : outside[0];
      const auto& others = ni == 1 ? outside : inside;
      const bool positive = (det > 0.0) == evenPermutation({apex, others[0], others[1], others[2]});
      // Toward larger values: toward the apex when it is the one inside.
      const bool flip = positive == (ni == 1);
      addTriangle(vertex(apex, others[0]), vertex(apex, others[1]), vertex(apex, others[2]), flip);
    } else {
      const bool positive = (det > 0.0) == evenPermutation({inside[0], inside[1], outside[0], outside[1]});
      const auto a = vertex(inside[0], outside[0]), b = vertex(inside[0], outside[1]);
      const auto c = vertex(inside[1], outside[1]), e = vertex(inside[1], outside[0]);
      addTriangle(a, b, c, positive);  // faces the outside corners when positive: turn it
      addTriangle(a, c, e, positive);
    }
  }

 private:
  // A vertex where the field crosses iso on edge (a, b); "inside" nodes are those >= iso.
  SurfaceMesh::VertexHandle vertexOn(NodeIndex a, NodeIndex b) {
    // A crossing exactly on a node is that node's vertex, shared by all its edges.
    constexpr std::uint64_t kNodeFlag = std::uint64_t(1) << 63;
    const std::uint64_t key = values_[a] == iso_ ? kNodeFlag | a : values_[b] == iso_ ? kNodeFlag | b : edgeKey(a, b);
    const auto [it, added] = vertexOfEdge_.try_emplace(key);
    if (added) {
      const double va = values_[a], vb = values_[b];
      const double t = va == vb ? 0.5 : std::clamp((iso_ - va) / (vb - va), 0.0, 1.0);
      const glm::dvec3 pa = positionOf_(a);
      const glm::dvec3 p = pa + t * (positionOf_(b) - pa) - out_.origin;
      it->second = out_.mesh.add_vertex(SurfaceMesh::Point(float(p.x), float(p.y), float(p.z)));
    }
    return it->second;
  }

  void addTriangle(SurfaceMesh::VertexHandle v0, SurfaceMesh::VertexHandle v1, SurfaceMesh::VertexHandle v2, bool flip) {
    if (v0 == v1 || v1 == v2 || v0 == v2) return;  // the crossing on a node: no area
    if (flip) std::swap(v1, v2);
    if (out_.mesh.add_face(v0, v1, v2).is_valid()) return;
    // Sheets that touch at a node exactly at iso (integer samples hit it) make a vertex no
    // manifold mesh can share: OpenMesh refuses the face. It is kept, with vertices of its
    // own at the same places, so that the picture and the export lose no triangle.
    const auto copy = [this](SurfaceMesh::VertexHandle v) { return out_.mesh.add_vertex(out_.mesh.point(v)); };
    out_.mesh.add_face(copy(v0), copy(v1), copy(v2));
    ++out_.separatedFaces;
  }

  static bool evenPermutation(std::array<int, 4> order) {
    int inversions = 0;
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) inversions += order[std::size_t(i)] > order[std::size_t(j)];
    return inversions % 2 == 0;
  }

  ExtractedSurface& out_;
  SampleView values_;
  double iso_;
  PositionOf positionOf_;
  std::unordered_map<std::uint64_t, SurfaceMesh::VertexHandle> vertexOfEdge_;
};

}  // namespace

ExtractedSurface extractIsoSurface(const TetMesh& tets, std::span<const double> values, double iso,
                                   const Progress& progress) {
  const Mesh& mesh = tets.mesh;
  if (values.size() != mesh.nodeCount())
    throw std::invalid_argument("iso-surface: " + std::to_string(values.size()) + " values for " +
                                std::to_string(mesh.nodeCount()) + " nodes");
  ExtractedSurface out;
  out.origin = mesh.bounds().center();
  IsoBuilder builder(out, values, iso, [&mesh](NodeIndex n) { return mesh.nodes[n]; });
  for (std::size_t c = 0; c < mesh.cellCount(); ++c) {
    const auto n = mesh.cellNodes(c);
    if (n.size() != 4) throw std::invalid_argument("iso-surface extraction needs tet4 cells");
    builder.addTet({n[0], n[1], n[2], n[3]});
    if ((c & 0xffff) == 0) progress.report(double(c) / double(mesh.cellCount()));
  }
  return out;
}

// Each cell the value iso passes through is split into the six tets around its diagonal
// from corner (0,0,0) to (1,1,1), the same split in every cell (Freudenthal's), so
// neighbours share their crossing vertices and the surface is watertight.
ExtractedSurface extractIsoSurface(const RegularGrid& grid, SampleView values, double iso,
                                   const Progress& progress) {
  if (values.size() != grid.pointCount())
    throw std::invalid_argument("iso-surface: " + std::to_string(values.size()) + " values for a grid of " +
                                std::to_string(grid.pointCount()) + " points");
  if (const std::string defect = grid.defect(); !defect.empty()) throw std::invalid_argument(defect);
  if (grid.pointCount() > std::size_t(std::numeric_limits<NodeIndex>::max()))
    throw std::length_error("iso-surface: a grid of " + std::to_string(grid.pointCount()) +
                            " points is more than 32-bit point indices number");
  ExtractedSurface out;
  out.origin = grid.bounds().center();
  const std::size_t nx = grid.dims[0], ny = grid.dims[1];
  IsoBuilder builder(out, values, iso, [&grid](NodeIndex n) { return grid.pointPosition(n); });
  for (std::size_t k = 0; k + 1 < grid.dims[2]; ++k) {
    for (std::size_t j = 0; j + 1 < ny; ++j)
      for (std::size_t i = 0; i + 1 < nx; ++i) {
        std::array<NodeIndex, 8> corner;
        double lo = INFINITY, hi = -INFINITY;
        for (int c = 0; c < 8; ++c) {
          corner[std::size_t(c)] = NodeIndex(grid.pointIndex(i + (c & 1), j + (c >> 1 & 1), k + (c >> 2 & 1)));
          const double v = values[corner[std::size_t(c)]];
          lo = std::min(lo, v), hi = std::max(hi, v);  // a NaN leaves both alone (its tets are skipped)
        }
        if (!(hi >= iso && lo < iso)) continue;  // all below, or all at or above: no crossing
        for (const auto& t : kGridCellTets) builder.addTet({corner[std::size_t(t[0])], corner[std::size_t(t[1])],
                                                    corner[std::size_t(t[2])], corner[std::size_t(t[3])]});
      }
    progress.report(double(k + 1) / double(grid.dims[2] - 1));
  }
  return out;
}

ExtractedSurface extractIsoSurface(const optics::ElementField& field, double iso, const RefinementLimits& limits,
                                   const Progress& progress) {
  const TetMesh& split = field.split();
  const std::vector<double> splitValues = split.nodeValues(field.mesh(), field.values());
  // Whether each cell's field can reach the value: -1 not yet known, 0 no, 1 yes.
  std::vector<signed char> reaches(field.mesh().cellCount(), -1);
  std::vector<std::uint32_t> chosen;
  for (std::size_t t = 0; t < split.mesh.cellCount(); ++t) {
    const std::uint32_t cell = split.sourceCell(t);
    if (field.linearIn(cell)) {
      double lo = INFINITY, hi = -INFINITY;
      for (NodeIndex n : split.mesh.cellNodes(t)) lo = std::min(lo, splitValues[n]), hi = std::max(hi, splitValues[n]);
      if (lo <= iso && iso <= hi) chosen.push_back(std::uint32_t(t));
      continue;
    }
    if (reaches[cell] < 0) {
      const auto bound = field.valueBound(cell);
      reaches[cell] = bound && bound->first <= iso && iso <= bound->second ? 1 : 0;
    }
    if (reaches[cell] == 1) chosen.push_back(std::uint32_t(t));
  }
  Progress refining = progress;
  refining.setStage("refining cells");
  const RefinedTetrahedra refined = refineTetrahedra(field, chosen, limits, refining);
  ExtractedSurface out = extractIsoSurface(refined.tets, refined.values, iso, progress);
  out.refinement = refined.level;
  out.deviation = refined.deviation;
  out.toleranceReached = refined.toleranceReached;
  return out;
}

}  // namespace volpost

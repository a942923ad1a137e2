// SPDX-License-Identifier: MIT
#include "host/IsoSurfaceExtraction.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <unordered_map>

namespace volpost {
namespace {

std::uint64_t edgeKey(NodeIndex a, NodeIndex b) {
  if (a > b) std::swap(a, b);
  return (std::uint64_t(a) << 32) | b;
}

}  // namespace

ExtractedSurface extractIsoSurface(const TetMesh& tets, std::span<const double> values, double iso,
                                   const Progress& progress) {
  const Mesh& mesh = tets.mesh;
  if (values.size() != mesh.nodeCount())
    throw std::invalid_argument("iso-surface: " + std::to_string(values.size()) + " values for " +
                                std::to_string(mesh.nodeCount()) + " nodes");
  ExtractedSurface out;
  out.origin = mesh.bounds().center();
  std::unordered_map<std::uint64_t, SurfaceMesh::VertexHandle> vertexOfEdge;
  // A vertex where the field crosses iso on edge (a, b); "inside" nodes are those >= iso.
  const auto vertexOn = [&](NodeIndex a, NodeIndex b) {
    // A crossing exactly on a node is that node's vertex, shared by all its edges.
    constexpr std::uint64_t kNodeFlag = std::uint64_t(1) << 63;
    const std::uint64_t key = values[a] == iso ? kNodeFlag | a : values[b] == iso ? kNodeFlag | b : edgeKey(a, b);
    const auto [it, added] = vertexOfEdge.try_emplace(key);
    if (added) {
      const double va = values[a], vb = values[b];
      const double t = va == vb ? 0.5 : std::clamp((iso - va) / (vb - va), 0.0, 1.0);
      const glm::dvec3 p = mesh.nodes[a] + t * (mesh.nodes[b] - mesh.nodes[a]) - out.origin;
      it->second = out.mesh.add_vertex(SurfaceMesh::Point(float(p.x), float(p.y), float(p.z)));
    }
    return it->second;
  };
  // Orients a triangle so its normal points toward increasing values (the gradient).
  const auto addOriented = [&](SurfaceMesh::VertexHandle v0, SurfaceMesh::VertexHandle v1, SurfaceMesh::VertexHandle v2,
                               const glm::dvec3& gradient) {
    if (v0 == v1 || v1 == v2 || v0 == v2) return;
    const auto p0 = out.mesh.point(v0), p1 = out.mesh.point(v1), p2 = out.mesh.point(v2);
    const auto n = (p1 - p0) % (p2 - p0);
    if (double(n[0]) * gradient.x + double(n[1]) * gradient.y + double(n[2]) * gradient.z < 0) std::swap(v1, v2);
    out.mesh.add_face(v0, v1, v2);
  };
  for (std::size_t c = 0; c < mesh.cellCount(); ++c) {
    const auto n = mesh.cellNodes(c);
    if (n.size() != 4) throw std::invalid_argument("iso-surface extraction needs tet4 cells");
    std::array<NodeIndex, 4> inside{}, outside{};
    int ni = 0, no = 0;
    bool finite = true;
    for (NodeIndex k : n) {
      finite = finite && std::isfinite(values[k]);
      (values[k] >= iso ? inside[std::size_t(ni++)] : outside[std::size_t(no++)]) = k;
    }
    if (!finite || ni == 0 || no == 0) continue;
    // Gradient of the linear field in this tet, for the orientation.
    const glm::dvec3 e1 = mesh.nodes[n[1]] - mesh.nodes[n[0]], e2 = mesh.nodes[n[2]] - mesh.nodes[n[0]],
                     e3 = mesh.nodes[n[3]] - mesh.nodes[n[0]];
    const double det = glm::dot(e1, glm::cross(e2, e3));
    if (det == 0.0) continue;
    const glm::dvec3 d(values[n[1]] - values[n[0]], values[n[2]] - values[n[0]], values[n[3]] - values[n[0]]);
    const glm::dvec3 gradient = (d.x * glm::cross(e2, e3) + d.y * glm::cross(e3, e1) + d.z * glm::cross(e1, e2)) / det;
    if (ni == 1 || no == 1) {
      const NodeIndex apex = ni == 1 ? inside[0] : outside[0];
      const auto& others = ni == 1 ? outside : inside;
      addOriented(vertexOn(apex, others[0]), vertexOn(apex, others[1]), vertexOn(apex, others[2]), gradient);
    } else {  // 2 and 2: a quadrilateral, split in two
      const auto a = vertexOn(inside[0], outside[0]), b = vertexOn(inside[0], outside[1]);
      const auto c2 = vertexOn(inside[1], outside[1]), d2 = vertexOn(inside[1], outside[0]);
      addOriented(a, b, c2, gradient);
      addOriented(a, c2, d2, gradient);
    }
    if ((c & 0xffff) == 0) progress.report(double(c) / double(mesh.cellCount()));
  }
  return out;
}

}  // namespace volpost

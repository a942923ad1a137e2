// SPDX-License-Identifier: MIT
#include "host/ClipCulling.hpp"

#include <array>
#include <limits>

namespace volpost {

CulledMesh cullToClipPlanes(const Mesh& tets, const std::vector<ClipPlane>& planes) {
  CulledMesh out;
  constexpr std::uint32_t kUnused = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::uint32_t> newIndex(tets.nodeCount(), kUnused);
  out.mesh.reserveCells(tets.cellCount(), tets.cellCount() * 4);
  for (std::size_t c = 0; c < tets.cellCount(); ++c) {
    const auto n = tets.cellNodes(c);
    bool hidden = false;
    for (const ClipPlane& plane : planes) {
      bool allOut = true;
      for (NodeIndex v : n) allOut = allOut && !plane.keeps(tets.nodes[v]);
      hidden = hidden || allOut;
    }
    if (hidden) continue;
    std::array<NodeIndex, 4> kept{};
    for (std::size_t k = 0; k < 4 && k < n.size(); ++k) {
      if (newIndex[n[k]] == kUnused) {
        newIndex[n[k]] = std::uint32_t(out.mesh.nodes.size());
        out.mesh.nodes.push_back(tets.nodes[n[k]]);
        out.nodeOf.push_back(n[k]);
      }
      kept[k] = newIndex[n[k]];
    }
    out.mesh.addCell(CellType::Tet4, kept);
    out.cellOf.push_back(std::uint32_t(c));
  }
  return out;
}

std::vector<double> CulledMesh::values(FieldLocation location, std::span<const double> source) const {
  const auto& map = location == FieldLocation::Node ? nodeOf : cellOf;
  std::vector<double> out(map.size());
  for (std::size_t i = 0; i < map.size(); ++i) out[i] = source[map[i]];
  return out;
}

}  // namespace volpost

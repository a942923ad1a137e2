// SPDX-License-Identifier: MIT
#include "FaceNodes.hpp"

#include <algorithm>
#include <array>
#include <map>

namespace volpost::meshio {

void appendFaceNodes(const Mesh& mesh, std::size_t cell, std::span<const int> vtkCorners,
                     std::vector<std::uint32_t>& out) {
  const auto nodes = mesh.cellNodes(cell);
  const CellTopology& t = topology(mesh.cellType(cell));
  const auto onFace = [&](int local) {
    return std::find(vtkCorners.begin(), vtkCorners.end(), local) != vtkCorners.end();
  };
  for (const int c : vtkCorners)
    if (c >= 0 && std::size_t(c) < nodes.size()) out.push_back(nodes[std::size_t(c)]);
  if (!t.quadratic) return;
  for (const CellEdge& e : t.edges)  // a cell edge between two of the face's corners is an edge of the face
    if (e.mid >= 0 && onFace(e.a) && onFace(e.b) && std::size_t(e.mid) < nodes.size())
      out.push_back(nodes[std::size_t(e.mid)]);
}

void appendFreeFaceNodes(const Mesh& mesh, std::span<const std::uint32_t> cells, std::vector<std::uint32_t>& out) {
  // Each face by its sorted corner nodes: seen once, it is on the outside of the group.
  std::map<std::array<std::uint32_t, 4>, std::pair<int, std::pair<std::uint32_t, std::uint8_t>>> faces;
  for (const std::uint32_t c : cells) {
    if (c >= mesh.cellCount()) continue;
    const auto nodes = mesh.cellNodes(c);
    const auto& topoFaces = topology(mesh.cellType(c)).faces;
    for (std::size_t f = 0; f < topoFaces.size(); ++f) {
      std::array<std::uint32_t, 4> key{~0u, ~0u, ~0u, ~0u};
      for (std::size_t k = 0; k < topoFaces[f].size; ++k) key[k] = nodes[topoFaces[f].corners[k]];
      std::sort(key.begin(), key.begin() + topoFaces[f].size);
      auto& seen = faces[key];
      ++seen.first;
      seen.second = {c, std::uint8_t(f)};
    }
  }
  for (const auto& [key, seen] : faces) {
    if (seen.first != 1) continue;
    const auto [cell, f] = seen.second;
    const CellFace& face = topology(mesh.cellType(cell)).faces[f];
    std::array<int, 4> corners{};
    for (std::size_t k = 0; k < face.size; ++k) corners[k] = face.corners[k];
    appendFaceNodes(mesh, cell, std::span<const int>(corners.data(), face.size), out);
  }
}

}  // namespace volpost::meshio

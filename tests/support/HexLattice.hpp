// SPDX-License-Identifier: MIT
// Meshes of hexahedra (hex8 or hex20) on a lattice carried to space by a function: boxes,
// bent boxes, quarter cylinders whose midside nodes sit on the arcs.
#pragma once

#include <volpost/core/CellShape.hpp>
#include <volpost/core/Mesh.hpp>

#include <glm/vec3.hpp>

#include <array>
#include <functional>
#include <map>
#include <vector>

namespace volpost::test {

// n^3 cells of `type` (hex8 or hex20) on the lattice [0, n]^3 carried to space by `place`;
// nodes shared between cells.
inline Mesh hexLattice(CellType type, int n, const std::function<glm::dvec3(const glm::dvec3&)>& place) {
  Mesh mesh;
  std::map<std::array<int, 3>, NodeIndex> index;  // by position in half-cell steps
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        std::vector<NodeIndex> ids;
        for (int node = 0; node < topology(type).nodeCount; ++node) {
          const glm::dvec3 g = 2.0 * glm::dvec3(i, j, k) + naturalCoordinatesOfNode(type, node) + 1.0;
          const std::array<int, 3> key{int(g.x), int(g.y), int(g.z)};
          const auto [it, fresh] = index.emplace(key, NodeIndex(mesh.nodes.size()));
          if (fresh) mesh.nodes.push_back(place(0.5 * g));
          ids.push_back(it->second);
        }
        mesh.addCell(type, ids);
      }
  return mesh;
}

}  // namespace volpost::test

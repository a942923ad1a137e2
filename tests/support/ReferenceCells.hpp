// SPDX-License-Identifier: MIT
// One cell of each type in VTK order with known volume; quadratic cells get their
// midside nodes at edge midpoints.
#pragma once

#include <volpost/core/Mesh.hpp>

#include <utility>

namespace volpost::test {

inline std::pair<Mesh, double> referenceCell(CellType type) {
  Mesh mesh;
  double volume = 0.0;
  const auto& topo = topology(type);
  switch (topo.cornerCount) {
    case 4: mesh.nodes = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}; volume = 1.0 / 6.0; break;
    case 8:
      mesh.nodes = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
      volume = 1.0;
      break;
    case 6:  // VTK: the first triangle's right-hand normal points away from the second
      mesh.nodes = {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {0, 0, 1}, {0, 1, 1}, {1, 0, 1}};
      volume = 0.5;
      break;
    case 5: mesh.nodes = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, 1}}; volume = 1.0 / 3.0; break;
  }
  for (const CellEdge& e : topo.edges)
    if (e.mid >= 0) {
      if (mesh.nodes.size() <= std::size_t(e.mid)) mesh.nodes.resize(std::size_t(e.mid) + 1);
      mesh.nodes[std::size_t(e.mid)] = 0.5 * (mesh.nodes[e.a] + mesh.nodes[e.b]);
    }
  std::vector<NodeIndex> nodes(std::size_t(topo.nodeCount));
  for (std::size_t i = 0; i < nodes.size(); ++i) nodes[i] = NodeIndex(i);
  mesh.addCell(type, nodes);
  return {std::move(mesh), volume};
}

}  // namespace volpost::test

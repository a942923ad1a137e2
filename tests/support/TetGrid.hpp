// SPDX-License-Identifier: MIT
// Tetrahedralized regular grids (Kuhn / Freudenthal: six tets per cube around its main
// diagonal, conforming across cubes): the hard case of axis-aligned rays through vertices,
// along edges and inside faces.
#pragma once

#include <volpost/core/Mesh.hpp>

#include <algorithm>
#include <array>

namespace volpost::test {

inline double signedTetVolume(const Mesh& m, const NodeIndex* t) {
  const glm::dvec3 a = m.nodes[t[1]] - m.nodes[t[0]], b = m.nodes[t[2]] - m.nodes[t[0]], c = m.nodes[t[3]] - m.nodes[t[0]];
  return a.x * (b.y * c.z - b.z * c.y) - a.y * (b.x * c.z - b.z * c.x) + a.z * (b.x * c.y - b.y * c.x);
}

inline Mesh tetGrid(int nx, int ny, int nz, glm::dvec3 origin = glm::dvec3(0.0), double cell = 1.0) {
  Mesh m;
  auto id = [&](int i, int j, int k) { return NodeIndex((k * (ny + 1) + j) * (nx + 1) + i); };
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) m.nodes.push_back(origin + cell * glm::dvec3(i, j, k));
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        std::array<int, 3> axes = {0, 1, 2};
        do {
          std::array<int, 3> c = {i, j, k};
          NodeIndex tet[4];
          tet[0] = id(c[0], c[1], c[2]);
          for (int s = 0; s < 3; ++s) {
            ++c[std::size_t(axes[std::size_t(s)])];
            tet[s + 1] = id(c[0], c[1], c[2]);
          }
          // Kuhn tets of odd permutations are mirrored: swap two nodes for positive volume.
          if (signedTetVolume(m, tet) < 0) std::swap(tet[1], tet[2]);
          m.addCell(CellType::Tet4, tet);
        } while (std::next_permutation(axes.begin(), axes.end()));
      }
  return m;
}

// `count` slabs of cells x cells x 1 unit cubes stacked along z, `spacing` apart (more than
// 1: with gaps between them): a non-convex mesh every ray along z enters `count` times.
inline Mesh stackedSlabs(int count, int cells, double spacing) {
  Mesh m;
  for (int k = 0; k < count; ++k) {
    const Mesh slab = tetGrid(cells, cells, 1, {0.0, 0.0, spacing * k});
    const NodeIndex base = NodeIndex(m.nodeCount());
    m.nodes.insert(m.nodes.end(), slab.nodes.begin(), slab.nodes.end());
    for (std::size_t c = 0; c < slab.cellCount(); ++c) {
      NodeIndex t[4];
      for (int i = 0; i < 4; ++i) t[i] = slab.cellNodes(c)[std::size_t(i)] + base;
      m.addCell(CellType::Tet4, t);
    }
  }
  return m;
}

// Three 3 x 3 x 1 slabs with gaps: every ray along z enters three times.
inline Mesh threeSlabs() { return stackedSlabs(3, 3, 1.5); }

}  // namespace volpost::test

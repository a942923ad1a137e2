// SPDX-License-Identifier: MIT
// The benches' Kuhn grid: n^3 unit cubes on [0, n]^3, each split into the 6 tets along its
// main diagonal (one per permutation of the axes, as in Espinha 2005's grids). Half of them
// are wound inward as generated; callers that need them outward turn them.
#pragma once

#include <volpost/core/Mesh.hpp>

#include <algorithm>

namespace volpost::bench {

inline Mesh kuhnGrid(int n) {
  Mesh m;
  const auto id = [n](int i, int j, int k) { return NodeIndex((k * (n + 1) + j) * (n + 1) + i); };
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) m.nodes.push_back({double(i), double(j), double(k)});
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        int axes[3] = {0, 1, 2};
        do {
          int c[3] = {i, j, k};
          NodeIndex t[4];
          t[0] = id(c[0], c[1], c[2]);
          for (int s = 0; s < 3; ++s) {
            ++c[axes[s]];
            t[s + 1] = id(c[0], c[1], c[2]);
          }
          m.addCell(CellType::Tet4, t);
        } while (std::next_permutation(axes, axes + 3));
      }
  return m;
}

}  // namespace volpost::bench

// SPDX-License-Identifier: MIT
#include "NodeOrder.hpp"

#include <stdexcept>
#include <string>

namespace volpost::meshio {

std::vector<int> vtkOrderFrom(CellType type, std::span<const int> corners,
                              std::span<const CornerPair> midsides) {
  const CellTopology& t = topology(type);
  if (int(corners.size()) != t.cornerCount)
    throw std::logic_error("node order for " + std::string(t.name) + ": wrong corner count");
  std::vector<int> vtk(std::size_t(t.nodeCount), -1);
  std::vector<int> vtkCornerOf(corners.size());  // format corner -> VTK corner
  for (std::size_t k = 0; k < corners.size(); ++k) {
    vtk[k] = corners[k];
    vtkCornerOf[std::size_t(corners[k])] = int(k);
  }
  if (!t.quadratic) return vtk;
  for (const CellEdge& e : t.edges) {
    for (std::size_t j = 0; j < midsides.size(); ++j) {
      const int a = vtkCornerOf[std::size_t(midsides[j].first)];
      const int b = vtkCornerOf[std::size_t(midsides[j].second)];
      if ((a == e.a && b == e.b) || (a == e.b && b == e.a)) vtk[std::size_t(e.mid)] = t.cornerCount + int(j);
    }
  }
  for (int v : vtk)
    if (v < 0) throw std::logic_error("node order for " + std::string(t.name) + ": an edge has no midside node");
  return vtk;
}

}  // namespace volpost::meshio

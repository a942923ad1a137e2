// SPDX-License-Identifier: MIT
#include "CellSplitTemplates.hpp"

#define TETLIBRARY
#include <tetgen.h>

#include <stdexcept>

namespace volpost::detail {
namespace {

// Reference corners in VTK order (positive volume with volpost's face tables).
std::vector<std::array<double, 3>> referenceCorners(CellType type) {
  switch (type) {
    case CellType::Hex8:
    case CellType::Hex20:
      return {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
    case CellType::Wedge6:
    case CellType::Wedge15:
      return {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {0, 0, 1}, {0, 1, 1}, {1, 0, 1}};
    case CellType::Pyramid5:
      return {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, 1}};
    default:
      throw std::logic_error("split templates are for hexahedra, wedges and pyramids");
  }
}

std::optional<std::vector<LocalTet>> computeTemplate(CellType type, unsigned diagonals) {
  const auto corners = referenceCorners(type);
  const CellTopology& topo = topology(type);
  std::vector<std::array<int, 3>> triangles;
  unsigned quad = 0;
  for (const CellFace& f : topo.faces) {
    const int a = f.corners[0], b = f.corners[1], c = f.corners[2];
    if (f.size == 3) {
      triangles.push_back({a, b, c});
      continue;
    }
    const int d = f.corners[3];
    if ((diagonals >> quad++) & 1u) {
      triangles.push_back({b, c, d});
      triangles.push_back({b, d, a});
    } else {
      triangles.push_back({a, b, c});
      triangles.push_back({a, c, d});
    }
  }
  tetgenio in, out;
  in.firstnumber = 0;
  in.numberofpoints = int(corners.size());
  in.pointlist = new REAL[corners.size() * 3];
  for (std::size_t i = 0; i < corners.size(); ++i)
    for (int k = 0; k < 3; ++k) in.pointlist[i * 3 + std::size_t(k)] = corners[i][std::size_t(k)];
  in.numberoffacets = int(triangles.size());
  in.facetlist = new tetgenio::facet[triangles.size()];
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    tetgenio::facet& f = in.facetlist[i];
    tetgenio::init(&f);
    f.numberofpolygons = 1;
    f.polygonlist = new tetgenio::polygon[1];
    tetgenio::init(&f.polygonlist[0]);
    f.polygonlist[0].numberofvertices = 3;
    f.polygonlist[0].vertexlist = new int[3]{triangles[i][0], triangles[i][1], triangles[i][2]};
  }
  // p: a piecewise linear complex; Y: keep its facets as given (no boundary Steiner
  // points, so the split conforms with the neighbours'); Q: quiet.
  char switches[] = "pYQ";
  tetrahedralize(switches, &in, &out);
  if (out.numberofpoints != in.numberofpoints) return std::nullopt;  // TetGen needed an interior point
  std::vector<LocalTet> tets;
  for (int t = 0; t < out.numberoftetrahedra; ++t) {
    LocalTet tet;
    for (int k = 0; k < 4; ++k) tet[std::size_t(k)] = std::uint8_t(out.tetrahedronlist[t * out.numberofcorners + k]);
    // volpost's (VTK's) orientation: positive (p1-p0).((p2-p0)x(p3-p0)).
    const auto& p0 = corners[tet[0]];
    double e[3][3];
    for (int r = 0; r < 3; ++r)
      for (int k = 0; k < 3; ++k) e[r][k] = corners[tet[std::size_t(r + 1)]][std::size_t(k)] - p0[std::size_t(k)];
    const double volume6 = e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) - e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
                           e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
    if (volume6 == 0.0) return std::nullopt;  // a flat tet: not a split to use
    if (volume6 < 0.0) std::swap(tet[1], tet[2]);
    tets.push_back(tet);
  }
  return tets;
}

}  // namespace

// Every configuration is computed once, on first use (74 small TetGen runs, a few ms);
// after that a lookup is a plain index, with no lock on the per-cell path.
const std::optional<std::vector<LocalTet>>& splitTemplate(CellType type, unsigned diagonals) {
  if (type != CellType::Hex8 && type != CellType::Hex20 && type != CellType::Wedge6 && type != CellType::Wedge15 &&
      type != CellType::Pyramid5)
    throw std::logic_error("split templates are for hexahedra, wedges and pyramids");
  using Table = std::vector<std::optional<std::vector<LocalTet>>>;
  const auto build = [](CellType t) {
    unsigned quads = 0;
    for (const CellFace& f : topology(t).faces) quads += f.size == 4;
    Table table;
    for (unsigned d = 0; d < (1u << quads); ++d) table.push_back(computeTemplate(t, d));
    return table;
  };
  static const Table hex = build(CellType::Hex8), wedge = build(CellType::Wedge6), pyramid = build(CellType::Pyramid5);
  const Table& table = type == CellType::Hex8 || type == CellType::Hex20 ? hex
                       : type == CellType::Pyramid5                      ? pyramid
                                                                         : wedge;
  return table.at(diagonals);
}

}  // namespace volpost::detail

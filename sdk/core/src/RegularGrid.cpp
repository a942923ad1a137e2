// SPDX-License-Identifier: MIT
#include <volpost/core/RegularGrid.hpp>

#include <limits>
#include <stdexcept>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace volpost {

std::size_t RegularGrid::cellCount() const {
  if (dims[0] < 2 || dims[1] < 2 || dims[2] < 2) return 0;
  return (dims[0] - 1) * (dims[1] - 1) * (dims[2] - 1);
}

glm::dvec3 RegularGrid::indexOf(const glm::dvec3& world) const { return glm::inverse(indexToWorld()) * (world - origin); }

Bounds RegularGrid::bounds() const {
  Bounds b;
  for (int c = 0; c < 8; ++c)
    b.extend(position((c & 1) ? double(dims[0] - 1) : 0.0, (c & 2) ? double(dims[1] - 1) : 0.0,
                      (c & 4) ? double(dims[2] - 1) : 0.0));
  return b;
}

std::string RegularGrid::defect() const {
  const std::string size = std::to_string(dims[0]) + " x " + std::to_string(dims[1]) + " x " + std::to_string(dims[2]);
  if (dims[0] < 2 || dims[1] < 2 || dims[2] < 2)
    return "a grid of " + size + " points has no volume: every axis needs at least 2 points";
  for (const glm::dvec3& a : axes)
    if (!std::isfinite(a.x) || !std::isfinite(a.y) || !std::isfinite(a.z)) return "a grid axis is not finite";
  if (!std::isfinite(origin.x) || !std::isfinite(origin.y) || !std::isfinite(origin.z))
    return "the grid's origin is not finite";
  for (int c = 0; c < 8; ++c) {  // the far corners too: a huge origin plus steps can overflow
    const glm::dvec3 p = position((c & 1) ? double(dims[0] - 1) : 0.0, (c & 2) ? double(dims[1] - 1) : 0.0,
                                  (c & 4) ? double(dims[2] - 1) : 0.0);
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      return "the grid's far corners are not finite numbers (origin or spacing too large)";
  }
  const double scale = glm::length(axes[0]) * glm::length(axes[1]) * glm::length(axes[2]);
  if (!(std::abs(glm::determinant(indexToWorld())) > 1e-12 * scale))
    return "the grid's axes are zero or lie in one plane (spacing 0?)";
  return {};
}

std::array<NodeIndex, 8> gridHexahedron(const RegularGrid& grid, std::size_t i, std::size_t j, std::size_t k) {
  const auto p = [&](std::size_t di, std::size_t dj, std::size_t dk) {
    return NodeIndex(grid.pointIndex(i + di, j + dj, k + dk));
  };
  std::array<NodeIndex, 8> hex{p(0, 0, 0), p(1, 0, 0), p(1, 1, 0), p(0, 1, 0),
                               p(0, 0, 1), p(1, 0, 1), p(1, 1, 1), p(0, 1, 1)};
  // A left-handed set of axes mirrors the hexahedra: list the bottom and top faces the
  // other way round so every cell keeps a positive volume.
  if (glm::determinant(grid.indexToWorld()) < 0.0) {
    std::swap(hex[1], hex[3]);
    std::swap(hex[5], hex[7]);
  }
  return hex;
}

Mesh hexahedraOfGrid(const RegularGrid& grid) {
  if (grid.pointCount() > std::size_t(std::numeric_limits<NodeIndex>::max()))
    throw std::length_error("a grid of " + std::to_string(grid.pointCount()) +
                            " points is too large for explicit cells (node indices are 32-bit): only the grid "
                            "renderers can draw it");
  Mesh mesh;
  const auto [nx, ny, nz] = grid.dims;
  mesh.nodes.reserve(grid.pointCount());
  for (std::size_t k = 0; k < nz; ++k)
    for (std::size_t j = 0; j < ny; ++j)
      for (std::size_t i = 0; i < nx; ++i) mesh.nodes.push_back(grid.position(double(i), double(j), double(k)));
  const std::size_t cells = grid.cellCount();
  mesh.reserveCells(cells, cells * 8);
  for (std::size_t k = 0; k + 1 < nz; ++k)
    for (std::size_t j = 0; j + 1 < ny; ++j)
      for (std::size_t i = 0; i + 1 < nx; ++i) mesh.addCell(CellType::Hex8, gridHexahedron(grid, i, j, k));
  return mesh;
}

namespace {

template <typename T>
double trilinearOf(const RegularGrid& grid, const T* values, const glm::dvec3& index) {
  std::size_t base[3];
  double w[3];
  for (int a = 0; a < 3; ++a) {
    const double top = double(grid.dims[a] - 1);
    const double x = std::clamp(std::isfinite(index[a]) ? index[a] : 0.0, 0.0, top);
    const double cell = std::min(std::floor(x), std::max(top - 1.0, 0.0));
    base[a] = std::size_t(cell);
    w[a] = x - cell;
  }
  const std::size_t di = grid.dims[0] > 1 ? 1 : 0, dj = grid.dims[1] > 1 ? grid.dims[0] : 0,
                    dk = grid.dims[2] > 1 ? grid.dims[0] * grid.dims[1] : 0;
  const std::size_t o = grid.pointIndex(base[0], base[1], base[2]);
  const double c00 = values[o] + w[0] * (double(values[o + di]) - values[o]);
  const double c10 = values[o + dj] + w[0] * (double(values[o + dj + di]) - values[o + dj]);
  const double c01 = values[o + dk] + w[0] * (double(values[o + dk + di]) - values[o + dk]);
  const double c11 = values[o + dk + dj] + w[0] * (double(values[o + dk + dj + di]) - values[o + dk + dj]);
  const double c0 = c00 + w[1] * (c10 - c00), c1 = c01 + w[1] * (c11 - c01);
  return c0 + w[2] * (c1 - c0);
}

}  // namespace

double trilinear(const RegularGrid& grid, const float* values, const glm::dvec3& index) {
  return trilinearOf(grid, values, index);
}
double trilinear(const RegularGrid& grid, const double* values, const glm::dvec3& index) {
  return trilinearOf(grid, values, index);
}

}  // namespace volpost

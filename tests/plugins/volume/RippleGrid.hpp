// SPDX-License-Identifier: MIT
// A rotated, anisotropic regular grid with a smooth rippled field: the test grid of the
// bricks' and the 2D transfer functions' image tests.
#pragma once

#include <volpost/core/RegularGrid.hpp>

#include <glm/geometric.hpp>

#include <array>
#include <cmath>
#include <vector>

namespace volpost::test {

/// `dims` points, spacings 0.5, 0.6 and 0.7 along axes turned 0.3 rad about z (the second
/// tilted a little).
inline RegularGrid rippleGrid(const std::array<std::size_t, 3>& dims) {
  RegularGrid g;
  g.dims = dims;
  const double c = std::cos(0.3), s = std::sin(0.3);
  g.origin = {-4.0, 2.0, 1.0};
  g.axes = {glm::dvec3(0.5 * c, 0.5 * s, 0.0), glm::dvec3(-0.6 * s, 0.6 * c, 0.05), glm::dvec3(0.0, 0.0, 0.7)};
  return g;
}

/// 3 + 2 sin(0.5 i) cos(0.4 j) + 0.2 k: values about 1 .. 5 plus the rise with k.
inline std::vector<double> rippleValues(const RegularGrid& g) {
  std::vector<double> v(g.pointCount());
  for (std::size_t k = 0; k < g.dims[2]; ++k)
    for (std::size_t j = 0; j < g.dims[1]; ++j)
      for (std::size_t i = 0; i < g.dims[0]; ++i)
        v[g.pointIndex(i, j, k)] = 3.0 + 2.0 * std::sin(0.5 * double(i)) * std::cos(0.4 * double(j)) + 0.2 * double(k);
  return v;
}

}  // namespace volpost::test

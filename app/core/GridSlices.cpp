// SPDX-License-Identifier: MIT
#include "GridSlices.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace volpost::app {

void checkGridSlices(const std::optional<RegularGrid>& grid, const GridSliceLabels& labels) {
  if (!labels[0] && !labels[1] && !labels[2]) return;
  if (!grid)
    throw std::invalid_argument(
        "grid slices (inline, crossline, time) need a regular grid (SEG-Y, image data); this "
        "model is a mesh: use clip planes");
  for (int a = 0; a < 3; ++a) {
    const auto& label = labels[std::size_t(a)];
    if (!label) continue;
    const double index = (*label - grid->firstLabel[std::size_t(a)]) / grid->labelStep[std::size_t(a)];
    const double last = double(grid->dims[std::size_t(a)] - 1);
    if (!std::isfinite(index) || index < -0.5 || index > last + 0.5) {
      const double from = grid->label(a, 0.0), to = grid->label(a, last);
      const auto number = [](double v) {
        std::ostringstream text;
        text << std::setprecision(10) << v;
        return text.str();
      };
      throw std::invalid_argument("the " + grid->axisNames[std::size_t(a)] + " slice at " + number(*label) +
                                  " lies outside the grid's " + grid->axisNames[std::size_t(a)] + " " +
                                  number(std::min(from, to)) + " .. " + number(std::max(from, to)));
    }
  }
}

int gridAxisNamed(const RegularGrid& grid, const std::string& name) {
  const auto lower = [](std::string s) {
    for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
    return s;
  };
  const std::string wanted = lower(name);
  for (int a = 0; a < 3; ++a) {
    const std::string axis = lower(grid.axisNames[std::size_t(a)]);
    const std::string firstWord = axis.substr(0, axis.find_first_of(" ("));
    if (wanted == axis || wanted == firstWord || wanted == std::string(1, char('i' + a)) ||
        wanted == std::to_string(a + 1))
      return a;
  }
  return -1;
}

std::vector<ClipPlane> gridSlicePlanesAt(const RegularGrid& g, const GridSliceLabels& labels) {
  std::vector<ClipPlane> planes;
  for (int a = 0; a < 3; ++a) {
    const auto& label = labels[std::size_t(a)];
    if (!label) continue;
    // At the label's position along its axis, across the other two axes; the first and last
    // layers a millionth of a step inside (a plane on the box's face cuts no cell), and a
    // label up to half a step outside cuts the outermost layer.
    const double last = double(g.dims[std::size_t(a)] - 1), inside = 1e-6;
    const double index =
        std::clamp((*label - g.firstLabel[std::size_t(a)]) / g.labelStep[std::size_t(a)], inside, last - inside);
    const glm::dvec3 normal =
        glm::normalize(glm::cross(g.axes[std::size_t((a + 1) % 3)], g.axes[std::size_t((a + 2) % 3)]));
    planes.push_back({g.origin + g.axes[std::size_t(a)] * index, normal});
  }
  return planes;
}

}  // namespace volpost::app

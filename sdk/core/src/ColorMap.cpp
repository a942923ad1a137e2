// SPDX-License-Identifier: MIT
#include <volpost/core/ColorMap.hpp>

#include <algorithm>
#include <array>
#include <initializer_list>
#include <cmath>
#include <stdexcept>

namespace volpost {
namespace {

ColorMap from8bit(const std::string& name, std::initializer_list<std::array<int, 3>> rgb) {
  std::vector<ColorMap::Point> points;
  const double n = double(rgb.size() - 1);
  int i = 0;
  for (const auto& c : rgb)
    points.push_back({i++ / n, glm::dvec3(c[0], c[1], c[2]) / 255.0});
  return ColorMap(name, std::move(points));
}

}  // namespace

ColorMap::ColorMap(std::string name, std::vector<Point> points)
    : name_(std::move(name)), points_(std::move(points)) {
  if (points_.size() < 2) throw std::invalid_argument("color map " + name_ + " needs 2 points");
  std::stable_sort(points_.begin(), points_.end(),
                   [](const Point& a, const Point& b) { return a.t < b.t; });
}

std::vector<std::string> ColorMap::names() { return {"cool-warm", "viridis", "rainbow", "grayscale", "seismic"}; }

std::string ColorMap::reversedName(const std::string& name) {
  if (name.size() > kReversed.size() && name.compare(name.size() - kReversed.size(), kReversed.size(), kReversed) == 0)
    return name.substr(0, name.size() - kReversed.size());
  return name + std::string(kReversed);
}

bool ColorMap::isReversed(const std::string& name) {
  return name.size() > kReversed.size() &&
         name.compare(name.size() - kReversed.size(), kReversed.size(), kReversed) == 0;
}

std::string ColorMap::label(const std::string& name) {
  if (isReversed(name)) return label(reversedName(name)) + ", reversed";
  if (name == "cool-warm") return "Cool to warm (diverging)";
  if (name == "viridis") return "Viridis";
  if (name == "rainbow") return "Rainbow";
  if (name == "grayscale") return "Grayscale";
  if (name == "seismic") return "Seismic (blue-white-red)";
  return name;
}

ColorMap ColorMap::named(const std::string& name) {
  if (isReversed(name)) {  // "viridis-reversed": the same colors from the other end
    const ColorMap forward = named(reversedName(name));
    std::vector<Point> points;
    for (auto p = forward.points_.rbegin(); p != forward.points_.rend(); ++p) points.push_back({1.0 - p->t, p->rgb});
    return ColorMap(name, std::move(points));
  }
  // Moreland's diverging cool-warm and a viridis approximation, sampled at 9 points.
  if (name == "cool-warm")
    return from8bit(name, {{59, 76, 192}, {98, 130, 234}, {141, 176, 254}, {184, 208, 249},
                           {221, 221, 221}, {245, 196, 173}, {244, 154, 123}, {222, 96, 77},
                           {180, 4, 38}});
  if (name == "viridis")
    return from8bit(name, {{68, 1, 84}, {71, 44, 122}, {59, 81, 139}, {44, 113, 142},
                           {33, 144, 141}, {39, 173, 129}, {92, 200, 99}, {170, 220, 50},
                           {253, 231, 37}});
  if (name == "rainbow")
    return from8bit(name, {{0, 0, 255}, {0, 255, 255}, {0, 255, 0}, {255, 255, 0}, {255, 0, 0}});
  if (name == "grayscale") return from8bit(name, {{0, 0, 0}, {255, 255, 255}});
  // Interpreters' red-white-blue: troughs blue, zero white, peaks red (dark at the ends).
  if (name == "seismic")
    return from8bit(name, {{0, 0, 77}, {0, 0, 255}, {255, 255, 255}, {255, 0, 0}, {128, 0, 0}});
  throw std::invalid_argument("unknown color map '" + name +
                              "' (known: cool-warm, viridis, rainbow, grayscale, seismic, each also NAME-reversed)");
}

glm::dvec3 ColorMap::at(double t) const {
  if (!(t >= 0.0)) t = 0.0;  // NaN too
  if (t > 1.0) t = 1.0;
  auto hi = std::lower_bound(points_.begin(), points_.end(), t,
                             [](const Point& p, double x) { return p.t < x; });
  if (hi == points_.begin()) return hi->rgb;
  if (hi == points_.end()) return points_.back().rgb;
  const auto lo = hi - 1;
  const double w = hi->t > lo->t ? (t - lo->t) / (hi->t - lo->t) : 0.0;
  return lo->rgb + (hi->rgb - lo->rgb) * w;
}

std::vector<unsigned char> ColorMap::rgba8(int count) const {
  std::vector<unsigned char> out(std::size_t(count) * 4);
  for (int i = 0; i < count; ++i) {
    // Texel i holds t = i / (count - 1); shaders sample texel centres accordingly.
    const glm::dvec3 c = at(count > 1 ? double(i) / (count - 1) : 0.0);
    for (int k = 0; k < 3; ++k)
      out[std::size_t(i) * 4 + k] = (unsigned char)std::lround(std::clamp(c[k], 0.0, 1.0) * 255.0);
    out[std::size_t(i) * 4 + 3] = 255;
  }
  return out;
}

}  // namespace volpost

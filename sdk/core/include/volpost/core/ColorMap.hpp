// SPDX-License-Identifier: MIT
// Color maps for results: piecewise-linear RGB over [0, 1].
#pragma once

#include <glm/vec3.hpp>

#include <string>
#include <string_view>
#include <vector>

namespace volpost {

class ColorMap {
 public:
  struct Point {
    double t;        ///< position in [0, 1]
    glm::dvec3 rgb;  ///< linear 0..1 display values
  };
  ColorMap(std::string name, std::vector<Point> points);

  /// Built-in maps: "cool-warm" (diverging, the default), "viridis", "rainbow", "grayscale".
  static ColorMap named(const std::string& name);
  static std::vector<std::string> names();
  /// What a menu shows for a name of names(), the same everywhere: "Cool to warm (diverging)".
  static std::string label(const std::string& name);
  /// "NAME-reversed" is every map run from its other end (named() knows it): this gives
  /// the other of the two names.
  static std::string reversedName(const std::string& name);
  static bool isReversed(const std::string& name);
  static constexpr std::string_view kReversed = "-reversed";

  const std::string& name() const { return name_; }
  glm::dvec3 at(double t) const;  ///< t clamped to [0, 1]
  /// `count` RGBA8 texels for a 1D texture; texel i holds the color at t = i / (count - 1).
  std::vector<unsigned char> rgba8(int count) const;

 private:
  std::string name_;
  std::vector<Point> points_;
};

}  // namespace volpost

// SPDX-License-Identifier: MIT
// How a mesh's node values vary inside a cell when a volume is drawn.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace volpost {

enum class FieldInterpolation {
  /// Linear on the tetrahedra each cell is split into (exact for tet4 cells; a hex8's
  /// trilinear field and a quadratic cell's field become piecewise linear).
  Tetrahedra,
  /// Each cell's own shape functions, as the solver defines the field: trilinear in a
  /// hex8, quadratic in a tet10, serendipity in a hex20 and a wedge15.
  Element,
};

inline std::string toString(FieldInterpolation i) {
  return i == FieldInterpolation::Element ? "element" : "tetrahedra";
}

inline std::optional<FieldInterpolation> fieldInterpolationFromString(std::string_view s) {
  if (s == "element") return FieldInterpolation::Element;
  if (s == "tetrahedra") return FieldInterpolation::Tetrahedra;
  return std::nullopt;
}

inline constexpr const char* kFieldInterpolationChoices = "element, tetrahedra";

}  // namespace volpost

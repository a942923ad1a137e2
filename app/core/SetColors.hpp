// SPDX-License-Identifier: MIT
// The model colored plainly by its element sets: each drawn cell in the color of the set
// holding it (the smallest such set, so a set inside an all-elements set shows), as the
// Abaqus viewer's color coding by set and ParaView's block colors do. A set keeps its color
// whatever else is shown or hidden: the color follows the set's place among the model's
// element sets.
#pragma once

#include "ModelSession.hpp"

#include <volpost/core/ColorMap.hpp>

#include <glm/vec3.hpp>

#include <string>
#include <vector>

namespace volpost::app {

/// Colors the sets cycle through, distinct side by side and none of them gray (the color of
/// a cell in no set).
inline constexpr int kSetPaletteSize = 12;
glm::dvec3 setPaletteColor(std::size_t index);

struct SetColoring {
  /// Per cell of the drawn model: its color's place in the palette plus one half, NaN for a
  /// cell in no element set (drawn gray). Drawn over the range [0, kSetPaletteSize] in
  /// kSetPaletteSize bands of colorMap().
  ScalarView view;
  struct Entry {
    std::string name;
    glm::dvec3 rgb{0.0};
    std::size_t cells = 0;  ///< drawn cells that take this set's color
  };
  std::vector<Entry> entries;  ///< the sets that color a drawn cell, in the model's order
  std::size_t cellsInNoSet = 0;
};

/// The palette as a color map of kSetPaletteSize flat bands over [0, 1].
ColorMap setPaletteMap();

/// How `drawn` (the model as drawn: a part of `whole`, or `whole` itself) is colored by
/// its element sets; the colors follow each set's place among `whole`'s element sets.
SetColoring setColoring(const ModelSession& drawn, const ModelSession& whole);

}  // namespace volpost::app

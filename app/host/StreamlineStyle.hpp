// SPDX-License-Identifier: MIT
// How streamlines look: lit lines of a width, or shaded tubes, with arrows along them. A
// plain value the scene's state keeps and the streamline renderer draws with.
#pragma once

namespace volpost {

struct StreamlineStyle {
  float width = 2.0f;          ///< lit lines: pixels
  bool tubes = false;          ///< shaded tubes instead of lines
  double tubeRadius = 0.0;     ///< model units (tubes and arrows)
  bool radiusByValue = false;  ///< tube radius from 0.25x to 1x by the colored scalar
  bool arrows = false;         ///< cones along the lines or tubes, pointing downstream
  double arrowSpacing = 0.0;   ///< model units between arrows
  bool operator==(const StreamlineStyle&) const = default;
};

}  // namespace volpost

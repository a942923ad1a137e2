// SPDX-License-Identifier: MIT
// How the model's boundary is drawn, in ParaView's words: its faces colored by the result
// (with or without element edges), only the element edges, only the nodes as points
// colored by the result, only the feature edges (sharp creases and borders), or only the
// bounding box. Sections, slices and iso-surfaces show whichever is chosen.
#pragma once

#include <optional>
#include <string>

namespace volpost::app {

enum class SurfaceRepresentation { Surface, Wireframe, Points, FeatureEdges, Outline };

/// "surface", "wireframe", "points", "feature-edges", "outline".
std::string toString(SurfaceRepresentation r);
std::optional<SurfaceRepresentation> surfaceRepresentationFromString(const std::string& text);
/// The names above, comma-separated, for messages and help.
std::string surfaceRepresentationChoices();

}  // namespace volpost::app

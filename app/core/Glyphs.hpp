// SPDX-License-Identifier: MIT
// Glyphs at the nodes: an arrow for a nodal vector field (scaled by its length or all the
// same length, colored by the length or any nodal quantity), or for a symmetric tensor
// field three bars along its principal directions, each as long as its principal value
// is large and colored by it on a range symmetric about zero (tension and compression
// apart on a diverging map). Built here as plain triangles (no GL): the drawing uploads
// them as a lit surface colored through the color map.
#pragma once

#include "ModelSession.hpp"

#include <volpost/core/ClipPlane.hpp>

#include <glm/vec3.hpp>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace volpost::app {

struct GlyphLayer {
  bool shown = false;
  std::string field;         ///< a nodal vector field (arrows) or symmetric tensor field (principal bars)
  std::string colorBy;       ///< a nodal quantity ("T", "S.mises"); empty: the length / each principal value
  bool fixedLength = false;  ///< arrows all one length: the direction only
  /// Model units per unit of the field (or the fixed length); nullopt: the longest glyph is
  /// kAutomaticGlyphSize of the model's diagonal (at a stride, of the spacing's share).
  std::optional<double> scale;
  int every = 0;          ///< every k-th of the nodes; 0: automatic, at most kAutomaticGlyphs
  bool allNodes = false;  ///< false: the surface's nodes (the ones an opaque model shows)
  bool operator==(const GlyphLayer&) const = default;
};

inline constexpr std::size_t kAutomaticGlyphs = 20000;
inline constexpr std::size_t kMaxGlyphs = 200000;
inline constexpr double kAutomaticGlyphSize = 0.06;

struct GlyphGeometry {
  std::vector<glm::dvec3> corners;      ///< three per triangle, model coordinates
  std::vector<double> values;           ///< one per corner: what the color map colors
  std::size_t glyphs = 0;               ///< nodes drawn (without a glyph: zero or not finite)
  std::size_t candidates = 0;           ///< places in the chosen set (nodes, cut faces' centres)
  std::size_t every = 1;                ///< the stride used
  double min = 0.0, max = 1.0;          ///< the colors' range
  double dataMin = 0.0, dataMax = 0.0;  ///< the values' own extremes (a tensor's range is widened about 0)
  double scale = 0.0;                   ///< model units per unit of the field used
  std::string valueName;                ///< what the colors show, for the legend
};

/// Throws std::invalid_argument naming the choices when the field is not a nodal vector or
/// symmetric tensor field, the coloring quantity is not given at the nodes, the scale is
/// not positive or the stride negative.
void checkGlyphLayer(const ModelSession& session, const GlyphLayer& layer);
/// The glyphs at a step (the field's last when it has fewer). `cuts` (the clip planes and
/// box): a node they cut away has no glyph, and with `onCutFaces` the surface's glyphs (not
/// allNodes) are joined by one at the centre of each cell's cut face, interpolated along its
/// cut edges (the surface view draws those faces; a volume does not).
/// Throws std::invalid_argument when the places chosen would give more than kMaxGlyphs glyphs.
GlyphGeometry buildGlyphs(const ModelSession& session, const GlyphLayer& layer, std::size_t step,
                          const std::vector<ClipPlane>& cuts = {}, bool onCutFaces = true);

}  // namespace volpost::app

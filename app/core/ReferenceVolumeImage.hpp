// SPDX-License-Identifier: MIT
// A scene's volume by the exact CPU reference renderer (double precision, exact
// transfer-function integration): for reports, and the yardstick of the GPU renderers.
#pragma once

#include "Scene.hpp"

#include "host/optics/ReferenceRenderer.hpp"

#include <volpost/core/Progress.hpp>

#include <string>
#include <vector>

namespace volpost::app {

/// The scene's result, transfer function, camera, clip planes (box included) and
/// iso-surfaces, rendered by the reference renderer on `threads` cores (0: all). Throws
/// std::invalid_argument without a result, Cancelled on request.
/// How a renderer draws cells that bend away from their tetrahedra's flat faces.
enum class BentCells {
  Followed,  ///< to their own curved faces (the reference, the refined pieces)
  Flat       ///< their field within the tetrahedra's flat faces (the CPU ray caster)
};

/// What the user should know after drawing the cells' own field: the cells drawn by their
/// split (no inverse map; their ids, the first ten), the stretches where the map did not
/// converge, and how cells that bend away from their split were drawn. Empty when there is
/// nothing to say.
std::vector<std::string> elementFieldNotes(const optics::ElementField& field, const Mesh& mesh,
                                           BentCells bent = BentCells::Followed);

optics::ReferenceImage renderVolumeReference(const Scene& scene, int width, int height, int threads = 0,
                                             const Progress& progress = {});

}  // namespace volpost::app

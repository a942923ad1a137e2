// SPDX-License-Identifier: MIT
// What a box dragged over the picture holds: the elements (or nodes) of the drawn model
// that show inside it, on the surface and the cut faces (what is seen: faces hidden behind
// others are not), or through the model's whole depth. Found on the CPU with a depth
// buffer of the box's pixels, so the window, tests and scripts select the same.
#pragma once

#include "Scene.hpp"

#include <cstdint>
#include <vector>

namespace volpost::app {

/// A box in a picture's pixels (top left origin); the corners in any order.
struct PictureBox {
  double x0 = 0.0, y0 = 0.0, x1 = 0.0, y1 = 0.0;
};

enum class SelectionDepth {
  Surface,  ///< what is seen: the boundary surface and the cut faces, nearest first
  Through,  ///< every element whose centre (node) projects into the box, hidden or not
};

/// The drawn model's elements in `box` of a `width` x `height` picture taken with
/// `camera` (Scene::pictureCamera), as indices of scene.session()'s cells, sorted. Cut
/// away by the clip planes and box: not selected. A hidden surface offers only its cut
/// faces. Empty for a regular grid (it has no elements to pick).
std::vector<std::uint32_t> elementsInBox(const Scene& scene, const Camera& camera, double width, double height,
                                         const PictureBox& box, SelectionDepth depth);
/// The same for nodes: the drawn elements' nodes inside the box, those on the seen
/// surface (Surface) or all (Through), as indices of the model's nodes, sorted.
std::vector<std::uint32_t> nodesInBox(const Scene& scene, const Camera& camera, double width, double height,
                                      const PictureBox& box, SelectionDepth depth);

}  // namespace volpost::app

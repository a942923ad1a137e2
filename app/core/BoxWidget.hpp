// SPDX-License-Identifier: MIT
// The clip box as the window shows it: its twelve edges and a knob at the middle of each
// face. Dragging a knob moves that face along its axis (the box keeps a positive size);
// the window draws the box as it is dragged and applies it on release, since a new box
// re-culls what the GPU holds. Geometry, hit test and drag arithmetic, free of widgets.
#pragma once

#include "SceneState.hpp"

#include <volpost/core/Camera.hpp>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <optional>

namespace volpost::app {

struct BoxWidget {
  std::array<glm::dvec3, 8> corners;       ///< corner c has x max when c & 1, y max when c & 2, z max when c & 4
  std::array<glm::dvec3, 6> faceCenters;   ///< xmin, xmax, ymin, ymax, zmin, zmax: the ClipBox's order
};

BoxWidget boxWidget(const ClipBox& box);

/// The twelve edges as pairs of corner indices.
const std::array<std::array<int, 2>, 12>& boxEdges();

/// The face (0..5, ClipBox order) whose knob is under `pixel` within `tolerance` pixels;
/// the nearest when several are; nullopt when none.
std::optional<int> hitBoxWidget(const BoxWidget& widget, const Camera& camera, double width, double height,
                                glm::dvec2 pixel, double tolerance);

/// The box with face `face` moved by the mouse's move from `from` to `to` (pixels) along its
/// axis, at the scale of the box's diagonal on the screen; the face stops 1e-3 of the
/// diagonal short of the opposite one.
ClipBox draggedBox(const ClipBox& box, int face, const Camera& camera, double width, double height, glm::dvec2 from,
                   glm::dvec2 to);

}  // namespace volpost::app

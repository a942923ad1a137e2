// SPDX-License-Identifier: MIT
// The clip plane as the window shows it: where the plane cuts the model's box (an outline,
// lightly filled) and a handle along its normal. Dragging the handle's knob turns the
// plane about the outline's centre; dragging its shaft slides the plane along the normal.
// Geometry, hit test and drag arithmetic live here, free of widgets, so they are tested
// without a window; the overlay paints the widget and the viewport forwards the mouse.
#pragma once

#include <volpost/core/Camera.hpp>
#include <volpost/core/ClipPlane.hpp>
#include <volpost/core/Mesh.hpp>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <vector>

namespace volpost::app {

struct PlaneWidget {
  std::vector<glm::dvec3> outline;  ///< the plane inside the (slightly enlarged) box, in order; empty if it misses it
  glm::dvec3 center{0.0};           ///< the outline's centre, on the plane
  glm::dvec3 knob{0.0};             ///< the end of the normal handle
};

/// The polygon where `plane` cuts `box` (3 to 6 corners, in order round the polygon;
/// empty when it misses the box or the box is invalid).
std::vector<glm::dvec3> planeInBox(const ClipPlane& plane, const Bounds& box);

/// The widget of `plane` over a model of bounds `bounds`: the box is enlarged by 2 % so
/// the outline shows beside the model's own faces; the handle is a quarter of the
/// diagonal long.
PlaneWidget planeWidget(const ClipPlane& plane, const Bounds& bounds);

enum class PlaneWidgetPart { None, Knob, Shaft };

/// The part of the widget under `pixel` (top-left origin) in a picture of width x height
/// seen by `camera`, within `tolerance` pixels; the knob wins over the shaft.
PlaneWidgetPart hitPlaneWidget(const PlaneWidget& widget, const Camera& camera, double width, double height,
                               glm::dvec2 pixel, double tolerance);

/// The plane turned so that its normal points from the widget's centre to the point under
/// `pixel`, taken in the plane through the knob that faces the camera; it goes through the
/// centre. Unchanged when the pixel's ray misses that plane.
ClipPlane turnedPlane(const ClipPlane& plane, const PlaneWidget& widget, const Camera& camera, double width,
                      double height, glm::dvec2 pixel);

/// The plane slid along its normal by the mouse's move from `from` to `to` (pixels): the
/// part of the move along the handle's direction on the screen, at the handle's scale.
/// With the normal pointing at the viewer, a move up the screen slides it toward the viewer.
ClipPlane slidPlane(const ClipPlane& plane, const PlaneWidget& widget, const Camera& camera, double width,
                    double height, glm::dvec2 from, glm::dvec2 to);

/// How far (model units) a mouse move from `from` to `to` (pixels) drags a point along the
/// unit `direction` from `anchor`: the part of the move along the direction's on-screen
/// image, scaled by `length` model units to the on-screen length of `length` along it. Seen
/// end on, up the screen is toward the viewer. Shared by the plane's and the box's handles.
double dragAlong(const glm::dvec3& anchor, const glm::dvec3& direction, double length, const Camera& camera,
                 double width, double height, glm::dvec2 from, glm::dvec2 to);

}  // namespace volpost::app

// SPDX-License-Identifier: MIT
// An orbit camera around a target point: rotate, pan, zoom, fit, standard views.
#pragma once

#include <volpost/core/Mesh.hpp>

#include <glm/gtc/quaternion.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <optional>
#include <string>

namespace volpost {

enum class StandardView { PlusX, MinusX, PlusY, MinusY, PlusZ, MinusZ, Isometric };
/// "+x" looks from +x toward the target (down the -x axis), likewise "-x", "+y", ...; "iso".
std::optional<StandardView> standardViewFromName(const std::string& name);

class Camera {
 public:
  enum class Projection { Perspective, Orthographic };

  /// Places the target at the bounds' center and backs off so the bounding sphere fits.
  void fit(const Bounds& bounds);
  void setView(StandardView view);
  /// Trackball rotation about the camera's own axes: azimuth about the screen's y axis,
  /// elevation about its x axis (degrees). Repeated drags can roll the model.
  void orbit(double azimuthDeg, double elevationDeg);
  /// Turntable rotation: azimuth about the world direction `up` (the model stays upright),
  /// elevation about the screen's x axis, stopping a degree short of looking along `up`.
  void turntable(double azimuthDeg, double elevationDeg, const glm::dvec3& up);
  /// Moves the target in the screen plane by a fraction of the view height.
  void pan(double dxFraction, double dyFraction);
  /// factor > 1 moves closer (perspective) or magnifies (orthographic).
  void zoom(double factor);

  /// Places the eye and the target explicitly; `up` need not be orthogonal to the view
  /// direction (it is made so). The scene radius set by fit() is kept (it sets the depth
  /// range). Throws std::invalid_argument if eye == target or up is parallel to the view.
  void lookAt(const glm::dvec3& eye, const glm::dvec3& target, const glm::dvec3& up);
  /// The camera exactly as another one holds it (target, rotation(), distance()): exact
  /// where the eye's coordinates are not (a model far from the origin, such as a
  /// georeferenced survey, where eye - target loses the direction's last bits). Throws
  /// std::invalid_argument for a non-finite or zero rotation or a distance that is not
  /// positive.
  void place(const glm::dvec3& target, const glm::dquat& rotation, double distance);
  /// The eye's orientation: its x right, y up, z backwards (from the target to the eye).
  const glm::dquat& rotation() const { return rotation_; }

  void setProjection(Projection p) { projection_ = p; }
  Projection projection() const { return projection_; }
  /// Angle of view across the picture's narrower side (the height of a wide picture, the
  /// width of a tall one), degrees, in (0, 180). Throws std::invalid_argument otherwise.
  void setFieldOfView(double degrees);
  double fieldOfView() const { return fovY_; }

  glm::dvec3 target() const { return target_; }
  glm::dvec3 eye() const;
  glm::dvec3 up() const;
  glm::dvec3 viewDirection() const;  ///< unit vector from the eye toward the target
  double distance() const { return distance_; }
  double viewHeight() const;         ///< height of the view at the target's depth

  /// View and projection matrices relative to `origin` (the model's center): GPU data is
  /// stored relative to it in float, so far-from-origin models keep their precision.
  glm::dmat4 viewMatrix(const glm::dvec3& origin = glm::dvec3(0.0)) const;
  glm::dmat4 projectionMatrix(double aspect) const;
  /// Where a model point lands in a picture of `width` x `height` (pixels, top left
  /// origin); nullopt behind the eye or for an empty picture.
  std::optional<glm::dvec2> projectToPicture(const glm::dvec3& point, double width, double height) const;

  /// A strip at the right of the picture, this fraction of its width (0..0.5), kept for the
  /// legend: the view is framed in the rest of the picture (an off-centre projection).
  void setRightMargin(double fraction);
  double rightMargin() const { return rightMargin_; }

 private:
  glm::dvec3 target_{0.0};
  glm::dquat rotation_{1.0, 0.0, 0.0, 0.0};  ///< camera-to-world rotation
  double distance_ = 1.0;
  double rightMargin_ = 0.0;
  double radius_ = 1.0;  ///< scene radius, sets clip planes
  double fovY_ = 30.0;
  Projection projection_ = Projection::Perspective;
};

}  // namespace volpost

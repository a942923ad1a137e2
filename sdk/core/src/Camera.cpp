// SPDX-License-Identifier: MIT
#include <volpost/core/Camera.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace volpost {
namespace {

glm::dquat lookRotation(const glm::dvec3& viewDir, const glm::dvec3& up) {
  const glm::dvec3 z = -glm::normalize(viewDir);
  const glm::dvec3 x = glm::normalize(glm::cross(up, z));
  const glm::dvec3 y = glm::cross(z, x);
  return glm::quat_cast(glm::dmat3(x, y, z));
}

}  // namespace

std::optional<StandardView> standardViewFromName(const std::string& name) {
  if (name == "+x") return StandardView::PlusX;
  if (name == "-x") return StandardView::MinusX;
  if (name == "+y") return StandardView::PlusY;
  if (name == "-y") return StandardView::MinusY;
  if (name == "+z") return StandardView::PlusZ;
  if (name == "-z") return StandardView::MinusZ;
  if (name == "iso") return StandardView::Isometric;
  return std::nullopt;
}

void Camera::fit(const Bounds& bounds) {
  target_ = bounds.valid ? bounds.center() : glm::dvec3(0.0);
  radius_ = bounds.valid ? std::max(0.5 * bounds.diagonal(), 1e-30) : 1.0;
  const double halfFov = glm::radians(fovY_) * 0.5;
  distance_ = radius_ / std::sin(halfFov) * 1.02;
}

void Camera::lookAt(const glm::dvec3& eye, const glm::dvec3& target, const glm::dvec3& up) {
  const glm::dvec3 view = target - eye;
  const double distance = glm::length(view);
  const bool finite = std::isfinite(distance) && std::isfinite(glm::length(up));
  if (!finite || !(distance > 0.0))
    throw std::invalid_argument("camera: the eye must differ from the target (finite coordinates)");
  if (!(glm::length(glm::cross(view / distance, up)) > 1e-9 * glm::length(up)))
    throw std::invalid_argument("camera: the up direction must not be parallel to the view direction");
  target_ = target;
  distance_ = distance;
  rotation_ = lookRotation(view, up);
}

void Camera::place(const glm::dvec3& target, const glm::dquat& rotation, double distance) {
  const double length = glm::length(rotation);
  if (!std::isfinite(distance) || !(distance > 0.0) || !std::isfinite(length) || !(length > 0.0) ||
      !std::isfinite(glm::length(target)))
    throw std::invalid_argument("camera: the rotation and distance must be finite and non-zero");
  target_ = target;
  distance_ = distance;
  // A unit quaternion as given stays bit for bit what it was (the view is then exactly the
  // saved one); another is made unit.
  rotation_ = std::abs(length - 1.0) < 1e-12 ? rotation : rotation / length;
}

void Camera::setFieldOfView(double degrees) {
  if (!(degrees > 0.0 && degrees < 180.0))
    throw std::invalid_argument("camera: the angle of view must lie between 0 and 180 degrees");
  fovY_ = degrees;
}

void Camera::setView(StandardView view) {
  const glm::dvec3 zUp(0, 0, 1), yUp(0, 1, 0);
  switch (view) {
    case StandardView::PlusX: rotation_ = lookRotation({-1, 0, 0}, zUp); break;
    case StandardView::MinusX: rotation_ = lookRotation({1, 0, 0}, zUp); break;
    case StandardView::PlusY: rotation_ = lookRotation({0, -1, 0}, zUp); break;
    case StandardView::MinusY: rotation_ = lookRotation({0, 1, 0}, zUp); break;
    case StandardView::PlusZ: rotation_ = lookRotation({0, 0, -1}, yUp); break;
    case StandardView::MinusZ: rotation_ = lookRotation({0, 0, 1}, yUp); break;
    case StandardView::Isometric: rotation_ = lookRotation({-1, -1, -1}, zUp); break;
  }
}

void Camera::orbit(double azimuthDeg, double elevationDeg) {
  // Rotations about the camera's own axes: dragging always turns the model the way the
  // mouse moves, whatever the current orientation.
  rotation_ = glm::normalize(rotation_ * glm::angleAxis(glm::radians(-azimuthDeg), glm::dvec3(0, 1, 0)) *
                             glm::angleAxis(glm::radians(-elevationDeg), glm::dvec3(1, 0, 0)));
}

void Camera::turntable(double azimuthDeg, double elevationDeg, const glm::dvec3& up) {
  if (!(glm::length(up) > 0.0) || !std::isfinite(azimuthDeg) || !std::isfinite(elevationDeg)) return;
  const glm::dvec3 axis = glm::normalize(up);
  rotation_ = glm::normalize(glm::angleAxis(glm::radians(-azimuthDeg), axis) * rotation_);
  // The screen's up keeps a positive part along the axis (at least sin 1 degree): the
  // model never turns over the pole. A step that would is shortened until it does not.
  const glm::dvec3 right = rotation_ * glm::dvec3(1, 0, 0);
  double step = elevationDeg;
  for (int tries = 0; tries < 12 && step != 0.0; ++tries, step *= 0.5) {
    const glm::dquat raised = glm::normalize(glm::angleAxis(glm::radians(-step), right) * rotation_);
    const double upright = glm::dot(raised * glm::dvec3(0, 1, 0), axis);
    if (upright >= std::sin(glm::radians(1.0)) || upright >= glm::dot(rotation_ * glm::dvec3(0, 1, 0), axis)) {
      rotation_ = raised;  // upright enough, or no worse than before
      return;
    }
  }
}

void Camera::pan(double dxFraction, double dyFraction) {
  const double h = viewHeight();
  target_ -= rotation_ * glm::dvec3(dxFraction * h, dyFraction * h, 0.0);
}

void Camera::zoom(double factor) {
  if (factor > 0.0 && std::isfinite(factor)) distance_ = std::max(distance_ / factor, radius_ * 1e-6);
}

glm::dvec3 Camera::eye() const { return target_ + rotation_ * glm::dvec3(0, 0, distance_); }
glm::dvec3 Camera::up() const { return rotation_ * glm::dvec3(0, 1, 0); }
glm::dvec3 Camera::viewDirection() const { return rotation_ * glm::dvec3(0, 0, -1); }

double Camera::viewHeight() const { return 2.0 * distance_ * std::tan(glm::radians(fovY_) * 0.5); }

glm::dmat4 Camera::viewMatrix(const glm::dvec3& origin) const {
  return glm::lookAt(eye() - origin, target_ - origin, up());
}

glm::dmat4 Camera::projectionMatrix(double aspect) const {
  // The view is framed in the picture left of the right margin: project for that part's
  // shape, then squeeze x into it.
  const double framed = aspect * (1.0 - rightMargin_);
  // The angle of view spans the narrower side: a tall picture shows the model whole too.
  const double widen = framed < 1.0 ? 1.0 / framed : 1.0;
  const double far = distance_ + 2.0 * radius_;
  glm::dmat4 projection;
  if (projection_ == Projection::Orthographic) {
    const double h = 0.5 * viewHeight() * widen, w = h * framed;
    projection = glm::ortho(-w, w, -h, h, distance_ - 2.0 * radius_, far);
  } else {
    const double near = std::max(distance_ - 2.0 * radius_, far * 1e-4);
    const double fov = 2.0 * std::atan(std::tan(glm::radians(fovY_) * 0.5) * widen);
    projection = glm::perspective(fov, framed, near, far);
  }
  if (rightMargin_ == 0.0) return projection;
  glm::dmat4 squeeze(1.0);  // x_ndc -> (1 - m) x_ndc - m: [-1, 1] onto [-1, 1 - 2m]
  squeeze[0][0] = 1.0 - rightMargin_;
  squeeze[3][0] = -rightMargin_;
  return squeeze * projection;
}

std::optional<glm::dvec2> Camera::projectToPicture(const glm::dvec3& point, double width, double height) const {
  if (!(width > 0.0 && height > 0.0)) return std::nullopt;
  const glm::dvec4 clip = projectionMatrix(width / height) * viewMatrix() * glm::dvec4(point, 1.0);
  if (!(clip.w > 0.0)) return std::nullopt;
  const glm::dvec2 ndc(clip.x / clip.w, clip.y / clip.w);
  return glm::dvec2((ndc.x + 1.0) * 0.5 * width, (1.0 - ndc.y) * 0.5 * height);
}

void Camera::setRightMargin(double fraction) {
  rightMargin_ = std::isfinite(fraction) ? std::clamp(fraction, 0.0, 0.5) : 0.0;
}

}  // namespace volpost

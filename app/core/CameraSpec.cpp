// SPDX-License-Identifier: MIT
#include "CameraSpec.hpp"

#include <charconv>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace volpost::app {
namespace {

double number(const std::string& item, const std::string& text) {
  double v = 0.0;
  const auto r = std::from_chars(text.data(), text.data() + text.size(), v);
  if (r.ec != std::errc() || r.ptr != text.data() + text.size() || !std::isfinite(v))
    throw std::invalid_argument("camera: '" + item + "' needs a number after '='");
  return v;
}

}  // namespace

void applyCameraSpec(Camera& camera, const std::string& spec) {
  std::istringstream in(spec);
  std::string item;
  double az = 0.0, el = 0.0, zoom = 1.0;
  while (std::getline(in, item, ',')) {
    if (item.empty()) continue;
    const auto eq = item.find('=');
    const std::string key = item.substr(0, eq), value = eq == std::string::npos ? "" : item.substr(eq + 1);
    if (auto view = standardViewFromName(item)) camera.setView(*view);
    else if (item == "ortho") camera.setProjection(Camera::Projection::Orthographic);
    else if (item == "persp") camera.setProjection(Camera::Projection::Perspective);
    else if (key == "az" && eq != std::string::npos) az = number(item, value);
    else if (key == "el" && eq != std::string::npos) el = number(item, value);
    else if (key == "zoom" && eq != std::string::npos) {
      zoom = number(item, value);
      if (zoom <= 0.0) throw std::invalid_argument("camera: zoom must be positive, got " + value);
    } else
      throw std::invalid_argument("camera: unknown item '" + item +
                                  "' (use iso, +x, -x, +y, -y, +z, -z, az=DEG, el=DEG, zoom=F, ortho, persp)");
  }
  camera.orbit(az, el);
  camera.zoom(zoom);
}

}  // namespace volpost::app

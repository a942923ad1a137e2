// SPDX-License-Identifier: MIT
// Renders a model to an image with no window and no X server (EGL), through the same
// SceneRenderer the window uses. Needs a QGuiApplication for the legend's text.
#pragma once

#include "ModelSession.hpp"
#include "SceneRenderer.hpp"

#include <QImage>

#include <optional>
#include <string>

namespace volpost::app {

struct ImageRequest {
  std::optional<Quantity> quantity;  ///< nullopt: plain surface, no legend
  std::size_t step = 0;              ///< 0-based
  std::string camera = "iso";        ///< see applyCameraSpec
  int width = 800, height = 600;
  std::string colorMap = "cool-warm";
  std::optional<DisplayRange> range; ///< nullopt: the values' own range
  bool edges = true;
  bool legend = true;
  bool lighting = true;
};

/// Throws std::exception subclasses with a message for the user (bad camera, no GL...).
QImage renderImage(const ModelSession& session, const ImageRequest& request);

}  // namespace volpost::app

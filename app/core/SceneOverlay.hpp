// SPDX-License-Identifier: MIT
// What is painted over the rendered picture, in the window and in `volpost render` alike:
// the legend, the probed points (numbered, with the shown quantity's value there) and the
// min/max markers.
#pragma once

#include "Scene.hpp"

#include <glm/vec2.hpp>

#include <optional>

class QPainter;
class QRect;

namespace volpost::app {

void paintSceneOverlay(QPainter& painter, const QRect& area, const Scene& scene);

}  // namespace volpost::app

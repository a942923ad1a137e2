// SPDX-License-Identifier: MIT
// A scene drawn with no window and no X server (EGL), as `volpost render` does: the picture
// a user sees (background, layers, legend) and, when a volume is shown, the volume's own
// premultiplied float image. Needs a QGuiApplication for the legend's text.
#pragma once

#include "Scene.hpp"

#include <volpost/core/Progress.hpp>

#include <QImage>

#include <vector>

namespace volpost::app {

struct SceneImage {
  QImage picture;                 ///< RGBA8, what the window would show at this size
  int width = 0, height = 0;
  std::vector<float> volumeRgba;  ///< premultiplied RGBA, top row first; empty without a volume
  std::vector<glm::dvec3> isoSurfaceCorners;  ///< the surface view's iso-surface triangles as drawn
};

/// Draws the scene with its GPU renderers in a headless context of its own (a SceneDrawing
/// made and released here), tracing its streamlines first where they need it. Throws
/// std::exception subclasses with a message for the user (no GL 4.5, a renderer error).
SceneImage renderSceneImage(Scene& scene, int width, int height);

/// The scene's volume by the exact CPU reference renderer, over the same background and
/// with the same legend as renderSceneImage. Cancelled on request.
SceneImage renderReferenceSceneImage(const Scene& scene, int width, int height, int threads = 0,
                                     const Progress& progress = {});

/// Paints the legend, probed points and min/max markers (paintSceneOverlay) over an image.
void paintSceneOverlay(QImage& image, const Scene& scene);

}  // namespace volpost::app

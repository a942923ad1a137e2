// SPDX-License-Identifier: MIT
// A scene drawn with no window and no X server (EGL), as `volpost render` does: the picture
// a user sees (background, layers, legend) and, when a volume is shown, the volume's own
// premultiplied float image. Needs a QGuiApplication for the legend's text.
#pragma once

#include "Scene.hpp"

#include <volpost/core/Progress.hpp>

#include <QImage>

#include <functional>
#include <vector>

namespace volpost::app {

struct SceneImage {
  QImage picture;                 ///< RGBA8, what the window would show at this size
  int width = 0, height = 0;
  std::vector<float> volumeRgba;  ///< premultiplied RGBA, top row first; empty without a volume
  std::vector<glm::dvec3> isoSurfaceCorners;      ///< the surface view's iso-surface triangles as drawn
  std::vector<glm::dvec3> curvedBoundaryCorners;  ///< the boundary as drawn in the cells' own shapes
  std::vector<std::string> notes;                 ///< what the user should know about how it was drawn
};

/// Draws the scene with its GPU renderers in a headless context of its own (a SceneDrawing
/// made and released here), tracing its streamlines first where they need it. Throws
/// std::exception subclasses with a message for the user (no GL 4.5, a renderer error).
/// `overlay` off: no legend, title or markers painted over it.
SceneImage renderSceneImage(Scene& scene, int width, int height, bool overlay = true);
/// The same in the GL context current now (the window's), with a drawing of its own.
SceneImage drawSceneImage(Scene& scene, int width, int height, bool overlay = true);

/// The scene's volume by the exact CPU reference renderer, over the same background and
/// with the same legend as renderSceneImage. Cancelled on request.
SceneImage renderReferenceSceneImage(const Scene& scene, int width, int height, int threads = 0,
                                     const Progress& progress = {}, bool overlay = true);

/// The picture with a transparent background: `draw` (a renderSceneImage or
/// renderReferenceSceneImage without the overlay) called over black and over white, each
/// pixel's coverage the difference (alpha = 1 - (white - black)), its color the one over
/// black divided by it; then the overlay painted, its words colored for the scene's own
/// background. Blended edges, see-through surfaces and volumes keep their partial
/// coverage. The volume's float image is the one drawn over black. The scene's background
/// is restored, also when `draw` throws.
SceneImage renderTransparent(Scene& scene, const std::function<SceneImage()>& draw);
/// Whether `path`'s picture format keeps transparency (.png, .tif, .tiff, .webp).
bool formatKeepsTransparency(const QString& path);

/// Paints the legend, probed points and min/max markers (paintSceneOverlay) over an image.
void paintSceneOverlay(QImage& image, const Scene& scene);

}  // namespace volpost::app

// SPDX-License-Identifier: MIT
#include "SceneImage.hpp"

#include "ReferenceVolumeImage.hpp"
#include "SceneDrawing.hpp"
#include "SceneOverlay.hpp"

#include <volpost/render/HeadlessContext.hpp>
#include <volpost/render/OffscreenTarget.hpp>
#include <volpost/render/ScopedInitialization.hpp>

#include <QFileInfo>
#include <QPainter>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace volpost::app {

void paintSceneOverlay(QImage& image, const Scene& scene) {
  QPainter painter(&image);
  paintSceneOverlay(painter, image.rect(), scene);
}

SceneImage renderSceneImage(Scene& scene, int width, int height, bool overlay) {
  HeadlessContext context;
  return drawSceneImage(scene, width, height, overlay);
}

SceneImage drawSceneImage(Scene& scene, int width, int height, bool overlay) {
  OffscreenTarget target(width, height);
  std::vector<std::uint8_t> pixels;
  SceneImage out;
  out.width = width;
  out.height = height;
  scene.updateStreamlines();  // a picture waits for its lines
  {
    // Released before the context goes, also when a frame throws.
    SceneDrawing drawing;
    const ScopedInitialization<SceneDrawing> initialized(drawing);
    RenderContext ctx;
    ctx.width = width;
    ctx.height = height;
    ctx.framebuffer = target.framebuffer();
    drawing.render(scene, ctx);
    glFinish();
    pixels = target.readPixels();
    out.volumeRgba = drawing.readVolumeImage();
    out.isoSurfaceCorners = drawing.isoSurfaceCorners();
    out.curvedBoundaryCorners = drawing.curvedBoundaryCorners();
    if (const optics::ElementField* field = drawing.elementField())
      out.notes = elementFieldNotes(*field, scene.session()->model().mesh(), BentCells::Flat);  // the CPU ray caster
    for (std::string& note : drawing.refinedVolumeNotes()) out.notes.push_back(std::move(note));
  }
  out.picture = QImage(width, height, QImage::Format_RGBA8888);
  for (int y = 0; y < height; ++y)
    std::memcpy(out.picture.scanLine(y), pixels.data() + std::size_t(y) * std::size_t(width) * 4, std::size_t(width) * 4);
  if (overlay) paintSceneOverlay(out.picture, scene);
  return out;
}

SceneImage renderReferenceSceneImage(const Scene& scene, int width, int height, int threads, const Progress& progress,
                                     bool overlay) {
  const optics::ReferenceImage reference = renderVolumeReference(scene, width, height, threads, progress);
  SceneImage out;
  out.width = width;
  out.height = height;
  out.notes = reference.notes;
  out.picture = QImage(width, height, QImage::Format_RGBA8888);
  out.volumeRgba.resize(reference.pixels.size() * 4);
  const glm::dvec3 background(scene.background());
  for (int y = 0; y < height; ++y) {
    uchar* line = out.picture.scanLine(y);
    for (int x = 0; x < width; ++x) {
      const std::size_t i = std::size_t(y) * std::size_t(width) + std::size_t(x);
      const glm::dvec4& p = reference.pixels[i];
      for (int k = 0; k < 4; ++k) out.volumeRgba[4 * i + std::size_t(k)] = float(p[k]);
      for (int k = 0; k < 3; ++k) {
        const double c = p[k] + (1.0 - p.a) * background[k];  // "over" the background, as the GPU composite does
        line[4 * x + k] = uchar(std::lround(std::clamp(c, 0.0, 1.0) * 255.0));
      }
      line[4 * x + 3] = 255;
    }
  }
  if (overlay) paintSceneOverlay(out.picture, scene);
  return out;
}

SceneImage renderTransparent(Scene& scene, const std::function<SceneImage()>& draw) {
  const glm::dvec3 own(scene.shown().background);
  struct Restore {
    Scene& scene;
    glm::dvec3 background;
    ~Restore() { scene.setBackground(background); }
  } restore{scene, own};
  scene.setBackground(glm::dvec3(0.0));
  SceneImage out = draw();
  scene.setBackground(glm::dvec3(1.0));
  const SceneImage overWhite = draw();
  scene.setBackground(own);
  QImage picture(out.width, out.height, QImage::Format_RGBA8888);
  const QImage black = out.picture.convertToFormat(QImage::Format_RGBA8888);
  const QImage white = overWhite.picture.convertToFormat(QImage::Format_RGBA8888);
  for (int y = 0; y < out.height; ++y) {
    const uchar* b = black.constScanLine(y);
    const uchar* w = white.constScanLine(y);
    uchar* o = picture.scanLine(y);
    for (int x = 0; x < out.width; ++x, b += 4, w += 4, o += 4) {
      // Over black a pixel is C*a; over white C*a + (1 - a): their difference is 1 - a.
      const double difference = ((w[0] - b[0]) + (w[1] - b[1]) + (w[2] - b[2])) / (3.0 * 255.0);
      const double alpha = std::clamp(1.0 - difference, 0.0, 1.0);
      for (int k = 0; k < 3; ++k)
        o[k] = alpha > 0.0 ? uchar(std::lround(std::clamp(b[k] / 255.0 / alpha, 0.0, 1.0) * 255.0)) : 0;
      o[3] = uchar(std::lround(alpha * 255.0));
    }
  }
  out.picture = picture;
  paintSceneOverlay(out.picture, scene);
  return out;
}

bool formatKeepsTransparency(const QString& path) {
  const QString suffix = QFileInfo(path).suffix().toLower();
  return suffix == "png" || suffix == "tif" || suffix == "tiff" || suffix == "webp";
}

}  // namespace volpost::app

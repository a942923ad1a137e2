// SPDX-License-Identifier: MIT
#include "ImageRender.hpp"

#include "CameraSpec.hpp"
#include "Legend.hpp"

#include <volpost/render/HeadlessContext.hpp>
#include <volpost/render/OffscreenTarget.hpp>

#include <QPainter>

#include <cstring>

namespace volpost::app {

QImage renderImage(const ModelSession& session, const ImageRequest& request) {
  Camera camera;
  camera.fit(session.model().mesh.bounds());
  applyCameraSpec(camera, request.camera);
  const ColorMap colorMap = ColorMap::named(request.colorMap);
  std::optional<ScalarView> view;
  if (request.quantity) view = session.evaluate(*request.quantity, request.step);
  const DisplayRange range = request.range ? *request.range : view ? autoRange(*view) : DisplayRange{};

  HeadlessContext context;
  OffscreenTarget target(request.width, request.height);
  SceneRenderer scene;
  scene.initialize();
  // The session outlives this function's GL objects; share it without taking ownership.
  scene.setSession(std::shared_ptr<const ModelSession>(&session, [](const ModelSession*) {}));
  scene.setColorMap(colorMap);
  scene.setShowEdges(request.edges);
  scene.setLighting(request.lighting);
  scene.setScalars(view ? &*view : nullptr, range);
  RenderContext ctx;
  ctx.camera = camera;
  ctx.width = request.width;
  ctx.height = request.height;
  ctx.framebuffer = target.framebuffer();
  scene.render(ctx);
  glFinish();
  const auto pixels = target.readPixels();
  scene.release();

  QImage image(request.width, request.height, QImage::Format_RGBA8888);
  for (int y = 0; y < request.height; ++y)
    std::memcpy(image.scanLine(y), pixels.data() + std::size_t(y) * std::size_t(request.width) * 4,
                std::size_t(request.width) * 4);
  if (view && request.legend) {
    QPainter painter(&image);
    LegendContent legend{QString::fromStdString(view->quantity.displayName()),
                         QString("%1%2").arg(QString::fromStdString(view->stepLabel),
                                             view->location == FieldLocation::Node ? "  per node" : "  per cell"),
                         range.min, range.max, view->range.nanCount};
    paintLegend(painter, image.rect(), colorMap, legend);
  }
  return image;
}

}  // namespace volpost::app

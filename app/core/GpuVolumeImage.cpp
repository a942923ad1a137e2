// SPDX-License-Identifier: MIT
#include "GpuVolumeImage.hpp"

#include "CameraSpec.hpp"
#include "Legend.hpp"
#include "SceneRenderer.hpp"

#include <volpost/core/ClipCulling.hpp>
#include <volpost/render/HeadlessContext.hpp>
#include <volpost/render/OffscreenTarget.hpp>

#include <QPainter>

#include <cstring>

namespace volpost::app {

ColorMap colorMapOf(const TransferFunction& tf) {
  std::vector<ColorMap::Point> points;
  const double lo = tf.minValue(), span = tf.maxValue() > lo ? tf.maxValue() - lo : 1.0;
  for (const ControlPoint& p : tf.points()) points.push_back({(p.value - lo) / span, p.color});
  if (points.size() < 2) points = {{0.0, glm::dvec3(0.5)}, {1.0, glm::dvec3(0.5)}};
  return ColorMap("transfer function", points);
}

QImage renderGpuVolume(const ModelSession& session, const VolumeRequest& request, VolumeRenderer& renderer,
                       IntegrationMode mode, bool legend) {
  const Mesh& mesh = session.model().mesh;
  const ScalarView view = session.evaluate(request.quantity, request.step);
  const TransferFunction tf =
      request.transferFunction ? *request.transferFunction : defaultTransferFunction(view, mesh.bounds().diagonal());
  Camera camera;
  camera.fit(mesh.bounds());
  applyCameraSpec(camera, request.camera);

  HeadlessContext context;
  OffscreenTarget target(request.width, request.height);
  renderer.initialize();
  // The GPU gets only what the clip planes can show (the picture is the same: the
  // renderer cuts exactly at the planes). Without planes there is nothing to cull.
  if (request.clipPlanes.empty()) {
    renderer.setVolume(session.tetrahedra().mesh, view.location, session.tetValues(view));
  } else {
    const CulledMesh culled = cullToClipPlanes(session.tetrahedra().mesh, request.clipPlanes);
    renderer.setVolume(culled.mesh, view.location, culled.values(view.location, session.tetValues(view)));
  }
  renderer.setTransferFunction(tf);
  renderer.setClipPlanes(request.clipPlanes);
  renderer.setIsoSurfaces(request.isoSurfaces);
  renderer.setIntegrationMode(mode);
  RenderContext ctx;
  ctx.camera = camera;
  ctx.width = request.width;
  ctx.height = request.height;
  ctx.framebuffer = target.framebuffer();
  SceneRenderer edges;  // the element edges, opaque: they end the rays at their depth
  edges.initialize();
  edges.setSession(std::shared_ptr<const ModelSession>(&session, [](const ModelSession*) {}));
  edges.setShowFaces(false);
  edges.setShowEdges(request.edges);
  edges.render(ctx);
  if (request.edges) ctx.depthTexture = target.depthTexture();
  renderer.render(ctx);
  glFinish();
  const auto pixels = target.readPixels();
  edges.release();
  renderer.release();

  QImage image(request.width, request.height, QImage::Format_RGBA8888);
  for (int y = 0; y < request.height; ++y)
    std::memcpy(image.scanLine(y), pixels.data() + std::size_t(y) * std::size_t(request.width) * 4,
                std::size_t(request.width) * 4);
  if (legend) {
    QPainter painter(&image);
    paintLegend(painter, image.rect(), colorMapOf(tf),
                {QString::fromStdString(view.quantity.displayName()),
                 QString("volume, %1").arg(view.location == FieldLocation::Node ? "per node" : "per cell"),
                 tf.minValue(), tf.maxValue(), view.range.nanCount});
  }
  return image;
}

}  // namespace volpost::app

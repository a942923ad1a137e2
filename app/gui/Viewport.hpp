// SPDX-License-Identifier: MIT
// The 3D view: an OpenGL 4.5 core QOpenGLWidget that draws the Scene and its legend and
// turns mouse input into camera moves (left: orbit, right/middle or shift+left: pan,
// wheel: zoom; Ctrl+left drags the clip plane). Whoever changes the scene calls update().
#pragma once

#include "../core/Scene.hpp"  // brings in epoxy before any Qt GL header

#include "host/render/OverlayRenderer.hpp"

#include <QOpenGLWidget>
#include <QPoint>

#include <optional>

namespace volpost::app {

class Viewport : public QOpenGLWidget {
  Q_OBJECT

 public:
  explicit Viewport(VolumeRendererFactory factory, QWidget* parent = nullptr);
  ~Viewport() override;

  Scene& scene() { return scene_; }
  const Scene& scene() const { return scene_; }

  void fit();
  void setStandardView(StandardView view);
  void setProjection(Camera::Projection projection);
  /// Moves the first free clip plane along its normal (model units); Ctrl+drag does this.
  void moveClipPlane(double distance);

  /// Rake mode: a left drag draws a line in the plane through the view's target, facing the
  /// viewer; on release rakePlaced() gives its ends (model coordinates). Off after one rake.
  void setRakeMode(bool on);
  bool rakeMode() const { return rakeMode_; }
  /// The point of that plane under a pixel of the widget.
  glm::dvec3 pointInTargetPlane(const QPointF& pixel) const;

  VolumeStats volumeStats() const { return scene_.volumeStats(); }
  /// Tets on the GPU (fewer than the model's when a clip box culls them).
  std::size_t uploadedTetCount() const { return volumeStats().tetrahedra; }

 signals:
  void glInfo(const QString& description);
  void renderFailed(const QString& message);
  void rakePlaced(glm::dvec3 from, glm::dvec3 to);

 protected:
  void initializeGL() override;
  void paintGL() override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void wheelEvent(QWheelEvent* event) override;
  void keyPressEvent(QKeyEvent* event) override;

 private:
  void cleanupGL();
  void drawLegend(int width, int height);

  Scene scene_;
  OverlayRenderer overlay_;
  bool overlayReady_ = false;
  QPoint lastMouse_;
  bool rakeMode_ = false;
  std::optional<QPointF> rakeStart_, rakeEnd_;  ///< the rake being drawn, widget pixels
};

}  // namespace volpost::app

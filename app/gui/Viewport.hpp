// SPDX-License-Identifier: MIT
// The 3D view: an OpenGL 4.5 core QOpenGLWidget that draws the scene and the legend and
// turns mouse input into camera moves (left: orbit, right/middle or shift+left: pan,
// wheel: zoom).
#pragma once

#include "../core/Legend.hpp"
#include "../core/SceneRenderer.hpp"  // brings in epoxy before any Qt GL header

#include <volpost/render/OverlayRenderer.hpp>

#include <QOpenGLWidget>
#include <QPoint>

#include <optional>

namespace volpost::app {

class Viewport : public QOpenGLWidget {
  Q_OBJECT

 public:
  explicit Viewport(QWidget* parent = nullptr);
  ~Viewport() override;

  void setSession(std::shared_ptr<const ModelSession> session);
  /// The values to color by (nullopt: plain surface) and the range mapped onto the colors.
  void setScalars(std::optional<ScalarView> view, DisplayRange range);
  void setColorMap(const ColorMap& map);
  void setShowEdges(bool show);
  void setShowLegend(bool show);

  void fit();
  void setStandardView(StandardView view);
  void setProjection(Camera::Projection projection);
  const Camera& camera() const { return camera_; }

 signals:
  void glInfo(const QString& description);
  void renderFailed(const QString& message);

 protected:
  void initializeGL() override;
  void paintGL() override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void wheelEvent(QWheelEvent* event) override;

 private:
  void cleanupGL();
  template <typename F>
  void withContext(F&& f);

  void drawLegend(int width, int height);

  SceneRenderer scene_;
  OverlayRenderer overlay_;
  std::shared_ptr<const ModelSession> session_;
  std::optional<ScalarView> view_;
  DisplayRange range_;
  ColorMap colorMap_ = ColorMap::named("cool-warm");
  Camera camera_;
  bool showLegend_ = true;
  QPoint lastMouse_;
};

}  // namespace volpost::app

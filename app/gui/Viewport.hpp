// SPDX-License-Identifier: MIT
// The 3D view: an OpenGL 4.5 core QOpenGLWidget that draws the scene and the legend and
// turns mouse input into camera moves (left: orbit, right/middle or shift+left: pan,
// wheel: zoom).
#pragma once

#include "../core/Legend.hpp"
#include "../core/SceneRenderer.hpp"  // brings in epoxy before any Qt GL header

#include <volpost/core/ClipCulling.hpp>
#include <volpost/render/OffscreenTarget.hpp>
#include <volpost/render/OverlayRenderer.hpp>
#include <volpost/render/VolumeRenderer.hpp>

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

  /// The GPU volume renderer (from a plugin); the viewport owns it. nullptr: none.
  void setVolumeRenderer(std::unique_ptr<VolumeRenderer> renderer);
  bool hasVolumeRenderer() const { return volume_ != nullptr; }
  /// Draws the volume of the current view's values with this transfer function instead of
  /// the surface. Throws std::invalid_argument (mesh not made of tetrahedra) and leaves
  /// the surface on.
  void showVolume(const TransferFunction& tf);
  /// A new transfer function for the volume (the mesh is not re-uploaded).
  void setTransferFunction(const TransferFunction& tf);
  const TransferFunction& transferFunction() const { return tf_; }
  void showSurface();
  bool volumeShown() const { return volumeShown_; }
  void setIntegrationMode(IntegrationMode mode);
  /// One clip plane through the model center along `axis` (0, 1, 2), or none (-1).
  void setClipAxis(int axis);
  const std::optional<ClipPlane>& clipPlane() const { return clip_; }
  /// A clip box (six planes, kept inside), with or without the dragged plane; empty: none.
  void setClipBox(std::vector<ClipPlane> planes);
  const std::vector<ClipPlane>& clipBox() const { return clipBox_; }
  /// Iso-surfaces drawn with the volume (up to 8).
  void setIsoSurfaces(std::vector<optics::IsoSurface> surfaces);
  const std::vector<optics::IsoSurface>& isoSurfaces() const { return isoSurfaces_; }
  /// Moves the clip plane along its normal (model units); Ctrl+drag does the same.
  void moveClipPlane(double distance);
  VolumeStats volumeStats() const { return volume_ ? volume_->stats() : VolumeStats{}; }
  /// Tets on the GPU (fewer than the model's when a clip box culls them).
  std::size_t uploadedTetCount() const { return volumeStats().tetrahedra; }

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
  void uploadVolume();

  SceneRenderer scene_;
  OverlayRenderer overlay_;
  std::shared_ptr<const ModelSession> session_;
  std::optional<ScalarView> view_;
  DisplayRange range_;
  ColorMap colorMap_ = ColorMap::named("cool-warm");
  Camera camera_;
  bool showLegend_ = true;
  void renderVolume(const RenderContext& ctx);

  std::unique_ptr<VolumeRenderer> volume_;
  std::unique_ptr<OffscreenTarget> depthTarget_;  ///< depth of the edges drawn over a volume
  bool volumeShown_ = false, volumeInitialized_ = false, volumeDirty_ = false, tfDirty_ = false;
  TransferFunction tf_;
  IntegrationMode mode_ = IntegrationMode::LinearSegments;
  std::optional<ClipPlane> clip_;
  std::vector<ClipPlane> clipBox_;
  std::vector<ClipPlane> uploadedBox_;     ///< the box the uploaded (culled) mesh was made for
  std::optional<CulledMesh> culled_;
  std::vector<optics::IsoSurface> isoSurfaces_;
  const Model* uploadedModel_ = nullptr;  ///< the mesh the volume renderer holds
  FieldLocation uploadedLocation_ = FieldLocation::Node;
  QPoint lastMouse_;
};

}  // namespace volpost::app

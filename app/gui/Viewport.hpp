// SPDX-License-Identifier: MIT
// The 3D view: an OpenGL 4.5 core QOpenGLWidget that draws the Scene and its legend and
// turns mouse input into camera moves (left: orbit, right/middle or shift+left: pan,
// wheel: zoom; Ctrl+left drags the clip plane). With a clip plane, its widget is shown:
// dragging the handle's knob turns the plane, dragging the shaft slides it; with a clip
// box, a knob on each face moves that face (applied on release). Whoever
// changes the scene calls update().
#pragma once

#include "../core/BoxSelection.hpp"
#include "../core/BoxWidget.hpp"
#include "../core/FrameTimes.hpp"
#include "../core/PlaneWidget.hpp"
#include "../core/SceneDrawing.hpp"  // brings in epoxy before any Qt GL header

#include "host/render/OverlayRenderer.hpp"

#include <QElapsedTimer>
#include <QOpenGLWidget>
#include <QPoint>

class QFile;
class QLabel;
class QTimer;

#include <memory>
#include <optional>
#include <vector>

namespace volpost::app {

class Viewport : public QOpenGLWidget {
  Q_OBJECT

 public:
  explicit Viewport(VolumeRendererFactory factory, QWidget* parent = nullptr);
  ~Viewport() override;

  Scene& scene() { return scene_; }
  const Scene& scene() const { return scene_; }
  /// What draws the scene in this widget's context, and what it last drew.
  const SceneDrawing& drawing() const { return drawing_; }

  void fit();
  void setStandardView(StandardView view);
  void setProjection(Camera::Projection projection);
  /// A left drag turns the model like a turntable (about the world axis nearest the
  /// screen's up when the drag starts: the model stays upright), or with trackball on
  /// about the screen's axes (free, can roll).
  void setTrackball(bool on) { trackball_ = on; }
  bool trackball() const { return trackball_; }
  /// Moves the first free clip plane along its normal (model units); Ctrl+drag does this.
  void moveClipPlane(double distance);

  /// Rake mode: a left drag draws a line in the plane through the view's target, facing the
  /// viewer; on release rakePlaced() gives its 20 seeds, each halfway through the model under its
  /// point of the dragged line (so a rake across holes or a thin part still seeds it). Off after one rake.
  void setRakeMode(bool on);
  bool rakeMode() const { return rakeMode_; }
  /// The point of that plane under a pixel of the widget.
  glm::dvec3 pointInTargetPlane(const QPointF& pixel) const;
  std::optional<glm::dvec3> rakePointAt(const QPointF& pixel) const;

  /// Select mode: a left drag draws a box and on release boxSelected() gives it (a click: the
  /// pixel under it); Ctrl or Shift held adds to the selection. The right button still pans
  /// and the wheel zooms. Stays on until set off; Escape sets it off (selectModeLeft()).
  void setSelectMode(bool on);
  bool selectMode() const { return selectMode_; }

  /// Probe mode: a left click (no drag) on the model emits picked() with the surface point
  /// under it; resting the mouse emits hovered(). Drags still orbit.
  void setProbeMode(bool on);
  bool probeMode() const { return probeMode_; }
  /// The model's surface point under a pixel of the widget, if any.
  std::optional<glm::dvec3> surfacePointAt(const QPointF& pixel) const;

  VolumeStats volumeStats() const { return drawing_.volumeStats(); }
  /// The scene as a picture of its own size (any, not the widget's), drawn in full in this
  /// widget's context as `volpost render` draws it: no handles, the words sized for the
  /// picture times `textScale`, the background transparent on request. Throws
  /// std::exception with a message (a renderer error, no GL context yet).
  QImage renderPicture(int width, int height, double textScale, bool transparent);
  /// The picture shown is a quick one while the full one is computed (as last painted).
  bool isRefining() const { return refining_; }
  /// Frames painted so far: a picture taken after a change waits for one more.
  std::size_t paintedFrames() const { return paintedFrames_; }
  /// Tets on the GPU (fewer than the model's when a clip box culls them).
  std::size_t uploadedTetCount() const { return volumeStats().tetrahedra; }

  /// View > Show Frame Rate: a readout at the view's top right of how long the frames that
  /// answer the mouse take, how many follow a drag each second, and how long the full picture
  /// takes after the last change (FrameTimes). Off by default.
  void setShowFrameRate(bool on);
  bool showsFrameRate() const { return frameRateLabel_ != nullptr; }
  /// Appends one line per timed frame to `path` ("12.345 s  frame 38 ms after input, quick"),
  /// empty: stops. Throws std::runtime_error naming the file when it cannot be written.
  void setFrameLog(const QString& path);
  QString frameLogPath() const;
  FrameTimes::Summary frameTimes() const { return frameTimes_.summary(); }

 signals:
  void glInfo(const QString& description);
  /// The picture shown is a quick one; the renderer is computing the full one (or is done).
  void refining(bool on);
  /// What the refinement under way is, for the status bar ("Refining the cells' field: 40%").
  void refiningMessage(const QString& message);
  void renderFailed(const QString& message);
  /// The seeds of a rake dragged across the view (model coordinates, in order).
  void rakePlaced(std::vector<glm::dvec3> seeds);
  void picked(glm::dvec3 point);
  /// A box dragged (or a pixel clicked) in select mode, in the widget's pixels; `add`: to
  /// the selection, not in its place.
  void boxSelected(volpost::app::PictureBox box, bool add);
  /// Escape left select mode.
  void selectModeLeft();
  /// The mouse rests over the model at `point` (hit) or off it (not hit).
  void hovered(QPoint globalPosition, bool hit, glm::dvec3 point);
  /// The plane widget moved the first clip plane (during the drag, each move).
  void clipPlaneDragged(const volpost::ClipPlane& plane);
  /// A face of the clip box was dragged and let go: the box to apply.
  void clipBoxDragged(const volpost::app::ClipBox& box);

 protected:
  void initializeGL() override;
  void paintGL() override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void leaveEvent(QEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void wheelEvent(QWheelEvent* event) override;
  void keyPressEvent(QKeyEvent* event) override;

 private:
  void cleanupGL();
  void drawLegend(int width, int height);
  void dragPlaneWidget(const QPointF& at);
  /// The camera or a plane moved by the user's hand: timed (FrameTimes), then drawn.
  void viewChangedByInput();
  void framePresented();
  double clockMs() const { return double(clock_.nsecsElapsed()) * 1e-6; }

  Scene scene_;
  SceneDrawing drawing_;
  OverlayRenderer overlay_;
  bool overlayReady_ = false;
  bool refining_ = false;  ///< last said by refining()
  QString refiningMessage_;  ///< last said by refiningMessage()
  std::size_t paintedFrames_ = 0;
  QPoint lastMouse_;
  bool rakeMode_ = false;
  bool trackball_ = false;
  glm::dvec3 dragUp_{0.0, 0.0, 1.0};  ///< the turntable's axis for the drag in progress
  std::optional<QPointF> rakeStart_, rakeEnd_;  ///< the rake being drawn, widget pixels
  bool probeMode_ = false;
  bool selectMode_ = false;
  std::optional<QPointF> selectStart_, selectEnd_;  ///< the box being dragged, widget pixels
  std::optional<QPointF> pressedAt_;  ///< where the left button went down (a click or a drag)
  QTimer* hoverTimer_ = nullptr;       ///< hover picks wait for the mouse to rest
  QElapsedTimer wheelTurning_;         ///< since the wheel last turned
  QPoint hoverAt_;
  PlaneWidgetPart planeDrag_ = PlaneWidgetPart::None;  ///< the widget part held by the left button
  std::size_t planeDragIndex_ = 0;                     ///< of the clip plane whose handle it is
  QPointF planeDragLast_;
  std::optional<int> boxDragFace_;  ///< the clip box's face held by the left button
  ClipBox boxDragged_{};            ///< where the drag has taken the box (applied on release)
  QElapsedTimer clock_;             ///< the frame timing's clock
  FrameTimes frameTimes_;
  QLabel* frameRateLabel_ = nullptr;  ///< the readout, while shown
  std::unique_ptr<QFile> frameLog_;
};

}  // namespace volpost::app

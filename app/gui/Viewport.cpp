// SPDX-License-Identifier: MIT
#include "Viewport.hpp"

#include "core/SceneImage.hpp"
#include "core/SceneOverlay.hpp"
#include "core/ScenePick.hpp"

#include <QFile>
#include <QImage>
#include <QKeyEvent>
#include <QLabel>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QPainter>
#include <QPen>
#include <QTimer>
#include <QWheelEvent>

#include <glm/gtc/matrix_inverse.hpp>

#include <cmath>

namespace volpost::app {

Viewport::Viewport(VolumeRendererFactory factory, QWidget* parent) : QOpenGLWidget(parent), scene_(std::move(factory)) {
  setMinimumSize(200, 150);
  setFocusPolicy(Qt::StrongFocus);
  drawing_.setAsynchronousUpdates(true);  // transfer-function drags never block the window
  clock_.start();
  // Presented, not only drawn: what the user sees is timed.
  connect(this, &QOpenGLWidget::frameSwapped, this, &Viewport::framePresented);
}

Viewport::~Viewport() { cleanupGL(); }

void Viewport::viewChangedByInput() {
  frameTimes_.inputAt(clockMs());
  update();
}

void Viewport::framePresented() {
  frameTimes_.paintedAt(clockMs(), refining_);
  if (frameRateLabel_) {
    frameRateLabel_->setText(QString::fromStdString(FrameTimes::text(frameTimes_.summary())));
    frameRateLabel_->adjustSize();
    frameRateLabel_->move(width() - frameRateLabel_->width() - 8, 8);
  }
}

void Viewport::setShowFrameRate(bool on) {
  if (on == showsFrameRate()) return;
  if (!on) {
    delete frameRateLabel_;
    frameRateLabel_ = nullptr;
    return;
  }
  frameTimes_.reset();  // what is shown is measured from now
  frameRateLabel_ = new QLabel(this);
  frameRateLabel_->setObjectName("frameRate");
  frameRateLabel_->setAttribute(Qt::WA_TransparentForMouseEvents);
  frameRateLabel_->setStyleSheet("QLabel { background: rgba(255, 255, 255, 200); color: black; padding: 2px 5px; }");
  frameRateLabel_->setText(QString::fromStdString(FrameTimes::text(frameTimes_.summary())));
  frameRateLabel_->adjustSize();
  frameRateLabel_->move(width() - frameRateLabel_->width() - 8, 8);
  frameRateLabel_->show();
}

void Viewport::setFrameLog(const QString& path) {
  if (path.isEmpty()) {
    frameLog_.reset();
    frameTimes_.setLog({});
    return;
  }
  auto file = std::make_unique<QFile>(path);
  if (!file->open(QIODevice::WriteOnly | QIODevice::Append | QIODevice::Text))
    throw std::runtime_error(path.toStdString() + ": cannot be written (" + file->errorString().toStdString() + ")");
  frameLog_ = std::move(file);
  frameTimes_.setLog([this](const std::string& line) {
    if (!frameLog_) return;
    const QString stamped = QString("%1 s  %2\n").arg(clockMs() / 1000.0, 0, 'f', 3).arg(QString::fromStdString(line));
    frameLog_->write(stamped.toUtf8());
    frameLog_->flush();  // readable while the window runs
  });
}

QString Viewport::frameLogPath() const { return frameLog_ ? frameLog_->fileName() : QString(); }

void Viewport::initializeGL() {
  // GL objects die with the context, which can go before the widget (reparenting).
  connect(context(), &QOpenGLContext::aboutToBeDestroyed, this, &Viewport::cleanupGL, Qt::UniqueConnection);
  try {
    drawing_.initialize();
    overlay_.initialize();
    overlayReady_ = true;
    emit glInfo(QString::fromStdString(gl::describeContext()));
  } catch (const std::exception& e) {
    emit renderFailed(QString("OpenGL 4.5 initialisation failed: %1").arg(e.what()));
  }
}

void Viewport::cleanupGL() {
  if (!drawing_.initialized() && !overlayReady_) return;
  makeCurrent();
  drawing_.release();
  if (overlayReady_) overlay_.release();
  overlayReady_ = false;
  doneCurrent();
}

void Viewport::fit() {
  scene_.rememberView();
  scene_.fitCamera();
  update();
}

void Viewport::setStandardView(StandardView view) {
  scene_.rememberView();
  scene_.camera().setView(view);
  scene_.fitCamera();
  update();
}

void Viewport::setProjection(Camera::Projection projection) {
  scene_.camera().setProjection(projection);
  update();
}

void Viewport::moveClipPlane(double distance) {
  std::vector<ClipPlane> planes = scene_.volume().clipPlanes;
  if (planes.empty()) return;
  planes.front().point += glm::normalize(planes.front().normal) * distance;
  scene_.setClipPlanes(planes);
  viewChangedByInput();
}

void Viewport::dragPlaneWidget(const QPointF& at) {
  std::vector<ClipPlane> planes = scene_.volume().clipPlanes;
  if (planeDragIndex_ >= planes.size() || !scene_.session()) return;
  ClipPlane& plane = planes[planeDragIndex_];  // the plane whose handle was taken
  const PlaneWidget widget = planeWidget(plane, scene_.session()->bounds());
  const Camera camera = scene_.pictureCamera(width(), height());
  const glm::dvec2 to(at.x(), at.y()), from(planeDragLast_.x(), planeDragLast_.y());
  plane = planeDrag_ == PlaneWidgetPart::Knob ? turnedPlane(plane, widget, camera, width(), height(), to)
                                              : slidPlane(plane, widget, camera, width(), height(), from, to);
  planeDragLast_ = at;
  scene_.setClipPlanes(planes);
  emit clipPlaneDragged(plane);
  viewChangedByInput();
}

void Viewport::paintGL() {
  if (!drawing_.initialized()) return;
  const qreal dpr = devicePixelRatioF();
  RenderContext ctx;
  ctx.width = int(std::lround(width() * dpr));
  ctx.height = int(std::lround(height() * dpr));
  ctx.framebuffer = defaultFramebufferObject();
  scene_.setDevicePixelRatio(dpr);
  try {
    drawing_.render(scene_, ctx);
  } catch (const std::exception& e) {
    scene_.setVolumeShown(false);  // back to the surface, which draws
    emit renderFailed(e.what());
    return;
  }
  // A table or a full frame still computed on worker threads: draw again when it may be there.
  const bool pending = drawing_.hasPendingWork();
  if (pending) QTimer::singleShot(30, this, [this] { update(); });
  const std::optional<double> refined = drawing_.volumeRefinement();
  const QString message = refined ? QString("Refining the cells' own field: %1%...").arg(int(*refined * 100.0))
                                  : QString("Refining the picture...");
  if (pending && message != refiningMessage_) emit refiningMessage(refiningMessage_ = message);
  if (pending != refining_) emit refining(refining_ = pending);
  if (overlayReady_) drawLegend(ctx.width, ctx.height);
  ++paintedFrames_;
}

QImage Viewport::renderPicture(int width, int height, double textScale, bool transparent) {
  if (!drawing_.initialized()) throw std::runtime_error("the view has no OpenGL context yet");
  // What the window shows that a picture does not: restored whatever happens.
  struct Restore {
    Scene& scene;
    double ratio, textScale;
    Scene::Handles handles;
    ~Restore() {
      scene.setDevicePixelRatio(ratio);
      scene.setTextScale(textScale);
      scene.setHandles(handles);
    }
  } restore{scene_, scene_.devicePixelRatio(), scene_.shown().textScale, scene_.handles()};
  scene_.setDevicePixelRatio(1.0);
  scene_.setTextScale(textScale);  // throws outside its range, nothing changed yet
  scene_.setHandles({});
  makeCurrent();
  struct Done {
    Viewport& v;
    ~Done() { v.doneCurrent(); }
  } done{*this};
  const auto draw = [&] { return drawSceneImage(scene_, width, height, !transparent); };
  return transparent ? renderTransparent(scene_, draw).picture : draw().picture;
}

// The legend is painted on the CPU (same code as the headless picture) and drawn as a
// texture: no QPainter on the GL context, so the core-profile state stays ours.
void Viewport::drawLegend(int w, int h) {
  const bool rake = rakeMode_ && rakeStart_ && rakeEnd_;
  const bool selecting = selectMode_ && selectStart_ && selectEnd_;
  if (!scene_.legend() && !rake && !selecting && scene_.probes().empty() && !scene_.marksExtremes() &&
      !scene_.showsTriad() && !scene_.showsPlaneWidget() && !scene_.showsBoxWidget() && !scene_.plotLine() &&
      !scene_.showsRakes() && scene_.setVisibility().marked.empty() && !scene_.highlight())
    return;
  QImage image(w, h, QImage::Format_RGBA8888_Premultiplied);
  image.setDevicePixelRatio(devicePixelRatioF());
  image.fill(Qt::transparent);
  {
    QPainter painter(&image);
    paintSceneOverlay(painter, rect(), scene_);
    if (rake) {  // the rake being placed: a line with its seed ends
      painter.setRenderHint(QPainter::Antialiasing);
      painter.setPen(QPen(QColor(230, 120, 20), 2.0));
      painter.drawLine(*rakeStart_, *rakeEnd_);
      painter.setBrush(QColor(230, 120, 20));
      painter.drawEllipse(*rakeStart_, 4.0, 4.0);
      painter.drawEllipse(*rakeEnd_, 4.0, 4.0);
    }
    if (selecting) {  // the box being dragged: a dashed frame over a light veil
      painter.setPen(QPen(QColor(255, 200, 40), 1.5, Qt::DashLine));
      painter.setBrush(QColor(255, 200, 40, 40));
      painter.drawRect(QRectF(*selectStart_, *selectEnd_).normalized());
    }
  }
  overlay_.setImage(w, h, {image.constBits(), std::size_t(image.sizeInBytes())});
  glBindFramebuffer(GL_FRAMEBUFFER, defaultFramebufferObject());
  glViewport(0, 0, w, h);
  overlay_.render();
}

void Viewport::setSelectMode(bool on) {
  selectMode_ = on;
  selectStart_.reset();
  selectEnd_.reset();
  if (on && rakeMode_) setRakeMode(false);
  setCursor(on ? Qt::CrossCursor : probeMode_ ? Qt::PointingHandCursor : Qt::ArrowCursor);
  update();
}

void Viewport::setRakeMode(bool on) {
  rakeMode_ = on;
  rakeStart_.reset();
  rakeEnd_.reset();
  setCursor(on ? Qt::CrossCursor : probeMode_ ? Qt::PointingHandCursor : Qt::ArrowCursor);
  update();
}

glm::dvec3 Viewport::pointInTargetPlane(const QPointF& pixel) const {
  const Camera camera = scene_.pictureCamera(width(), height());
  const double aspect = height() > 0 ? double(width()) / double(height()) : 1.0;
  const glm::dmat4 toModel = glm::inverse(camera.projectionMatrix(aspect) * camera.viewMatrix());
  const double x = 2.0 * pixel.x() / width() - 1.0, y = 1.0 - 2.0 * pixel.y() / height();
  const glm::dvec4 n = toModel * glm::dvec4(x, y, -1.0, 1.0), f = toModel * glm::dvec4(x, y, 1.0, 1.0);
  const glm::dvec3 a = glm::dvec3(n) / n.w, b = glm::dvec3(f) / f.w;
  const glm::dvec3 normal = camera.viewDirection();
  const double t = glm::dot(camera.target() - a, normal) / glm::dot(b - a, normal);
  return a + t * (b - a);
}

// A rake's seed under a pixel: halfway through the model where the pixel's ray first crosses
// it (a thin part seen face on gets its seeds inside it, not in a plane through the view's
// centre that misses it between spokes or holes); nullopt off the model.
std::optional<glm::dvec3> Viewport::rakePointAt(const QPointF& pixel) const {
  if (!scene_.session()) return std::nullopt;
  const PickRay ray = pixelRay(scene_.pictureCamera(width(), height()), pixel.x(), pixel.y(), width(), height());
  const auto entry = pickSurface(*scene_.session(), ray);
  if (!entry) return std::nullopt;
  const double slack = 1e-9 * std::max(scene_.session()->bounds().diagonal(), 1e-300);
  const auto exit = pickSurface(*scene_.session(), ray, [&](const glm::dvec3& p) {
    return glm::dot(p - ray.origin, ray.direction) > entry->distance + slack;
  });
  return exit ? 0.5 * (entry->point + exit->point) : entry->point;
}

void Viewport::setProbeMode(bool on) {
  probeMode_ = on;
  setMouseTracking(on);
  setCursor(on ? Qt::PointingHandCursor : Qt::ArrowCursor);
  if (!on && hoverTimer_) hoverTimer_->stop();
}

std::optional<glm::dvec3> Viewport::surfacePointAt(const QPointF& pixel) const {
  if (!scene_.session()) return std::nullopt;
  return pickScenePoint(scene_,
                        pixelRay(scene_.pictureCamera(width(), height()), pixel.x(), pixel.y(), width(), height()),
                        drawing_.isoSurfaceCorners(), drawing_.curvedBoundaryCorners());
}

void Viewport::mousePressEvent(QMouseEvent* event) {
  lastMouse_ = event->position().toPoint();
  if (event->button() == Qt::LeftButton) pressedAt_ = event->position();
  // The turntable turns about the world axis closest to the screen's up, signed.
  const glm::dvec3 up = scene_.camera().up();
  int axis = 0;
  for (int k = 1; k < 3; ++k)
    if (std::abs(up[k]) > std::abs(up[axis])) axis = k;
  dragUp_ = glm::dvec3(0.0);
  dragUp_[axis] = up[axis] < 0.0 ? -1.0 : 1.0;
  scene_.rememberView();  // View > Previous View comes back here (a click that moves nothing adds nothing)
  if (selectMode_ && event->button() == Qt::LeftButton) {
    selectStart_ = selectEnd_ = event->position();
    update();
    return;
  }
  if (rakeMode_ && event->button() == Qt::LeftButton) {
    rakeStart_ = rakeEnd_ = event->position();
    update();
    return;
  }
  planeDrag_ = PlaneWidgetPart::None;
  // The widget takes the drag where it is hit; Ctrl+drag keeps sliding the plane from anywhere.
  if (event->button() == Qt::LeftButton && scene_.showsPlaneWidget() && !(event->modifiers() & Qt::ControlModifier)) {
    // Each free plane has a handle: the first one hit takes the drag.
    const Camera camera = scene_.pictureCamera(width(), height());
    const std::vector<ClipPlane>& planes = scene_.volume().clipPlanes;
    for (std::size_t i = 0; i < planes.size() && planeDrag_ == PlaneWidgetPart::None; ++i) {
      const PlaneWidget widget = planeWidget(planes[i], scene_.session()->bounds());
      planeDrag_ =
          hitPlaneWidget(widget, camera, width(), height(), {event->position().x(), event->position().y()}, 6.0);
      planeDragIndex_ = i;
    }
    planeDragLast_ = event->position();
  }
  boxDragFace_.reset();
  if (event->button() == Qt::LeftButton && planeDrag_ == PlaneWidgetPart::None && scene_.showsBoxWidget() &&
      !(event->modifiers() & Qt::ControlModifier)) {
    boxDragged_ = *scene_.shownClipBox();
    const Camera camera = scene_.pictureCamera(width(), height());
    boxDragFace_ = hitBoxWidget(boxWidget(boxDragged_), camera, width(), height(),
                                {event->position().x(), event->position().y()}, 7.0);
    planeDragLast_ = event->position();
  }
}

void Viewport::mouseReleaseEvent(QMouseEvent* event) {
  if (selectMode_ && selectStart_ && event->button() == Qt::LeftButton) {
    const QPointF a = *selectStart_, b = event->position();
    selectStart_.reset();
    selectEnd_.reset();
    pressedAt_.reset();
    update();
    const bool add = event->modifiers() & (Qt::ControlModifier | Qt::ShiftModifier);
    if ((b - a).manhattanLength() < 4.0)  // a click: the pixel under it
      emit boxSelected(PictureBox{b.x(), b.y(), b.x(), b.y()}, add);
    else emit boxSelected(PictureBox{a.x(), a.y(), b.x(), b.y()}, add);
    return;
  }
  const bool click = event->button() == Qt::LeftButton && pressedAt_ &&
                     (event->position() - *pressedAt_).manhattanLength() < 4.0;
  if (event->button() == Qt::LeftButton && boxDragFace_) {
    boxDragFace_.reset();
    if (!click) {
      pressedAt_.reset();
      scene_.setClipBoxPreview(std::nullopt);
      emit clipBoxDragged(boxDragged_);
      update();
      return;  // the end of a box drag, not a pick
    }
  }
  if (event->button() == Qt::LeftButton && planeDrag_ != PlaneWidgetPart::None) {
    planeDrag_ = PlaneWidgetPart::None;
    if (!click) {
      pressedAt_.reset();
      return;  // the end of a widget drag, not a pick
    }
  }
  if (event->button() == Qt::LeftButton) pressedAt_.reset();
  if (probeMode_ && click && !rakeMode_ && !(event->modifiers() & Qt::ControlModifier)) {
    if (const auto p = surfacePointAt(event->position())) emit picked(*p);
    return;
  }
  if (!rakeMode_ || !rakeStart_ || event->button() != Qt::LeftButton) return;
  const QPointF a = *rakeStart_, b = event->position();
  setRakeMode(false);
  if ((b - a).manhattanLength() < 4.0) return;  // a click, not a rake
  // 20 seeds along the dragged line, each placed through the model under it; pixels off the
  // model give none. Off the model altogether: the line in the plane through the view's centre.
  constexpr int kSeeds = 20;
  std::vector<glm::dvec3> seeds;
  for (int i = 0; i < kSeeds; ++i)
    if (const auto p = rakePointAt(a + (b - a) * (double(i) / (kSeeds - 1)))) seeds.push_back(*p);
  if (seeds.empty())
    for (int i = 0; i < kSeeds; ++i) seeds.push_back(pointInTargetPlane(a + (b - a) * (double(i) / (kSeeds - 1))));
  emit rakePlaced(seeds);
}

// Escape leaves rake placement without seeds (the lines shown stay as they were).
void Viewport::keyPressEvent(QKeyEvent* event) {
  if (rakeMode_ && event->key() == Qt::Key_Escape) {
    setRakeMode(false);
    return;
  }
  if (selectMode_ && event->key() == Qt::Key_Escape) {
    setSelectMode(false);
    emit selectModeLeft();
    return;
  }
  QOpenGLWidget::keyPressEvent(event);
}

// The mouse left the view: nothing is under it (the hover's tooltip and outline go).
void Viewport::leaveEvent(QEvent* event) {
  if (hoverTimer_) {
    hoverTimer_->stop();
    emit hovered(QPoint(), false, glm::dvec3(0.0));
  }
  QOpenGLWidget::leaveEvent(event);
}

void Viewport::mouseMoveEvent(QMouseEvent* event) {
  if (probeMode_ && event->buttons() == Qt::NoButton) {  // hovering: pick when the mouse rests
    hoverAt_ = event->position().toPoint();
    if (!hoverTimer_) {
      hoverTimer_ = new QTimer(this);
      hoverTimer_->setSingleShot(true);
      connect(hoverTimer_, &QTimer::timeout, this, [this] {
        if (!probeMode_ || !underMouse()) return;
        const auto p = surfacePointAt(hoverAt_);
        emit hovered(mapToGlobal(hoverAt_), p.has_value(), p.value_or(glm::dvec3(0.0)));
      });
    }
    hoverTimer_->start(120);
    return;
  }
  if (selectMode_ && selectStart_ && (event->buttons() & Qt::LeftButton)) {
    selectEnd_ = event->position();
    update();
    return;
  }
  if (rakeMode_ && rakeStart_) {
    rakeEnd_ = event->position();
    update();
    return;
  }
  if (planeDrag_ != PlaneWidgetPart::None && (event->buttons() & Qt::LeftButton)) {
    dragPlaneWidget(event->position());
    return;
  }
  if (boxDragFace_ && (event->buttons() & Qt::LeftButton)) {
    const Camera camera = scene_.pictureCamera(width(), height());
    boxDragged_ = draggedBox(boxDragged_, *boxDragFace_, camera, width(), height(),
                             {planeDragLast_.x(), planeDragLast_.y()}, {event->position().x(), event->position().y()});
    planeDragLast_ = event->position();
    scene_.setClipBoxPreview(boxDragged_);
    viewChangedByInput();
    return;
  }
  const QPoint p = event->position().toPoint();
  const QPoint d = p - lastMouse_;
  lastMouse_ = p;
  Camera& camera = scene_.camera();
  if ((event->buttons() & Qt::LeftButton) && (event->modifiers() & Qt::ControlModifier) &&
      !scene_.volume().clipPlanes.empty()) {
    moveClipPlane(-double(d.y()) / height() * camera.viewHeight());
    return;
  }
  const bool pan = (event->buttons() & (Qt::RightButton | Qt::MiddleButton)) ||
                   ((event->buttons() & Qt::LeftButton) && (event->modifiers() & Qt::ShiftModifier));
  if (pan) camera.pan(double(d.x()) / height(), -double(d.y()) / height());
  else if ((event->buttons() & Qt::LeftButton) && trackball_) camera.orbit(-0.4 * d.x(), -0.4 * d.y());
  else if (event->buttons() & Qt::LeftButton) camera.turntable(-0.4 * d.x(), -0.4 * d.y(), dragUp_);
  else return;
  viewChangedByInput();
}

void Viewport::wheelEvent(QWheelEvent* event) {
  // One turn of the wheel, however many steps, is one view to come back to.
  if (!wheelTurning_.isValid() || wheelTurning_.elapsed() > 800) scene_.rememberView();
  wheelTurning_.start();
  scene_.camera().zoom(std::pow(1.1, event->angleDelta().y() / 120.0));
  viewChangedByInput();
}

}  // namespace volpost::app

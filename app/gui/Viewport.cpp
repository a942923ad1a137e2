// SPDX-License-Identifier: MIT
#include "Viewport.hpp"

#include "../core/GpuVolumeImage.hpp"

#include <volpost/core/ClipCulling.hpp>

#include <QMouseEvent>
#include <QTimer>
#include <QOpenGLContext>
#include <QImage>
#include <QPainter>
#include <QWheelEvent>

#include <cmath>

namespace volpost::app {

Viewport::Viewport(QWidget* parent) : QOpenGLWidget(parent) {
  setMinimumSize(200, 150);
  setFocusPolicy(Qt::StrongFocus);
}

Viewport::~Viewport() { cleanupGL(); }

template <typename F>
void Viewport::withContext(F&& f) {
  if (!scene_.initialized()) return;  // applied in initializeGL
  makeCurrent();
  try {
    f();
  } catch (const std::exception& e) {
    emit renderFailed(e.what());
  }
  doneCurrent();
}

void Viewport::initializeGL() {
  // GL objects die with the context, which can go before the widget (reparenting).
  connect(context(), &QOpenGLContext::aboutToBeDestroyed, this, &Viewport::cleanupGL, Qt::UniqueConnection);
  try {
    scene_.initialize();
    overlay_.initialize();
    scene_.setSession(session_);
    scene_.setColorMap(colorMap_);
    scene_.setScalars(view_ ? &*view_ : nullptr, range_);
    if (volume_) {
      volume_->initialize();
      volumeInitialized_ = true;
      volumeDirty_ = true;
    }
    emit glInfo(QString::fromStdString(gl::describeContext()));
  } catch (const std::exception& e) {
    emit renderFailed(QString("OpenGL 4.5 initialisation failed: %1").arg(e.what()));
  }
}

void Viewport::cleanupGL() {
  if (!scene_.initialized()) return;
  makeCurrent();
  scene_.release();
  overlay_.release();
  if (volume_ && volumeInitialized_) volume_->release();
  volumeInitialized_ = false;
  uploadedModel_ = nullptr;
  depthTarget_.reset();
  doneCurrent();
}

void Viewport::setVolumeRenderer(std::unique_ptr<VolumeRenderer> renderer) {
  if (volume_ && volumeInitialized_) withContext([&] { volume_->release(); });  // GL objects die with their context current
  volumeInitialized_ = false;
  volume_ = std::move(renderer);
  uploadedModel_ = nullptr;  // the new renderer holds no mesh yet
  volumeDirty_ = true;
  if (volume_) volume_->setAsynchronousUpdates(true);  // TF drags never block the window
  if (volume_ && scene_.initialized()) {
    withContext([&] { volume_->initialize(); });
    volumeInitialized_ = true;
  }
  update();
}

void Viewport::showVolume(const TransferFunction& tf) {
  if (!volume_ || !session_ || !view_) throw std::invalid_argument("no volume renderer or no result to render");
  tf_ = tf;
  volumeShown_ = true;
  volumeDirty_ = true;
  update();
}

void Viewport::setTransferFunction(const TransferFunction& tf) {
  tf_ = tf;
  tfDirty_ = true;
  update();
}

void Viewport::showSurface() {
  volumeShown_ = false;
  update();
}

void Viewport::setIntegrationMode(IntegrationMode mode) {
  mode_ = mode;
  volumeDirty_ = true;
  update();
}

void Viewport::setClipAxis(int axis) {
  if (axis < 0 || !session_) {
    clip_.reset();
  } else {
    glm::dvec3 n(0.0);
    n[axis] = 1.0;
    clip_ = ClipPlane{session_->model().mesh.bounds().center(), n};
  }
  volumeDirty_ = true;
  update();
}

void Viewport::setClipBox(std::vector<ClipPlane> planes) {
  clipBox_ = std::move(planes);
  volumeDirty_ = true;
  update();
}

void Viewport::setIsoSurfaces(std::vector<optics::IsoSurface> surfaces) {
  isoSurfaces_ = std::move(surfaces);
  volumeDirty_ = true;
  update();
}

void Viewport::moveClipPlane(double distance) {
  if (!clip_) return;
  clip_->point += glm::normalize(clip_->normal) * distance;
  volumeDirty_ = true;
  update();
}

// Uploads what changed since the last frame; the mesh only when the data did.
void Viewport::uploadVolume() {
  if ((!volumeDirty_ && !tfDirty_) || !volume_ || !view_ || !session_) return;
  if (volumeDirty_) {
    const std::vector<double> values = session_->tetValues(*view_);  // on the conforming tetrahedra
    const bool sameGeometry = uploadedModel_ == &session_->model() && uploadedLocation_ == view_->location &&
                              uploadedBox_ == clipBox_;
    if (sameGeometry) {
      volume_->setValues(culled_ ? culled_->values(view_->location, values) : values);  // only the values travel
    } else if (clipBox_.empty()) {
      culled_.reset();
      volume_->setVolume(session_->tetrahedra().mesh, view_->location, values);
    } else {
      // A clip box is a region of interest: the GPU holds only what it can show. (A
      // dragged plane never rebuilds: the renderer cuts exactly at it.)
      culled_ = cullToClipPlanes(session_->tetrahedra().mesh, clipBox_);
      volume_->setVolume(culled_->mesh, view_->location, culled_->values(view_->location, values));
    }
    uploadedModel_ = &session_->model();
    uploadedLocation_ = view_->location;
    uploadedBox_ = clipBox_;
    volume_->setIntegrationMode(mode_);
    std::vector<ClipPlane> planes = clipBox_;
    if (clip_ && planes.size() < 6) planes.push_back(*clip_);
    volume_->setClipPlanes(planes);
    volume_->setIsoSurfaces(isoSurfaces_);
  }
  volume_->setTransferFunction(tf_);  // a TF edit alone ends here: tables only
  volumeDirty_ = tfDirty_ = false;
}

// The element edges stay visible over the volume and end its rays: they are drawn into
// the window and, depth only, into a texture the ray caster reads.
void Viewport::renderVolume(const RenderContext& ctx) {
  uploadVolume();
  // A table still building on a worker thread: draw again when it may be there.
  if (volume_->hasPendingWork()) QTimer::singleShot(30, this, [this] { update(); });
  scene_.setShowFaces(false);
  RenderContext volumeCtx = ctx;
  if (scene_.showEdges()) {
    if (!depthTarget_ || depthTarget_->width() != ctx.width || depthTarget_->height() != ctx.height)
      depthTarget_ = std::make_unique<OffscreenTarget>(ctx.width, ctx.height);
    RenderContext depthCtx = ctx;
    depthCtx.framebuffer = depthTarget_->framebuffer();
    scene_.render(depthCtx);
    volumeCtx.depthTexture = depthTarget_->depthTexture();
    scene_.render(ctx);
  } else {
    scene_.renderBackground(ctx);
  }
  scene_.setShowFaces(true);
  volume_->render(volumeCtx);
}

void Viewport::setSession(std::shared_ptr<const ModelSession> session) {
  session_ = std::move(session);
  view_.reset();
  volumeShown_ = false;
  clip_.reset();
  clipBox_.clear();
  isoSurfaces_.clear();
  uploadedModel_ = nullptr;
  withContext([&] { scene_.setSession(session_); });
  camera_.setView(StandardView::Isometric);
  fit();
}

void Viewport::setScalars(std::optional<ScalarView> view, DisplayRange range) {
  view_ = std::move(view);
  range_ = range;
  volumeDirty_ = true;
  if (!view_) volumeShown_ = false;
  withContext([&] { scene_.setScalars(view_ ? &*view_ : nullptr, range_); });
  update();
}

void Viewport::setColorMap(const ColorMap& map) {
  colorMap_ = map;
  withContext([&] { scene_.setColorMap(map); });
  update();
}

void Viewport::setShowEdges(bool show) {
  scene_.setShowEdges(show);
  update();
}

void Viewport::setShowLegend(bool show) {
  showLegend_ = show;
  update();
}

void Viewport::fit() {
  if (session_) camera_.fit(session_->model().mesh.bounds());
  update();
}

void Viewport::setStandardView(StandardView view) {
  camera_.setView(view);
  fit();
}

void Viewport::setProjection(Camera::Projection projection) {
  camera_.setProjection(projection);
  update();
}

void Viewport::paintGL() {
  if (!scene_.initialized()) return;
  const qreal dpr = devicePixelRatioF();
  RenderContext ctx;
  ctx.camera = camera_;
  ctx.width = int(std::lround(width() * dpr));
  ctx.height = int(std::lround(height() * dpr));
  ctx.framebuffer = defaultFramebufferObject();
  try {
    if (volumeShown_ && volume_ && volumeInitialized_) {
      renderVolume(ctx);
    } else {
      scene_.render(ctx);
    }
  } catch (const std::exception& e) {
    volumeShown_ = false;
    emit renderFailed(e.what());
    return;
  }
  if (showLegend_ && view_) drawLegend(ctx.width, ctx.height);
}

// The legend is painted on the CPU (same code as the PNG export) and drawn as a texture:
// no QPainter on the GL context, so the core-profile state stays ours.
void Viewport::drawLegend(int w, int h) {
  QImage image(w, h, QImage::Format_RGBA8888_Premultiplied);
  image.setDevicePixelRatio(devicePixelRatioF());
  image.fill(Qt::transparent);
  {
    QPainter painter(&image);
    const LegendContent legend{QString::fromStdString(view_->quantity.displayName()),
                               QString("%1%2").arg(QString::fromStdString(view_->stepLabel),
                                                   view_->location == FieldLocation::Node ? "  per node" : "  per cell"),
                               range_.min, range_.max, view_->range.nanCount};
    if (volumeShown_) {
      LegendContent v = legend;
      v.subtitle = "volume  " + v.subtitle.trimmed();
      v.min = tf_.minValue();
      v.max = tf_.maxValue();
      paintLegend(painter, rect(), colorMapOf(tf_), v);
    } else {
      paintLegend(painter, rect(), colorMap_, legend);
    }
  }
  overlay_.setImage(w, h, {image.constBits(), std::size_t(image.sizeInBytes())});
  glBindFramebuffer(GL_FRAMEBUFFER, defaultFramebufferObject());
  glViewport(0, 0, w, h);
  overlay_.render();
}

void Viewport::mousePressEvent(QMouseEvent* event) { lastMouse_ = event->position().toPoint(); }

void Viewport::mouseMoveEvent(QMouseEvent* event) {
  const QPoint p = event->position().toPoint();
  const QPoint d = p - lastMouse_;
  lastMouse_ = p;
  if ((event->buttons() & Qt::LeftButton) && (event->modifiers() & Qt::ControlModifier) && clip_) {
    moveClipPlane(-double(d.y()) / height() * camera_.viewHeight());
    return;
  }
  const bool pan = (event->buttons() & (Qt::RightButton | Qt::MiddleButton)) ||
                   ((event->buttons() & Qt::LeftButton) && (event->modifiers() & Qt::ShiftModifier));
  if (pan) camera_.pan(double(d.x()) / height(), -double(d.y()) / height());
  else if (event->buttons() & Qt::LeftButton) camera_.orbit(-0.4 * d.x(), -0.4 * d.y());
  else return;
  update();
}

void Viewport::wheelEvent(QWheelEvent* event) {
  camera_.zoom(std::pow(1.1, event->angleDelta().y() / 120.0));
  update();
}

}  // namespace volpost::app

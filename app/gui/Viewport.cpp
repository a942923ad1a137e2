// SPDX-License-Identifier: MIT
#include "Viewport.hpp"

#include <QMouseEvent>
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
  doneCurrent();
}

void Viewport::setSession(std::shared_ptr<const ModelSession> session) {
  session_ = std::move(session);
  view_.reset();
  withContext([&] { scene_.setSession(session_); });
  camera_.setView(StandardView::Isometric);
  fit();
}

void Viewport::setScalars(std::optional<ScalarView> view, DisplayRange range) {
  view_ = std::move(view);
  range_ = range;
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
    scene_.render(ctx);
  } catch (const std::exception& e) {
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
    paintLegend(painter, rect(), colorMap_, legend);
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

// SPDX-License-Identifier: MIT
#include "Viewport.hpp"

#include <QImage>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QPainter>
#include <QTimer>
#include <QWheelEvent>

#include <cmath>

namespace volpost::app {

Viewport::Viewport(VolumeRendererFactory factory, QWidget* parent) : QOpenGLWidget(parent), scene_(std::move(factory)) {
  setMinimumSize(200, 150);
  setFocusPolicy(Qt::StrongFocus);
  scene_.setInteractive(true);  // transfer-function drags never block the window
}

Viewport::~Viewport() { cleanupGL(); }

void Viewport::initializeGL() {
  // GL objects die with the context, which can go before the widget (reparenting).
  connect(context(), &QOpenGLContext::aboutToBeDestroyed, this, &Viewport::cleanupGL, Qt::UniqueConnection);
  try {
    scene_.initialize();
    overlay_.initialize();
    overlayReady_ = true;
    emit glInfo(QString::fromStdString(gl::describeContext()));
  } catch (const std::exception& e) {
    emit renderFailed(QString("OpenGL 4.5 initialisation failed: %1").arg(e.what()));
  }
}

void Viewport::cleanupGL() {
  if (!scene_.initialized() && !overlayReady_) return;
  makeCurrent();
  scene_.release();
  if (overlayReady_) overlay_.release();
  overlayReady_ = false;
  doneCurrent();
}

void Viewport::fit() {
  scene_.fitCamera();
  update();
}

void Viewport::setStandardView(StandardView view) {
  scene_.camera().setView(view);
  fit();
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
  update();
}

void Viewport::paintGL() {
  if (!scene_.initialized()) return;
  const qreal dpr = devicePixelRatioF();
  RenderContext ctx;
  ctx.width = int(std::lround(width() * dpr));
  ctx.height = int(std::lround(height() * dpr));
  ctx.framebuffer = defaultFramebufferObject();
  try {
    scene_.render(ctx);
  } catch (const std::exception& e) {
    scene_.setVolumeShown(false);  // back to the surface, which draws
    emit renderFailed(e.what());
    return;
  }
  // A table still building on a worker thread: draw again when it may be there.
  if (scene_.hasPendingWork()) QTimer::singleShot(30, this, [this] { update(); });
  if (overlayReady_) drawLegend(ctx.width, ctx.height);
}

// The legend is painted on the CPU (same code as the headless picture) and drawn as a
// texture: no QPainter on the GL context, so the core-profile state stays ours.
void Viewport::drawLegend(int w, int h) {
  const auto legend = scene_.legend();
  if (!legend) return;
  QImage image(w, h, QImage::Format_RGBA8888_Premultiplied);
  image.setDevicePixelRatio(devicePixelRatioF());
  image.fill(Qt::transparent);
  {
    QPainter painter(&image);
    paintLegend(painter, rect(), legend->colors, legend->content);
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
  Camera& camera = scene_.camera();
  if ((event->buttons() & Qt::LeftButton) && (event->modifiers() & Qt::ControlModifier) &&
      !scene_.volume().clipPlanes.empty()) {
    moveClipPlane(-double(d.y()) / height() * camera.viewHeight());
    return;
  }
  const bool pan = (event->buttons() & (Qt::RightButton | Qt::MiddleButton)) ||
                   ((event->buttons() & Qt::LeftButton) && (event->modifiers() & Qt::ShiftModifier));
  if (pan) camera.pan(double(d.x()) / height(), -double(d.y()) / height());
  else if (event->buttons() & Qt::LeftButton) camera.orbit(-0.4 * d.x(), -0.4 * d.y());
  else return;
  update();
}

void Viewport::wheelEvent(QWheelEvent* event) {
  scene_.camera().zoom(std::pow(1.1, event->angleDelta().y() / 120.0));
  update();
}

}  // namespace volpost::app

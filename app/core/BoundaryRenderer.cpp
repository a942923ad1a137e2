// SPDX-License-Identifier: MIT
#include "BoundaryRenderer.hpp"

#include <cmath>

namespace volpost::app {

DisplayRange autoRange(const ScalarView& view) {
  if (!view.range.valid()) return {0.0, 1.0};
  return {view.range.min, view.range.max};
}

void BoundaryRenderer::initialize() {
  surface_.initialize();
  initialized_ = true;
  if (session_) surface_.setSurface(session_->surface());
}

void BoundaryRenderer::release() {
  surface_.release();
  initialized_ = false;
}

void BoundaryRenderer::setSession(std::shared_ptr<const ModelSession> session) {
  session_ = std::move(session);
  surface_.clearScalars();
  if (initialized_ && session_) surface_.setSurface(session_->surface());
}

void BoundaryRenderer::setScalars(const ScalarView* view, DisplayRange range) {
  if (!view) {
    surface_.clearScalars();
    return;
  }
  surface_.setScalars(view->location, view->values, range.min, range.max);
}

void BoundaryRenderer::renderBackground(const RenderContext& ctx) {
  glBindFramebuffer(GL_FRAMEBUFFER, ctx.framebuffer);
  glViewport(0, 0, ctx.width, ctx.height);
  glClearColor(background.r, background.g, background.b, 1.0f);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

void BoundaryRenderer::render(const RenderContext& ctx) {
  renderBackground(ctx);
  renderOver(ctx);
}

void BoundaryRenderer::renderOver(const RenderContext& ctx) {
  glBindFramebuffer(GL_FRAMEBUFFER, ctx.framebuffer);
  glViewport(0, 0, ctx.width, ctx.height);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  if (session_) {
    RenderContext local = ctx;
    local.origin = session_->surface().origin;
    surface_.render(local);
  }
  glDisable(GL_DEPTH_TEST);
}

}  // namespace volpost::app

// SPDX-License-Identifier: MIT
#include "BoundaryRenderer.hpp"

#include "host/SectionCut.hpp"

#include <algorithm>
#include <cmath>

namespace volpost::app {

DisplayRange autoRange(const ScalarView& view) {
  if (!view.range.valid()) return {0.0, 1.0};
  return {view.range.min, view.range.max};
}

void BoundaryRenderer::initialize() {
  surface_.initialize();
  sections_.initialize();
  sections_.setShowEdges(false);
  cutFor_.reset();
  initialized_ = true;
  if (session_) surface_.setSurface(session_->surface());
}

void BoundaryRenderer::release() {
  surface_.release();
  sections_.release();
  cutFor_.reset();
  initialized_ = false;
}

void BoundaryRenderer::setSession(std::shared_ptr<const ModelSession> session) {
  session_ = std::move(session);
  cutFor_.reset();
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

void BoundaryRenderer::setCuts(const std::vector<ClipPlane>& planes, const ScalarView* view, std::uint64_t viewVersion,
                               DisplayRange range) {
  if (!initialized_ || !session_) return;
  const CutKey key{planes, viewVersion, range, view != nullptr};
  if (cutFor_ == key) return;
  cutFor_ = key;
  const double tolerance = 1e-5 * std::max(session_->model().mesh.bounds().diagonal(), 1e-300);
  // What lies on a plane is kept: a section on its own plane, a face of the model on a
  // plane of the box (float rounding would otherwise speckle it).
  surface_.setClipPlanes(planes, tolerance);
  sections_.setClipPlanes(planes, tolerance);
  std::vector<glm::dvec3> corners;
  std::vector<double> values;
  if (!planes.empty()) {
    const TetMesh& tets = session_->tetrahedra();
    const std::vector<double> tetValues = view ? session_->tetValues(*view) : std::vector<double>{};
    const bool perNode = view && view->location == FieldLocation::Node;
    for (const ClipPlane& plane : planes) {
      SectionTriangles cut = cutTetrahedra(tets, tetValues, perNode, plane);
      corners.insert(corners.end(), cut.positions.begin(), cut.positions.end());
      values.insert(values.end(), cut.values.begin(), cut.values.end());
    }
  }
  sectionTriangles_ = corners.size() / 3;
  sections_.setTriangles(corners, session_->surface().origin);
  if (view) sections_.setScalars(FieldLocation::Node, values, range.min, range.max);
  else sections_.clearScalars();
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
    if (sectionTriangles_ > 0) sections_.render(local);
  }
  glDisable(GL_DEPTH_TEST);
}

}  // namespace volpost::app

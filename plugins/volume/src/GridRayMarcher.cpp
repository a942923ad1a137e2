// SPDX-License-Identifier: MIT
#include "GridRayMarcher.hpp"

#include "VolumeBindings.hpp"

#include <glm/gtc/type_ptr.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

namespace volpost::volume {

void GridRayMarcher::setVolume(const Mesh&, FieldLocation, std::span<const double>) {
  throw std::invalid_argument("the texture ray marcher draws regular grids (SEG-Y, image data), not meshes of "
                              "tetrahedra: choose another volume renderer for this model");
}

void GridRayMarcher::ensureResumeImage(int width, int height) {
  if (resume_ && resumeWidth_ == width && resumeHeight_ == height) return;
  resume_ = gl::createTexture(GL_TEXTURE_2D);
  glTextureStorage2D(resume_.id(), 1, GL_RG32F, width, height);
  resumeWidth_ = width;
  resumeHeight_ = height;
}

void GridRayMarcher::release() {
  resume_.reset();
  resumeWidth_ = resumeHeight_ = 0;
  quick_.release();
  volume_.release();
}

int GridRayMarcher::passesFor() const {
  const Bounds box = volume_.grid().bounds();
  const double steps = glm::length(box.size()) / marchStep() + 4.0;
  return int(std::min(std::ceil(steps / kStepsPerPass), 1e6));
}

GLuint GridRayMarcher::beginMarch(const RenderContext& ctx, GLuint image) {
  const GLuint p = volume_.program({"volume/gridmarch.comp"});
  glUseProgram(p);
  volume_.setSegmentUniforms(p, ctx);
  glProgramUniform1f(p, glGetUniformLocation(p, "marchStep"), float(marchStep()));
  glProgramUniform1i(p, glGetUniformLocation(p, "stepsPerPass"), kStepsPerPass);
  volume_.bindSegmentResources(ctx);
  ensureResumeImage(ctx.width, ctx.height);
  glBindImageTexture(0, image, 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA32F);
  glBindImageTexture(1, resume_.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_RG32F);
  return p;
}

void GridRayMarcher::marchPass(const RenderContext& ctx, GLuint program, int pass) {
  glProgramUniform1i(program, glGetUniformLocation(program, "firstPass"), pass == 0);
  glDispatchCompute(GLuint((ctx.width + 7) / 8), GLuint((ctx.height + 7) / 8), 1);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
}

double GridRayMarcher::renderWhole(const RenderContext& ctx, GLuint image) {
  const auto start = std::chrono::steady_clock::now();
  const GLuint p = beginMarch(ctx, image);
  const int passes = passesFor();
  for (int pass = 0; pass < passes; ++pass) marchPass(ctx, p, pass);
  lastPasses_ = passes;
  if (!volume_.asynchronous()) return 0.0;
  glFinish();  // timed for sizing quick frames: the window's path only
  return millisecondsSince(start);
}

bool GridRayMarcher::refine(const RenderContext& ctx) {
  const auto start = std::chrono::steady_clock::now();
  const GLuint p = beginMarch(ctx, volume_.image());
  const int passes = passesFor();
  while (refinePass_ < passes) {
    marchPass(ctx, p, refinePass_++);
    glFinish();
    if (refinePass_ < passes && millisecondsSince(start) >= quick_.sliceMs()) {
      refineMs_ += millisecondsSince(start);
      return false;
    }
  }
  refineMs_ += millisecondsSince(start);
  lastPasses_ = passes;
  quick_.measured(refineMs_, ctx.width, ctx.height);
  return true;
}

void GridRayMarcher::render(const RenderContext& ctx) {
  if (!volume_.initialized() || !volume_.hasGrid() || ctx.width <= 0 || ctx.height <= 0) return;
  volume_.prepare(ctx);
  if (!volume_.asynchronous()) {
    quick_.forget();
    renderWhole(ctx, volume_.image());
    volume_.compositeOver(ctx);
    gl::check("GridRayMarcher::render");
    return;
  }
  const GLuint shown = quick_.frame(
      ctx, volume_.revision(), volume_.meshRevision(), 0, volume_.image(),
      [this](const RenderContext& c, GLuint image) { return renderWhole(c, image); },
      [this] {
        refinePass_ = 0;
        refineMs_ = 0.0;
      },
      [this, &ctx] { return refine(ctx); });
  volume_.compositeOver(ctx, shown);
  gl::check("GridRayMarcher::render");
}

}  // namespace volpost::volume

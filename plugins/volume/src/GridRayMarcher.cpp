// SPDX-License-Identifier: MIT
#include "GridRayMarcher.hpp"

#include "VolumeBindings.hpp"

#include <glm/gtc/type_ptr.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
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
  volume_.release();
}

void GridRayMarcher::render(const RenderContext& ctx) {
  if (!volume_.initialized() || !volume_.hasGrid() || ctx.width <= 0 || ctx.height <= 0) return;
  volume_.prepare(ctx);
  const GLuint p = volume_.program({"volume/gridmarch.comp"});
  glUseProgram(p);
  volume_.setSegmentUniforms(p, ctx);
  const auto u = [p](const char* n) { return glGetUniformLocation(p, n); };
  const double step = marchStep();
  glProgramUniform1f(p, u("marchStep"), float(step));
  glProgramUniform1i(p, u("stepsPerPass"), kStepsPerPass);
  volume_.bindSegmentResources(ctx);
  ensureResumeImage(ctx.width, ctx.height);
  glBindImageTexture(0, volume_.image(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA32F);
  glBindImageTexture(1, resume_.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_RG32F);
  // Enough passes for the longest ray inside the grid (its diagonal) at this step.
  const Bounds box = volume_.grid().bounds();
  const double steps = glm::length(box.size()) / step + 4.0;
  const int passes = int(std::min(std::ceil(steps / kStepsPerPass), 1e6));
  for (int pass = 0; pass < passes; ++pass) {
    glProgramUniform1i(p, u("firstPass"), pass == 0);
    glDispatchCompute(GLuint((ctx.width + 7) / 8), GLuint((ctx.height + 7) / 8), 1);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT |
                    GL_TEXTURE_UPDATE_BARRIER_BIT);
  }
  lastPasses_ = passes;
  volume_.compositeOver(ctx);
  gl::check("GridRayMarcher::render");
}

}  // namespace volpost::volume

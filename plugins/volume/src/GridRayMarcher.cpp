// SPDX-License-Identifier: MIT
#include "GridRayMarcher.hpp"

#include "VolumeBindings.hpp"

#include <glm/gtc/type_ptr.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <array>
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

int GridRayMarcher::passesFor(std::size_t brick) const {
  const GridBrick& b = volume_.gridBricks().bricks()[brick];
  const RegularGrid& grid = volume_.grid();
  const glm::dvec3 diagonal = grid.indexToWorld() * glm::dvec3(double(b.points[0] - 1), double(b.points[1] - 1),
                                                             double(b.points[2] - 1));
  // Along the brick's diagonal bound (|a u + b v + c w| <= |a u| + |b v| + |c w|), plus the
  // steps a lattice adds at both ends.
  double length = 0.0;
  for (int a = 0; a < 3; ++a) length += glm::length(grid.axes[std::size_t(a)]) * double(b.points[std::size_t(a)] - 1);
  length = std::max(length, glm::length(diagonal));
  const double steps = length / marchStep() + 4.0;
  return int(std::min(std::ceil(steps / kStepsPerPass), 1e6));
}

// A frame starts from nothing: no color, transmittance 1, every ray done (each brick's first
// pass starts the rays it meets).
void GridRayMarcher::clearFrame(GLuint image) {
  const float nothing[4] = {0.0f, 0.0f, 0.0f, 0.0f}, done[2] = {-1.0f, 1.0f};
  glClearTexImage(image, 0, GL_RGBA, GL_FLOAT, nothing);
  glClearTexImage(resume_.id(), 0, GL_RG, GL_FLOAT, done);
}

GLuint GridRayMarcher::beginMarch(const RenderContext& ctx, GLuint image) {
  const GLuint p = volume_.program({"volume/gridmarch.comp"});
  glUseProgram(p);
  volume_.setSegmentUniforms(p, ctx);
  glProgramUniform1f(p, glGetUniformLocation(p, "marchStep"), float(marchStep()));
  glProgramUniform1i(p, glGetUniformLocation(p, "stepsPerPass"), kStepsPerPass);
  glProgramUniform1i(p, glGetUniformLocation(p, "cellCuts"), volume_.readsGradient());
  volume_.bindSegmentResources(ctx);
  ensureResumeImage(ctx.width, ctx.height);
  glBindImageTexture(0, image, 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA32F);
  glBindImageTexture(1, resume_.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_RG32F);
  return p;
}

void GridRayMarcher::marchPass(GLuint program, const Step& step) {
  if (step.pass == 0) volume_.bindGridBrick(program, step.brick);
  glProgramUniform1i(program, glGetUniformLocation(program, "firstPass"), step.pass == 0);
  glProgramUniform2i(program, glGetUniformLocation(program, "pixelOffset"), step.pixels[0], step.pixels[1]);
  glProgramUniform2i(program, glGetUniformLocation(program, "pixelEnd"), step.pixels[2], step.pixels[3]);
  glDispatchCompute(GLuint((step.pixels[2] - step.pixels[0] + 7) / 8), GLuint((step.pixels[3] - step.pixels[1] + 7) / 8), 1);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
}

std::vector<GridRayMarcher::Step> GridRayMarcher::planFrame(const RenderContext& ctx) const {
  std::vector<Step> steps;
  for (const std::size_t b : volume_.gridBricksInOrder(ctx, false)) {
    // The pixels whose rays can meet the brick (normalized coordinates, y down the image).
    const auto [lo, hi] = volume_.gridBrickOnScreen(ctx, b);
    const std::array<int, 4> pixels{
        std::clamp(int(std::floor((lo.x + 1.0f) * 0.5f * float(ctx.width))), 0, ctx.width),
        std::clamp(int(std::floor((lo.y + 1.0f) * 0.5f * float(ctx.height))), 0, ctx.height),
        std::clamp(int(std::ceil((hi.x + 1.0f) * 0.5f * float(ctx.width))), 0, ctx.width),
        std::clamp(int(std::ceil((hi.y + 1.0f) * 0.5f * float(ctx.height))), 0, ctx.height)};
    if (pixels[2] <= pixels[0] || pixels[3] <= pixels[1]) continue;  // off the picture
    for (int pass = 0, passes = passesFor(b); pass < passes; ++pass) steps.push_back({b, pass, pixels});
  }
  return steps;
}

double GridRayMarcher::renderWhole(const RenderContext& ctx, GLuint image) {
  const auto start = std::chrono::steady_clock::now();
  const GLuint p = beginMarch(ctx, image);
  clearFrame(image);
  const std::vector<Step> steps = planFrame(ctx);
  for (const Step& step : steps) marchPass(p, step);
  lastPasses_ = int(steps.size());
  if (!volume_.asynchronous()) return 0.0;
  glFinish();  // timed for sizing quick frames: the window's path only
  return millisecondsSince(start);
}

bool GridRayMarcher::refine(const RenderContext& ctx) {
  const auto start = std::chrono::steady_clock::now();
  const GLuint p = beginMarch(ctx, volume_.image());
  // A brick's first pass binds it; a later one goes on in the brick an earlier call bound.
  if (refineStep_ < refinePlan_.size() && refinePlan_[refineStep_].pass > 0)
    volume_.bindGridBrick(p, refinePlan_[refineStep_].brick);
  while (refineStep_ < refinePlan_.size()) {
    marchPass(p, refinePlan_[refineStep_++]);
    glFinish();
    if (refineStep_ < refinePlan_.size() && millisecondsSince(start) >= quick_.sliceMs()) {
      refineMs_ += millisecondsSince(start);
      return false;
    }
  }
  refineMs_ += millisecondsSince(start);
  lastPasses_ = int(refinePlan_.size());
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
      [this, &ctx] {
        refinePlan_ = planFrame(ctx);
        refineStep_ = 0;
        ensureResumeImage(ctx.width, ctx.height);
        clearFrame(volume_.image());
        refineMs_ = 0.0;
      },
      [this, &ctx] { return refine(ctx); });
  volume_.compositeOver(ctx, shown);
  gl::check("GridRayMarcher::render");
}

}  // namespace volpost::volume

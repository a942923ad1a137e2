// SPDX-License-Identifier: MIT
#include "RayCaster.hpp"

#include "GpuLimits.hpp"
#include "VolumeBindings.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>

namespace volpost::volume {
namespace {

constexpr std::size_t kRayStateBytes = 16;  // one uvec4 per pixel (raycast.comp)

}  // namespace

void RayCaster::initialize() {
  volume_.initialize();
  counters_ = gl::createBuffer();
  glNamedBufferStorage(counters_.id(), 2 * sizeof(GLuint), nullptr, GL_DYNAMIC_STORAGE_BIT);
  rayState_.reset();
  rayStateBytes_ = 0;
  quick_.release();
}

void RayCaster::release() {
  volume_.release();
  counters_.reset();
  rayState_.reset();
  rayStateBytes_ = 0;
  quick_.release();
}

void RayCaster::setStepsPerPass(int steps) {
  stepsPerPass_ = std::clamp(steps, 1, kStepsPerPass);
  sliceSteps_ = std::min(sliceSteps_, stepsPerPass_);
}

VolumeStats RayCaster::stats() const {
  VolumeStats s = volume_.stats();
  s.gpuBytes += rayStateBytes_ + 2 * sizeof(GLuint) + quick_.bytes();
  return s;
}

int RayCaster::bandRows(int width, int height) const {
  GLint64 limit = 0;
  glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &limit);
  std::int64_t rows = height;
  if (limit > 0) rows = std::min<std::int64_t>(rows, limit / (std::int64_t(width) * std::int64_t(kRayStateBytes)));
  if (bandRowsLimit_ > 0) rows = std::min<std::int64_t>(rows, bandRowsLimit_);
  return int(std::max<std::int64_t>(rows, 1));
}

void RayCaster::beginBand(int width, int rows) {
  const std::size_t bytes = std::size_t(width) * std::size_t(rows) * kRayStateBytes;
  if (bytes > rayStateBytes_) {  // grows only: a resized window reuses the larger buffer
    rayState_ = gl::createBuffer();
    glNamedBufferStorage(rayState_.id(), GLsizeiptr(bytes), nullptr, GL_DYNAMIC_STORAGE_BIT);
    rayStateBytes_ = bytes;
  }
  glClearNamedBufferSubData(rayState_.id(), GL_R32UI, 0, GLsizeiptr(bytes), GL_RED_INTEGER, GL_UNSIGNED_INT, nullptr);
}

std::size_t RayCaster::dispatch(const RenderContext& ctx, GLuint image, int firstRow, int rows, int steps) {
  const GLuint p = volume_.program({"volume/raycast.comp"});
  glUseProgram(p);
  volume_.setSegmentUniforms(p, ctx);
  glProgramUniform1i(p, glGetUniformLocation(p, "maxSteps"), rayStepCap(volume_.mesh().tetCount));
  glProgramUniform1ui(p, glGetUniformLocation(p, "farNeighborBase"), GLuint(volume_.mesh().tetCount * 3));
  glProgramUniform1ui(p, glGetUniformLocation(p, "farNeighborCount"), GLuint(volume_.mesh().farNeighbors));
  glProgramUniform1i(p, glGetUniformLocation(p, "stepsPerPass"), steps);
  glProgramUniform1f(p, glGetUniformLocation(p, "reentryTolerance"), float(1e-6 * volume_.mesh().diagonal));
  glProgramUniform2i(p, glGetUniformLocation(p, "band"), firstRow, rows);
  volume_.bindSegmentResources(ctx);
  const GLuint zeros[2] = {0, 0};
  glNamedBufferSubData(counters_.id(), 0, sizeof(zeros), zeros);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kRayState, rayState_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kRayCounters, counters_.id());
  glBindImageTexture(0, image, 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA32F);
  // The last pass' image and states are read by this one.
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  glDispatchCompute(GLuint((ctx.width + 7) / 8), GLuint((rows + 7) / 8), 1);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT |
                  GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
  GLuint counts[2] = {0, 0};
  glGetNamedBufferSubData(counters_.id(), 0, sizeof(counts), counts);  // waits for the dispatch
  ++building_.dispatches;
  building_.cappedRays += counts[1];
  return counts[0];
}

double RayCaster::renderWhole(const RenderContext& ctx, GLuint image) {
  const auto start = std::chrono::steady_clock::now();
  building_ = {};
  const int rowsPerBand = bandRows(ctx.width, ctx.height);
  for (int first = 0; first < ctx.height; first += rowsPerBand) {
    const int rows = std::min(rowsPerBand, ctx.height - first);
    beginBand(ctx.width, rows);
    // Each dispatch takes every unfinished ray at least one tet further, and no ray goes
    // past the step cap: this ends.
    while (dispatch(ctx, image, first, rows, stepsPerPass_) > 0) {
    }
  }
  building_.milliseconds = millisecondsSince(start);
  lastFrame_ = building_;
  return lastFrame_.milliseconds;
}

void RayCaster::beginRefining(const RenderContext& ctx) {
  building_ = {};
  refineFirstRow_ = 0;
  refineRows_ = std::min(bandRows(ctx.width, ctx.height), ctx.height);
  beginBand(ctx.width, refineRows_);
}

bool RayCaster::refine(const RenderContext& ctx) {
  const auto start = std::chrono::steady_clock::now();
  for (;;) {
    const auto passStart = std::chrono::steady_clock::now();
    const std::size_t unfinished = dispatch(ctx, volume_.image(), refineFirstRow_, refineRows_, sliceSteps_);
    const double ms = millisecondsSince(passStart);
    building_.milliseconds += ms;
    // Tets per dispatch follow the measured time (a dispatch costs about its steps).
    const double factor = std::clamp(quick_.sliceMs() / std::max(ms, 0.1), 0.25, 4.0);
    sliceSteps_ = std::clamp(int(sliceSteps_ * factor), 16, stepsPerPass_);
    if (unfinished == 0) {
      const int bandRowsNow = refineRows_;
      refineFirstRow_ += bandRowsNow;
      if (refineFirstRow_ >= ctx.height) {
        lastFrame_ = building_;
        quick_.measured(lastFrame_.milliseconds, ctx.width, ctx.height);
        return true;
      }
      refineRows_ = std::min(bandRowsNow, ctx.height - refineFirstRow_);
      beginBand(ctx.width, refineRows_);
    }
    if (millisecondsSince(start) >= quick_.sliceMs()) return false;
  }
}

void RayCaster::render(const RenderContext& ctx) {
  if (!volume_.initialized() || !volume_.hasTets() || ctx.width <= 0 || ctx.height <= 0) return;
  volume_.prepare(ctx);
  if (!volume_.asynchronous()) {
    quick_.forget();
    renderWhole(ctx, volume_.image());
    volume_.compositeOver(ctx);
    gl::check("RayCaster::render");
    return;
  }
  const GLuint shown = quick_.frame(
      ctx, volume_.revision(), volume_.meshRevision(), 0, volume_.image(),
      [this](const RenderContext& c, GLuint image) { return renderWhole(c, image); },
      [this, &ctx] { beginRefining(ctx); }, [this, &ctx] { return refine(ctx); });
  volume_.compositeOver(ctx, shown);
  gl::check("RayCaster::render");
}

}  // namespace volpost::volume

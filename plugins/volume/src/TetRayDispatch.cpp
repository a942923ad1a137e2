// SPDX-License-Identifier: MIT
#include "TetRayDispatch.hpp"

#include "GpuLimits.hpp"
#include "QuickFrames.hpp"
#include "VolumeBindings.hpp"

#include <algorithm>
#include <chrono>
#include <cstdint>

namespace volpost::volume {
namespace {

constexpr std::size_t kRayStateBytes = 16;  // one uvec4 per pixel (raycast.comp)

}  // namespace

void TetRayDispatch::initialize() {
  counters_ = gl::createBuffer();
  glNamedBufferStorage(counters_.id(), 2 * sizeof(GLuint), nullptr, GL_DYNAMIC_STORAGE_BIT);
  rayState_.reset();
  rayStateBytes_ = 0;
}

void TetRayDispatch::release() {
  counters_.reset();
  rayState_.reset();
  rayStateBytes_ = 0;
}

std::size_t TetRayDispatch::bytes() const { return counters_ ? rayStateBytes_ + 2 * sizeof(GLuint) : 0; }

void TetRayDispatch::setBandRowsLimit(int rows) { bandRowsLimit_ = std::max(rows, 0); }

int TetRayDispatch::bandRows(int width, int height) const {
  GLint64 limit = 0;
  glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &limit);
  std::int64_t rows = height;
  if (limit > 0) rows = std::min<std::int64_t>(rows, limit / (std::int64_t(width) * std::int64_t(kRayStateBytes)));
  if (bandRowsLimit_ > 0) rows = std::min<std::int64_t>(rows, bandRowsLimit_);
  return int(std::max<std::int64_t>(rows, 1));
}

void TetRayDispatch::beginBand(int width, int rows) {
  const std::size_t bytes = std::size_t(width) * std::size_t(rows) * kRayStateBytes;
  if (bytes > rayStateBytes_) {  // grows only: a resized window reuses the larger buffer
    rayState_ = gl::createBuffer();
    glNamedBufferStorage(rayState_.id(), GLsizeiptr(bytes), nullptr, GL_DYNAMIC_STORAGE_BIT);
    rayStateBytes_ = bytes;
  }
  glClearNamedBufferSubData(rayState_.id(), GL_R32UI, 0, GLsizeiptr(bytes), GL_RED_INTEGER, GL_UNSIGNED_INT, nullptr);
}

std::size_t TetRayDispatch::dispatch(GpuVolume& volume, const RenderContext& ctx, GLuint image, int firstRow, int rows,
                                     int steps, RayFrameReport& report) {
  const GLuint p = volume.program({"volume/raycast.comp"});
  glUseProgram(p);
  volume.setSegmentUniforms(p, ctx);
  glProgramUniform1i(p, glGetUniformLocation(p, "maxSteps"), rayStepCap(volume.mesh().tetCount));
  glProgramUniform1ui(p, glGetUniformLocation(p, "farNeighborBase"), GLuint(volume.mesh().tetCount * 3));
  glProgramUniform1ui(p, glGetUniformLocation(p, "farNeighborCount"), GLuint(volume.mesh().farNeighbors));
  glProgramUniform1i(p, glGetUniformLocation(p, "stepsPerPass"), steps);
  glProgramUniform1f(p, glGetUniformLocation(p, "reentryTolerance"), float(1e-6 * volume.mesh().diagonal));
  glProgramUniform2i(p, glGetUniformLocation(p, "band"), firstRow, rows);
  volume.bindSegmentResources(ctx);
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
  ++report.dispatches;
  report.cappedRays += counts[1];
  return counts[0];
}

RayFrameReport TetRayDispatch::renderWhole(GpuVolume& volume, const RenderContext& ctx, GLuint image, int stepsPerPass) {
  const auto start = std::chrono::steady_clock::now();
  RayFrameReport report;
  const int rowsPerBand = bandRows(ctx.width, ctx.height);
  for (int first = 0; first < ctx.height; first += rowsPerBand) {
    const int rows = std::min(rowsPerBand, ctx.height - first);
    beginBand(ctx.width, rows);
    // Each dispatch takes every unfinished ray at least one tet further, and no ray goes
    // past the step cap: this ends.
    while (dispatch(volume, ctx, image, first, rows, stepsPerPass, report) > 0) {
    }
  }
  report.milliseconds = millisecondsSince(start);
  return report;
}

}  // namespace volpost::volume

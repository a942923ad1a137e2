// SPDX-License-Identifier: MIT
#include "TetRayDispatch.hpp"

#include "GpuLimits.hpp"
#include "QuickFrames.hpp"
#include "VolumeBindings.hpp"

#include <glm/mat4x4.hpp>

#include <algorithm>
#include <chrono>
#include <cstdint>

namespace volpost::volume {
namespace {

constexpr std::size_t kRayStateBytes = 16;  // one uvec4 per pixel (raycast.comp)
constexpr std::size_t kMostMapFaces = std::size_t(0x7fffffff) / 6;  // six vertices a face, the ids ints

// The GL state drawEntryMaps changes, taken on construction and put back on destruction: the
// window draws its scene with it after the volume.
class SavedDrawState {
 public:
  SavedDrawState() {
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &drawFramebuffer_);
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &readFramebuffer_);
    glGetIntegerv(GL_VIEWPORT, viewport_);
    glGetIntegerv(GL_DEPTH_FUNC, &depthFunc_);
    glGetBooleanv(GL_DEPTH_WRITEMASK, &depthMask_);
  }
  ~SavedDrawState() {
    glBindVertexArray(0);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(drawFramebuffer_));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(readFramebuffer_));
    glViewport(viewport_[0], viewport_[1], viewport_[2], viewport_[3]);
    glDepthFunc(GLenum(depthFunc_));
    glDepthMask(depthMask_);
    if (!depthTest_) glDisable(GL_DEPTH_TEST);
    if (blend_) glEnable(GL_BLEND);
    if (cull_) glEnable(GL_CULL_FACE);
  }
  SavedDrawState(const SavedDrawState&) = delete;
  SavedDrawState& operator=(const SavedDrawState&) = delete;

 private:
  GLint drawFramebuffer_ = 0, readFramebuffer_ = 0, depthFunc_ = GL_LESS, viewport_[4] = {0, 0, 0, 0};
  GLboolean depthMask_ = GL_TRUE;
  bool depthTest_ = glIsEnabled(GL_DEPTH_TEST), blend_ = glIsEnabled(GL_BLEND), cull_ = glIsEnabled(GL_CULL_FACE);
};

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
  nearest_.reset();
  farthest_.reset();
  mapsDepth_.reset();
  mapsFramebuffer_.reset();
  emptyVertexArray_.reset();
  mapsWidth_ = mapsHeight_ = 0;
  hasMaps_ = false;
}

std::size_t TetRayDispatch::bytes() const {
  const std::size_t maps = std::size_t(mapsWidth_) * std::size_t(mapsHeight_) * (8 + 4 + 4);
  return counters_ ? rayStateBytes_ + 2 * sizeof(GLuint) + maps : 0;
}

void TetRayDispatch::sizeMaps(int width, int height) {
  if (mapsFramebuffer_ && mapsWidth_ == width && mapsHeight_ == height) return;
  const auto texture = [&](GLenum format) {
    gl::Texture t = gl::createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(t.id(), 1, format, width, height);
    glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    return t;
  };
  nearest_ = texture(GL_RG32UI);
  farthest_ = texture(GL_R32UI);
  mapsDepth_ = texture(GL_DEPTH_COMPONENT32F);
  mapsFramebuffer_ = gl::createFramebuffer();
  glNamedFramebufferTexture(mapsFramebuffer_.id(), GL_COLOR_ATTACHMENT0, nearest_.id(), 0);
  glNamedFramebufferTexture(mapsFramebuffer_.id(), GL_DEPTH_ATTACHMENT, mapsDepth_.id(), 0);
  emptyVertexArray_ = gl::createVertexArray();  // core profile: a draw needs one bound, even empty
  mapsWidth_ = width;
  mapsHeight_ = height;
}

void TetRayDispatch::drawEntryMaps(GpuVolume& volume, const RenderContext& ctx) {
  if (beginEntryMaps(volume, ctx)) drawEntryMapFaces(volume, ctx, mapsFaces_);
}

bool TetRayDispatch::beginEntryMaps(GpuVolume& volume, const RenderContext& ctx) {
  hasMaps_ = false;
  // Drawing the maps costs about the faces (six vertices each), the searches they save
  // about the rays: on a small image (a quick frame) of a mesh with many faces the BVH is
  // cheaper (post_fine's 23K faces at 64x48: 4.3 instead of 23 frames per second).
  const std::size_t faces = volume.entryFaceCount();
  if (!entryMaps_ || faces > kMostMapFaces || std::size_t(ctx.width) * std::size_t(ctx.height) < 2 * faces) return false;
  sizeMaps(ctx.width, ctx.height);
  const GLuint none[4] = {0xffffffffu, 0xffffffffu, 0, 0}, zero = 0;
  const float farthestDepth = 1.0f;
  glClearNamedFramebufferuiv(mapsFramebuffer_.id(), GL_COLOR, 0, none);
  glClearNamedFramebufferfv(mapsFramebuffer_.id(), GL_DEPTH, 0, &farthestDepth);
  glClearTexImage(farthest_.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
  mapsFaces_ = faces;
  mapsNextFace_ = 0;
  return true;
}

bool TetRayDispatch::drawEntryMapFaces(GpuVolume& volume, const RenderContext& ctx, std::size_t count) {
  const std::size_t first = mapsNextFace_, n = std::min(count, mapsFaces_ - first);
  if (n > 0) {
    const SavedDrawState saved;
    const GLuint p = volume.program({"volume/entry_faces.vert", "volume/entry_faces.frag"});
    glUseProgram(p);
    volume.setSegmentUniforms(p, ctx);
    const glm::mat4 vp = volume.imageViewProjection(ctx);
    glProgramUniformMatrix4fv(p, glGetUniformLocation(p, "viewProjection"), 1, GL_FALSE, &vp[0][0]);
    glProgramUniform2f(p, glGetUniformLocation(p, "viewportSize"), float(ctx.width), float(ctx.height));
    volume.bindSegmentResources(ctx);
    glBindFramebuffer(GL_FRAMEBUFFER, mapsFramebuffer_.id());
    glViewport(0, 0, ctx.width, ctx.height);
    glBindVertexArray(emptyVertexArray_.id());
    glEnable(GL_DEPTH_TEST);
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    glBindImageTexture(1, farthest_.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
    glDrawArrays(GL_TRIANGLES, GLint(first * 6), GLsizei(n * 6));  // gl_VertexID counts from first * 6
  }
  mapsNextFace_ = first + n;
  if (mapsNextFace_ < mapsFaces_) return false;
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);  // the image's atomics, read by texelFetch
  hasMaps_ = true;
  gl::check("TetRayDispatch::drawEntryMapFaces");
  return true;
}

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
  glProgramUniform1i(p, glGetUniformLocation(p, "hasEntryMaps"), hasMaps_);
  volume.bindSegmentResources(ctx);
  glBindTextureUnit(binding::kNearestEntry, hasMaps_ ? nearest_.id() : 0);
  glBindTextureUnit(binding::kFarthestEntry, hasMaps_ ? farthest_.id() : 0);
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
  report.entryMaps = hasMaps_;
  report.cappedRays += counts[1];
  return counts[0];
}

RayFrameReport TetRayDispatch::renderWhole(GpuVolume& volume, const RenderContext& ctx, GLuint image, int stepsPerPass) {
  const auto start = std::chrono::steady_clock::now();
  RayFrameReport report;
  drawEntryMaps(volume, ctx);
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

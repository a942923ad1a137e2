// SPDX-License-Identifier: MIT
#include "CellProjector.hpp"

#include "GpuLimits.hpp"

#include "VolumeBindings.hpp"

#include <glm/gtc/type_ptr.hpp>
#include <glm/mat4x4.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace volpost::volume {

void CellProjector::initialize() {
  volume_.setKeepsTetrahedraOnHost(true);  // sorted on the CPU every frame
  volume_.initialize();
  order_ = gl::createBuffer();
  framebuffer_ = gl::createFramebuffer();
  emptyVertexArray_ = gl::createVertexArray();  // core profile: a draw needs one bound, even empty
  attachedImage_ = 0;
  quickRays_.initialize();
  quick_.release();
  quick_.setQuickFramesElsewhere(true);
  gl::check("CellProjector::initialize");
}

void CellProjector::release() {
  quick_.release();
  quickRays_.release();
  order_.reset();
  framebuffer_.reset();
  emptyVertexArray_.reset();
  attachedImage_ = 0;
  volume_.release();
}

// The sort sees exactly the tets the GPU holds, in the GPU's numbering, with the GPU
// structure's adjacency.
void CellProjector::updateSorter() {
  if (sorter_ && sortedRevision_ == volume_.meshRevision()) return;
  const TetMeshGpu& g = volume_.mesh();
  sortMesh_ = Mesh();
  sortMesh_.nodes.reserve(g.nodes.size());
  for (const glm::vec4& n : g.nodes) sortMesh_.nodes.push_back(glm::dvec3(n) + g.origin);
  sortMesh_.reserveCells(g.tetCount, g.tetCount * 4);
  for (std::size_t i = 0; i < g.tetCount; ++i) {
    const glm::uvec4 t = g.tetNodes(i);
    const std::array<NodeIndex, 4> v = {t.x, t.y, t.z, t.w};
    sortMesh_.addCell(CellType::Tet4, v);
  }
  std::vector<glm::ivec4> neighbors(g.tetCount);
  for (std::size_t t = 0; t < g.tetCount; ++t) neighbors[t] = g.neighborsOf(t);
  sorter_ = std::make_unique<VisibilitySorter>(sortMesh_, std::move(neighbors));
  sortedRevision_ = volume_.meshRevision();
}

void CellProjector::sortFor(const RenderContext& ctx) {
  lastOrder_ = sorter_->order(ctx.camera, method_, ctx.width, ctx.height);
  glNamedBufferData(order_.id(), GLsizeiptr(std::max<std::size_t>(lastOrder_.backToFront.size() * 4, 16)),
                    lastOrder_.backToFront.data(), GL_STREAM_DRAW);
}

void CellProjector::beginDrawing(const RenderContext& ctx, GLuint image, bool clear) {
  GpuVolume::beginDrawingIntoImage(framebuffer_, attachedImage_, image, ctx, clear);
  const GLuint p = volume_.program({"volume/vicp.vert", "volume/vicp.frag"});
  glUseProgram(p);
  volume_.setSegmentUniforms(p, ctx);
  const glm::mat4 vp = volume_.imageViewProjection(ctx);
  glProgramUniformMatrix4fv(p, glGetUniformLocation(p, "viewProjection"), 1, GL_FALSE, glm::value_ptr(vp));
  glProgramUniform2f(p, glGetUniformLocation(p, "viewportSize"), float(ctx.width), float(ctx.height));
  volume_.bindSegmentResources(ctx);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kOrder, order_.id());
  glBindVertexArray(emptyVertexArray_.id());
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);  // back to front, premultiplied "over"
}

void CellProjector::drawRun(std::size_t first, std::size_t count) {
  // Two triangles per tet; the vertex shader finds its tet from gl_VertexID / 6.
  (void)projectionVertexCount(first + count);  // the largest vertex id stays an int
  glDrawArrays(GL_TRIANGLES, GLint(first * 6), projectionVertexCount(count));
}

void CellProjector::endDrawing() {
  glDisable(GL_BLEND);
  glBindVertexArray(0);
}

double CellProjector::drawWhole(const RenderContext& ctx, GLuint image) {
  const auto start = std::chrono::steady_clock::now();
  beginDrawing(ctx, image, true);
  drawRun(0, lastOrder_.backToFront.size());
  endDrawing();
  if (!volume_.asynchronous()) return 0.0;
  glFinish();  // timed for sizing quick frames: the window's path only
  return millisecondsSince(start);
}

bool CellProjector::refine(const RenderContext& ctx) {
  const auto start = std::chrono::steady_clock::now();
  if (sortPending_) {  // not while the view moves: only once it rests for a frame
    sortFor(ctx);
    sortPending_ = false;
    refineMs_ += millisecondsSince(start);
    if (millisecondsSince(start) >= quick_.sliceMs()) return false;  // the sort was this slice
  }
  const std::size_t total = lastOrder_.backToFront.size();
  beginDrawing(ctx, volume_.image(), false);
  double lastMs = 0.0;  // the slice's previous run
  for (;;) {
    // Another run only where the slice can hold one like the last.
    if (lastMs > 0.0 && millisecondsSince(start) + lastMs > quick_.sliceMs()) {
      endDrawing();
      return false;
    }
    const auto runStart = std::chrono::steady_clock::now();
    const std::size_t count = std::min(tetsPerRun_, total - drawnTets_);
    drawRun(drawnTets_, count);
    glFinish();
    const double ms = millisecondsSince(runStart);
    refineMs_ += ms;
    lastMs = ms;
    drawnTets_ += count;
    const double factor = std::clamp(quick_.sliceMs() / std::max(ms, 0.1), 0.25, 4.0);
    tetsPerRun_ = std::clamp<std::size_t>(std::size_t(double(tetsPerRun_) * factor), 64, std::size_t(1) << 26);
    if (drawnTets_ >= total) break;
    if (millisecondsSince(start) >= quick_.sliceMs()) {
      endDrawing();
      return false;
    }
  }
  endDrawing();
  quick_.measuredFull(refineMs_, ctx.width, ctx.height);
  return true;
}

void CellProjector::render(const RenderContext& ctx) {
  if (!volume_.initialized() || !volume_.hasTets() || ctx.width <= 0 || ctx.height <= 0) return;
  volume_.prepare(ctx);
  updateSorter();
  if (!volume_.asynchronous()) {
    quick_.forget();
    sortFor(ctx);
    drawWhole(ctx, volume_.image());
    volume_.compositeOver(ctx);
    gl::check("CellProjector::render");
    return;
  }
  const GLuint shown = quick_.frame(
      ctx, volume_.revision(), volume_.meshRevision(), int(method_), volume_.image(),
      [this, &ctx](const RenderContext& c, GLuint image) {
        if (c.width == ctx.width && c.height == ctx.height) {  // the full frame fits the budget
          const auto start = std::chrono::steady_clock::now();
          sortFor(ctx);
          drawWhole(c, image);
          return millisecondsSince(start);
        }
        // A quick frame: ray cast from the same GPU data, the same picture (the two
        // renderers share the segment integration); cell projection's own cost is per tet
        // and would hardly shrink with the resolution.
        return quickRays_.renderWhole(volume_, c, image, TetRayDispatch::kStepsPerPass).milliseconds;
      },
      [this, &ctx] {
        beginDrawing(ctx, volume_.image(), true);  // the full frame starts empty
        endDrawing();
        drawnTets_ = 0;
        refineMs_ = 0.0;
        sortPending_ = true;
      },
      [this, &ctx] { return refine(ctx); });
  volume_.compositeOver(ctx, shown);
  gl::check("CellProjector::render");
}

VolumeStats CellProjector::stats() const {
  VolumeStats s = volume_.stats();
  s.gpuBytes += lastOrder_.backToFront.size() * 4 + quick_.bytes() + quickRays_.bytes();
  s.meshBytes += sortMesh_.cellCount() * 4;  // the sorted index list
  s.lastSortMs = lastOrder_.milliseconds;
  return s;
}

}  // namespace volpost::volume

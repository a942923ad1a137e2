// SPDX-License-Identifier: MIT
#include "CellProjector.hpp"

#include "GpuLimits.hpp"

#include "VolumeBindings.hpp"

#include <glm/gtc/type_ptr.hpp>
#include <glm/mat4x4.hpp>

namespace volpost::volume {

void CellProjector::initialize() {
  volume_.initialize();
  order_ = gl::createBuffer();
  framebuffer_ = gl::createFramebuffer();
  emptyVertexArray_ = gl::createVertexArray();  // core profile: a draw needs one bound, even empty
  attachedImage_ = 0;
  gl::check("CellProjector::initialize");
}

void CellProjector::release() {
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
  sortMesh_.reserveCells(g.tets.size(), g.tets.size() * 4);
  for (const glm::uvec4& t : g.tets) {
    const std::array<NodeIndex, 4> v = {t.x, t.y, t.z, t.w};
    sortMesh_.addCell(CellType::Tet4, v);
  }
  sorter_ = std::make_unique<VisibilitySorter>(sortMesh_, g.neighbors);
  sortedRevision_ = volume_.meshRevision();
}

void CellProjector::render(const RenderContext& ctx) {
  if (!volume_.initialized() || !volume_.hasTets() || ctx.width <= 0 || ctx.height <= 0) return;
  volume_.prepare(ctx);
  updateSorter();
  lastOrder_ = sorter_->order(ctx.camera, method_, ctx.width, ctx.height);
  glNamedBufferData(order_.id(), GLsizeiptr(std::max<std::size_t>(lastOrder_.backToFront.size() * 4, 16)),
                    lastOrder_.backToFront.data(), GL_STREAM_DRAW);
  volume_.beginDrawingIntoImage(framebuffer_, attachedImage_, ctx);

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
  glDrawArrays(GL_TRIANGLES, 0, projectionVertexCount(lastOrder_.backToFront.size()));  // two triangles per tet
  glDisable(GL_BLEND);
  glBindVertexArray(0);
  volume_.compositeOver(ctx);
  gl::check("CellProjector::render");
}

VolumeStats CellProjector::stats() const {
  VolumeStats s = volume_.stats();
  s.gpuBytes += lastOrder_.backToFront.size() * 4;
  s.meshBytes += sortMesh_.cellCount() * 4;  // the sorted index list
  s.lastSortMs = lastOrder_.milliseconds;
  return s;
}

}  // namespace volpost::volume

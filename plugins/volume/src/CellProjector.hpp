// SPDX-License-Identifier: MIT
// View-Independent Cell Projection (Weiler et al. 2003; Espinha 2005, 3.1 and 4.1.1): the
// tets are sorted back to front on the CPU (VisibilityOrder) and drawn from the
// GPU-resident mesh by vertex pulling from the sorted index list; each fragment integrates
// its tet's segment with the same GLSL as the ray caster (common/tet_segment.glsl) and
// blends into a float image. Only the 4-byte-per-tet order travels per frame.
#pragma once

#include "TetVolumeRenderer.hpp"
#include "VisibilityOrder.hpp"

#include <memory>

namespace volpost::volume {

class CellProjector final : public TetVolumeRenderer {
 public:
  explicit CellProjector(OrderMethod method = OrderMethod::Mpvonc) : method_(method) {}
  std::string name() const override { return method_ == OrderMethod::ImageSpace ? "vicp-exact" : "vicp"; }
  void initialize() override;
  void release() override;
  void render(const RenderContext& ctx) override;
  VolumeStats stats() const override;

  void setOrderMethod(OrderMethod method) { method_ = method; }
  const VisibilityOrder& lastOrder() const { return lastOrder_; }

 private:
  void updateSorter();

  OrderMethod method_;
  Mesh sortMesh_;  ///< the GPU's tets (oriented, degenerate ones left out) in model coordinates
  std::unique_ptr<VisibilitySorter> sorter_;
  std::size_t sortedRevision_ = std::size_t(-1);  ///< the volume's mesh revision the sorter was built for
  VisibilityOrder lastOrder_;
  gl::Buffer order_;
  gl::Framebuffer framebuffer_;
  gl::VertexArray emptyVertexArray_;
  GLuint attachedImage_ = 0;
};

}  // namespace volpost::volume

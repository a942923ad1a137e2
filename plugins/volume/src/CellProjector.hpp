// SPDX-License-Identifier: MIT
// View-Independent Cell Projection (Weiler et al. 2003; seed 004, 3.1 and 4.1.1): the tets
// are sorted back to front on the CPU (VisibilityOrder) and drawn from the GPU-resident
// mesh by vertex pulling from the sorted index list; each front-face fragment integrates
// its tet's segment with the ray caster's own code and blends into a float image. It
// shares the ray caster's mesh structure, tables, clip planes and iso-surfaces: it is a
// ray caster whose per-pixel walk is replaced by rasterization in visibility order.
#pragma once

#include "RayCaster.hpp"
#include "VisibilityOrder.hpp"

#include <memory>

namespace volpost::volume {

class CellProjector : public RayCaster {
 public:
  explicit CellProjector(OrderMethod method = OrderMethod::Mpvonc) : method_(method) {}
  std::string name() const override { return method_ == OrderMethod::ImageSpace ? "vicp-exact" : "vicp"; }
  void initialize() override;
  void release() override;
  void render(const RenderContext& ctx) override;
  void setVolume(const Mesh& mesh, FieldLocation location, std::span<const double> values) override;
  VolumeStats stats() const override;

  void setOrderMethod(OrderMethod method) { method_ = method; }
  const VisibilityOrder& lastOrder() const { return lastOrder_; }

 private:
  OrderMethod method_;
  Mesh sortMesh_;  ///< the GPU's tets (oriented, degenerate ones left out) in model coordinates
  std::unique_ptr<VisibilitySorter> sorter_;
  VisibilityOrder lastOrder_;
  ModePrograms projectionPrograms_;
  gl::Buffer order_;
  gl::Framebuffer framebuffer_;
  gl::VertexArray emptyVertexArray_;
  GLuint attachedImage_ = 0;
};

}  // namespace volpost::volume

// SPDX-License-Identifier: MIT
// View-Independent Cell Projection (Weiler et al. 2003; Espinha 2005, 3.1 and 4.1.1): the
// tets are sorted back to front on the CPU (VisibilityOrder) and drawn from the
// GPU-resident mesh by vertex pulling from the sorted index list; each fragment integrates
// its tet's segment with the same GLSL as the ray caster (common/tet_segment.glsl) and
// blends into a float image. Only the 4-byte-per-tet order travels per frame.
//
// With asynchronous updates (the window), a changed view or scene is first drawn at reduced
// resolution by the ray caster's shader on the same GPU data (sized from its measured cost
// per pixel to take ~40 ms; cell projection's own cost is per tet, sort and vertex work,
// and hardly shrinks with the resolution: 0.9 s a quick frame on llvmpipe); once the view
// rests, the tets are sorted and the full-resolution frame is drawn in runs of the sorted
// order, about 30 ms per render() call, and shown once complete: the same blends in the
// same order, so the same image as the synchronous path. Where a full frame fits the
// quick frame's budget it is drawn at once.
#pragma once

#include "QuickFrames.hpp"
#include "TetRayDispatch.hpp"
#include "TetVolumeRenderer.hpp"
#include "VisibilityOrder.hpp"

#include <cstdint>
#include <memory>

namespace volpost::volume {

class CellProjector final : public TetVolumeRenderer {
 public:
  explicit CellProjector(OrderMethod method = OrderMethod::Mpvonc) : method_(method) {}
  std::string name() const override { return method_ == OrderMethod::ImageSpace ? "vicp-exact" : "vicp"; }
  VolumeRendererTraits traits() const override {
    VolumeRendererTraits t;
    t.label = method_ == OrderMethod::ImageSpace ? "Cell projection (exact sort per pixel)"
                                                 : "Cell projection (fast sort, may err on non-convex meshes)";
    t.modes = allIntegrationModes();
    return t;
  }
  void initialize() override;
  void release() override;
  void render(const RenderContext& ctx) override;
  VolumeStats stats() const override;

  void setOrderMethod(OrderMethod method) { method_ = method; }
  const VisibilityOrder& lastOrder() const { return lastOrder_; }
  bool hasPendingWork() const override { return volume_.hasPendingWork() || quick_.refining(); }
  /// The shown image's reduction (1: full resolution; n: one pixel per n x n).
  int shownReduction() const { return quick_.shownReduction(); }
  /// What a quick frame and one slice of the full frame may take (asynchronous updates).
  void setFrameBudget(double quickMs, double sliceMs) { quick_.setBudget(quickMs, sliceMs); }

 private:
  void updateSorter();
  /// Sorts the tets for ctx's view and uploads the order.
  void sortFor(const RenderContext& ctx);
  /// Binds `image` as the target (cleared if asked) with the program and state of a draw.
  void beginDrawing(const RenderContext& ctx, GLuint image, bool clear);
  /// Draws the sorted tets [first, first + count) over what the image holds.
  void drawRun(std::size_t first, std::size_t count);
  void endDrawing();
  /// Draws the whole order into `image`; returns the milliseconds it took (GPU included).
  double drawWhole(const RenderContext& ctx, GLuint image);
  /// Advances the full frame for about the slice's time; true when it is complete.
  bool refine(const RenderContext& ctx);

  OrderMethod method_;
  Mesh sortMesh_;  ///< the GPU's tets (oriented, degenerate ones left out) in model coordinates
  std::unique_ptr<VisibilitySorter> sorter_;
  std::size_t sortedRevision_ = std::size_t(-1);  ///< the volume's mesh revision the sorter was built for
  VisibilityOrder lastOrder_;
  gl::Buffer order_;
  gl::Framebuffer framebuffer_;
  gl::VertexArray emptyVertexArray_;
  GLuint attachedImage_ = 0;
  QuickFrames quick_;               ///< asynchronous updates: the quick frame and the refinement's state
  std::size_t drawnTets_ = 0;       ///< of the full frame being refined
  std::size_t tetsPerRun_ = 4096;   ///< adapted to the slice's time
  double refineMs_ = 0.0;           ///< the full frame's sorting and drawing so far
  bool sortPending_ = false;        ///< the full frame being refined still has to be sorted
  TetRayDispatch quickRays_;        ///< the quick frames' ray casting
};

}  // namespace volpost::volume

// SPDX-License-Identifier: MIT
// How a slow GPU renderer keeps the window responsive (asynchronous updates): when the
// view or the scene changes, a quick frame at reduced resolution (sized from the measured
// cost per pixel to take ~40 ms) is drawn and shown at once; the renderer then refines the
// full-resolution frame in slices of ~30 ms per render() call and shows it when complete.
// This holds the bookkeeping each such renderer shares: what the shown frame depends on,
// the reduction, the quick image, the measured cost.
#pragma once

#include <volpost/render/GlObjects.hpp>
#include <volpost/render/RenderContext.hpp>

#include <glm/mat4x4.hpp>

#include <chrono>
#include <cstddef>
#include <cstdint>

namespace volpost::volume {

class QuickFrames {
 public:
  /// True when ctx's view, its size, its scene depth or the renderer's state (`revision`,
  /// `meshRevision`, `extra`: e.g. a sort method) differ from the last call's; it then
  /// remembers them and stops any refinement in progress.
  bool viewChanged(const RenderContext& ctx, std::uint64_t revision, std::size_t meshRevision, int extra = 0);
  /// Forgets the last view (the next call to viewChanged is true): the synchronous path.
  void forget();

  /// One asynchronous render() call of a renderer, returning the image to show. On a changed
  /// view or scene: `whole(context, image)` draws a complete frame and returns its
  /// milliseconds, the full frame when it fits the budget, else a quick one, after which
  /// `beginRefining()` starts the full frame; otherwise, while refining, `refine()` advances
  /// it for about sliceMs() and returns true when it is complete.
  template <typename Whole, typename Begin, typename Refine>
  GLuint frame(const RenderContext& ctx, std::uint64_t revision, std::size_t meshRevision, int extra,
               GLuint fullImage, Whole&& whole, Begin&& beginRefining, Refine&& refine) {
    if (viewChanged(ctx, revision, meshRevision, extra)) {
      const int reduction = reductionFor(ctx.width, ctx.height);
      if (reduction == 1) {
        const double ms = whole(ctx, fullImage);
        if (quickFramesElsewhere_) measuredFull(ms, ctx.width, ctx.height);
        else measured(ms, ctx.width, ctx.height);
      } else {
        const RenderContext quick = quickContext(ctx, reduction);  // sizes the quick image: first
        measured(whole(quick, quickImage()), quick.width, quick.height);
        beginRefining();
        startRefining(reduction);
      }
    } else if (refining_ && refine()) {
      doneRefining();
    }
    return refining_ ? quickImage() : fullImage;
  }

  /// One pixel per reduction x reduction for a quick frame of width x height (1: the full
  /// frame fits the budget; 4 before anything was measured).
  int reductionFor(int width, int height) const;
  /// The quick frame's context (reduced size, no scene depth: one depth per full-size
  /// pixel) and its image, sized for it.
  RenderContext quickContext(const RenderContext& ctx, int reduction);
  GLuint quickImage() const { return quickImage_.id(); }
  /// A complete frame of width x height took `ms` (GPU work included): the cost per pixel.
  void measured(double ms, int width, int height);
  /// The last measured cost per pixel (0 before any).
  double msPerPixel() const { return msPerPixel_; }
  /// For a renderer whose quick frames are drawn another way than its full frames (cell
  /// projection's by ray casting: its own cost is per tet and does not shrink with the
  /// resolution): measured() then sizes the quick frames, and the full frame is drawn at
  /// once only where its own cost, given here, fits the quick frame's budget.
  void setQuickFramesElsewhere(bool elsewhere) { quickFramesElsewhere_ = elsewhere; }
  void measuredFull(double ms, int width, int height);

  /// The full frame is being refined; the quick one is shown meanwhile.
  void startRefining(int reduction) {
    refining_ = true;
    reduction_ = reduction;
  }
  void doneRefining() { refining_ = false; }
  bool refining() const { return refining_; }
  /// The shown image's reduction (1: full resolution).
  int shownReduction() const { return refining_ ? reduction_ : 1; }

  void setBudget(double quickMs, double sliceMs) {
    quickMs_ = quickMs;
    sliceMs_ = sliceMs;
  }
  double sliceMs() const { return sliceMs_; }
  std::size_t bytes() const { return std::size_t(quickWidth_) * std::size_t(quickHeight_) * 16; }
  void release();

 private:
  struct Key {
    glm::dmat4 viewProjection{0.0};
    int width = 0, height = 0;
    std::uint64_t revision = 0;
    std::size_t meshRevision = 0;
    GLuint depthTexture = 0;
    int extra = 0;
    bool operator==(const Key&) const = default;
  };
  Key key_;
  bool refining_ = false;
  int reduction_ = 1;
  double quickMs_ = 40.0, sliceMs_ = 30.0;
  double msPerPixel_ = 0.0;
  bool quickFramesElsewhere_ = false;
  double fullMsPerPixel_ = 0.0;  ///< with quick frames drawn elsewhere: the full frame's cost
  gl::Texture quickImage_;
  int quickWidth_ = 0, quickHeight_ = 0;
};

/// Milliseconds since `start`.
double millisecondsSince(std::chrono::steady_clock::time_point start);

}  // namespace volpost::volume

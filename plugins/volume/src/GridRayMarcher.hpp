// SPDX-License-Identifier: MIT
// GPU ray marching through a regular grid (compute shader, one invocation per pixel): each
// ray is cut to the grid's box and the clip planes, then stepped on a fixed lattice along
// it (half the shortest grid spacing unless a sampling step is set); the value at each
// step is the trilinear interpolation of the 8 surrounding points (in float, in the
// shader), and each piece between steps is integrated with the scalar linear along it, in
// the chosen mode (exact linear segments, pre-integrated, sampled), iso-surfaces shaded by
// the trilinear gradient. A grid larger than the GPU memory budget is marched brick by brick
// (GridBricks), front to back. The float image is composited over the target. In the window a
// changed view first gets a quick reduced frame, then the full one in slices of passes
// (QuickFrames).
#pragma once

#include "QuickFrames.hpp"
#include "TetVolumeRenderer.hpp"

#include <array>
#include <vector>

namespace volpost::volume {

class GridRayMarcher final : public GpuVolumeRenderer<GridVolumeRenderer> {
 public:
  std::string name() const override { return "texture-raymarch"; }
  VolumeRendererTraits traits() const override {
    return gridTraits("Ray marching through a 3D texture (regular grids)");
  }
  void setVolume(const Mesh&, FieldLocation, std::span<const double>) override;
  void setGrid(const RegularGrid& grid, SampleView values) override { volume_.setGrid(grid, values); }
  void setGridValues(SampleView values) override { volume_.setGridValues(values); }
  void setShading(bool on) override { volume_.setShading(on); }
  void setTransferFunction2D(const std::optional<TransferFunction2D>& tf) override { volume_.setTransferFunction2D(tf); }
  void initialize() override {
    volume_.initialize();
    quick_.release();
  }
  void release() override;
  void render(const RenderContext& ctx) override;
  /// The step along the ray the next frame uses, model units.
  double marchStep() const { return volume_.gridStep(); }
  /// Bricks the grid is drawn in (1: one texture; more when it exceeds the GPU memory
  /// budget), once a frame has been drawn.
  std::size_t brickCount() const { return volume_.gridBricks().count(); }
  /// Bricks uploaded since the grid was laid out (more than brickCount() when streamed).
  std::size_t brickUploads() const { return volume_.gridBricks().uploads(); }
  std::size_t brickUploadedBytes() const { return volume_.gridBricks().uploadedBytes(); }
  /// Compute passes the last frame took (each at most kStepsPerPass steps per ray through
  /// one brick).
  int lastPasses() const { return lastPasses_; }
  bool hasPendingWork() const override { return volume_.hasPendingWork() || quick_.refining(); }
  int shownReduction() const { return quick_.shownReduction(); }
  void setFrameBudget(double quickMs, double sliceMs) { quick_.setBudget(quickMs, sliceMs); }
  VolumeStats stats() const override {
    VolumeStats s = volume_.stats();
    s.gpuBytes += std::size_t(resumeWidth_) * std::size_t(resumeHeight_) * 8 + quick_.bytes();
    return s;
  }
  /// Steps per ray in one pass: with the ~14 loop iterations a step costs in the shader,
  /// far below the 65535 loop iterations llvmpipe allows an invocation.
  static constexpr int kStepsPerPass = 1024;

 private:
  /// One compute pass of a frame: a pass through one brick (the whole grid unbricked).
  struct Step {
    std::size_t brick = 0;
    int pass = 0;                 ///< 0: rays start where they enter the brick
    std::array<int, 4> pixels{};  ///< the pixels it covers: x0, y0, x1, y1 (exclusive)
  };
  void ensureResumeImage(int width, int height);
  /// Passes a brick needs: enough for the longest ray inside it.
  int passesFor(std::size_t brick) const;
  /// The frame's passes: the bricks front to back, each brick's passes.
  std::vector<Step> planFrame(const RenderContext& ctx) const;
  /// Sets up the march's program for ctx into `image`; returns the program.
  GLuint beginMarch(const RenderContext& ctx, GLuint image);
  void marchPass(GLuint program, const Step& step);
  /// Clears `image` and the rays' state for a new frame.
  void clearFrame(GLuint image);
  /// The whole frame into `image`; returns the milliseconds it took (asynchronous path only).
  double renderWhole(const RenderContext& ctx, GLuint image);
  /// Advances the full frame by passes for about the slice's time; true when complete.
  bool refine(const RenderContext& ctx);
  QuickFrames quick_;
  std::vector<Step> refinePlan_;  ///< the full frame's passes while it is refined
  std::size_t refineStep_ = 0;
  double refineMs_ = 0.0;
  gl::Texture resume_;
  int resumeWidth_ = 0, resumeHeight_ = 0;
  int lastPasses_ = 0;
};

}  // namespace volpost::volume

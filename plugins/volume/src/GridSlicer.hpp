// SPDX-License-Identifier: MIT
// View-aligned slicing of a regular grid's 3D texture (texture-based volume rendering as
// Silva et al. survey it): planes perpendicular to the view direction, sliceSpacing apart on
// a fixed lattice of depths (the picture does not shimmer while the camera moves), are cut
// with the grid's box on the CPU into polygons and drawn back to front, then a quad over
// the picture for where rays enter. Each fragment integrates its ray from
// its slice to the next one behind, or from where the ray enters to the first slice, with
// the scalar linear along it and perspective-correct lengths: the parts partition every
// ray exactly, so the same integration modes, clip planes and iso-surfaces as the ray
// marcher apply and the two pictures converge to the same reference. The slice spacing is the sampling step (0:
// half the shortest grid spacing); a larger one is the interactive mode. In the window a
// changed view first gets a quick reduced frame, with slices as many times further apart
// as its pixels are (the interactive mode), then the full one in runs of slices drawn back
// to front over several paints (QuickFrames), shown when complete (the detailed mode). A grid
// larger than the GPU memory budget is drawn brick by brick (GridBricks), back to front, each
// brick's slices on the same lattice of depths, cut with the brick's box.
#pragma once

#include "QuickFrames.hpp"
#include "TetVolumeRenderer.hpp"

#include <array>
#include <functional>
#include <vector>

namespace volpost::volume {

class GridSlicer final : public GpuVolumeRenderer<GridVolumeRenderer> {
 public:
  std::string name() const override { return "texture-slices"; }
  VolumeRendererTraits traits() const override { return gridTraits("View-aligned texture slices (regular grids)"); }
  void setVolume(const Mesh&, FieldLocation, std::span<const double>) override;
  void setGrid(const RegularGrid& grid, SampleView values) override { volume_.setGrid(grid, values); }
  void setGridValues(SampleView values) override { volume_.setGridValues(values); }
  void setShading(bool on) override { volume_.setShading(on); }
  void setTransferFunction2D(const std::optional<TransferFunction2D>& tf) override { volume_.setTransferFunction2D(tf); }
  void initialize() override;
  void release() override;
  void render(const RenderContext& ctx) override;
  /// The distance between slices the next frame uses, model units.
  double sliceSpacing() const { return volume_.gridStep(); }
  /// Bricks the grid is drawn in (1: one texture; more when it exceeds the GPU memory
  /// budget), once a frame has been drawn.
  std::size_t brickCount() const { return volume_.gridBricks().count(); }
  /// Bricks uploaded since the grid was laid out (more than brickCount() when streamed).
  std::size_t brickUploads() const { return volume_.gridBricks().uploads(); }
  std::size_t brickUploadedBytes() const { return volume_.gridBricks().uploadedBytes(); }
  /// Whether the last frame's slices were spherical shells round the eye (perspective, the
  /// eye inside the grid or nearer it than half its diagonal) rather than planes.
  bool lastUsedShells() const { return shells_; }
  /// Slices the last frame drew (a quick frame's while the full one is refined).
  std::size_t lastSlices() const { return lastSlices_; }
  bool hasPendingWork() const override { return volume_.hasPendingWork() || quick_.refining(); }
  int shownReduction() const { return quick_.shownReduction(); }
  void setFrameBudget(double quickMs, double sliceMs) { quick_.setBudget(quickMs, sliceMs); }
  VolumeStats stats() const override {
    VolumeStats s = volume_.stats();
    s.gpuBytes += quick_.bytes();
    return s;
  }

 private:
  /// What one brick draws (the whole grid unbricked): its slices' vertices, back to
  /// front, then its entry quad's 6.
  struct BrickDraw {
    std::size_t brick = 0;
    std::size_t first = 0, count = 0;  ///< slice vertices
    std::size_t entryFirst = 0;
  };
  /// Cuts ctx's slices, `spacing` apart, with each brick's box, and uploads them with each
  /// brick's entry quad, the bricks back to front (brickDraws_).
  void uploadSlices(const RenderContext& ctx, double spacing);
  /// Binds everything a draw into `image` for ctx needs (clearing it first if asked).
  GLuint beginDrawing(const RenderContext& ctx, GLuint image, bool clear, double spacing);
  /// Slice triangles [first, first + count), back to front; splitting a frame anywhere
  /// between triangles leaves the picture the same (one slice's triangles do not overlap).
  void drawSlices(GLuint program, std::size_t first, std::size_t count);
  /// The part of every ray from its entry into the brick to the brick's nearest slice:
  /// after the brick's slices, over them.
  void drawEntry(GLuint program, const BrickDraw& draw);
  void endDrawing();
  /// The whole frame into `image`, slices `spacing` apart; returns its milliseconds
  /// (asynchronous path only).
  double drawWhole(const RenderContext& ctx, GLuint image, double spacing);
  /// Advances the full frame by runs of slice triangles for about the slice's time; true
  /// when complete.
  bool refine(const RenderContext& ctx);

  gl::Framebuffer framebuffer_;
  gl::VertexArray vertexArray_;
  gl::Buffer vertices_;
  GLuint attachedImage_ = 0;
  std::size_t lastSlices_ = 0;
  bool useShells(const RenderContext& ctx) const;
  std::vector<BrickDraw> brickDraws_;
  bool shells_ = false;
  QuickFrames quick_;
  std::size_t refineBrick_ = 0, drawnVertices_ = 0, verticesPerRun_ = 3 * 1024;
  double refineMs_ = 0.0;
};

/// The polygons (as triangles, 3 points each) where planes at depths spacing * k along
/// `viewDir` from `eye` cut the parallelepiped `corner + a u + b v + c w` (a, b, c in 0..1),
/// farthest plane first; only planes deeper than `nearest`. `grow(depth)`, if given, moves
/// each polygon's corners that much further from its centre. For tests and the renderer.
std::vector<glm::vec3> slicePolygons(const glm::dvec3& corner, const glm::dvec3& u, const glm::dvec3& v,
                                     const glm::dvec3& w, const glm::dvec3& eye, const glm::dvec3& viewDir,
                                     double spacing, double nearest, std::size_t* slices = nullptr,
                                     const std::function<double(double)>& grow = {});

}  // namespace volpost::volume

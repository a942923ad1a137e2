// SPDX-License-Identifier: MIT
// What every GPU volume renderer of this plugin shares: the volume on the GPU (tetrahedra
// and their values, TetMeshGpu, or a regular grid's values as 3D textures, GridTexture), the
// transfer-function tables, clip planes and iso-surfaces, the float image a frame is
// integrated into, and the GLSL that integrates a ray piece (common/volume_segment.glsl;
// through one tet: common/tet_segment.glsl). The ray caster walks rays through the tets;
// cell projection rasterizes them; the grid ray marcher samples the texture. Each owns one.
//
// The setters only record state (no GL). prepare(), with the context current, uploads
// and rebuilds what changed since the last frame, once: the mesh after setVolume, the
// values after setValues, the tables after a new transfer function, mode or value range.
// Clip planes, iso-surfaces and the camera are uniforms and cost nothing to change.
#pragma once

#include "GridTexture.hpp"
#include "ImageComposite.hpp"
#include "TetMeshGpu.hpp"
#include "TransferFunctionTables.hpp"
#include "VisibleTetsGpu.hpp"

#include <volpost/core/RegularGrid.hpp>
#include <volpost/core/TransferFunction2D.hpp>
#include <volpost/render/GlObjects.hpp>

#include <volpost/render/VolumeRenderer.hpp>

#include <chrono>
#include <utility>
#include <cstdint>
#include <future>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace volpost::volume {

class GpuVolume {
 public:
  // ---- state (no GL) ----
  void setVolume(const Mesh& mesh, FieldLocation location, std::span<const double> values);
  /// A regular grid instead of tetrahedra: its point values go to a 3D texture. Throws
  /// std::invalid_argument for a wrong count or a grid with a defect.
  void setGrid(const RegularGrid& grid, SampleView values);
  /// New values on the same tetrahedra or grid.
  void setValues(SampleView values);
  /// New values on the same grid (std::logic_error before setGrid).
  void setGridValues(SampleView values);
  void setTransferFunction(const TransferFunction& tf);
  /// Grids only: a 2D transfer function over the value and its gradient magnitude instead
  /// of the 1D one (nullopt: the 1D one again). Its table is integrated linearly between
  /// the samples, like the 1D one in sampling mode's lattice (compiled as its own mode).
  void setTransferFunction2D(const std::optional<TransferFunction2D>& tf);
  bool hasTransferFunction2D() const { return tf2d_.has_value(); }
  /// Whether what is drawn reads the grid's gradient (shading, a 2D transfer function), which
  /// jumps across cell faces: the grid ray marcher then also cuts its pieces there.
  bool readsGradient() const { return grid_.has() && (shading_ || tf2d_); }
  void setClipPlanes(const std::vector<ClipPlane>& planes);
  void setIsoSurfaces(const std::vector<optics::IsoSurface>& surfaces);
  void setIntegrationMode(IntegrationMode mode);
  void setSamplingStep(double step) {
    samplingStep_ = step;
    ++revision_;
  }
  void setTerminationThreshold(double transmittance) {
    termination_ = transmittance;
    ++revision_;
  }
  /// Headlight shading by the gradient (the grid renderers' shaders honour it).
  void setShading(bool on) {
    shading_ = on;
    ++revision_;
  }
  void setAsynchronousUpdates(bool on) { asynchronous_ = on; }
  /// Tets only: whether rays skip the tets the transfer function and the iso-surfaces leave
  /// transparent (VisibleTetsGpu; on by default). Off, every tet a ray crosses is walked;
  /// the picture is the same (tested).
  void setEmptySpaceSkipping(bool on) {
    if (on == emptySpaceSkipping_) return;
    emptySpaceSkipping_ = on;
    visibleDirty_ = true;
    ++revision_;
  }
  /// The part the last prepare() found: tets that can show something, and the faces where it ends.
  const VisibleTetsGpu& visibleTets() const { return visible_; }
  /// The faces rays enter by, as bindSegmentResources binds them: the visible part's when
  /// hidden tets are skipped, else the mesh's boundary.
  std::size_t entryFaceCount() const {
    return skipsHiddenTets() ? visible_.boundaryFaces() : gpu_.boundaryFaces.size();
  }
  /// Whether the tets and their neighbours stay in host memory after they went to the GPU
  /// (cell projection sorts them on the CPU every frame). Otherwise they are let go once
  /// uploaded (32 bytes per tet: at 100M tets, 3.2 GB of host memory the ray caster never
  /// reads again), and a renderer released and initialized again needs setVolume again.
  void setKeepsTetrahedraOnHost(bool keep) { keepsTetrahedraOnHost_ = keep; }
  bool asynchronous() const { return asynchronous_; }
  bool hasPendingWork() const { return tables_.pending(); }
  /// Changes with anything that changes the picture besides the camera: every setter, and
  /// a transfer-function table that arrives from its worker thread. Renderers that build a
  /// frame over several calls start again when it moves.
  std::uint64_t revision() const { return revision_; }

  const TetMeshGpu& mesh() const { return gpu_; }
  /// Changes whenever the set of tets changes (another mesh, or values that drop tets).
  std::size_t meshRevision() const { return meshRevision_; }
  bool hasTets() const { return gpu_.tetCount > 0; }
  bool hasGrid() const { return grid_.has(); }
  const RegularGrid& grid() const { return grid_.grid(); }
  /// The grid's bricks (one when the grid fits the GPU memory budget), once prepare() has
  /// laid them out.
  const GridBricks& gridBricks() const { return grid_.bricks(); }
  /// The bricks' order for ctx's camera: back to front, or front to back.
  std::vector<std::size_t> gridBricksInOrder(const RenderContext& ctx, bool backToFront) const;
  /// Where brick b can cover the picture: the rectangle round its projected corners in
  /// imageViewProjection's normalized coordinates (-1..1, y down the image), a pixel wider,
  /// or the whole picture when a corner lies behind the eye. Rays outside it miss the brick.
  std::pair<glm::vec2, glm::vec2> gridBrickOnScreen(const RenderContext& ctx, std::size_t b) const;
  /// Makes brick b resident (uploading it if the budget did not keep it), binds its texture
  /// and sets its place in the grid (brickFirst, brickPoints of common/grid_sampling.glsl).
  void bindGridBrick(GLuint program, std::size_t b);
  double samplingStep() const { return samplingStep_; }
  /// The grid renderers' step along rays (or slice spacing): the sampling step when set,
  /// else half the shortest grid spacing (two samples per spacing).
  double gridStep() const { return samplingStep_ > 0.0 ? samplingStep_ : 0.5 * gpu_.maxEdge; }

  // ---- GL (a context current) ----
  void initialize();
  void release();
  bool initialized() const { return initialized_; }
  /// Uploads what changed and sizes the float image for the frame.
  void prepare(const RenderContext& ctx);
  /// The program for these stage files in the current integration mode (built on first
  /// use; the mode, the bindings and the limits are compiled in).
  GLuint program(const std::vector<std::string>& stageFiles);
  /// The uniforms of common/volume_segment.glsl: camera, tables' range, clip planes,
  /// iso-surfaces, scene depth; with a grid, those of common/grid_sampling.glsl too.
  void setSegmentUniforms(GLuint program, const RenderContext& ctx) const;
  /// With a grid, also its uniforms (worldToIndex: volume-relative positions to continuous
  /// indices; gridSize) for common/grid_sampling.glsl.
  void bindSegmentResources(const RenderContext& ctx) const;
  /// For renderers that rasterize into a float image (cell projection, slicing: the full
  /// image or a quick frame's): attaches `image` to `framebuffer` (when `attachedImage`
  /// says another is), binds it, sets the viewport to ctx's size and, if asked, clears it
  /// to transparent.
  static void beginDrawingIntoImage(gl::Framebuffer& framebuffer, GLuint& attachedImage, GLuint image,
                                    const RenderContext& ctx, bool clear);
  /// Their view-projection, volume-relative, drawn upside down so the image's first row is
  /// the top as the compute renderers write it.
  glm::mat4 imageViewProjection(const RenderContext& ctx) const;
  /// Composites the premultiplied float image over what the target already holds.
  void compositeOver(const RenderContext& ctx) const { compositeOver(ctx, image_.id()); }
  /// The same for another float image of the renderer's (e.g. a reduced quick frame).
  void compositeOver(const RenderContext& ctx, GLuint image) const;
  GLuint image() const { return image_.id(); }

  VolumeStats stats() const;
  std::vector<float> readImage() const;

 private:
  void uploadMesh();
  void findVisibleTets(const RenderContext& ctx);
  bool skipsHiddenTets() const { return emptySpaceSkipping_ && !grid_.has() && !visibleDirty_ && visible_.skipping(); }
  void uploadValues();
  void uploadGrid();
  void ensureImage(int width, int height);

  // State.
  const Mesh* mesh_ = nullptr;
  GridTexture grid_;  ///< a regular grid's values, when a grid is drawn instead of tetrahedra
  FieldLocation location_ = FieldLocation::Node;
  TetMeshGpu gpu_;
  bool keepsTetrahedraOnHost_ = false;
  bool tetrahedraOnlyOnGpu_ = false;  ///< gpu_.tets and neighbors were let go after the upload
  TransferFunction tf_;
  std::optional<TransferFunction2D> tf2d_;
  std::vector<ClipPlane> clipPlanes_;
  std::vector<optics::IsoSurface> isoSurfaces_;
  IntegrationMode mode_ = IntegrationMode::LinearSegments;
  double samplingStep_ = 0.0;  ///< 0: a quarter of the mean edge
  double termination_ = 0.002;
  bool shading_ = false;
  bool asynchronous_ = false;
  bool emptySpaceSkipping_ = true;
  std::size_t meshRevision_ = 0;
  std::uint64_t revision_ = 0;

  // What the GPU holds relative to that state.
  bool meshDirty_ = true, valuesDirty_ = false, tablesDirty_ = true, visibleDirty_ = true;
  std::size_t builtRevision_ = std::size_t(-1);
  std::size_t meshUploads_ = 0, valueUploads_ = 0;
  bool initialized_ = false;

  std::map<std::string, gl::Program> programs_;  ///< by stage files and mode
  ImageComposite composite_;
  TransferFunctionTables tables_;  ///< the transfer function as the shaders read it
  gl::Buffer nodes_, tets_, neighbors_, cellValues_, bvh_, boundary_;
  gl::Texture image_;
  bool tf2dDirty_ = false;
  VisibleTetsGpu visible_;
  int imageWidth_ = 0, imageHeight_ = 0;
};

}  // namespace volpost::volume

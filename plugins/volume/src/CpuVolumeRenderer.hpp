// SPDX-License-Identifier: MIT
// The CPU ray caster as a volume renderer of this plugin ("cpu"): the same state as the GPU
// renderers (volume, transfer function, clip planes, iso-surfaces, early termination), the
// frame computed on all cores and blended over the target like theirs. For machines whose
// OpenGL is a software rasterizer, where it is several times faster than the GPU renderers
// and exact. Regular grids are marched (CpuGridMarcher) rather than split into tetrahedra.
//
// With asynchronous updates (the window), a frame never blocks for long: when the view or
// the scene changes, a quick frame at reduced resolution (sized from the measured cost per
// ray to take ~40 ms) is drawn at once, and the full frame is computed on worker threads
// and shown when done (hasPendingWork() says to draw again); a newer change cancels it.
#pragma once

#include "CpuGridMarcher.hpp"
#include "CpuRayCaster.hpp"
#include "ImageComposite.hpp"

#include <volpost/render/GlObjects.hpp>
#include <volpost/render/GridVolumeRenderer.hpp>

#include <atomic>
#include <functional>
#include <future>
#include <memory>
#include <optional>

namespace volpost::volume {

class CpuVolumeRenderer : public GridVolumeRenderer {
 public:
  std::string name() const override { return "cpu"; }
  VolumeRendererTraits traits() const override {
    VolumeRendererTraits t;
    t.label = "Ray casting on the CPU (exact, all cores)";
    t.drawsGrids = t.transferFunction2D = t.shading = true;
    t.samplingStepOnMeshes = false;  // meshes are integrated exactly; grids are marched
    t.runsOnCpu = true;
    t.elementInterpolation = t.elementTolerance = true;
    return t;
  }
  void initialize() override;
  void release() override;
  void render(const RenderContext& ctx) override;

  void setVolume(const Mesh& mesh, FieldLocation location, std::span<const double> values) override;
  void setElementField(std::shared_ptr<const optics::ElementField> field,
                       std::vector<std::uint32_t> cellOfTet) override;
  void setGrid(const RegularGrid& grid, SampleView values) override;
  void setGridValues(SampleView values) override;
  /// Grids only (the marcher shades by the trilinear gradient); meshes are drawn unlit.
  void setShading(bool on) override;
  /// Grids only; a mesh's frame with one set is refused.
  void setTransferFunction2D(const std::optional<TransferFunction2D>& tf) override;
  void setValues(std::span<const double> values) override;
  void setElementTolerance(double tolerance) override;
  void setTransferFunction(const TransferFunction& tf) override {
    tf_ = tf;
    ++revision_;
    visible_.reset();
  }
  void setClipPlanes(const std::vector<ClipPlane>& planes) override;
  void setIsoSurfaces(const std::vector<optics::IsoSurface>& surfaces) override;
  /// The CPU ray caster always integrates exactly: every mode gives the exact image.
  void setIntegrationMode(IntegrationMode mode) override { mode_ = mode; }
  /// Grids only: the march's step (0: half the shortest spacing). Meshes are exact.
  void setSamplingStep(double step) override;
  void setTerminationThreshold(double transmittance) override;
  VolumeStats stats() const override;
  std::vector<float> readImage() const override { return image_.rgba; }
  void setAsynchronousUpdates(bool on) override;
  bool hasPendingWork() const override { return job_.valid(); }

  /// The last frame's counts and times (rays, tets crossed, early stops and their error bound).
  const CpuRenderStats& lastFrame() const { return image_.stats; }
  /// The shown image's reduction (1: full resolution; n: one ray per n x n pixels).
  int shownReduction() const { return shownReduction_; }
  /// Threads for the frames (0: all cores).
  void setThreads(int threads) { threads_ = threads; }
  /// What a quick frame may take while the full one is computed (asynchronous updates).
  void setQuickFrameBudget(double ms) { quickFrameMs_ = ms; }
  ~CpuVolumeRenderer() override;

 private:
  // What a frame depends on besides the state setters (their revision).
  struct FrameKey {
    glm::dmat4 viewProjection{0.0};
    int width = 0, height = 0;
    std::uint64_t revision = 0;
    std::vector<float> depth;
    bool operator==(const FrameKey&) const = default;
  };
  void show(const RenderContext& ctx);  ///< uploads image_ and blends it over the target
  void cancelJob();
  std::shared_ptr<const VisiblePart> visiblePart();  ///< found once per mesh, values, TF and iso-surfaces
  int reductionFor(int width, int height) const;
  /// A frame of whatever is set (mesh or grid); a std::function so worker threads can own it.
  std::function<CpuImage(const Camera&, int, int, const CpuRaySettings&, const Progress&)> frameMaker();

  const Mesh* mesh_ = nullptr;
  FieldLocation location_ = FieldLocation::Node;
  std::shared_ptr<const TetWalkMesh> walkMesh_;
  std::shared_ptr<const GridSamples> grid_;  ///< set instead of walkMesh_ for a grid
  double gridStep_ = 0.0;
  std::uint64_t revision_ = 0;
  std::shared_ptr<const VisiblePart> visible_;  ///< reset by what changes it
  bool asynchronous_ = false;
  double quickFrameMs_ = 40.0;
  double msPerRay_ = 0.0;  ///< measured, for sizing quick frames
  FrameKey shownKey_;
  int shownReduction_ = 1;
  std::future<CpuImage> job_;
  FrameKey jobKey_;
  std::shared_ptr<std::atomic<bool>> jobCancelled_;
  TransferFunction tf_;
  CpuRaySettings settings_;
  IntegrationMode mode_ = IntegrationMode::LinearSegments;
  int threads_ = 0;
  CpuImage image_;
  gl::Texture texture_;
  ImageComposite composite_;
  int textureWidth_ = 0, textureHeight_ = 0;
  bool uploaded_ = false;  ///< image_ is in texture_
  std::size_t meshUploads_ = 0, valueUploads_ = 0;
};

}  // namespace volpost::volume

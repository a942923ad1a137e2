// SPDX-License-Identifier: MIT
// GPU ray casting through tetrahedra (compute shader, one invocation per pixel), drawn
// into a float image and composited over the target.
#pragma once

#include "TetMeshGpu.hpp"

#include <volpost/render/GlObjects.hpp>
#include <volpost/render/VolumeRenderer.hpp>

#include <array>
#include <chrono>
#include <future>

namespace volpost::volume {

class RayCaster : public VolumeRenderer {
 public:
  std::string name() const override { return "raycast"; }
  void initialize() override;
  void release() override;
  void render(const RenderContext& ctx) override;

  void setVolume(const Mesh& mesh, FieldLocation location, std::span<const double> values) override;
  void setValues(std::span<const double> values) override;
  void setTransferFunction(const TransferFunction& tf) override;
  void setClipPlanes(const std::vector<ClipPlane>& planes) override;
  void setIsoSurfaces(const std::vector<optics::IsoSurface>& surfaces) override;
  void setIntegrationMode(IntegrationMode mode) override;
  void setSamplingStep(double step) override { samplingStep_ = step; }
  void setTerminationThreshold(double transmittance) override { termination_ = transmittance; }
  VolumeStats stats() const override;
  std::vector<float> readImage() const override;
  void setAsynchronousUpdates(bool on) override { asynchronous_ = on; }
  bool hasPendingWork() const override { return preFuture_.valid(); }

  /// Texture sizes (set before the first TF): psi table N^2, iso table N^2, pre-integration N^3.
  int psiResolution = 512, isoResolution = 256, preResolution = 64;

 protected:
  // For renderers that integrate the same segments another way (cell projection).
  void prepareFrame(const RenderContext& ctx);
  void setSegmentUniforms(GLuint program, const RenderContext& ctx) const;
  void bindSegmentResources(const RenderContext& ctx) const;
  void compositeOver(const RenderContext& ctx) const;
  bool ready() const { return initialized_ && !gpu_.tets.empty(); }
  const TetMeshGpu& gpuMesh() const { return gpu_; }
  const gl::Texture& image() const { return image_; }
  /// Programs compiled per integration mode (the mode is compiled in, see
  /// tet_segment.glsl), each on first use.
  using ModePrograms = std::array<gl::Program, 3>;
  GLuint programForMode(ModePrograms& programs, const std::vector<std::string>& stageFiles) const;

 private:
  void uploadMesh();
  void rebuildTables();
  void launchPreintegration();
  void uploadPreintegration(const std::vector<float>& values);
  void collectPreintegration(bool wait);
  void ensureImage(int width, int height);

  const Mesh* mesh_ = nullptr;
  FieldLocation location_ = FieldLocation::Node;
  TetMeshGpu gpu_;
  TransferFunction tf_;
  std::vector<ClipPlane> clipPlanes_;
  std::vector<optics::IsoSurface> isoSurfaces_;
  IntegrationMode mode_ = IntegrationMode::LinearSegments;
  double samplingStep_ = 0.0;  ///< 0: a quarter of the mean edge
  double termination_ = 0.002;
  double lastTfMs_ = 0.0;
  std::chrono::steady_clock::time_point tfChanged_;
  bool asynchronous_ = false;
  std::future<std::vector<float>> preFuture_;  ///< the pre-integration table being built
  bool preOutdated_ = false;                   ///< the TF changed again while it was built
  bool initialized_ = false;

  ModePrograms programs_;
  gl::Program compositeProgram_;
  gl::VertexArray quad_;
  gl::Buffer nodes_, tets_, neighbors_, cellValues_, bvh_, boundary_, tfColorTau_, tfValues_;
  gl::Texture psiTable_, isoTable_, preTable_, image_;
  int imageWidth_ = 0, imageHeight_ = 0;
  double tableLo_ = 0.0, tableHi_ = 1.0, preMaxLength_ = 1.0;
};

}  // namespace volpost::volume

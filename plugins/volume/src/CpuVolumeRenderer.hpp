// SPDX-License-Identifier: MIT
// The CPU ray caster as a volume renderer of this plugin ("cpu"): the same state as the GPU
// renderers (volume, transfer function, clip planes, iso-surfaces, early termination), the
// frame computed on all cores and blended over the target like theirs. For machines whose
// OpenGL is a software rasterizer, where it is several times faster than the GPU renderers
// and exact.
#pragma once

#include "CpuRayCaster.hpp"

#include <volpost/render/GlObjects.hpp>
#include <volpost/render/VolumeRenderer.hpp>

#include <memory>
#include <optional>

namespace volpost::volume {

class CpuVolumeRenderer : public VolumeRenderer {
 public:
  std::string name() const override { return "cpu"; }
  void initialize() override;
  void release() override;
  void render(const RenderContext& ctx) override;

  void setVolume(const Mesh& mesh, FieldLocation location, std::span<const double> values) override;
  void setValues(std::span<const double> values) override;
  void setTransferFunction(const TransferFunction& tf) override { tf_ = tf; }
  void setClipPlanes(const std::vector<ClipPlane>& planes) override;
  void setIsoSurfaces(const std::vector<optics::IsoSurface>& surfaces) override;
  /// The CPU ray caster always integrates exactly: every mode gives the exact image.
  void setIntegrationMode(IntegrationMode mode) override { mode_ = mode; }
  void setSamplingStep(double) override {}
  void setTerminationThreshold(double transmittance) override;
  VolumeStats stats() const override;
  std::vector<float> readImage() const override { return image_.rgba; }

  /// The last frame's counts and times (rays, tets crossed, early stops and their error bound).
  const CpuRenderStats& lastFrame() const { return image_.stats; }
  /// Threads for the frames (0: all cores).
  void setThreads(int threads) { threads_ = threads; }

 private:
  const Mesh* mesh_ = nullptr;
  FieldLocation location_ = FieldLocation::Node;
  std::unique_ptr<TetWalkMesh> walkMesh_;
  TransferFunction tf_;
  CpuRaySettings settings_;
  IntegrationMode mode_ = IntegrationMode::LinearSegments;
  int threads_ = 0;
  CpuImage image_;
  gl::Texture texture_;
  gl::Program composite_;
  gl::VertexArray quad_;
  int textureWidth_ = 0, textureHeight_ = 0;
  std::size_t meshUploads_ = 0, valueUploads_ = 0;
};

}  // namespace volpost::volume

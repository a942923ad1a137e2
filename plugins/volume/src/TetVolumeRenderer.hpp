// SPDX-License-Identifier: MIT
// The part of the VolumeRenderer interface that every GPU renderer of this plugin answers
// the same way: state goes to its GpuVolume. A renderer adds how it turns that volume into
// a frame (walking rays, projecting tets, marching through a grid). `Interface` is
// VolumeRenderer, or GridVolumeRenderer for the grid renderers.
#pragma once

#include "GpuVolume.hpp"

#include <volpost/render/GridVolumeRenderer.hpp>

namespace volpost::volume {

template <typename Interface>
class GpuVolumeRenderer : public Interface {
 public:
  void setVolume(const Mesh& mesh, FieldLocation location, std::span<const double> values) override {
    volume_.setVolume(mesh, location, values);
  }
  void setValues(std::span<const double> values) override { volume_.setValues(values); }
  void setTransferFunction(const TransferFunction& tf) override { volume_.setTransferFunction(tf); }
  void setClipPlanes(const std::vector<ClipPlane>& planes) override { volume_.setClipPlanes(planes); }
  void setIsoSurfaces(const std::vector<optics::IsoSurface>& surfaces) override { volume_.setIsoSurfaces(surfaces); }
  void setIntegrationMode(IntegrationMode mode) override { volume_.setIntegrationMode(mode); }
  void setSamplingStep(double step) override { volume_.setSamplingStep(step); }
  void setTerminationThreshold(double transmittance) override { volume_.setTerminationThreshold(transmittance); }
  void setAsynchronousUpdates(bool on) override { volume_.setAsynchronousUpdates(on); }
  bool hasPendingWork() const override { return volume_.hasPendingWork(); }
  VolumeStats stats() const override { return volume_.stats(); }
  std::vector<float> readImage() const override { return volume_.readImage(); }

  /// For tests and benches that look inside.
  const GpuVolume& volume() const { return volume_; }
  GpuVolume& volume() { return volume_; }

 protected:
  /// What a renderer of grids only says of itself: grids as a texture, with every mode,
  /// shading and 2D transfer functions.
  static VolumeRendererTraits gridTraits(std::string label) {
    VolumeRendererTraits t;
    t.label = std::move(label);
    t.drawsMeshes = false;
    t.drawsGrids = t.transferFunction2D = t.shading = true;
    t.modes = allIntegrationModes();
    return t;
  }

  GpuVolume volume_;
};

using TetVolumeRenderer = GpuVolumeRenderer<VolumeRenderer>;

}  // namespace volpost::volume

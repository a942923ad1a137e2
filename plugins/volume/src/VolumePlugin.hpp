// SPDX-License-Identifier: MIT
// The volume plugin: hands the host its volume renderers by name (each says what it is and
// draws through traits()).
#pragma once

#include "CellProjector.hpp"
#include "CpuVolumeRenderer.hpp"
#include "GridRayMarcher.hpp"
#include "GridSlicer.hpp"
#include "RayCaster.hpp"

#include <volpost/plugin/PluginInterfaces.hpp>

#include <QObject>

namespace volpost::volume {

class VolumePlugin : public QObject, public RendererPlugin {
  Q_OBJECT
  Q_PLUGIN_METADATA(IID VOLPOST_RENDERER_PLUGIN_IID FILE "volume.meta.json")
  Q_INTERFACES(volpost::RendererPlugin)

 public:
  /// raycast; vicp: cell projection sorted by MPVONC (fast); vicp-exact: cell projection
  /// sorted in image space (valid on every pixel ray of non-convex meshes); cpu: ray casting on
  /// the CPU's cores (exact on meshes, marching on grids; the fast choice where OpenGL is a
  /// software rasterizer); texture-raymarch: regular grids (seismic cubes, image data) as a
  /// 3D texture marched along rays; texture-slices: the same texture in view-aligned slices.
  QStringList rendererNames() const override {
    return {"raycast", "vicp", "vicp-exact", "cpu", "texture-raymarch", "texture-slices"};
  }
  std::unique_ptr<Renderer> createRenderer(const QString& name) const override {
    if (name == "raycast") return std::make_unique<RayCaster>();
    if (name == "vicp") return std::make_unique<CellProjector>(OrderMethod::Mpvonc);
    if (name == "vicp-exact") return std::make_unique<CellProjector>(OrderMethod::ImageSpace);
    if (name == "cpu") return std::make_unique<CpuVolumeRenderer>();
    if (name == "texture-raymarch") return std::make_unique<GridRayMarcher>();
    if (name == "texture-slices") return std::make_unique<GridSlicer>();
    return nullptr;
  }
};

}  // namespace volpost::volume

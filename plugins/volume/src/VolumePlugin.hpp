// SPDX-License-Identifier: MIT
// The volume plugin: hands the host its GPU volume renderers.
#pragma once

#include "RayCaster.hpp"

#include <volpost/plugin/PluginInterfaces.hpp>

#include <QObject>

namespace volpost::volume {

class VolumePlugin : public QObject, public RendererPlugin {
  Q_OBJECT
  Q_PLUGIN_METADATA(IID VOLPOST_RENDERER_PLUGIN_IID FILE "volume.meta.json")
  Q_INTERFACES(volpost::RendererPlugin)

 public:
  QStringList rendererNames() const override { return {"raycast"}; }
  std::unique_ptr<Renderer> createRenderer(const QString& name) const override {
    if (name == "raycast") return std::make_unique<RayCaster>();
    return nullptr;
  }
};

}  // namespace volpost::volume

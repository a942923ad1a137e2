// SPDX-License-Identifier: MIT
#include "PluginRenderers.hpp"

#include <volpost/plugin/PluginInterfaces.hpp>
#include <volpost/render/GridVolumeRenderer.hpp>

namespace volpost::app {
namespace {

std::unique_ptr<VolumeRenderer> create(const PluginManager& plugins, const QString& name) {
  for (RendererPlugin* plugin : plugins.rendererPlugins()) {
    if (!plugin->rendererNames().contains(name)) continue;
    std::unique_ptr<Renderer> r = plugin->createRenderer(name);
    if (auto* v = dynamic_cast<VolumeRenderer*>(r.get())) {
      r.release();
      return std::unique_ptr<VolumeRenderer>(v);
    }
  }
  return nullptr;
}

}  // namespace

std::vector<RendererEntry> volumeRenderers(const PluginManager& plugins) {
  std::vector<RendererEntry> out;
  for (RendererPlugin* plugin : plugins.rendererPlugins())
    for (const QString& name : plugin->rendererNames())
      if (const auto renderer = create(plugins, name)) {
        const auto* grid = dynamic_cast<const GridVolumeRenderer*>(renderer.get());
        out.push_back({name, plugin->rendererLabel(name), !grid || grid->drawsTetrahedra(), grid != nullptr});
      }
  return out;
}

VolumeRendererFactory volumeRendererFactory(const PluginManager& plugins) {
  return [&plugins](const std::string& name) { return create(plugins, QString::fromStdString(name)); };
}

}  // namespace volpost::app

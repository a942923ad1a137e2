// SPDX-License-Identifier: MIT
#include "PluginRenderers.hpp"

#include <volpost/plugin/PluginInterfaces.hpp>
#include <volpost/render/VolumeRenderer.hpp>

#include <QStringList>

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
      if (const auto renderer = create(plugins, name)) out.push_back({name, renderer->traits()});
  return out;
}

RendererEntry referenceRenderer() {
  RendererEntry r;
  r.name = "reference";
  r.traits.label = "Exact reference on the CPU (double precision, slow)";
  r.traits.drawsGrids = r.traits.transferFunction2D = r.traits.shading = true;
  r.traits.samplingStepOnMeshes = r.traits.samplingStepOnGrids = false;  // integrates exactly
  r.traits.earlyTermination = false;
  r.traits.runsOnCpu = true;
  r.traits.elementInterpolation = true;
  r.drawsSceneLayers = false;
  r.takesThreadCount = true;
  return r;
}

VolumeRendererFactory volumeRendererFactory(const PluginManager& plugins) {
  std::vector<std::string> names;
  for (const RendererPlugin* plugin : plugins.rendererPlugins())
    for (const QString& name : plugin->rendererNames()) names.push_back(name.toStdString());
  VolumeRendererFactory factory{
      [&plugins](const std::string& name) { return create(plugins, QString::fromStdString(name)); }, std::move(names)};
  factory.describeApart(referenceRenderer().name.toStdString(), referenceRenderer().traits);
  return factory;
}

QString rendererNamesWhere(const std::vector<RendererEntry>& entries, bool (*has)(const RendererEntry&)) {
  QStringList names;
  for (const RendererEntry& e : entries)
    if (has(e)) names << e.name;
  return names.join(", ");
}

}  // namespace volpost::app

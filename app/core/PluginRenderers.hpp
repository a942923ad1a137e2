// SPDX-License-Identifier: MIT
// The volume renderers the loaded plugins offer, by name and in words.
#pragma once

#include "Scene.hpp"

#include <volpost/plugin/PluginManager.hpp>

#include <QString>

#include <vector>

namespace volpost::app {

struct RendererEntry {
  QString name;   ///< what the command line and state files say ("raycast")
  QString label;  ///< what the menu says ("Ray casting"), from the plugin
  bool drawsMeshes = true;   ///< meshes of tetrahedra (any mesh, split into them)
  bool drawsGrids = false;   ///< regular grids as grids (a GridVolumeRenderer)
};

/// Every volume renderer of every loaded renderer plugin, in plugin order.
std::vector<RendererEntry> volumeRenderers(const PluginManager& plugins);

/// Creates volume renderers by name from the plugins (which must outlive it).
VolumeRendererFactory volumeRendererFactory(const PluginManager& plugins);

}  // namespace volpost::app

// SPDX-License-Identifier: MIT
// The volume renderers the loaded plugins offer, by name, each with what it says of itself.
#pragma once

#include "Scene.hpp"

#include <volpost/plugin/PluginManager.hpp>
#include <volpost/render/VolumeRendererTraits.hpp>

#include <QString>

#include <vector>

namespace volpost::app {

struct RendererEntry {
  QString name;                 ///< what the command line and state files say ("raycast")
  VolumeRendererTraits traits;  ///< what it draws and takes, and its words for a menu
  /// Drawn by the scene with its other layers (edges, slices, streamlines); false for the
  /// host's reference, which draws the volume alone, off the GL path.
  bool drawsSceneLayers = true;
  /// Takes a thread count (--threads).
  bool takesThreadCount = false;
  QString label() const { return QString::fromStdString(traits.label); }
  /// Draws this kind of model's values as it is: a grid as a grid, a mesh as tetrahedra.
  bool drawsKindOf(bool grid) const { return grid ? traits.drawsGrids : traits.drawsMeshes; }
};

/// Every volume renderer of every loaded renderer plugin, in plugin order.
std::vector<RendererEntry> volumeRenderers(const PluginManager& plugins);

/// The host's exact reference renderer ("reference": CPU, double precision, the yardstick
/// of the others; ReferenceVolumeImage.hpp), described like a plugin's.
RendererEntry referenceRenderer();

/// Creates volume renderers by name from the plugins (which must outlive it).
VolumeRendererFactory volumeRendererFactory(const PluginManager& plugins);

/// The names of the renderers in `entries` for which `has` is true: "texture-raymarch,
/// texture-slices, cpu", for messages that say which renderers take an option.
QString rendererNamesWhere(const std::vector<RendererEntry>& entries, bool (*has)(const RendererEntry&));

}  // namespace volpost::app

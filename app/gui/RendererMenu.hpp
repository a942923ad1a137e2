// SPDX-License-Identifier: MIT
// The window's choice of volume renderer: View > Volume Renderer (every renderer the
// plugins offer, in their own words) and View > Volume Integration (the modes the chosen
// renderer has). What is offered, checked and chosen by default comes from what each
// renderer says of itself (VolumeRendererTraits); the scene is the record of the choice.
#pragma once

#include "ChangeScene.hpp"

#include "../core/PluginRenderers.hpp"

#include <QObject>
#include <QString>

#include <functional>
#include <vector>

class QAction;
class QMainWindow;
class QMenu;

namespace volpost::app {

class Scene;

class RendererMenu : public QObject {
  Q_OBJECT

 public:
  /// Adds the two menus to `view`; the first renderer is the scene's until another is
  /// chosen. `shown`: the scene's renderer changed (the window repaints a shown volume).
  RendererMenu(QMainWindow& window, Scene& scene, std::vector<RendererEntry> renderers, QMenu& view,
               ChangeScene changeScene, std::function<void()> shown);

  const std::vector<RendererEntry>& renderers() const { return renderers_; }
  /// OpenGL drawn by the CPU (`glDescription` names a software rasterizer): the first
  /// renderer that computes on the CPU goes first in the menu and is chosen, unless the
  /// user or a state file chose one; the others say they are slow here.
  void preferCpuOnSoftwareGl(const QString& glDescription);
  /// Another model: renderers that cannot draw its kind are shown but not offered, and the
  /// scene's renderer gives way to the first that draws it where it cannot.
  void fitToModel(bool grid);
  /// The menus show the scene's renderer and mode (after a state file, which names its
  /// renderer: no automatic choice after it).
  void syncToScene();

 private:
  void choose(const QString& name);
  void check(const QString& name);
  void fitModes();
  QAction* actionOf(const QString& name) const;

  QMainWindow& window_;
  Scene& scene_;
  std::vector<RendererEntry> renderers_;
  ChangeScene changeScene_;
  std::function<void()> shown_;
  QMenu* rendererMenu_ = nullptr;
  QMenu* modeMenu_ = nullptr;
  bool chosen_ = false;  ///< by the user or a state file: no automatic choice then
};

}  // namespace volpost::app

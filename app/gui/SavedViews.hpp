// SPDX-License-Identifier: MIT
// The window's views: View > Previous View (back through the cameras before each drag,
// zoom, standard or saved view), Save View... (the camera under a name) and Saved Views
// (turn to one, or remove it). The scene keeps them, so state files and `render --view
// NAME` have them too; the menu lists what the scene holds.
#pragma once

#include "ChangeScene.hpp"

#include <QObject>
#include <QString>

#include <functional>

class QAction;
class QMainWindow;
class QMenu;

namespace volpost::app {

class Scene;

class SavedViews : public QObject {
  Q_OBJECT

 public:
  /// Adds the entries to `view`; `redraw`: the view repaints.
  SavedViews(QMainWindow& window, Scene& scene, QMenu& view, ChangeScene changeScene, std::function<void()> redraw);

  /// View > Save View...: asks for a name (the next free "View N" offered).
  void save();
  /// Saves the camera as it is under `name`; false, saying why, when it cannot be one.
  bool saveAs(const QString& name);
  /// View > Previous View; false (said in the status bar) when there is none.
  bool previous();
  /// The Saved Views menu lists the scene's views (after a state file or a new model).
  void syncToScene();

 private:
  QMainWindow& window_;
  Scene& scene_;
  ChangeScene changeScene_;
  std::function<void()> redraw_;
  QMenu* saved_ = nullptr;
  QMenu* remove_ = nullptr;
};

}  // namespace volpost::app

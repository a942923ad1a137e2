// SPDX-License-Identifier: MIT
// View > Representation: how the model's boundary is drawn (surface, wireframe, points,
// feature edges, outline), whether it is drawn at all, and the points' size; View >
// Background Color. The entries
// show the scene's state (a state file's included); the scene is the one record.
#pragma once

#include "ChangeScene.hpp"

#include "../core/SurfaceRepresentation.hpp"

#include <QObject>

#include <map>

class QAction;
class QMenu;
class QWidget;

namespace volpost::app {

class Scene;

class DisplayActions : public QObject {
  Q_OBJECT

 public:
  /// Adds the Representation menu to `view`.
  DisplayActions(QWidget& window, Scene& scene, QMenu& view, ChangeScene changeScene);
  void syncToScene();

 private:
  void choosePointSize();
  /// View > Background Color: behind the model, in the window and its pictures.
  void chooseBackground();

  QWidget& window_;
  Scene& scene_;
  ChangeScene changeScene_;
  std::map<SurfaceRepresentation, QAction*> representations_;
  QAction* shown_ = nullptr;
};

}  // namespace volpost::app

// SPDX-License-Identifier: MIT
// Results > Select: picking elements and nodes in the view. Select Elements (S) and Select
// Nodes (N) take what is seen inside a dragged box (or under a click): the surface and the
// cut faces; their Through variants take everything whose centre (node) lies in the box,
// however deep. Ctrl or Shift adds to the selection. The selection becomes the sets
// "selected elements" and "selected nodes" (the Sets panel shows, hides, colors and numbers
// them) and is marked in the picture; Clear Selection forgets it.
#pragma once

#include "../core/BoxSelection.hpp"
#include "ChangeScene.hpp"

#include <QObject>

#include <functional>

class QAction;
class QActionGroup;
class QMainWindow;
class QMenu;

namespace volpost::app {

class Viewport;

class SelectionActions : public QObject {
  Q_OBJECT

 public:
  /// `changed` runs after the selection changed (the panels follow it).
  SelectionActions(QMainWindow& window, Viewport& viewport, QMenu& resultsMenu, ChangeScene change,
                   std::function<void()> changed);
  /// The actions follow the scene (another model, a state file).
  void syncToScene();

 private:
  struct Mode {
    bool nodes = false;
    SelectionDepth depth = SelectionDepth::Surface;
  };
  QAction* addMode(QMenu& menu, const QString& text, const QKeySequence& key, Mode mode, const QString& tip);
  void select(const PictureBox& box, bool add);
  void clear();

  QMainWindow& window_;
  Viewport& viewport_;
  ChangeScene change_;
  std::function<void()> changed_;
  QActionGroup* modes_ = nullptr;
  QAction* clear_ = nullptr;
  Mode mode_;
};

}  // namespace volpost::app

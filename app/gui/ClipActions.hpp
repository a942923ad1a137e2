// SPDX-License-Identifier: MIT
// The window's clipping: View > Clip Plane (off, a plane through the model's centre along
// an axis, a typed plane, the handles, a typed clip box) and what the viewport's handles
// drag. The menu shows the scene's first plane as it is: the axis entry of its normal, or
// none for a typed or turned plane; the scene is the one record of the planes and the box.
#pragma once

#include "ChangeScene.hpp"

#include "../core/SceneState.hpp"

#include <QObject>

#include <array>
#include <cstddef>
#include <functional>

class QAction;
class QMainWindow;
class QMenu;

namespace volpost::app {

class Scene;

class ClipActions : public QObject {
  Q_OBJECT

 public:
  /// Adds the Clip Plane menu to `results`. `redraw`: the view repaints; `drawNow`: it
  /// draws at once and answers how many tetrahedra the volume renderer holds (for the
  /// clip box's message).
  ClipActions(QMainWindow& window, Scene& scene, QMenu& results, ChangeScene changeScene, std::function<void()> redraw,
              std::function<std::size_t()> drawNow);

  /// Off (-1) or a plane through the model's centre with the normal +X (0), +Y (1), +Z (2).
  void setAxis(int axis);
  /// View > Clip Plane > Type Plane...: a point and a normal, until valid or cancelled.
  void typePlane();
  /// View > Clip Plane > Clip Box...: six numbers, until valid or cancelled; empty: none.
  void typeBox();
  /// A box from the dialog or the viewport's face handles (on release).
  void applyBox(const ClipBox& box);
  /// Clip Plane > Invert Plane: the first plane keeps the other side.
  void invertPlane();
  /// Clip Plane > Slice Here: the first plane becomes a slice (its section drawn, nothing
  /// cut away).
  void planeToSlice();
  /// Clip Plane > Slices...: the slices typed, one plane per line; empty: none.
  void typeSlices();
  /// The viewport's handle moved a plane: the menu and the status bar say where; Invert
  /// Plane then turns that one.
  void planeDragged(const ClipPlane& plane);
  /// The menu shows the scene's first plane (a state file's, another model's none).
  void syncToScene();

 private:
  void checkAxisOf(const ClipPlane* plane);

  QMainWindow& window_;
  Scene& scene_;
  ChangeScene changeScene_;
  std::function<void()> redraw_;
  std::function<std::size_t()> drawNow_;
  QMenu* menu_ = nullptr;
  std::array<QAction*, 4> axisActions_{};  ///< Off, +X, +Y, +Z
  std::size_t activePlane_ = 0;            ///< the free plane last dragged (Invert Plane turns it)
};

}  // namespace volpost::app

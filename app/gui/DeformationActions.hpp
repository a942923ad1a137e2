// SPDX-License-Identifier: MIT
// The window's deformed shape: Results > Deformed Shape (D), Undeformed Outline and
// Deformation Scale. The displacement is the field named as one (U, DISP, displacement),
// else the one the user picks among the nodal vectors; the scale is automatic or typed.
// The scene is the one record of the deformation; the menu shows it.
#pragma once

#include "ChangeScene.hpp"

#include <QObject>

#include <functional>
#include <optional>
#include <string>

class QAction;
class QMainWindow;
class QMenu;

namespace volpost::app {

class Scene;

class DeformationActions : public QObject {
  Q_OBJECT

 public:
  /// Adds the entries to `menu`. `changed`: the drawn model changed (lines to trace again,
  /// panels to tell).
  DeformationActions(QMainWindow& window, Scene& scene, QMenu& menu, ChangeScene changeScene,
                     std::function<void()> changed);

  /// Shows the model deformed (or not) with this scale (nullopt: automatic); asks for the
  /// field when none is named as a displacement.
  void show(bool on, std::optional<double> scale);
  /// Results > Deformation Scale...: a factor, or empty for the automatic one.
  void typeScale();
  /// The menu shows the scene's deformation.
  void syncToScene();

 private:
  std::optional<std::string> chooseDisplacementField();

  QMainWindow& window_;
  Scene& scene_;
  ChangeScene changeScene_;
  std::function<void()> changed_;
  QAction* shown_ = nullptr;
  QAction* outline_ = nullptr;
};

}  // namespace volpost::app

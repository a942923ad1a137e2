// SPDX-License-Identifier: MIT
// The window's volume entries: View > Volume Rendering (V), Shade the Volume by Its
// Gradient (grids), the Cells' Own Interpolation and its tolerance (meshes), Load a 2D Transfer Function
// (grids)... and Use the 1D Transfer Function. The scene is the one record of them; the entries show it.
#pragma once

#include "../core/ReferenceVolumeImage.hpp"
#include "ChangeScene.hpp"

#include <volpost/core/TransferFunction2D.hpp>

#include <QObject>
#include <QString>

#include <functional>
#include <optional>
#include <string>
#include <vector>

class QAction;
class QMainWindow;
class QMenu;

namespace volpost::app {

class Scene;

class VolumeActions : public QObject {
  Q_OBJECT

 public:
  /// What the window does when the volume changes.
  struct Followers {
    std::function<void()> shown;          ///< the volume is shown: its transfer-function panels open
    std::function<void()> viewChanged;    ///< volume or surface: the panels follow
    std::function<void()> tablesChanged;  ///< a 2D transfer function came or went: the editors show it
  };

  /// Adds the entries to `view`; without a volume renderer loaded, Volume Rendering is
  /// disabled and says why.
  VolumeActions(QMainWindow& window, Scene& scene, QMenu& view, bool renderersLoaded, ChangeScene changeScene,
                Followers followers);

  /// Volume rendering of the shown result on or off; off again, saying why, without a
  /// result or when the scene refuses it.
  void show(bool on);
  /// A 2D transfer function (grids only), or nullopt for the 1D one; false, saying why in
  /// the status bar, when the scene keeps its own.
  bool setTransferFunction2D(const std::optional<TransferFunction2D>& tf);
  /// Reads a volpost-tf2d file and draws with it; false (and a message naming the file)
  /// when it is not one or the model is not a grid.
  bool loadTransferFunction2D(const QString& path);
  /// The cells' own field's tolerance per pixel channel (0: exact); false, saying why in
  /// the status bar, where the scene refuses the value.
  bool setElementTolerance(double tolerance);
  /// The entries show the scene's volume and shading.
  void syncToScene();

 private:
  QMainWindow& window_;
  Scene& scene_;
  ChangeScene changeScene_;
  Followers followers_;
  QAction* volume_ = nullptr;
  QAction* shading_ = nullptr;
  QAction* edges_ = nullptr;          ///< element edges over the volume
  QAction* outline_ = nullptr;        ///< the model's feature edges over the volume
  QAction* interpolation_ = nullptr;  ///< the cells' own interpolation (else the tetrahedra's)
  QAction* tolerance_ = nullptr;      ///< its tolerance, shown in the entry's text
  /// Asks for the tolerance (a number box starting at the current one).
  void askElementTolerance();
  /// The cells' own interpolation on or off; refused, saying why, where the renderer in use
  /// draws the tetrahedra's field only.
  void drawCellsOwnField(bool on);
  /// What the user should know of the cells' own field on this model: the cells drawn by
  /// their split (folded, inverted or collapsed), named.
  std::vector<std::string> cellsDrawnBySplit(BentCells bent) const;
};

}  // namespace volpost::app

// SPDX-License-Identifier: MIT
// The window's streamlines: View > Streamlines (the dialog, placing a rake, showing them)
// and their tracing, on a worker thread behind a cancellable progress dialog, handed to
// the scene when done. The scene is the one record of the layer and of the lines traced;
// the lines are traced in the model as drawn (deformed, when the deformed shape is shown).
#pragma once

#include "ChangeScene.hpp"

#include <glm/vec3.hpp>

#include <QObject>
#include <QString>

#include <functional>
#include <vector>

class QAction;
class QMainWindow;
class QMenu;

namespace volpost::app {

class Scene;
struct StreamlineLayer;

class StreamlineActions : public QObject {
  Q_OBJECT

 public:
  /// Adds the Streamlines menu to `results`. `startRake`: the viewport's rake mode starts
  /// (a drag across the model then comes back as placeRake); `redraw`: the view repaints.
  StreamlineActions(QMainWindow& window, Scene& scene, QMenu& results, ChangeScene changeScene,
                    std::function<void()> startRake, std::function<void()> redraw);

  /// View > Streamlines > Streamlines...: the dialog, until its layer is accepted by the
  /// scene or it is cancelled.
  void choose();
  /// A rake drawn with the mouse: its points become the seeds of the streamlines of the
  /// layer's field, or of the model's first nodal vector field.
  void placeRake(const std::vector<glm::dvec3>& seeds);
  /// Traces the scene's streamlines if they need it, then shows them; emits traced. A
  /// change while tracing traces again at the end.
  void trace();
  /// The menu shows whether the scene shows streamlines.
  void syncToScene();

 signals:
  /// The streamlines shown were traced (ok) or could not be (message says why).
  void traced(bool ok, const QString& message);

 private:
  /// Shows the layer (the surface see-through so the lines show) and traces it.
  bool show(const StreamlineLayer& layer);
  void showTraced();

  QMainWindow& window_;
  Scene& scene_;
  ChangeScene changeScene_;
  std::function<void()> redraw_;
  QAction* shown_ = nullptr;
  bool tracing_ = false;
};

}  // namespace volpost::app

// SPDX-License-Identifier: MIT
#include "SeeThroughSurface.hpp"

#include "../core/Scene.hpp"

#include <QMainWindow>
#include <QPointer>
#include <QStatusBar>
#include <QTimer>

namespace volpost::app {

void seeThroughSurface(QMainWindow& window, Scene& scene, const QString& what) {
  if (scene.shown().surfaceOpacity < 1.0) return;
  scene.setSurfaceOpacity(0.3);
  // After the change's own message, which would otherwise replace this one.
  QTimer::singleShot(0, &window, [window = QPointer<QMainWindow>(&window), what] {
    if (!window) return;
    window->statusBar()->showMessage(
        QString("The surface is see-through so that %1 show (View > Surface Opacity...)").arg(what), 10000);
  });
}

}  // namespace volpost::app

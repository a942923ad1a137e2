// SPDX-License-Identifier: MIT
// What is inside the model (iso-surfaces, streamlines) does not show through an opaque
// surface: the parts that add it make the surface see-through and say why.
#pragma once

#include <QString>

class QMainWindow;

namespace volpost::app {

class Scene;

/// Makes the surface see-through (30 %) when it is opaque, and says so in the window's
/// status bar, naming `what` would not show otherwise ("the streamlines inside").
void seeThroughSurface(QMainWindow& window, Scene& scene, const QString& what);

}  // namespace volpost::app

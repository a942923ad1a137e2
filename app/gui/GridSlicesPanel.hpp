// SPDX-License-Identifier: MIT
// View > Grid Slices (a dock): a regular grid's three slices (inline, crossline and time for a
// survey), each switched on by its box and moved by its slider (arrow keys, Page Up/Down
// once it has the focus), its label shown beside it; the picture follows as the slider
// moves. A box for the model's surface, which hides the slices inside the volume.
#pragma once

#include <QWidget>

#include <array>
#include <functional>
#include <optional>

class QCheckBox;
class QLabel;
class QSlider;

namespace volpost {
struct RegularGrid;
}

namespace volpost::app {

class Scene;

class GridSlicesPanel : public QWidget {
  Q_OBJECT

 public:
  /// `changed`: the scene changed (the window redraws).
  GridSlicesPanel(Scene& scene, std::function<void()> changed, QWidget* parent = nullptr);
  /// Another model: the controls follow its grid (or are disabled without one).
  void followScene();

 private:
  void apply();

  Scene& scene_;
  std::function<void()> changed_;
  std::array<QCheckBox*, 3> shown_{};
  std::array<QSlider*, 3> sliders_{};
  std::array<QLabel*, 3> labels_{};
  QCheckBox* surface_ = nullptr;
  bool following_ = false;
};

}  // namespace volpost::app

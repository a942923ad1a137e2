// SPDX-License-Identifier: MIT
// Steps and load cases in the window: previous / next / play (Page Up, Page Down,
// Ctrl+Space) beside the step box, the color range (each step's own, over all steps, or
// typed), and File > Export Animation: a video or one numbered picture per step.
#pragma once

#include "../core/AnimationFrames.hpp"

#include <QObject>

#include <functional>

class QAction;
class QComboBox;
class QLineEdit;
class QMainWindow;
class QMenu;
class QTimer;
class QToolBar;

namespace volpost::app {

class Viewport;

class StepController : public QObject {
  Q_OBJECT

 public:
  /// `stepBox`: the window's step chooser (choosing in it shows the step); `changed`: the
  /// scene's colors changed (panels and legend follow).
  StepController(QMainWindow& window, Viewport& viewport, QToolBar& toolbar, QComboBox& stepBox, QMenu& viewMenu,
                 QMenu& fileMenu, std::function<void()> changed);

  /// Another model or result: the buttons follow the step count, playing stops.
  void refresh();
  /// Another quantity: a typed range (in the old quantity's units) gives way to each
  /// step's own.
  void quantityChanged();
  /// The range controls follow the scene (after a state file is opened).
  void syncToScene();
  /// Writes the view at every step as numbered pictures next to `path` (path_001.png ...),
  /// or as one video when `path` is one (.mp4 ...; `framesPerSecond` frames per second),
  /// with `between` frames interpolated between each step and the next (0..100), with a
  /// cancellable progress dialog; returns how many frames were written (0 for a video
  /// that was cancelled or failed: then no file is left).
  int exportAnimation(const QString& path, double framesPerSecond = AnimationOutput::kDefaultFramesPerSecond,
                      int between = 0);
  bool playing() const;

 private:
  void step(int delta);
  void setPlaying(bool on);
  void chooseRangeMode(int index);
  void applyTypedRange();
  void showRangeFields();

  QMainWindow& window_;
  Viewport& viewport_;
  QComboBox& stepBox_;
  std::function<void()> changed_;
  QAction* previous_ = nullptr;
  QAction* next_ = nullptr;
  QAction* play_ = nullptr;
  QTimer* timer_ = nullptr;
  QComboBox* rangeBox_ = nullptr;
  QLineEdit* minEdit_ = nullptr;
  QLineEdit* maxEdit_ = nullptr;
  QAction* minField_ = nullptr;
  QAction* maxField_ = nullptr;
};

}  // namespace volpost::app

// SPDX-License-Identifier: MIT
// The window's state files: File > Open State... and Save State... (and a .json dropped on
// the window). A state names its model: when another model is shown, that one is read
// first, then the state is applied; the scene checks it whole and keeps what it had when
// it does not fit. `volpost render --state` draws the same picture from the same file.
#pragma once

#include "../core/SceneState.hpp"

#include <QObject>
#include <QString>

#include <functional>

class QMainWindow;
class QMenu;

namespace volpost::app {

class Scene;

class StateFiles : public QObject {
  Q_OBJECT

 public:
  /// Reads a model and shows it, then calls `then` (ok, or the error); false when it cannot
  /// start (another file is still being read).
  using OpenModel = std::function<bool(const QString& path, const ReaderOptions& options,
                                       std::function<void(bool ok, const QString& error)> then)>;

  /// Adds Open State... and Save State... to `file`. `followScene`: the scene took a state;
  /// the window's controls and panels follow it.
  StateFiles(QMainWindow& window, Scene& scene, QMenu& file, OpenModel openModel, std::function<void()> followScene);

  /// Writes the view (model, result, camera, colors, layers) to `path`; false, saying why
  /// in the status bar, when it cannot be written (the file there stays as it was).
  bool save(const QString& path);
  /// Reads a state file: its model first when another is shown, then its view. Emits
  /// applied(ok, message) when done.
  void open(const QString& path);
  /// Applies a state to the model shown; emits applied. A volume the state draws apart
  /// (with the exact reference) is drawn by the window's renderer instead, and said so.
  void apply(const SceneState& state);

 signals:
  void applied(bool ok, const QString& message);

 private:
  void chooseToSave();
  void chooseToOpen();
  bool showsModelOf(const SceneState& state) const;

  QMainWindow& window_;
  Scene& scene_;
  OpenModel openModel_;
  std::function<void()> followScene_;
};

}  // namespace volpost::app

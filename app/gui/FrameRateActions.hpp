// SPDX-License-Identifier: MIT
// View > Show Frame Rate and View > Log Frame Times...: how long the user waits for the
// view, measured in the window itself (Viewport's FrameTimes), shown at the view's corner
// and, on request, written line by line to a file.
#pragma once

#include <QObject>

class QAction;
class QMenu;
class QStatusBar;
class QWidget;

namespace volpost::app {

class Viewport;

class FrameRateActions : public QObject {
  Q_OBJECT

 public:
  FrameRateActions(QWidget& window, Viewport& viewport, QMenu& view, QStatusBar& status);
  /// Starts (a path) or stops (empty) the log; false with the reason in the status bar
  /// when the file cannot be written. The entry shows whether a log is written.
  bool logTo(const QString& path);

 private:
  QWidget& window_;
  Viewport& viewport_;
  QStatusBar& status_;
  QAction* show_ = nullptr;
  QAction* log_ = nullptr;
};

}  // namespace volpost::app

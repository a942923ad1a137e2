// SPDX-License-Identifier: MIT
// Waits until a viewport shows its full picture: a frame painted after the wait began, and
// no full frame still computed behind a quick one (the status bar's "Refining the
// picture..."), seen twice 50 ms apart since a paint may be queued. For `volpost
// --screenshot`, which must save what the view settles on, not its quick frame.
#pragma once

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

namespace volpost::app {

class Viewport;

class SettledView : public QObject {
  Q_OBJECT

 public:
  /// Starts waiting at once; `settled` comes at least `minimumMs` later, or `timedOut`
  /// after `limitMs` if the view is still refining then.
  SettledView(Viewport* view, int minimumMs = 300, int limitMs = 10 * 60 * 1000, QObject* parent = nullptr);

 signals:
  void settled();
  void timedOut();

 private:
  void poll();

  Viewport* view_;
  QTimer timer_;
  QElapsedTimer clock_;
  std::size_t framesBefore_;
  int minimumMs_, limitMs_, calmPolls_ = 0;
};

}  // namespace volpost::app

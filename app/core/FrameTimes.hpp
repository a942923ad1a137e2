// SPDX-License-Identifier: MIT
// What the user waits for in the window, timed: from an input that changes the view (a
// drag's move, a wheel step) to the frame that shows it, how many frames a second follow a
// drag, and from the last change to the full picture (a renderer that draws a quick frame
// first computes the full one meanwhile). Times are milliseconds of one steady clock, given
// by the caller, so that tests can drive it.
#pragma once

#include <cstddef>
#include <deque>
#include <functional>
#include <optional>
#include <string>

namespace volpost::app {

class FrameTimes {
 public:
  struct Summary {
    std::optional<double> inputToFrameMs;   ///< median over the recent frames that answered input
    std::optional<double> framesPerSecond;  ///< while the view is moved: from the median interval
    std::optional<double> changeToFullMs;   ///< the last full picture, after the last change
    std::size_t framesAnswered = 0;         ///< since the start (or reset)
  };

  /// An input that changes the picture arrived at `ms`.
  void inputAt(double ms);
  /// A frame was presented at `ms`; `quick`: it is a quick one, the full picture follows.
  void paintedAt(double ms, bool quick);
  Summary summary() const;
  /// Forgets what was measured (a new model, the readout switched on).
  void reset();
  /// Called with one line per measurement ("frame 23.4 ms after input, quick"): the log.
  void setLog(std::function<void(const std::string&)> log) { log_ = std::move(log); }
  /// "frame 38 ms after input, 24 per second; full picture 0.84 s after the last change".
  static std::string text(const Summary& s);

 private:
  static constexpr std::size_t kRecent = 30;   ///< frames the medians look at
  static constexpr double kNewDragMs = 500.0;  ///< a longer pause between frames starts a new drag

  std::optional<double> firstInput_;  ///< the first input the next frame answers
  std::optional<double> lastInput_;   ///< the last input: the full picture's clock
  std::optional<double> lastAnswer_;  ///< when the last frame that answered input was presented
  bool awaitingFull_ = false;
  std::deque<double> latencies_, intervals_;
  std::optional<double> changeToFull_;
  std::size_t answered_ = 0;
  std::function<void(const std::string&)> log_;
};

}  // namespace volpost::app

// SPDX-License-Identifier: MIT
// The window's frame timing on a clock the test drives: latency from the first input a
// frame answers, the rate while dragging (a pause starts a new drag), the full picture after
// the last change, and the log's lines.
#include "core/FrameTimes.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace volpost::app {
namespace {

TEST(FrameTimes, ADragIsTimedFromInputToFrameAndToTheFullPicture) {
  FrameTimes times;
  std::vector<std::string> log;
  times.setLog([&](const std::string& line) { log.push_back(line); });
  EXPECT_EQ(FrameTimes::text(times.summary()), "move the view to time its frames");
  // A drag: moves every 10 ms, a quick frame every 50 ms answering the moves since the last.
  double t = 0.0;
  for (int frame = 0; frame < 5; ++frame) {
    for (int move = 0; move < 5; ++move, t += 10.0) times.inputAt(t);
    times.paintedAt(t + 30.0, true);  // 80 ms after the first of its 5 moves
  }
  times.paintedAt(t + 100.0, true);    // a repaint that answers nothing: not a frame
  times.paintedAt(t + 1200.0, false);  // the full picture
  const FrameTimes::Summary s = times.summary();
  ASSERT_TRUE(s.inputToFrameMs && s.framesPerSecond && s.changeToFullMs);
  EXPECT_DOUBLE_EQ(*s.inputToFrameMs, 80.0);
  EXPECT_DOUBLE_EQ(*s.framesPerSecond, 20.0);   // one frame every 50 ms
  EXPECT_DOUBLE_EQ(*s.changeToFullMs, 1210.0);  // from the last move, at t - 10
  EXPECT_EQ(s.framesAnswered, 5u);
  EXPECT_EQ(FrameTimes::text(s), "frame 80 ms after input, 20 per second; full picture 1.21 s after the last change");
  ASSERT_EQ(log.size(), 6u);
  EXPECT_EQ(log.front(), "frame 80 ms after input, quick");
  EXPECT_EQ(log.back(), "full picture 1.21 s after the last change");
}

TEST(FrameTimes, APauseStartsANewDragAndResetForgets) {
  FrameTimes times;
  times.inputAt(0.0);
  times.paintedAt(20.0, false);  // a surface frame: full at once
  times.inputAt(5000.0);
  times.paintedAt(5040.0, false);
  FrameTimes::Summary s = times.summary();
  EXPECT_FALSE(s.framesPerSecond) << "5 s apart: two clicks, not a drag at 0.2 frames a second";
  EXPECT_DOUBLE_EQ(*s.inputToFrameMs, 30.0);  // the median of 20 and 40
  EXPECT_DOUBLE_EQ(*s.changeToFullMs, 40.0);
  times.reset();
  s = times.summary();
  EXPECT_FALSE(s.inputToFrameMs);
  EXPECT_EQ(s.framesAnswered, 0u);
}

}  // namespace
}  // namespace volpost::app

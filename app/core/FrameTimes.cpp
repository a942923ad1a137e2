// SPDX-License-Identifier: MIT
#include "FrameTimes.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace volpost::app {
namespace {

double median(const std::deque<double>& values) {
  std::vector<double> v(values.begin(), values.end());
  const auto mid = v.begin() + std::ptrdiff_t(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  if (v.size() % 2 == 1) return *mid;
  return 0.5 * (*mid + *std::max_element(v.begin(), mid));
}

void keepRecent(std::deque<double>& values, double value, std::size_t count) {
  values.push_back(value);
  if (values.size() > count) values.pop_front();
}

std::string milliseconds(double ms) {
  char text[32];
  if (ms < 1000.0) std::snprintf(text, sizeof text, "%.0f ms", ms);
  else std::snprintf(text, sizeof text, "%.2f s", ms / 1000.0);
  return text;
}

}  // namespace

void FrameTimes::inputAt(double ms) {
  if (!firstInput_) firstInput_ = ms;
  lastInput_ = ms;
}

void FrameTimes::paintedAt(double ms, bool quick) {
  if (firstInput_) {
    const double latency = ms - *firstInput_;
    keepRecent(latencies_, latency, kRecent);
    if (lastAnswer_ && ms - *lastAnswer_ < kNewDragMs) keepRecent(intervals_, ms - *lastAnswer_, kRecent);
    lastAnswer_ = ms;
    firstInput_.reset();
    awaitingFull_ = true;
    ++answered_;
    if (log_) log_("frame " + milliseconds(latency) + " after input" + (quick ? ", quick" : ", full"));
  }
  if (awaitingFull_ && !quick && lastInput_) {
    changeToFull_ = ms - *lastInput_;
    awaitingFull_ = false;
    if (log_) log_("full picture " + milliseconds(*changeToFull_) + " after the last change");
  }
}

FrameTimes::Summary FrameTimes::summary() const {
  Summary s;
  if (!latencies_.empty()) s.inputToFrameMs = median(latencies_);
  if (!intervals_.empty()) s.framesPerSecond = 1000.0 / std::max(median(intervals_), 1e-3);
  s.changeToFullMs = changeToFull_;
  s.framesAnswered = answered_;
  return s;
}

void FrameTimes::reset() {
  auto log = std::move(log_);
  *this = FrameTimes();
  log_ = std::move(log);
}

std::string FrameTimes::text(const Summary& s) {
  if (!s.inputToFrameMs) return "move the view to time its frames";
  std::string out = "frame " + milliseconds(*s.inputToFrameMs) + " after input";
  if (s.framesPerSecond) {
    char rate[32];
    std::snprintf(rate, sizeof rate, ", %.*f per second", *s.framesPerSecond < 10.0 ? 1 : 0, *s.framesPerSecond);
    out += rate;
  }
  if (s.changeToFullMs) out += "; full picture " + milliseconds(*s.changeToFullMs) + " after the last change";
  return out;
}

}  // namespace volpost::app

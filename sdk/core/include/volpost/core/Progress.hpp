// SPDX-License-Identifier: MIT
// Progress reporting and cancellation for long work (reading, extraction, rendering).
#pragma once

#include <volpost/core/Error.hpp>

#include <functional>
#include <string>

namespace volpost {

/// The worker calls report(fraction); the callback returns false to cancel, which makes
/// report() throw Cancelled. Callbacks may come from a worker thread.
class Progress {
 public:
  using Callback = std::function<bool(double fraction, const std::string& stage)>;
  Progress() = default;
  explicit Progress(Callback callback) : callback_(std::move(callback)) {}

  void setStage(std::string stage) { stage_ = std::move(stage); }
  void report(double fraction) const {
    if (callback_ && !callback_(fraction, stage_)) throw Cancelled();
  }

 private:
  Callback callback_;
  std::string stage_;
};

}  // namespace volpost

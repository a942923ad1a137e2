// SPDX-License-Identifier: MIT
// An OpenGL 4.5 core context with no window and no X server (EGL: Mesa's surfaceless
// platform, or the first EGL device, as on NVIDIA's driver).
#pragma once

#include <memory>
#include <string>

namespace volpost {

class HeadlessContext {
 public:
  /// Creates the context and makes it current on this thread. Throws std::runtime_error
  /// saying which EGL step failed.
  HeadlessContext();
  ~HeadlessContext();
  HeadlessContext(const HeadlessContext&) = delete;
  HeadlessContext& operator=(const HeadlessContext&) = delete;

  void makeCurrent();
  std::string platform() const;  ///< "surfaceless" or "device"

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace volpost

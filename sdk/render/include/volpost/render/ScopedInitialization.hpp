// SPDX-License-Identifier: MIT
// Pairs a renderer's initialize() with its release() for headless use: declared after the
// context, it releases the renderer's GL objects before the context goes, also when the
// frame throws.
#pragma once

#include <volpost/render/Renderer.hpp>

namespace volpost {

template <typename R = Renderer>
class ScopedInitialization {
 public:
  explicit ScopedInitialization(R& renderer) : renderer_(renderer) { renderer_.initialize(); }
  ~ScopedInitialization() { renderer_.release(); }
  ScopedInitialization(const ScopedInitialization&) = delete;
  ScopedInitialization& operator=(const ScopedInitialization&) = delete;

 private:
  R& renderer_;
};

}  // namespace volpost

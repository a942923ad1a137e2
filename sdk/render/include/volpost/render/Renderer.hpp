// SPDX-License-Identifier: MIT
// The interface of every renderer (surface, volume, ...). No widgets: the same renderer
// draws in the window and headless.
#pragma once

#include <volpost/render/RenderContext.hpp>

#include <string>

namespace volpost {

class Renderer {
 public:
  virtual ~Renderer() = default;
  virtual std::string name() const = 0;
  /// Creates GL objects; a context is current.
  virtual void initialize() = 0;
  /// Frees GL objects; the same context is current. The renderer may be initialized again.
  virtual void release() = 0;
  /// Draws into ctx.framebuffer (already bound, depth-tested, viewport set).
  virtual void render(const RenderContext& ctx) = 0;
};

}  // namespace volpost

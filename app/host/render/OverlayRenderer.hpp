// SPDX-License-Identifier: MIT
// Draws a premultiplied RGBA image over the whole viewport (legends, labels painted on
// the CPU), blended onto what is already there.
#pragma once

#include <volpost/render/GlObjects.hpp>

#include <cstdint>
#include <span>

namespace volpost {

class OverlayRenderer {
 public:
  void initialize();
  void release();
  /// Pixels are premultiplied RGBA8, top row first, width x height.
  void setImage(int width, int height, std::span<const std::uint8_t> pixels);
  /// Draws into the bound framebuffer with the current viewport.
  void render();

 private:
  gl::Program program_;
  gl::VertexArray vao_;
  gl::Texture texture_;
  int width_ = 0, height_ = 0;
};

}  // namespace volpost

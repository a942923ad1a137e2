// SPDX-License-Identifier: MIT
// A framebuffer of its own (RGBA8 color + a depth texture) to render into and read back.
#pragma once

#include <volpost/render/GlObjects.hpp>

#include <cstdint>
#include <vector>

namespace volpost {

class OffscreenTarget {
 public:
  /// Needs a current context. Throws if the framebuffer is incomplete.
  OffscreenTarget(int width, int height);
  GLuint framebuffer() const { return fbo_.id(); }
  GLuint depthTexture() const { return depth_.id(); }
  int width() const { return width_; }
  int height() const { return height_; }
  /// RGBA8 pixels, top row first (ready for an image file).
  std::vector<std::uint8_t> readPixels() const;

 private:
  int width_, height_;
  gl::Framebuffer fbo_;
  gl::Renderbuffer color_;
  gl::Texture depth_;
};

}  // namespace volpost

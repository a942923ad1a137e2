// SPDX-License-Identifier: MIT
#include <volpost/render/OffscreenTarget.hpp>

#include <cstring>
#include <stdexcept>
#include <string>

namespace volpost {

OffscreenTarget::OffscreenTarget(int width, int height)
    : width_(width), height_(height),
      fbo_(gl::createFramebuffer()),
      color_(gl::createRenderbuffer()),
      depth_(gl::createTexture(GL_TEXTURE_2D)) {
  if (width <= 0 || height <= 0 || width > 16384 || height > 16384)
    throw std::invalid_argument("image size " + std::to_string(width) + "x" + std::to_string(height) +
                                " is out of range (1..16384)");
  glNamedRenderbufferStorage(color_.id(), GL_RGBA8, width, height);
  glTextureStorage2D(depth_.id(), 1, GL_DEPTH_COMPONENT32F, width, height);
  glTextureParameteri(depth_.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTextureParameteri(depth_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glNamedFramebufferRenderbuffer(fbo_.id(), GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color_.id());
  glNamedFramebufferTexture(fbo_.id(), GL_DEPTH_ATTACHMENT, depth_.id(), 0);
  if (glCheckNamedFramebufferStatus(fbo_.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    throw std::runtime_error("offscreen framebuffer is incomplete");
}

std::vector<std::uint8_t> OffscreenTarget::readPixels() const {
  std::vector<std::uint8_t> pixels(std::size_t(width_) * std::size_t(height_) * 4);
  glNamedFramebufferReadBuffer(fbo_.id(), GL_COLOR_ATTACHMENT0);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_.id());
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  // GL's first row is the bottom one; images start at the top.
  const std::size_t row = std::size_t(width_) * 4;
  std::vector<std::uint8_t> tmp(row);
  for (int y = 0; y < height_ / 2; ++y) {
    auto* a = pixels.data() + std::size_t(y) * row;
    auto* b = pixels.data() + std::size_t(height_ - 1 - y) * row;
    std::memcpy(tmp.data(), a, row);
    std::memcpy(a, b, row);
    std::memcpy(b, tmp.data(), row);
  }
  return pixels;
}

}  // namespace volpost

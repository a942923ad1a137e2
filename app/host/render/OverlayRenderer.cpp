// SPDX-License-Identifier: MIT
#include "host/render/OverlayRenderer.hpp"

#include "host/render/HostShaders.hpp"

#include <volpost/render/ShaderLibrary.hpp>
#include <volpost/render/VolumeLimits.hpp>

namespace volpost {

void OverlayRenderer::initialize() {
  registerHostShaders();
  program_ = gl::buildProgram({"host/overlay.vert", "host/overlay.frag"}, volumeLimitDefines());
  vao_ = gl::createVertexArray();  // the quad comes from gl_VertexID
}

void OverlayRenderer::release() {
  program_.reset();
  vao_.reset();
  texture_.reset();
  width_ = height_ = 0;
}

void OverlayRenderer::setImage(int width, int height, std::span<const std::uint8_t> pixels) {
  if (width != width_ || height != height_ || !texture_) {
    texture_ = gl::createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(texture_.id(), 1, GL_RGBA8, width, height);
    glTextureParameteri(texture_.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(texture_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    width_ = width;
    height_ = height;
  }
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTextureSubImage2D(texture_.id(), 0, 0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
  gl::check("OverlayRenderer::setImage");
}

void OverlayRenderer::render() {
  if (!texture_) return;
  glUseProgram(program_.id());
  glBindTextureUnit(0, texture_.id());
  glProgramUniform1i(program_.id(), glGetUniformLocation(program_.id(), "image"), 0);
  glBindVertexArray(vao_.id());
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);  // premultiplied "over"
  glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
  glDisable(GL_BLEND);
  glBindVertexArray(0);
  glUseProgram(0);
  gl::check("OverlayRenderer::render");
}

}  // namespace volpost

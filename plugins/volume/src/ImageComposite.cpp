// SPDX-License-Identifier: MIT
#include "ImageComposite.hpp"

#include "VolumeBindings.hpp"
#include "VolumeShaders.hpp"

#include <volpost/render/ShaderLibrary.hpp>

namespace volpost::volume {

gl::Texture floatImageTexture(int width, int height) {
  gl::Texture texture = gl::createTexture(GL_TEXTURE_2D);
  glTextureStorage2D(texture.id(), 1, GL_RGBA32F, width, height);
  glTextureParameteri(texture.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTextureParameteri(texture.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  return texture;
}

void ImageComposite::initialize() {
  registerVolumeShaders();
  program_ = gl::buildProgram({"volume/composite.vert", "volume/composite.frag"}, binding::glslDefines());
  quad_ = gl::createVertexArray();
}

void ImageComposite::release() {
  program_.reset();
  quad_.reset();
}

void ImageComposite::draw(const RenderContext& ctx, GLuint image) const {
  const bool depthTest = glIsEnabled(GL_DEPTH_TEST);
  glBindFramebuffer(GL_FRAMEBUFFER, ctx.framebuffer);
  glViewport(0, 0, ctx.width, ctx.height);
  glUseProgram(program_.id());
  glProgramUniform2f(program_.id(), glGetUniformLocation(program_.id(), "viewportSize"), float(ctx.width),
                     float(ctx.height));
  glBindTextureUnit(binding::kImage, image);
  glBindVertexArray(quad_.id());
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
  glDisable(GL_BLEND);
  if (depthTest) glEnable(GL_DEPTH_TEST);
  glBindVertexArray(0);
  glUseProgram(0);
}

}  // namespace volpost::volume

// SPDX-License-Identifier: MIT
// The textures the volume renderers make the same way: 2D storage clamped at the edges, and
// one filter for minification and magnification.
#pragma once

#include <volpost/render/GlObjects.hpp>

namespace volpost::volume {

inline gl::Texture texture2D(GLenum format, int w, int h) {
  gl::Texture t = gl::createTexture(GL_TEXTURE_2D);
  glTextureStorage2D(t.id(), 1, format, w, h);
  glTextureParameteri(t.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(t.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return t;
}

inline void setFilter(GLuint tex, GLint filter) {
  glTextureParameteri(tex, GL_TEXTURE_MIN_FILTER, filter);
  glTextureParameteri(tex, GL_TEXTURE_MAG_FILTER, filter);
}

}  // namespace volpost::volume

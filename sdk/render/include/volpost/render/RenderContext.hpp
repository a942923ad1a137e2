// SPDX-License-Identifier: MIT
// Everything a renderer needs to draw one frame, and nothing of the window it draws in.
#pragma once

#include <volpost/core/Camera.hpp>
#include <volpost/render/GL.hpp>

#include <glm/vec4.hpp>

namespace volpost {

struct RenderContext {
  Camera camera;
  int width = 0, height = 0;       ///< viewport in pixels
  GLuint framebuffer = 0;          ///< target FBO (0 = default)
  glm::dvec3 origin{0.0};          ///< model center; GPU data is relative to it
  /// Depth texture of the opaque geometry already drawn with this camera (window depth
  /// 0..1, bottom row first), or 0. Volume renderers end their rays there.
  GLuint depthTexture = 0;
  double aspect() const { return height > 0 ? double(width) / double(height) : 1.0; }
};

}  // namespace volpost

// SPDX-License-Identifier: MIT
// The last pass of every volume renderer of this plugin: a premultiplied RGBA float image
// (first row at the top; one texel per pixel, or per block of pixels for a reduced image)
// blended "over" what the target holds.
#pragma once

#include <volpost/render/GlObjects.hpp>
#include <volpost/render/RenderContext.hpp>

namespace volpost::volume {

/// A premultiplied RGBA float image of width x height as the composite draws it (nearest
/// filtering: a reduced image shows its blocks as they are).
gl::Texture floatImageTexture(int width, int height);

class ImageComposite {
 public:
  void initialize();  ///< a context is current
  void release();
  /// Blends `image` over ctx.framebuffer, its whole viewport. Leaves depth testing as it found it.
  void draw(const RenderContext& ctx, GLuint image) const;

 private:
  gl::Program program_;
  gl::VertexArray quad_;
};

}  // namespace volpost::volume

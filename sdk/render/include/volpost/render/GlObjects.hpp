// SPDX-License-Identifier: MIT
// Move-only owners of GL 4.5 objects (direct state access). Destroy them only while their
// context is current: renderers free them in release(), never in destructors alone.
#pragma once

#include <volpost/render/GL.hpp>

#include <utility>

namespace volpost::gl {

template <typename Deleter>
class Handle {
 public:
  Handle() = default;
  explicit Handle(GLuint id) : id_(id) {}
  Handle(Handle&& o) noexcept : id_(std::exchange(o.id_, 0)) {}
  Handle& operator=(Handle&& o) noexcept {
    if (this != &o) {
      reset();
      id_ = std::exchange(o.id_, 0);
    }
    return *this;
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  ~Handle() { reset(); }

  GLuint id() const { return id_; }
  explicit operator bool() const { return id_ != 0; }
  void reset() {
    if (id_) Deleter{}(id_);
    id_ = 0;
  }

 private:
  GLuint id_ = 0;
};

struct BufferDeleter { void operator()(GLuint id) const { glDeleteBuffers(1, &id); } };
struct TextureDeleter { void operator()(GLuint id) const { glDeleteTextures(1, &id); } };
struct VertexArrayDeleter { void operator()(GLuint id) const { glDeleteVertexArrays(1, &id); } };
struct FramebufferDeleter { void operator()(GLuint id) const { glDeleteFramebuffers(1, &id); } };
struct RenderbufferDeleter { void operator()(GLuint id) const { glDeleteRenderbuffers(1, &id); } };
struct ProgramDeleter { void operator()(GLuint id) const { glDeleteProgram(id); } };

using Buffer = Handle<BufferDeleter>;
using Texture = Handle<TextureDeleter>;
using VertexArray = Handle<VertexArrayDeleter>;
using Framebuffer = Handle<FramebufferDeleter>;
using Renderbuffer = Handle<RenderbufferDeleter>;
using Program = Handle<ProgramDeleter>;

inline Buffer createBuffer() { GLuint id = 0; glCreateBuffers(1, &id); return Buffer(id); }
inline VertexArray createVertexArray() { GLuint id = 0; glCreateVertexArrays(1, &id); return VertexArray(id); }
inline Texture createTexture(GLenum target) { GLuint id = 0; glCreateTextures(target, 1, &id); return Texture(id); }
inline Framebuffer createFramebuffer() { GLuint id = 0; glCreateFramebuffers(1, &id); return Framebuffer(id); }
inline Renderbuffer createRenderbuffer() { GLuint id = 0; glCreateRenderbuffers(1, &id); return Renderbuffer(id); }

}  // namespace volpost::gl

// SPDX-License-Identifier: MIT
// Shader storage buffers filled from the host (the volume's mesh and tables, the visible
// part's faces and BVH): the buffer is created on first use and resized to the data.
#pragma once

#include <volpost/render/GlObjects.hpp>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace volpost::volume {

inline void uploadBytes(gl::Buffer& buffer, const void* data, std::size_t bytes) {
  if (!buffer) buffer = gl::createBuffer();
  // Zero-size SSBOs cannot be bound: keep one element.
  glNamedBufferData(buffer.id(), GLsizeiptr(std::max<std::size_t>(bytes, 16)), nullptr, GL_STATIC_DRAW);
  if (bytes > 0) glNamedBufferSubData(buffer.id(), 0, GLsizeiptr(bytes), data);
}

template <typename T>
void upload(gl::Buffer& buffer, const std::vector<T>& data) {
  uploadBytes(buffer, data.data(), data.size() * sizeof(T));
}

}  // namespace volpost::volume

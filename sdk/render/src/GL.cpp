// SPDX-License-Identifier: MIT
#include <volpost/render/GL.hpp>

#include <cstdio>
#include <stdexcept>

namespace volpost::gl {

void check(const char* where) {
  const GLenum err = glGetError();
  if (err == GL_NO_ERROR) return;
  while (glGetError() != GL_NO_ERROR) {}
  char code[16];
  std::snprintf(code, sizeof code, "0x%04x", err);
  throw std::runtime_error(std::string("OpenGL error ") + code + " in " + where);
}

std::string describeContext() {
  const auto str = [](GLenum name) {
    const auto* s = reinterpret_cast<const char*>(glGetString(name));
    return std::string(s ? s : "?");
  };
  return "OpenGL " + str(GL_VERSION) + ", " + str(GL_RENDERER);
}

bool isSoftwareRasterizer(const std::string& description) {
  for (const char* name : {"llvmpipe", "softpipe", "SwiftShader", "GDI Generic", "Software Rasterizer"})
    if (description.find(name) != std::string::npos) return true;
  return false;
}

}  // namespace volpost::gl

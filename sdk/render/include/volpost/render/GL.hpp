// SPDX-License-Identifier: MIT
// The one place GL comes from: libepoxy, so the same code runs in a QOpenGLWidget and in a
// headless EGL context. Include this before any Qt GL header.
#pragma once

#include <epoxy/gl.h>

#include <string>

namespace volpost::gl {

/// Throws std::runtime_error naming `where` if glGetError reports an error. Rendering
/// code calls it at the end of each pass; tests make any GL error a failure this way.
void check(const char* where);

/// "OpenGL 4.5 (Core Profile) Mesa 22.3.6, llvmpipe (LLVM 15.0.6, 256 bits)"
std::string describeContext();

/// Whether a context description (describeContext()) names a software rasterizer (Mesa's
/// llvmpipe or softpipe, SwiftShader, Windows' GDI Generic): there the CPU ray caster is
/// the faster volume renderer.
bool isSoftwareRasterizer(const std::string& description);

}  // namespace volpost::gl

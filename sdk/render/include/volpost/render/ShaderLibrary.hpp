// SPDX-License-Identifier: MIT
// GLSL sources from shaders/ (embedded at build time), with a small #include resolver.
#pragma once

#include <volpost/render/GlObjects.hpp>

#include <string>
#include <vector>

namespace volpost::gl {

/// The source of an embedded shader file ("surface.frag", "common/colormap.glsl") with
/// `#include "file"` lines replaced by those files. If $VOLPOST_SHADER_DIR is set, files
/// are read from that folder instead (edit shaders without rebuilding).
std::string shaderSource(const std::string& name);
/// Names of all embedded shader files.
std::vector<std::string> shaderNames();

/// Compiles and links a program from stage files named by extension (.vert, .frag,
/// .geom, .comp). `defines` ("#define NAME VALUE" lines) go into every stage right after
/// its #version line: variants of one source without run-time branches. Throws
/// std::runtime_error with the log and the numbered source.
Program buildProgram(const std::vector<std::string>& stageFiles, const std::string& defines = {});

}  // namespace volpost::gl

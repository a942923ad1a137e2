// SPDX-License-Identifier: MIT
// The shader registry: GLSL sources embedded into the libraries that own them (the host's
// shaders/, a plugin's shaders/), registered under a prefix, compiled with a small
// #include resolver. An out-of-tree renderer embeds its own with volpost_embed_shaders()
// (installed with the SDK) and registers them the same way.
#pragma once

#include <volpost/render/GlObjects.hpp>

#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace volpost::gl {

/// Registers shader files under `prefix` ("volume": "raycast.comp" becomes
/// "volume/raycast.comp"; an empty prefix keeps the names). The sources must live as long
/// as the process (embedded string literals). Registering the same name again with the
/// same text is a no-op; with other text it throws std::logic_error (two owners).
void registerShaders(const std::string& prefix, const std::map<std::string, std::string_view>& files);

/// The source of a registered file ("volume/raycast.comp") with `#include "file"` lines
/// replaced by those files. An include is looked up under the including file's prefix
/// first ("volume/common/x.glsl"), then as written. If $VOLPOST_SHADER_DIR is set, a file
/// found there under its full name wins (edit shaders without rebuilding).
std::string shaderSource(const std::string& name);
/// Names of all registered shader files.
std::vector<std::string> shaderNames();

/// Compiles and links a program from stage files named by extension (.vert, .frag,
/// .geom, .comp). `defines` ("#define NAME VALUE" lines) go into every stage right after
/// its #version line: variants of one source without run-time branches. Throws
/// std::runtime_error with the log and the numbered source.
Program buildProgram(const std::vector<std::string>& stageFiles, const std::string& defines = {});

}  // namespace volpost::gl

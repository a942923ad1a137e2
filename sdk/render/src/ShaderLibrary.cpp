// SPDX-License-Identifier: MIT
#include <volpost/render/ShaderLibrary.hpp>

#include <filesystem>
#include <fstream>
#include <mutex>
#include <set>
#include <sstream>
#include <stdexcept>

namespace volpost::gl {
namespace {

struct Registry {
  std::mutex mutex;
  std::map<std::string, std::string_view> files;  ///< full name -> source
};

Registry& registry() {
  static Registry r;
  return r;
}

bool registered(const std::string& name) {
  Registry& r = registry();
  const std::lock_guard lock(r.mutex);
  return r.files.count(name) > 0;
}

std::string rawSource(const std::string& name) {
  if (const char* dir = std::getenv("VOLPOST_SHADER_DIR")) {
    std::ifstream in(std::filesystem::path(dir) / name);
    if (in) return std::string(std::istreambuf_iterator<char>(in), {});
  }
  Registry& r = registry();
  const std::lock_guard lock(r.mutex);
  const auto it = r.files.find(name);
  if (it == r.files.end()) throw std::runtime_error("no shader file named " + name + " is registered");
  return std::string(it->second);
}

// "volume/raycast.comp" includes "common/x.glsl": "volume/common/x.glsl" if there is one.
std::string includeTarget(const std::string& includer, const std::string& written) {
  const auto slash = includer.find('/');
  if (slash != std::string::npos) {
    const std::string underPrefix = includer.substr(0, slash + 1) + written;
    if (registered(underPrefix)) return underPrefix;
  }
  return written;
}

std::string resolveIncludes(const std::string& name, std::set<std::string>& seen) {
  if (!seen.insert(name).second) return "";  // each file once (include guards for free)
  std::istringstream in(rawSource(name));
  std::ostringstream out;
  std::string line;
  while (std::getline(in, line)) {
    const auto pos = line.find("#include");
    if (pos != std::string::npos && line.find_first_not_of(" \t") == pos) {
      const auto a = line.find('"'), b = line.rfind('"');
      if (a == std::string::npos || b <= a) throw std::runtime_error(name + ": bad #include line: " + line);
      out << resolveIncludes(includeTarget(name, line.substr(a + 1, b - a - 1)), seen);
    } else {
      out << line << '\n';
    }
  }
  return out.str();
}

GLenum stageOf(const std::string& file) {
  const std::string ext = std::filesystem::path(file).extension().string();
  if (ext == ".vert") return GL_VERTEX_SHADER;
  if (ext == ".frag") return GL_FRAGMENT_SHADER;
  if (ext == ".geom") return GL_GEOMETRY_SHADER;
  if (ext == ".comp") return GL_COMPUTE_SHADER;
  throw std::runtime_error("unknown shader stage for " + file);
}

std::string numbered(const std::string& source) {
  std::istringstream in(source);
  std::ostringstream out;
  std::string line;
  for (int n = 1; std::getline(in, line); ++n) out << n << ": " << line << '\n';
  return out.str();
}

// The defines go after the #version line, which must stay first.
std::string withDefines(std::string source, const std::string& defines) {
  if (defines.empty()) return source;
  const auto versionLine = source.find("#version");
  const auto insertAt = versionLine == std::string::npos ? 0 : source.find('\n', versionLine);
  if (insertAt == std::string::npos) return source + "\n" + defines + "\n";
  return source.insert(insertAt == 0 ? 0 : insertAt + 1, defines.back() == '\n' ? defines : defines + "\n");
}

}  // namespace

void registerShaders(const std::string& prefix, const std::map<std::string, std::string_view>& files) {
  Registry& r = registry();
  const std::lock_guard lock(r.mutex);
  for (const auto& [file, source] : files) {
    const std::string name = prefix.empty() ? file : prefix + "/" + file;
    const auto [it, inserted] = r.files.emplace(name, source);
    if (!inserted && it->second != source)
      throw std::logic_error("shader " + name + " is registered twice with different sources");
  }
}

std::string shaderSource(const std::string& name) {
  std::set<std::string> seen;
  return resolveIncludes(name, seen);
}

std::vector<std::string> shaderNames() {
  Registry& r = registry();
  const std::lock_guard lock(r.mutex);
  std::vector<std::string> names;
  for (const auto& [name, _] : r.files) names.push_back(name);
  return names;
}

Program buildProgram(const std::vector<std::string>& stageFiles, const std::string& defines) {
  Program program(glCreateProgram());
  std::vector<GLuint> shaders;
  for (const std::string& file : stageFiles) {
    const std::string src = withDefines(shaderSource(file), defines);
    const GLuint shader = glCreateShader(stageOf(file));
    const char* text = src.c_str();
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    GLint ok = 0;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
      char log[4096];
      glGetShaderInfoLog(shader, sizeof log, nullptr, log);
      glDeleteShader(shader);
      for (GLuint s : shaders) glDeleteShader(s);
      throw std::runtime_error("compiling " + file + ":\n" + log + "\nsource:\n" + numbered(src));
    }
    glAttachShader(program.id(), shader);
    shaders.push_back(shader);
  }
  glLinkProgram(program.id());
  for (GLuint s : shaders) glDeleteShader(s);
  GLint ok = 0;
  glGetProgramiv(program.id(), GL_LINK_STATUS, &ok);
  if (!ok) {
    char log[4096];
    glGetProgramInfoLog(program.id(), sizeof log, nullptr, log);
    std::string names;
    for (const auto& f : stageFiles) names += f + " ";
    throw std::runtime_error("linking " + names + ":\n" + log);
  }
  return program;
}

}  // namespace volpost::gl

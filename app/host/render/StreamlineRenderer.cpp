// SPDX-License-Identifier: MIT
#include "host/render/StreamlineRenderer.hpp"

#include "host/render/ClipUniforms.hpp"
#include "host/render/HostShaders.hpp"

#include <volpost/render/ShaderLibrary.hpp>
#include <volpost/render/VolumeLimits.hpp>

#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace volpost {
namespace {

constexpr int kColorMapTexels = 256;
constexpr float kNoValue = 1.0e38f;
constexpr int kRing = 8;                        // tube cross-section
constexpr std::size_t kMaxTubeVertices = 32u << 20;

struct Vertex {
  glm::vec3 position;
  glm::vec3 direction;  // tangent (lines) or normal (tubes, cones)
  float value;
};

float valueOf(double v) { return std::isfinite(v) ? float(v) : kNoValue; }

// Unit tangents by central differences (one-sided at the ends).
std::vector<glm::dvec3> tangents(const std::vector<glm::dvec3>& p) {
  std::vector<glm::dvec3> t(p.size(), glm::dvec3(1, 0, 0));
  for (std::size_t i = 0; i < p.size(); ++i) {
    const glm::dvec3 d = p[std::min(i + 1, p.size() - 1)] - p[i == 0 ? 0 : i - 1];
    if (glm::dot(d, d) > 0.0) t[i] = glm::normalize(d);
    else if (i > 0) t[i] = t[i - 1];
  }
  return t;
}

void configure(GLuint vao, GLuint vbo, GLuint ibo) {
  glVertexArrayVertexBuffer(vao, 0, vbo, 0, sizeof(Vertex));
  glVertexArrayElementBuffer(vao, ibo);
  glEnableVertexArrayAttrib(vao, 0);
  glVertexArrayAttribFormat(vao, 0, 3, GL_FLOAT, GL_FALSE, offsetof(Vertex, position));
  glEnableVertexArrayAttrib(vao, 1);
  glVertexArrayAttribFormat(vao, 1, 3, GL_FLOAT, GL_FALSE, offsetof(Vertex, direction));
  glEnableVertexArrayAttrib(vao, 2);
  glVertexArrayAttribFormat(vao, 2, 1, GL_FLOAT, GL_FALSE, offsetof(Vertex, value));
  for (GLuint a = 0; a < 3; ++a) glVertexArrayAttribBinding(vao, a, 0);
}

}  // namespace

void StreamlineRenderer::initialize() {
  registerHostShaders();
  lineProgram_ =
      gl::buildProgram({"host/streamline.vert", "host/streamline.geom", "host/streamline.frag"}, volumeLimitDefines());
  tubeProgram_ = gl::buildProgram({"host/tube.vert", "host/tube.frag"}, volumeLimitDefines());
  lineVao_ = gl::createVertexArray();
  tubeVao_ = gl::createVertexArray();
  lineVbo_ = gl::createBuffer();
  lineIbo_ = gl::createBuffer();
  tubeVbo_ = gl::createBuffer();
  tubeIbo_ = gl::createBuffer();
  colorMap_ = gl::createTexture(GL_TEXTURE_1D);
  glTextureStorage1D(colorMap_.id(), 1, GL_RGBA8, kColorMapTexels);
  glTextureParameteri(colorMap_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(colorMap_.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(colorMap_.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  setColorMap(ColorMap::named("viridis"));
  segmentIndices_ = tubeVertices_ = 0;
  gl::check("StreamlineRenderer::initialize");
}

void StreamlineRenderer::release() {
  lineProgram_.reset();
  tubeProgram_.reset();
  lineVao_.reset();
  tubeVao_.reset();
  lineVbo_.reset();
  lineIbo_.reset();
  tubeVbo_.reset();
  tubeIbo_.reset();
  colorMap_.reset();
  segmentIndices_ = tubeVertices_ = 0;
}

void StreamlineRenderer::setColorMap(const ColorMap& map) {
  const auto texels = map.rgba8(kColorMapTexels);
  glTextureSubImage1D(colorMap_.id(), 0, 0, kColorMapTexels, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
}

void StreamlineRenderer::setRange(double min, double max) {
  min_ = float(min);
  max_ = float(max);
}

void StreamlineRenderer::uploadLines(const std::vector<std::vector<glm::dvec3>>& lines,
                                     const std::vector<std::vector<double>>& values) {
  std::vector<Vertex> vertices;
  std::vector<std::uint32_t> indices;
  for (std::size_t l = 0; l < lines.size(); ++l) {
    const auto& p = lines[l];
    const auto t = tangents(p);
    const std::uint32_t base = std::uint32_t(vertices.size());
    for (std::size_t i = 0; i < p.size(); ++i)
      vertices.push_back({glm::vec3(p[i] - origin_), glm::vec3(t[i]), valueOf(values[l][i])});
    for (std::uint32_t i = 0; i + 1 < p.size(); ++i) indices.insert(indices.end(), {base + i, base + i + 1});
  }
  glNamedBufferData(lineVbo_.id(), GLsizeiptr(std::max<std::size_t>(vertices.size(), 1) * sizeof(Vertex)),
                    vertices.empty() ? nullptr : vertices.data(), GL_STATIC_DRAW);
  glNamedBufferData(lineIbo_.id(), GLsizeiptr(std::max<std::size_t>(indices.size(), 1) * 4),
                    indices.empty() ? nullptr : indices.data(), GL_STATIC_DRAW);
  configure(lineVao_.id(), lineVbo_.id(), lineIbo_.id());
  segmentIndices_ = GLsizei(indices.size());
}

struct StreamlineRenderer::Triangles {
  std::vector<Vertex> vertices;
  std::vector<std::uint32_t> indices;
};

// The style's radius, or grown from 0.25x to 1x with the value over the lines' range.
struct StreamlineRenderer::Radius {
  Radius(const StreamlineStyle& style, const std::vector<std::vector<double>>& values);
  double at(double value) const;
  double base, lo = 1e300, hi = -1e300;
  bool byValue;
};

StreamlineRenderer::Radius::Radius(const StreamlineStyle& style, const std::vector<std::vector<double>>& values)
    : base(style.tubeRadius), byValue(style.radiusByValue) {
  for (const auto& v : values)
    for (double x : v)
      if (std::isfinite(x)) lo = std::min(lo, x), hi = std::max(hi, x);
}

double StreamlineRenderer::Radius::at(double v) const {
  if (!byValue || !(hi > lo) || !std::isfinite(v)) return base;
  return base * (0.25 + 0.75 * (v - lo) / (hi - lo));
}

// Tubes: a ring of kRing vertices per point, its frame carried along by parallel
// transport (no twist), rings joined by quads.
void StreamlineRenderer::appendTubes(const std::vector<std::vector<glm::dvec3>>& lines,
                                     const std::vector<std::vector<double>>& values, const Radius& radius,
                                     Triangles& out) const {
  for (std::size_t l = 0; l < lines.size(); ++l) {
    const auto& p = lines[l];
    if (p.size() < 2) continue;
    const auto t = tangents(p);
    glm::dvec3 n = std::abs(t[0].x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    n = glm::normalize(n - glm::dot(n, t[0]) * t[0]);
    const std::uint32_t base = std::uint32_t(out.vertices.size());
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (i > 0) {
        const glm::dvec3 carried = n - glm::dot(n, t[i]) * t[i];
        if (glm::dot(carried, carried) > 1e-24) n = glm::normalize(carried);
      }
      const glm::dvec3 b = glm::cross(t[i], n);
      const double r = radius.at(values[l][i]);
      for (int k = 0; k < kRing; ++k) {
        const double a = 2.0 * M_PI * k / kRing;
        const glm::dvec3 normal = std::cos(a) * n + std::sin(a) * b;
        out.vertices.push_back({glm::vec3(p[i] + r * normal - origin_), glm::vec3(normal), valueOf(values[l][i])});
      }
      if (i > 0) {
        const std::uint32_t r0 = base + std::uint32_t((i - 1) * kRing), r1 = r0 + kRing;
        for (std::uint32_t k = 0; k < kRing; ++k) {
          const std::uint32_t k1 = (k + 1) % kRing;
          out.indices.insert(out.indices.end(), {r0 + k, r1 + k, r1 + k1, r0 + k, r1 + k1, r0 + k1});
        }
      }
    }
  }
}

// Arrows: cones at even arc length (every arrowSpacing, the first half a spacing from the
// line's start), a ring 2.5 radii wide around the line, the tip 5 radii downstream.
void StreamlineRenderer::appendArrows(const std::vector<std::vector<glm::dvec3>>& lines,
                                      const std::vector<std::vector<double>>& values, const Radius& radius,
                                      Triangles& out) const {
  for (std::size_t l = 0; l < lines.size(); ++l) {
    const auto& p = lines[l];
    if (p.size() < 2) continue;
    const auto t = tangents(p);
    double sinceArrow = 0.5 * style_.arrowSpacing;
    for (std::size_t i = 1; i < p.size(); ++i) {
      sinceArrow += glm::length(p[i] - p[i - 1]);
      if (sinceArrow < style_.arrowSpacing) continue;
      sinceArrow = 0.0;
      const glm::dvec3 axis = t[i];
      glm::dvec3 u = std::abs(axis.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
      u = glm::normalize(u - glm::dot(u, axis) * axis);
      const glm::dvec3 w = glm::cross(axis, u);
      const double r = radius.at(values[l][i]);
      const glm::dvec3 tip = p[i] + 5.0 * r * axis;
      const float value = valueOf(values[l][i]);
      const std::uint32_t cone = std::uint32_t(out.vertices.size());
      for (int k = 0; k < kRing; ++k) {
        const double a = 2.0 * M_PI * k / kRing;
        const glm::dvec3 radial = std::cos(a) * u + std::sin(a) * w;
        const glm::dvec3 normal = glm::normalize(radial + 0.5 * axis);
        out.vertices.push_back({glm::vec3(p[i] + 2.5 * r * radial - origin_), glm::vec3(normal), value});
        out.vertices.push_back({glm::vec3(tip - origin_), glm::vec3(normal), value});
      }
      for (std::uint32_t k = 0; k < kRing; ++k) {
        const std::uint32_t k1 = (k + 1) % kRing;
        out.indices.insert(out.indices.end(), {cone + 2 * k, cone + 2 * k1, cone + 2 * k + 1});
      }
    }
  }
}

void StreamlineRenderer::setLines(const std::vector<std::vector<glm::dvec3>>& lines,
                                  const std::vector<std::vector<double>>& values, const glm::dvec3& origin,
                                  const StreamlineStyle& style) {
  origin_ = origin;
  style_ = style;
  segmentIndices_ = tubeVertices_ = 0;
  std::size_t points = 0;
  for (const auto& l : lines) points += l.size();
  const std::size_t perPoint = (style.tubes ? kRing : 0) + (style.arrows ? 2 * kRing : 0);
  if (points * perPoint > kMaxTubeVertices)
    throw std::invalid_argument(std::string(style.tubes ? "tubes" : "arrows") + " for " + std::to_string(points) +
                                " streamline points would need more than " + std::to_string(kMaxTubeVertices) +
                                " vertices: draw plain lines instead, or fewer seeds");
  if (!style.tubes) uploadLines(lines, values);
  // Tubes and arrow cones are shaded triangles; arrows go with lit lines as well as tubes.
  Triangles triangles;
  const Radius radius(style_, values);
  if (style.tubes) appendTubes(lines, values, radius, triangles);
  if (style.arrows && style.arrowSpacing > 0.0) appendArrows(lines, values, radius, triangles);
  glNamedBufferData(tubeVbo_.id(), GLsizeiptr(std::max<std::size_t>(triangles.vertices.size(), 1) * sizeof(Vertex)),
                    triangles.vertices.empty() ? nullptr : triangles.vertices.data(), GL_STATIC_DRAW);
  glNamedBufferData(tubeIbo_.id(), GLsizeiptr(std::max<std::size_t>(triangles.indices.size(), 1) * 4),
                    triangles.indices.empty() ? nullptr : triangles.indices.data(), GL_STATIC_DRAW);
  configure(tubeVao_.id(), tubeVbo_.id(), tubeIbo_.id());
  tubeVertices_ = GLsizei(triangles.indices.size());
  gl::check("StreamlineRenderer::setLines");
}

void StreamlineRenderer::setCommonUniforms(GLuint p, const RenderContext& ctx) const {
  const glm::mat4 view(ctx.camera.viewMatrix(origin_));
  const glm::mat4 proj(ctx.camera.projectionMatrix(ctx.aspect()));
  const auto u = [&](const char* name) { return glGetUniformLocation(p, name); };
  glProgramUniformMatrix4fv(p, u("modelView"), 1, GL_FALSE, glm::value_ptr(view));
  glProgramUniformMatrix4fv(p, u("projection"), 1, GL_FALSE, glm::value_ptr(proj));
  glProgramUniform1i(p, u("colorMap"), 0);
  glProgramUniform1f(p, u("valueMin"), min_);
  glProgramUniform1f(p, u("valueMax"), max_);
  glProgramUniform1i(p, u("orthographic"), ctx.camera.projection() == Camera::Projection::Orthographic);
  glProgramUniform3fv(p, u("lightDirection"), 1, glm::value_ptr(lightDirection));
  glProgramUniform3fv(p, u("noValueColor"), 1, glm::value_ptr(noValueColor));
  setClipUniforms(p, clipPlanes_, origin_);
  glBindTextureUnit(0, colorMap_.id());
}

void StreamlineRenderer::render(const RenderContext& ctx) {
  if (empty() || ctx.width <= 0 || ctx.height <= 0) return;
  glBindFramebuffer(GL_FRAMEBUFFER, ctx.framebuffer);
  glViewport(0, 0, ctx.width, ctx.height);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  if (segmentIndices_ > 0) {
    const GLuint p = lineProgram_.id();
    glUseProgram(p);
    setCommonUniforms(p, ctx);
    const auto u = [&](const char* name) { return glGetUniformLocation(p, name); };
    glProgramUniform2f(p, u("viewportSize"), float(ctx.width), float(ctx.height));
    glProgramUniform1f(p, u("lineWidth"), std::max(style_.width, 1.0f));
    glProgramUniform1f(p, u("ambient"), ambient);
    glProgramUniform1f(p, u("diffuse"), diffuse);
    glProgramUniform1f(p, u("specular"), specular);
    glProgramUniform1f(p, u("diffuseExponent"), diffuseExponent);
    glProgramUniform1f(p, u("shininess"), shininess);
    glBindVertexArray(lineVao_.id());
    glDrawElements(GL_LINES, segmentIndices_, GL_UNSIGNED_INT, nullptr);
  }
  if (tubeVertices_ > 0) {  // tubes, arrow cones or both
    const GLuint p = tubeProgram_.id();
    glUseProgram(p);
    setCommonUniforms(p, ctx);
    glBindVertexArray(tubeVao_.id());
    glDrawElements(GL_TRIANGLES, tubeVertices_, GL_UNSIGNED_INT, nullptr);
  }
  glBindVertexArray(0);
  glUseProgram(0);
  glDisable(GL_DEPTH_TEST);
  gl::check("StreamlineRenderer::render");
}

}  // namespace volpost

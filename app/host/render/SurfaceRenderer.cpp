// SPDX-License-Identifier: MIT
#include "host/render/SurfaceRenderer.hpp"

#include "host/render/ClipUniforms.hpp"
#include "host/render/HostShaders.hpp"

#include <volpost/render/ShaderLibrary.hpp>
#include <volpost/render/VolumeLimits.hpp>

#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <unordered_map>
#include <vector>

namespace volpost {
namespace {

struct SurfaceVertex {
  float position[3];
  float normal[3];
  std::uint32_t node;
  std::uint32_t cell;
};
static_assert(sizeof(SurfaceVertex) == 32);

// Non-finite results are uploaded as this value; the shader draws them in noValueColor.
// (A sentinel rather than NaN: interpolation and comparisons of NaN are not portable.)
constexpr float kNoValue = 3.0e38f;
constexpr int kColorMapTexels = 256;
constexpr std::uint32_t kNoId = 0xffffffffu;  ///< an edge end with no surface vertex or face to take a value of

}  // namespace

void SurfaceRenderer::initialize() {
  registerHostShaders();
  surfaceProgram_ = gl::buildProgram({"host/surface.vert", "host/surface.frag"}, volumeLimitDefines());
  edgeProgram_ = gl::buildProgram({"host/edges.vert", "host/edges.frag"}, volumeLimitDefines());
  surfaceVao_ = gl::createVertexArray();
  edgeVao_ = gl::createVertexArray();
  surfaceVbo_ = gl::createBuffer();
  edgeVbo_ = gl::createBuffer();
  edgeIds_ = gl::createBuffer();
  scalars_ = gl::createBuffer();
  colorMap_ = gl::createTexture(GL_TEXTURE_1D);
  glTextureStorage1D(colorMap_.id(), 1, GL_RGBA8, kColorMapTexels);
  glTextureParameteri(colorMap_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(colorMap_.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(colorMap_.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  setColorMap(ColorMap::named("cool-warm"));

  const GLuint vao = surfaceVao_.id();
  glEnableVertexArrayAttrib(vao, 0);
  glVertexArrayAttribFormat(vao, 0, 3, GL_FLOAT, GL_FALSE, offsetof(SurfaceVertex, position));
  glEnableVertexArrayAttrib(vao, 1);
  glVertexArrayAttribFormat(vao, 1, 3, GL_FLOAT, GL_FALSE, offsetof(SurfaceVertex, normal));
  glEnableVertexArrayAttrib(vao, 2);
  glVertexArrayAttribIFormat(vao, 2, 1, GL_UNSIGNED_INT, offsetof(SurfaceVertex, node));
  glEnableVertexArrayAttrib(vao, 3);
  glVertexArrayAttribIFormat(vao, 3, 1, GL_UNSIGNED_INT, offsetof(SurfaceVertex, cell));
  for (GLuint a = 0; a < 4; ++a) glVertexArrayAttribBinding(vao, a, 0);
  // An edge vertex: its position, the segment's other end and how far apart the edges
  // around it are over its length (for how crowded it is on screen).
  for (GLuint a = 0; a < 3; ++a) {
    glEnableVertexArrayAttrib(edgeVao_.id(), a);
    glVertexArrayAttribFormat(edgeVao_.id(), a, a < 2 ? 3 : 1, GL_FLOAT, GL_FALSE, a * 3 * sizeof(float));
    glVertexArrayAttribBinding(edgeVao_.id(), a, 0);
  }
  // And, from a buffer of their own, the surface vertex and face it takes values from.
  for (GLuint a = 3; a < 5; ++a) {
    glEnableVertexArrayAttrib(edgeVao_.id(), a);
    glVertexArrayAttribIFormat(edgeVao_.id(), a, 1, GL_UNSIGNED_INT, (a - 3) * sizeof(std::uint32_t));
    glVertexArrayAttribBinding(edgeVao_.id(), a, 1);
  }
  uploadEdgeIds({});
  // An empty buffer still needs storage to be bound as an SSBO.
  const float none = kNoValue;
  glNamedBufferData(scalars_.id(), sizeof none, &none, GL_DYNAMIC_DRAW);
  gl::check("SurfaceRenderer::initialize");
}

void SurfaceRenderer::release() {
  surfaceProgram_.reset();
  edgeProgram_.reset();
  surfaceVao_.reset();
  edgeVao_.reset();
  surfaceVbo_.reset();
  edgeVbo_.reset();
  edgeIds_.reset();
  scalars_.reset();
  colorMap_.reset();
  triangleVertices_ = edgeVertices_ = 0;
}

void SurfaceRenderer::setSurface(const BoundarySurface& surface) {
  origin_ = surface.origin;
  const SurfaceMesh& m = surface.mesh;
  std::vector<SurfaceVertex> vertices;
  vertices.reserve(m.n_faces() * 3);
  // The scalars buffer holds the surface's own nodes and cells only (a 512^3 grid's
  // boundary touches 1.6M of its 134M points): one value per surface vertex and per face,
  // gathered from the model's node or cell each stands for.
  scalarNodes_.resize(m.n_vertices());
  scalarCells_.resize(m.n_faces());
  for (const auto v : m.vertices()) scalarNodes_[std::size_t(v.idx())] = m.property(surface.nodeOfVertex, v);
  for (const auto f : m.faces()) {
    const auto n = m.normal(f);
    const auto face = std::uint32_t(f.idx());
    scalarCells_[face] = m.property(surface.cellOfFace, f);
    for (const auto v : f.vertices()) {
      const auto p = m.point(v);
      vertices.push_back({{p[0], p[1], p[2]}, {n[0], n[1], n[2]}, std::uint32_t(v.idx()), face});
    }
  }
  triangleVertices_ = GLsizei(vertices.size());
  glNamedBufferData(surfaceVbo_.id(), GLsizeiptr(vertices.size() * sizeof(SurfaceVertex)),
                    vertices.data(), GL_STATIC_DRAW);
  glVertexArrayVertexBuffer(surfaceVao_.id(), 0, surfaceVbo_.id(), 0, sizeof(SurfaceVertex));

  // Edge endpoints come from the mesh nodes through the vertex property.
  std::vector<glm::vec3> positionOfNode;
  std::vector<float> edgeData;
  std::vector<std::uint32_t> edgeIds;  // per edge vertex: its surface vertex, a face on the edge
  edgeData.reserve(surface.edges.size() * 6);
  std::unordered_map<NodeIndex, glm::vec3> nodePos;
  std::unordered_map<NodeIndex, SurfaceMesh::VertexHandle> vertexOf;
  nodePos.reserve(m.n_vertices());
  vertexOf.reserve(m.n_vertices());
  for (const auto v : m.vertices()) {
    const auto p = m.point(v);
    nodePos[m.property(surface.nodeOfVertex, v)] = glm::vec3(p[0], p[1], p[2]);
    vertexOf[m.property(surface.nodeOfVertex, v)] = v;
  }
  // How far apart the edges are near each node: its shortest edge. A long edge between
  // nodes whose other edges are short (the 25 m lines on a 4 ms time side) crowds its
  // neighbours as closely as those are short, and fades with them.
  std::unordered_map<NodeIndex, float> shortestAt;
  const auto lengthOf = [&](const std::array<NodeIndex, 2>& e) {
    return glm::length(nodePos.at(e[1]) - nodePos.at(e[0]));
  };
  const bool spacingGiven = surface.edgeSpacing.size() == surface.edges.size();
  std::vector<float> spacing;
  for (const auto& e : surface.edges) {
    if (spacingGiven || !nodePos.count(e[0]) || !nodePos.count(e[1])) continue;
    const float length = lengthOf(e);
    for (NodeIndex n : e) {
      const auto [it, added] = shortestAt.try_emplace(n, length);
      if (!added) it->second = std::min(it->second, length);
    }
  }
  for (std::size_t i = 0; i < surface.edges.size(); ++i) {
    const auto& e = surface.edges[i];
    const auto a = nodePos.find(e[0]), b = nodePos.find(e[1]);
    if (a == nodePos.end() || b == nodePos.end()) continue;
    edgeData.insert(edgeData.end(), {a->second.x, a->second.y, a->second.z, b->second.x, b->second.y, b->second.z});
    // Over the segment's own length: the shader scales it by the segment as projected.
    const float length = lengthOf(e);
    const float near = spacingGiven ? surface.edgeSpacing[i] : std::min(shortestAt[e[0]], shortestAt[e[1]]);
    spacing.push_back(length > 0.0f ? near / length : 1.0f);
    // A face on the edge gives its element's value; none found (an edge the triangles do
    // not follow): no value per element.
    const auto va = vertexOf.at(e[0]), vb = vertexOf.at(e[1]);
    auto h = m.find_halfedge(va, vb);
    if (h.is_valid() && !m.face_handle(h).is_valid()) h = m.opposite_halfedge_handle(h);
    const std::uint32_t face =
        h.is_valid() && m.face_handle(h).is_valid() ? std::uint32_t(m.face_handle(h).idx()) : kNoId;
    edgeIds.insert(edgeIds.end(), {std::uint32_t(va.idx()), face, std::uint32_t(vb.idx()), face});
  }
  edgeVertices_ = GLsizei(edgeData.size() / 3);
  edgeData = withOtherEnds(edgeData, spacing);
  fadeDenseEdges_ = true;
  edgesHaveValues_ = true;
  uploadEdgeIds(edgeIds);
  glNamedBufferData(edgeVbo_.id(), GLsizeiptr(edgeData.size() * sizeof(float)), edgeData.data(), GL_STATIC_DRAW);
  glVertexArrayVertexBuffer(edgeVao_.id(), 0, edgeVbo_.id(), 0, 7 * sizeof(float));
  gl::check("SurfaceRenderer::setSurface");
}

void SurfaceRenderer::setTriangles(const std::vector<glm::dvec3>& corners, const glm::dvec3& origin) {
  origin_ = origin;
  scalarNodes_.clear();  // one value per corner, in order
  scalarCells_.clear();
  std::vector<SurfaceVertex> vertices;
  vertices.reserve(corners.size());
  for (std::size_t t = 0; t + 2 < corners.size(); t += 3) {
    const glm::vec3 n(glm::normalize(glm::cross(corners[t + 1] - corners[t], corners[t + 2] - corners[t])));
    for (std::size_t k = t; k < t + 3; ++k) {
      const glm::vec3 p(corners[k] - origin);
      vertices.push_back({{p.x, p.y, p.z}, {n.x, n.y, n.z}, std::uint32_t(k), 0u});
    }
  }
  triangleVertices_ = GLsizei(vertices.size());
  glNamedBufferData(surfaceVbo_.id(), GLsizeiptr(std::max<std::size_t>(vertices.size(), 1) * sizeof(SurfaceVertex)),
                    vertices.empty() ? nullptr : vertices.data(), GL_DYNAMIC_DRAW);
  glVertexArrayVertexBuffer(surfaceVao_.id(), 0, surfaceVbo_.id(), 0, sizeof(SurfaceVertex));
  edgeVertices_ = 0;
  edgesHaveValues_ = false;
  gl::check("SurfaceRenderer::setTriangles");
}

void SurfaceRenderer::setLines(const std::vector<glm::dvec3>& endpoints, const glm::dvec3& origin) {
  origin_ = origin;
  triangleVertices_ = 0;
  std::vector<float> edgeData;
  edgeData.reserve(endpoints.size() * 3);
  for (const glm::dvec3& p : endpoints) {
    const glm::vec3 q(p - origin);
    edgeData.insert(edgeData.end(), {q.x, q.y, q.z});
  }
  edgeData.resize(endpoints.size() / 2 * 6);
  edgeVertices_ = GLsizei(endpoints.size() / 2 * 2);
  edgeData = withOtherEnds(edgeData, {});
  fadeDenseEdges_ = false;  // an outline: always drawn
  edgesHaveValues_ = false;  // and in its own color
  uploadEdgeIds(std::vector<std::uint32_t>(std::size_t(edgeVertices_) * 2, kNoId));
  glNamedBufferData(edgeVbo_.id(), GLsizeiptr(std::max<std::size_t>(edgeData.size(), 7) * sizeof(float)),
                    edgeData.empty() ? nullptr : edgeData.data(), GL_STATIC_DRAW);
  glVertexArrayVertexBuffer(edgeVao_.id(), 0, edgeVbo_.id(), 0, 7 * sizeof(float));
  gl::check("SurfaceRenderer::setLines");
}

void SurfaceRenderer::setScalars(FieldLocation location, SampleView values, double min, double max) {
  const std::vector<std::uint32_t>& used = location == FieldLocation::Node ? scalarNodes_ : scalarCells_;
  const bool gathered = !used.empty();  // a surface: its own nodes or cells; else one value per corner
  std::vector<float> data(gathered ? used.size() : values.size());
  values.visit([&](auto typed) {
    for (std::size_t i = 0; i < data.size(); ++i) {
      const std::size_t from = gathered ? used[i] : i;
      const double v = from < typed.size() ? double(typed[from]) : NAN;
      data[i] = std::isfinite(v) ? float(v) : kNoValue;
    }
  });
  if (data.empty()) data.push_back(kNoValue);
  glNamedBufferData(scalars_.id(), GLsizeiptr(data.size() * sizeof(float)), data.data(), GL_DYNAMIC_DRAW);
  location_ = location == FieldLocation::Node ? 0 : 1;
  min_ = float(min);
  max_ = float(max);
  gl::check("SurfaceRenderer::setScalars");
}

void SurfaceRenderer::clearScalars() { location_ = -1; }

void SurfaceRenderer::uploadEdgeIds(const std::vector<std::uint32_t>& ids) {
  const std::uint32_t none[2] = {kNoId, kNoId};  // a buffer still needs storage to be bound
  glNamedBufferData(edgeIds_.id(), GLsizeiptr(std::max<std::size_t>(ids.size(), 2) * sizeof(std::uint32_t)),
                    ids.empty() ? none : ids.data(), GL_STATIC_DRAW);
  glVertexArrayVertexBuffer(edgeVao_.id(), 1, edgeIds_.id(), 0, 2 * sizeof(std::uint32_t));
}

void SurfaceRenderer::setColorMap(const ColorMap& map) {
  const auto texels = map.rgba8(kColorMapTexels);
  glTextureSubImage1D(colorMap_.id(), 0, 0, kColorMapTexels, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
}

// Each segment's two vertices as (position, other end, spacing over length): 3 floats per
// point in, 7 out. No spacing given: 1 (the segment's own length).
std::vector<float> SurfaceRenderer::withOtherEnds(const std::vector<float>& segments, const std::vector<float>& spacing) {
  std::vector<float> out;
  out.reserve(segments.size() / 6 * 14);
  for (std::size_t i = 0; i + 5 < segments.size(); i += 6) {
    const float* a = &segments[i];
    const float* b = &segments[i + 3];
    const float ratio = i / 6 < spacing.size() ? spacing[i / 6] : 1.0f;
    out.insert(out.end(), {a[0], a[1], a[2], b[0], b[1], b[2], ratio, b[0], b[1], b[2], a[0], a[1], a[2], ratio});
  }
  return out;
}

void SurfaceRenderer::render(const RenderContext& ctx) {
  if (triangleVertices_ == 0 && edgeVertices_ == 0) return;
  const glm::mat4 view(ctx.camera.viewMatrix(ctx.origin));
  const glm::mat4 proj(ctx.camera.projectionMatrix(ctx.aspect()));
  const bool ortho = ctx.camera.projection() == Camera::Projection::Orthographic;

  const GLuint p = surfaceProgram_.id();
  glUseProgram(p);
  glProgramUniformMatrix4fv(p, glGetUniformLocation(p, "modelView"), 1, GL_FALSE, glm::value_ptr(view));
  glProgramUniformMatrix4fv(p, glGetUniformLocation(p, "projection"), 1, GL_FALSE, glm::value_ptr(proj));
  glProgramUniform1i(p, glGetUniformLocation(p, "scalarLocation"), location_);
  glProgramUniform1f(p, glGetUniformLocation(p, "valueMin"), min_);
  glProgramUniform1f(p, glGetUniformLocation(p, "valueMax"), max_);
  glProgramUniform1i(p, glGetUniformLocation(p, "lighting"), lighting_ ? 1 : 0);
  glProgramUniform1f(p, glGetUniformLocation(p, "opacity"), opacity_);
  glProgramUniform1i(p, glGetUniformLocation(p, "orthographic"), ortho ? 1 : 0);
  glProgramUniform3fv(p, glGetUniformLocation(p, "noValueColor"), 1, glm::value_ptr(noValueColor));
  glProgramUniform3fv(p, glGetUniformLocation(p, "plainColor"), 1, glm::value_ptr(plainColor));
  glProgramUniform1i(p, glGetUniformLocation(p, "colorMap"), 0);
  glProgramUniform1i(p, glGetUniformLocation(p, "colorBands"), colorBands_);
  glProgramUniform1i(p, glGetUniformLocation(p, "logScale"), logScale_ && min_ > 0.0f ? 1 : 0);
  glProgramUniform1i(p, glGetUniformLocation(p, "useBelowColor"), belowColor_ ? 1 : 0);
  glProgramUniform1i(p, glGetUniformLocation(p, "useAboveColor"), aboveColor_ ? 1 : 0);
  const glm::vec3 below = belowColor_.value_or(glm::vec3(0.0f)), above = aboveColor_.value_or(glm::vec3(0.0f));
  glProgramUniform3fv(p, glGetUniformLocation(p, "belowColor"), 1, glm::value_ptr(below));
  glProgramUniform3fv(p, glGetUniformLocation(p, "aboveColor"), 1, glm::value_ptr(above));
  setClipUniforms(p, clipPlanes_, origin_, clipTolerance_);
  glBindTextureUnit(0, colorMap_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, scalars_.id());
  glBindVertexArray(surfaceVao_.id());
  // Push the faces back a little so element edges drawn on them are not z-fighting (by 2,
  // not 1: a curved cell's edges come in short pieces, whose ends otherwise dip behind).
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(2.0f, 2.0f);
  if (showFaces_ && !showPoints_ && opacity_ < 1.0f) {
    // See-through: blended over what is drawn, hiding nothing behind it (no depth write).
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glDepthMask(GL_FALSE);
    glDrawArrays(GL_TRIANGLES, 0, triangleVertices_);
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
  } else if (showPoints_) {
    // Each node once per triangle it belongs to, all in the node's color: the same pixels.
    glProgramUniform1i(p, glGetUniformLocation(p, "lighting"), 0);
    glPointSize(pointPixels_);
    glDrawArrays(GL_POINTS, 0, triangleVertices_);
  } else if (showFaces_) {
    glDrawArrays(GL_TRIANGLES, 0, triangleVertices_);
  }
  glDisable(GL_POLYGON_OFFSET_FILL);

  if (showEdges_ && edgeVertices_ > 0) {
    const GLuint e = edgeProgram_.id();
    glUseProgram(e);
    glProgramUniform2f(e, glGetUniformLocation(e, "viewportSize"), float(ctx.width), float(ctx.height));
    glProgramUniform1f(e, glGetUniformLocation(e, "densePixels"),
                       fadeDenseEdges_ && allowFading_ ? kDenseEdgePixels : 0.0f);
    glEnable(GL_BLEND);  // a fading edge blends over the face under it
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glProgramUniformMatrix4fv(e, glGetUniformLocation(e, "modelView"), 1, GL_FALSE, glm::value_ptr(view));
    glProgramUniformMatrix4fv(e, glGetUniformLocation(e, "projection"), 1, GL_FALSE, glm::value_ptr(proj));
    glProgramUniform3fv(e, glGetUniformLocation(e, "color"), 1, glm::value_ptr(edgeColor));
    // A wireframe in the result's colors: the surface's scalars and map, bound above.
    const int edgeValues = colorEdges_ && edgesHaveValues_ ? location_ : -1;
    glProgramUniform1i(e, glGetUniformLocation(e, "scalarLocation"), edgeValues);
    glProgramUniform1i(e, glGetUniformLocation(e, "colorMap"), 0);
    glProgramUniform1f(e, glGetUniformLocation(e, "valueMin"), min_);
    glProgramUniform1f(e, glGetUniformLocation(e, "valueMax"), max_);
    glProgramUniform3fv(e, glGetUniformLocation(e, "noValueColor"), 1, glm::value_ptr(noValueColor));
    glProgramUniform1i(e, glGetUniformLocation(e, "colorBands"), colorBands_);
    glProgramUniform1i(e, glGetUniformLocation(e, "logScale"), logScale_ && min_ > 0.0f ? 1 : 0);
    glProgramUniform1i(e, glGetUniformLocation(e, "useBelowColor"), belowColor_ ? 1 : 0);
    glProgramUniform1i(e, glGetUniformLocation(e, "useAboveColor"), aboveColor_ ? 1 : 0);
    glProgramUniform3fv(e, glGetUniformLocation(e, "belowColor"), 1, glm::value_ptr(below));
    glProgramUniform3fv(e, glGetUniformLocation(e, "aboveColor"), 1, glm::value_ptr(above));
    setClipUniforms(e, clipPlanes_, origin_, clipTolerance_);
    glBindVertexArray(edgeVao_.id());
    glDrawArrays(GL_LINES, 0, edgeVertices_);
    glDisable(GL_BLEND);
  }
  glBindVertexArray(0);
  glUseProgram(0);
  gl::check("SurfaceRenderer::render");
}

}  // namespace volpost

// SPDX-License-Identifier: MIT
// Draws streamlines as illuminated lines of a given width (lit by their tangent, as
// Araujo & Farias and Zockler et al.), or as shaded tubes with optional arrow glyphs,
// colored by a scalar through a color map, depth-tested with the rest of the scene and cut
// by clip planes. GL objects: initialize() and release() with the context current.
#pragma once

#include "host/StreamlineStyle.hpp"

#include <volpost/core/ClipPlane.hpp>
#include <volpost/core/ColorMap.hpp>
#include <volpost/render/GlObjects.hpp>
#include <volpost/render/RenderContext.hpp>

#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace volpost {

class StreamlineRenderer {
 public:
  void initialize();
  void release();

  /// The lines (model coordinates, in flow order) and a value per point. Uploads (context
  /// current). Throws std::invalid_argument when tubes would need more than 32M vertices.
  void setLines(const std::vector<std::vector<glm::dvec3>>& lines, const std::vector<std::vector<double>>& values,
                const glm::dvec3& origin, const StreamlineStyle& style);
  void setColorMap(const ColorMap& map);
  void setRange(double min, double max);
  void setClipPlanes(const std::vector<ClipPlane>& planes) { clipPlanes_ = planes; }
  /// Draws into the bound framebuffer with depth testing (ctx.camera, ctx.width/height).
  void render(const RenderContext& ctx);
  bool empty() const { return segmentIndices_ == 0 && tubeVertices_ == 0; }

  // Lighting of the lit lines (Banks 1994's diffuse exponent by default).
  glm::vec3 lightDirection{0.3f, 0.5f, 1.0f};  ///< view space, toward the light
  float ambient = 0.15f, diffuse = 0.85f, specular = 0.3f, diffuseExponent = 4.8f, shininess = 32.0f;
  glm::vec3 noValueColor{0.55f, 0.55f, 0.55f};

 private:
  struct Triangles;  // shaded triangles: tubes and arrow cones
  struct Radius;     // the tube's (and arrow's) radius at a value
  void uploadLines(const std::vector<std::vector<glm::dvec3>>& lines, const std::vector<std::vector<double>>& values);
  void appendTubes(const std::vector<std::vector<glm::dvec3>>& lines, const std::vector<std::vector<double>>& values,
                   const Radius& radius, Triangles& out) const;
  void appendArrows(const std::vector<std::vector<glm::dvec3>>& lines, const std::vector<std::vector<double>>& values,
                    const Radius& radius, Triangles& out) const;
  void setCommonUniforms(GLuint program, const RenderContext& ctx) const;

  gl::Program lineProgram_, tubeProgram_;
  gl::VertexArray lineVao_, tubeVao_;
  gl::Buffer lineVbo_, lineIbo_, tubeVbo_, tubeIbo_;
  gl::Texture colorMap_;
  GLsizei segmentIndices_ = 0, tubeVertices_ = 0;
  glm::dvec3 origin_{0.0};
  StreamlineStyle style_;
  float min_ = 0.0f, max_ = 1.0f;
  std::vector<ClipPlane> clipPlanes_;
};

}  // namespace volpost

// SPDX-License-Identifier: MIT
// Draws the model's boundary surface colored by a scalar result, with element edges.
#pragma once

#include <volpost/core/ClipPlane.hpp>
#include <volpost/core/ColorMap.hpp>
#include <volpost/core/Field.hpp>
#include <volpost/core/SampleView.hpp>
#include <volpost/render/GlObjects.hpp>

#include "host/BoundarySurface.hpp"

#include <vector>
#include <volpost/render/Renderer.hpp>

#include <glm/vec3.hpp>

#include <span>

namespace volpost {

class SurfaceRenderer : public Renderer {
 public:
  std::string name() const override { return "surface"; }
  void initialize() override;
  void release() override;
  void render(const RenderContext& ctx) override;

  /// Uploads the triangles and edges (once per model).
  void setSurface(const BoundarySurface& surface);
  /// Uploads triangles given by their corners (model coordinates, three per triangle; a
  /// section cut) without edges. Vertex i takes value i of setScalars(FieldLocation::Node, ...).
  void setTriangles(const std::vector<glm::dvec3>& corners, const glm::dvec3& origin);
  /// Uploads line segments only (two endpoints each, model coordinates; no faces), drawn
  /// as edges in edgeColor: an outline.
  void setLines(const std::vector<glm::dvec3>& endpoints, const glm::dvec3& origin);
  /// Fragments on the cut side of any plane are not drawn; `tolerance` (model units) keeps
  /// geometry lying on a plane (a section) from being cut by its own plane.
  void setClipPlanes(std::vector<ClipPlane> planes, double tolerance = 0.0) {
    clipPlanes_ = std::move(planes);
    clipTolerance_ = tolerance;
  }
  /// Uploads one value per node or per cell (only this changes with the field or step).
  /// Non-finite values are drawn in noValueColor. [min, max] maps onto the color map.
  void setScalars(FieldLocation location, SampleView values, double min, double max);
  /// No result: the surface is drawn in a neutral gray.
  void clearScalars();
  void setColorMap(const ColorMap& map);
  /// Discrete bands of equal width over [min, max] (0: continuous colors).
  void setColorBands(int bands) { colorBands_ = bands; }
  /// Colors by the value's logarithm over the range's (which must be positive; values of
  /// 0 and below are below it).
  void setLogScale(bool on) { logScale_ = on; }
  /// Values below min (above max) in this color instead of the map's end color.
  void setOutOfRangeColors(std::optional<glm::vec3> below, std::optional<glm::vec3> above) {
    belowColor_ = below;
    aboveColor_ = above;
  }
  /// Each element edge fades out as the distance on screen between it and its neighbours
  /// (the shortest edge at either end, scaled as the edge itself is projected) falls from
  /// kDenseEdgePixels to a third of it: a 256 x 256 face of a seismic cube, or a fine mesh seen whole, would
  /// otherwise be painted over in edge color. Zooming in brings the edges back. Outlines
  /// (setLines) are always drawn in full.
  void setShowEdges(bool show) { showEdges_ = show; }
  static constexpr float kDenseEdgePixels = 6.0f;
  /// Faces off: only the element edges are drawn (over a volume).
  void setShowFaces(bool show) { showFaces_ = show; }
  /// Points on: the surface's nodes are drawn as square points of this size (device
  /// pixels) in their result colors, unlit, instead of its faces.
  void setShowPoints(bool show, float pixels = 4.0f) {
    showPoints_ = show;
    pointPixels_ = pixels;
  }
  /// Off: dense element edges are drawn in full (a wireframe, with no faces to crowd).
  void setFadeDenseEdges(bool on) { allowFading_ = on; }
  /// On: the surface's element edges are drawn in the result's colors (a wireframe colored
  /// as ParaView colors one: by the value at each end for a result per node, by a face's
  /// element for one per element); off, or without a result: in edgeColor.
  void setColorEdgesByValue(bool on) { colorEdges_ = on; }
  bool showEdges() const { return showEdges_; }
  /// Shading off draws exact color-map colors (used by the image tests).
  void setLighting(bool on) { lighting_ = on; }
  /// Below 1 the faces are blended over what is already drawn (streamlines inside show
  /// through); draw the opaque things first.
  void setOpacity(float opacity) { opacity_ = opacity; }

  glm::vec3 noValueColor{0.55f, 0.55f, 0.55f};
  glm::vec3 edgeColor{0.1f, 0.1f, 0.1f};
  glm::vec3 plainColor{0.8f, 0.8f, 0.8f};

 private:
  gl::Program surfaceProgram_, edgeProgram_;
  gl::VertexArray surfaceVao_, edgeVao_;
  gl::Buffer surfaceVbo_, edgeVbo_, edgeIds_, scalars_;
  gl::Texture colorMap_;
  int colorBands_ = 0;
  bool logScale_ = false;
  std::optional<glm::vec3> belowColor_, aboveColor_;
  GLsizei triangleVertices_ = 0, edgeVertices_ = 0;
  int location_ = -1;  ///< -1 none, 0 node, 1 cell
  float min_ = 0.f, max_ = 1.f;
  bool showEdges_ = true, showFaces_ = true, lighting_ = true, showPoints_ = false, allowFading_ = true;
  float pointPixels_ = 4.0f;
  float opacity_ = 1.0f;
  static std::vector<float> withOtherEnds(const std::vector<float>& segments, const std::vector<float>& spacing);
  bool fadeDenseEdges_ = true;  ///< element edges fade where they crowd; outlines do not
  bool colorEdges_ = false;
  bool edgesHaveValues_ = false;  ///< the edges are the surface's (setSurface), not an outline's
  /// Each edge vertex's surface vertex and a face holding the edge (binding 1 of the edges).
  void uploadEdgeIds(const std::vector<std::uint32_t>& ids);
  glm::dvec3 origin_{0.0};  ///< what the uploaded positions are relative to
  /// The model's node of each surface vertex and cell of each face, in the order of their
  /// scalars on the GPU (setSurface); empty after setTriangles, whose scalars are one per
  /// corner.
  std::vector<std::uint32_t> scalarNodes_, scalarCells_;
  std::vector<ClipPlane> clipPlanes_;
  double clipTolerance_ = 0.0;
};

}  // namespace volpost

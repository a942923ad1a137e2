// SPDX-License-Identifier: MIT
// Draws a model's boundary surface colored by the active quantity, with its element
// edges (also alone, over a volume). A layer of the Scene; holds GL objects, so
// initialize() and release() need the context current.
#pragma once

#include "ModelSession.hpp"
#include "SceneState.hpp"

#include <volpost/core/optics/ElementField.hpp>
#include <volpost/core/optics/IsoTables.hpp>

#include <volpost/core/ColorMap.hpp>
#include "host/ElementRefinement.hpp"
#include "host/render/SurfaceRenderer.hpp"

#include <glm/vec3.hpp>

#include <atomic>
#include <cstdint>
#include <future>
#include <memory>
#include <optional>
#include <vector>

namespace volpost::app {

class BoundaryRenderer {
 public:
  BoundaryRenderer() = default;
  BoundaryRenderer(const BoundaryRenderer&) = delete;
  BoundaryRenderer& operator=(const BoundaryRenderer&) = delete;
  ~BoundaryRenderer() { stopRefining(); }
  void initialize();
  /// On (the window): a surface in the cells' own shapes that must be refined anew is refined
  /// on a worker thread while the model's flat faces are drawn with the same values;
  /// pending() until it can be drawn. Off (pictures): refined before the frame is drawn.
  void setAsynchronousUpdates(bool on) { asynchronous_ = on; }
  /// A curved surface still being refined on a worker thread, or refined and not yet shown
  /// while the surface is drawn: draw again later to show it.
  bool pending() const;
  /// A frame begins: pending() then counts a refined surface as waiting only once the
  /// frame has drawn the surface (a volume view does not wait for it).
  void frameStarted() { surfaceDrawn_ = false; }
  void release();
  bool initialized() const { return initialized_; }

  void setSession(std::shared_ptr<const ModelSession> session);
  /// How node values vary inside a cell for sections and iso-surfaces: with the cells'
  /// own shape functions, a mesh of other cells than tet4 has its sections cut through the
  /// cells' own (curved) shapes and colored by their own field, and its iso-surfaces
  /// found in that field, and its boundary surface drawn in the cells' own shapes and
  /// field (ElementRefinement). Takes effect at the next setCuts, setSlices and
  /// setIsoSurfaces, and for the surface at the next draw.
  void setFieldInterpolation(FieldInterpolation interpolation) { interpolation_ = interpolation; }
  /// How finely the cells' own shapes and field are followed (limitsForElementTolerance):
  /// another tolerance refines the boundary, sections and iso-surfaces again.
  void setRefinementLimits(const RefinementLimits& limits);
  /// Colors by the view's values (`viewVersion` changes with them); nullptr shows the plain
  /// surface.
  void setScalars(const ScalarView* view, DisplayRange range, std::uint64_t viewVersion);
  void setOutOfRangeColors(std::optional<glm::vec3> below, std::optional<glm::vec3> above) {
    surface_.setOutOfRangeColors(below, above);
    sections_.setOutOfRangeColors(below, above);
    slices_.setOutOfRangeColors(below, above);
  }
  void setColorBands(int bands) {
    surface_.setColorBands(bands);
    sections_.setColorBands(bands);
    slices_.setColorBands(bands);
  }
  void setLogScale(bool on) {
    surface_.setLogScale(on);
    sections_.setLogScale(on);
    slices_.setLogScale(on);
  }
  void setColorMap(const ColorMap& map) {
    surface_.setColorMap(map);
    sections_.setColorMap(map);
    slices_.setColorMap(map);
  }
  /// Slices through the model on these planes (a regular grid's inline, crossline and time
  /// slices), colored by the view's values as the surface is, without cutting anything
  /// away, themselves cut by `clipPlanes` (the clip planes and box). Recomputed only when
  /// the planes, `viewVersion` or the range change.
  void setSlices(const std::vector<ClipPlane>& planes, const std::vector<ClipPlane>& clipPlanes, const ScalarView* view,
                 std::uint64_t viewVersion, DisplayRange range);
  std::size_t sliceTriangles() const { return sliceTriangles_; }
  /// Only the slices, depth-tested, over what the target holds (the opaque part of a
  /// volume picture).
  void renderSlices(const RenderContext& ctx);
  /// Section cuts: the surface is cut away on the far side of each plane (the side its
  /// normal points away from) and the model's cross-section on each plane is drawn, colored
  /// by the view's values interpolated in the tets, as the surface is. Recomputed only when
  /// the planes, `viewVersion` (the values) or the range change. Empty: no cuts.
  void setCuts(const std::vector<ClipPlane>& planes, const ScalarView* view, std::uint64_t viewVersion,
               DisplayRange range);
  /// Iso-surfaces of the view's values (nodal results) drawn in their colors, cut by the
  /// same planes. Re-extracted only when the surfaces or `viewVersion` change.
  void setIsoSurfaces(const std::vector<optics::IsoSurface>& surfaces, const ScalarView* view, std::uint64_t viewVersion);
  std::size_t isoTriangles() const { return isoTriangles_; }
  /// The iso-surfaces' triangles now drawn, three corners each, model coordinates (picking).
  const std::vector<glm::dvec3>& isoCorners() const { return isoCorners_; }
  /// The boundary's triangles as last drawn in the cells' own shapes, three corners each,
  /// model coordinates (picking: a click lands on the curved face the user sees); empty
  /// when the surface is drawn with the model's own flat faces.
  const std::vector<glm::dvec3>& curvedCorners() const { return curvedCorners_; }
  /// Triangles of the cross-sections now shown (for tests and the status bar).
  std::size_t sectionTriangles() const { return sectionTriangles_; }
  void setShowEdges(bool show) { surface_.setShowEdges(show); }
  bool showEdges() const { return surface_.showEdges(); }
  /// Faces off: render() draws only the element edges (the opaque geometry over a volume).
  void setShowFaces(bool show) { surface_.setShowFaces(show); }
  /// The surface's nodes as points (device pixels) instead of its faces.
  void setShowPoints(bool show, float pixels) {
    showPoints_ = show;
    surface_.setShowPoints(show, pixels);
  }
  void setFadeDenseEdges(bool on) { surface_.setFadeDenseEdges(on); }
  /// The surface's element edges in the result's colors (a wireframe).
  void setColorEdgesByValue(bool on) { surface_.setColorEdgesByValue(on); }
  void setLighting(bool on) {
    surface_.setLighting(on);
    sections_.setLighting(on);
    slices_.setLighting(on);
  }

  /// Off: only the sections and iso-surfaces are drawn, not the boundary surface.
  void setSurfaceShown(bool shown) { surfaceShown_ = shown; }
  void setOpacity(float opacity) {
    opacity_ = opacity;
    surface_.setOpacity(opacity);
  }

  /// Clears ctx.framebuffer to the background and draws.
  void render(const RenderContext& ctx);
  /// Draws over what the target holds (no clear): the see-through surface over lines.
  void renderOver(const RenderContext& ctx);
  /// Only clears to the background (under a volume).
  void renderBackground(const RenderContext& ctx);

  glm::vec3 background{0.96f, 0.96f, 0.97f};

 private:
  SurfaceRenderer surface_;
  SurfaceRenderer sections_;
  SurfaceRenderer slices_;
  std::shared_ptr<const ModelSession> session_;
  struct CutKey {
    std::vector<ClipPlane> planes;
    std::uint64_t viewVersion = 0;
    DisplayRange range;
    bool hasView = false;
    FieldInterpolation interpolation = FieldInterpolation::Tetrahedra;
    bool operator==(const CutKey&) const = default;
  };
  /// The cells' own field of the view's node values (zeros for geometry alone) when
  /// sections and iso-surfaces follow it; nullptr when they use the split.
  std::shared_ptr<const optics::ElementField> elementField(const ScalarView* view, std::uint64_t viewVersion) const;
  FieldInterpolation interpolation_ = FieldInterpolation::Tetrahedra;
  RefinementLimits limits_;
  mutable std::shared_ptr<const optics::ElementField> elementField_;
  mutable std::optional<std::uint64_t> elementFieldFor_;  ///< its view version (0: geometry alone)
  std::optional<CutKey> cutFor_;  ///< what the sections now uploaded were cut for
  std::optional<CutKey> slicesFor_;  ///< and the slices
  std::size_t sliceTriangles_ = 0;
  std::vector<std::unique_ptr<SurfaceRenderer>> isoRenderers_;  ///< one per iso-surface
  std::optional<std::pair<std::vector<double>, std::uint64_t>> isoFor_;  ///< values and view version extracted
  std::size_t isoTriangles_ = 0;
  std::vector<glm::dvec3> isoCorners_;
  float opacity_ = 1.0f;
  bool surfaceShown_ = true;
  std::size_t sectionTriangles_ = 0;
  bool initialized_ = false;
  /// Uploads the boundary (the session's, or in the cells' own shapes and field) and its
  /// colors where they are not current.
  void ensureSurface();
  /// The curved surface refined on a worker thread for `key` (curvedFor_'s meaning).
  struct Refining {
    std::optional<std::uint64_t> key;
    std::shared_ptr<std::atomic<bool>> cancel;
    std::future<RefinedSurface> result;
  };
  std::optional<Refining> refining_;
  bool asynchronous_ = false;
  bool surfaceDrawn_ = false;  ///< this frame drew the surface
  /// Cancels the refinement under way, if any, and waits for its thread.
  void stopRefining();
  /// Uploads a curved surface refined for `key`.
  void showCurved(RefinedSurface curved, std::optional<std::uint64_t> key);
  /// Whether the surface is drawn in the cells' own shapes and field (faces, not the nodes
  /// as points, of a mesh with other cells than tet4).
  bool curvedSurfaceWanted() const;
  bool showPoints_ = false;
  /// The view version the uploaded curved surface was refined for (0: geometry alone);
  /// none: the session's own surface is uploaded.
  std::optional<std::uint64_t> curvedFor_;
  RefinedSurface curved_;  ///< the curved surface drawn: its points' values and origins (its mesh is on the GPU)
  std::vector<glm::dvec3> curvedCorners_;
  /// The model's cross-sections on these planes into `target`, colored by the view's
  /// values (sections and slices); returns their triangle count.
  std::size_t uploadCrossSections(SurfaceRenderer& target, const std::vector<ClipPlane>& planes, const ScalarView* view,
                                  std::uint64_t viewVersion, DisplayRange range) const;
  bool surfaceUploaded_ = false;
  // The view is the caller's (the Scene's), not a copy: a volume picture of a large grid
  // must not hold its values twice for a surface nobody draws. Every change of the view
  // reaches setScalars before the next draw, so the pointer is current when it is used.
  struct ShownScalars {
    const ScalarView* view;
    DisplayRange range;
    std::uint64_t version;
  };
  std::optional<ShownScalars> scalars_;  ///< what the surface is colored by; none: plain
  bool scalarsUploaded_ = false;
};

}  // namespace volpost::app

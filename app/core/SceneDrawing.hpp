// SPDX-License-Identifier: MIT
// Draws a Scene with OpenGL: it owns the GL objects (the boundary surface, the deformed
// model's outline, the streamlines, the volume renderer from a plugin, the depth target
// the volume's rays end at) and draws a const scene. It keeps the scene's revision counts
// it last drew and hands each layer only what changed since: a dragged plane reaches the
// volume renderer as a new plane and nothing else.
//
// The window's viewport holds one for its context; a headless picture (renderSceneImage)
// makes one for its own.
#pragma once

#include "BoundaryRenderer.hpp"
#include "RefinedElementVolume.hpp"
#include "Scene.hpp"

#include "host/ClipCulling.hpp"
#include "host/render/StreamlineRenderer.hpp"
#include "host/render/SurfaceRenderer.hpp"

#include <volpost/render/GridVolumeRenderer.hpp>
#include <volpost/render/OffscreenTarget.hpp>
#include <volpost/render/RenderContext.hpp>
#include <volpost/render/VolumeRenderer.hpp>

#include <memory>
#include <string>
#include <vector>

namespace volpost::app {

class SceneDrawing {
 public:
  SceneDrawing();
  ~SceneDrawing();
  SceneDrawing(const SceneDrawing&) = delete;
  SceneDrawing& operator=(const SceneDrawing&) = delete;

  // ---- GL (a context current) ----
  void initialize();
  void release();
  bool initialized() const { return initialized_; }
  /// Interactive use (the window): the volume's slow tables build off the GUI thread and
  /// streamlines are drawn once the caller has traced them (Scene::setStreamlineResult).
  void setAsynchronousUpdates(bool on);
  /// Draws the scene into ctx.framebuffer (cleared to the background). The legend is not
  /// drawn: callers paint the scene's legend over the image their own way. Lines that need
  /// tracing are left out (Scene::updateStreamlines traces them). Throws
  /// std::invalid_argument when the volume renderer cannot draw what the scene shows.
  void render(const Scene& scene, const RenderContext& ctx);

  // ---- what the last frame drew ----
  VolumeStats volumeStats() const;
  /// The last frame's volume alone: premultiplied RGBA floats, top row first; empty when
  /// it drew no volume.
  std::vector<float> readVolumeImage() const;
  /// Triangles of the section cuts the last surface frame drew.
  std::size_t sectionTriangles() const { return boundary_.sectionTriangles(); }
  /// Triangles of the iso-surfaces the last surface frame drew.
  std::size_t isoTriangles() const { return boundary_.isoTriangles(); }
  /// The surface view's iso-surface triangles as last drawn (three corners each).
  const std::vector<glm::dvec3>& isoSurfaceCorners() const { return boundary_.isoCorners(); }
  /// The boundary as last drawn in the cells' own shapes (BoundaryRenderer::curvedCorners).
  const std::vector<glm::dvec3>& curvedBoundaryCorners() const { return boundary_.curvedCorners(); }
  /// The cells' own field the volume renderer draws (null: it draws the tetrahedra's).
  const optics::ElementField* elementField() const { return volumeDrawn_ ? elementField_.get() : nullptr; }
  /// The volume renderer is still refining or building tables off the GUI thread, or the
  /// surface in the cells' own shapes is still refined (asynchronous updates).
  bool hasPendingWork() const {
    return (volume_ && volume_->hasPendingWork()) || boundary_.pending() || refinedVolume_.pending();
  }
  /// How far the cells' own field is refined for the volume on a worker thread (0..1);
  /// nullopt when no refinement is under way.
  std::optional<double> volumeRefinement() const { return refinedVolume_.progress(); }
  /// What the last frame's volume says of the cells' own field it drew on refined
  /// tetrahedra (empty: it drew none).
  std::vector<std::string> refinedVolumeNotes() const;

 private:
  void applyToBoundary(const Scene& scene);
  void applyToStreamlines(const Scene& scene);
  void applyToVolume(const Scene& scene);
  void applyToGridVolume(const Scene& scene, GridVolumeRenderer& renderer);
  void applyVolumeSettings(const Scene& scene);
  /// The cells' own field to a renderer that draws it (or none, for the tetrahedra's field),
  /// built again only where `volumeSent` (setVolume or setValues dropped it) or it was off.
  void applyElementField(const Scene& scene, bool volumeSent);
  /// The scene asks for the cells' own field of a renderer that draws the tetrahedra's only.
  bool refinesElementField(const Scene& scene) const;
  bool applyRefinedElementField(const Scene& scene, const std::vector<ClipPlane>& cullPlanes);
  void renderSurface(const Scene& scene, const RenderContext& ctx);
  void renderVolume(const Scene& scene, const RenderContext& ctx);
  void drawUndeformedOutline(const Scene& scene, const RenderContext& ctx);
  /// Forget what the renderers hold: everything is handed over again on the next frame.
  void forgetAll();
  /// Forget what the volume renderer holds (a new renderer, or the other kind of data).
  void forgetVolume();

  /// The scene's counts as last handed to the renderers; kNever for what was never.
  static constexpr std::uint64_t kNever = ~std::uint64_t(0);
  SceneRevisions drawn_;
  bool asynchronous_ = false;

  BoundaryRenderer boundary_;
  SurfaceRenderer undeformedEdges_;  ///< the undeformed model's element edges (deformation's outline)
  const ModelSession* undeformedUploaded_ = nullptr;
  SurfaceRenderer glyphRenderer_;  ///< arrows or principal bars at the nodes
  std::shared_ptr<const GlyphGeometry> glyphsUploaded_;
  std::string glyphColorMap_;  ///< the map the glyphs' texture holds (uploaded when it changes, not per frame)
  /// Uploads the scene's glyphs when they changed; false when none are shown.
  bool applyToGlyphs(const Scene& scene);
  void drawGlyphs(const Scene& scene, const RenderContext& ctx);
  SurfaceRenderer modelLines_;  ///< the model's feature edges or bounding box (representations, volume outline)
  std::pair<const ModelSession*, SurfaceRepresentation> modelLinesFor_{nullptr, SurfaceRepresentation::Surface};
  /// Draws the model's feature edges or its bounding box, depth-tested, cut by the planes.
  void drawModelLines(const Scene& scene, const RenderContext& ctx, SurfaceRepresentation lines);
  StreamlineRenderer streamlineRenderer_;
  const StreamlineResult* linesUploaded_ = nullptr;    ///< the lines streamlineRenderer_ holds
  std::shared_ptr<const StreamlineResult> linesHeld_;  ///< kept alive while uploaded
  std::unique_ptr<VolumeRenderer> volume_;
  std::string volumeName_;                                    ///< the renderer volume_ is
  VolumeRendererTraits volumeTraits_;                         ///< what it says of itself (asked once)
  bool volumeGivenAGrid_ = false;                             ///< volume_ was given the grid (else tetrahedra)
  bool volumeDrawn_ = false;                                  ///< the last frame drew the volume
  std::optional<CulledMesh> culled_;                          ///< the tets the renderer holds, when culled
  std::vector<ClipPlane> culledFor_;                          ///< the planes culled_ was made for
  std::shared_ptr<const optics::ElementField> elementField_;  ///< what the renderer draws, if the cells' own field
  std::unique_ptr<OffscreenTarget> depthTarget_;              ///< depth of the edges drawn over a volume
  RefinedElementVolume refinedVolume_;  ///< the cells' own field refined for a renderer of tetrahedra
  std::shared_ptr<const RefinedElementMesh> refinedShown_;    ///< what the renderer holds of it, if anything
  std::optional<RefinedElementKey> shownKey_;                 ///< what refinedShown_ was made for
  std::shared_ptr<const RefinedElementMesh> refinedSkipped_;  ///< too many pieces: the split is drawn, and said
  bool initialized_ = false;
};

}  // namespace volpost::app

// SPDX-License-Identifier: MIT
#include "SceneDrawing.hpp"

#include "FeatureEdges.hpp"
#include "ReferenceVolumeImage.hpp"

#include <volpost/core/ResourceLimits.hpp>

#include <algorithm>
#include <stdexcept>

namespace volpost::app {
namespace {

// Before a renderer builds its structure (face adjacency, per-tet data, the GPU copy),
// the memory it will need next to the model is checked against the budget: a clear
// message with the figure instead of the system killing the program. About 96 bytes per
// tet and 48 per node cover the peaks volpost_scale_bench measures for the CPU and GPU ray
// casters above the model (docs/methods/scale.md).
void requireVolumeMemory(const Model& model, const Mesh& tets) {
  const double modelBytes = double(model.mesh().cellBytes()) + 24.0 * double(model.nodeCount());
  const double rendererBytes = 96.0 * double(tets.cellCount()) + 48.0 * double(tets.nodeCount());
  requireMemory(modelBytes + rendererBytes, model.sourcePath,
                "the model and the volume renderer's structures for " + std::to_string(tets.cellCount()) +
                    " tetrahedra (about 96 bytes per tet)");
}

// Draws `renderer` (positions relative to `origin`) into ctx's target, hidden behind what
// is nearer there.
void drawDepthTested(SurfaceRenderer& renderer, const RenderContext& ctx, const glm::dvec3& origin) {
  glBindFramebuffer(GL_FRAMEBUFFER, ctx.framebuffer);
  glViewport(0, 0, ctx.width, ctx.height);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  RenderContext local = ctx;
  local.origin = origin;
  renderer.render(local);
  glDisable(GL_DEPTH_TEST);
}

constexpr SceneRevisions never() {
  constexpr std::uint64_t n = ~std::uint64_t(0);
  return {n, n, n, n, n, n, n, n, n, n, n, n};
}

// Whether a count moved since it was drawn; the drawn count follows it.
bool catchUp(std::uint64_t& drawn, std::uint64_t now) {
  const bool changed = drawn != now;
  drawn = now;
  return changed;
}

// The volume's counts follow the scene's once everything reached the renderer: a frame
// that throws (over the memory budget, a refusal) leaves them behind, and the next tries again.
void volumeCaughtUp(SceneRevisions& drawn, const SceneRevisions& now) {
  drawn.geometry = now.geometry;
  drawn.values = now.values;
  drawn.tables = now.tables;
  drawn.planes = now.planes;
  drawn.iso = now.iso;
  drawn.mode = now.mode;
}

}  // namespace

SceneDrawing::SceneDrawing() : drawn_(never()) { boundary_.background = kSceneBackground; }

SceneDrawing::~SceneDrawing() = default;

void SceneDrawing::forgetAll() {
  drawn_ = never();
  linesUploaded_ = nullptr;
  linesHeld_.reset();
  forgetVolume();
}

void SceneDrawing::forgetVolume() {
  drawn_.geometry = drawn_.values = drawn_.tables = drawn_.planes = drawn_.iso = drawn_.mode = kNever;
  refinedShown_.reset();
  refinedSkipped_.reset();
  refinedVolume_.stop();
  culled_.reset();
  culledFor_.clear();
  elementField_.reset();
}

void SceneDrawing::initialize() {
  boundary_.initialize();
  undeformedEdges_.initialize();
  undeformedUploaded_ = nullptr;
  modelLines_.initialize();
  modelLinesFor_.first = nullptr;
  glyphRenderer_.initialize();
  glyphsUploaded_.reset();
  glyphColorMap_.clear();
  streamlineRenderer_.initialize();
  initialized_ = true;
  forgetAll();  // a fresh context holds nothing
}

void SceneDrawing::release() {
  if (!initialized_) return;
  if (volume_) volume_->release();
  volume_.reset();
  volumeName_.clear();
  volumeDrawn_ = false;
  depthTarget_.reset();
  streamlineRenderer_.release();
  boundary_.release();
  undeformedEdges_.release();
  undeformedUploaded_ = nullptr;
  modelLines_.release();
  modelLinesFor_.first = nullptr;
  glyphRenderer_.release();
  glyphsUploaded_.reset();
  glyphColorMap_.clear();
  initialized_ = false;
  forgetAll();
}

void SceneDrawing::setAsynchronousUpdates(bool on) {
  asynchronous_ = on;
  boundary_.setAsynchronousUpdates(on);
  if (volume_) volume_->setAsynchronousUpdates(on);
}

VolumeStats SceneDrawing::volumeStats() const { return volume_ ? volume_->stats() : VolumeStats{}; }

std::vector<float> SceneDrawing::readVolumeImage() const {
  return volume_ && volumeDrawn_ ? volume_->readImage() : std::vector<float>{};
}

void SceneDrawing::applyToBoundary(const Scene& scene) {
  const SceneRevisions& now = scene.revisions();
  const SceneState& s = scene.shown();
  const VersionedView values = scene.surfaceValues();  // the result's, or the sets' colors
  const DisplayRange range = scene.surfaceRange();
  // The surface's uploads do not throw: the counts can follow at once.
  const bool model = catchUp(drawn_.model, now.model);
  const bool scalars = catchUp(drawn_.scalars, now.scalars);
  if (model) boundary_.setSession(scene.sharedSession());
  if (model || scalars) boundary_.setScalars(values.view, range, values.version);
  if (catchUp(drawn_.colorMap, now.colorMap)) {
    const auto asFloat = [](const std::optional<glm::dvec3>& c) {
      return c ? std::optional<glm::vec3>(glm::vec3(*c)) : std::nullopt;
    };
    if (s.sets.colors) {  // each set's color flat over its band of the palette
      boundary_.setColorMap(setPaletteMap());
      boundary_.setColorBands(kSetPaletteSize);
      boundary_.setLogScale(false);
      boundary_.setOutOfRangeColors(std::nullopt, std::nullopt);
    } else {
      boundary_.setColorMap(ColorMap::named(s.colorMap));
      boundary_.setColorBands(s.colorBands);
      boundary_.setLogScale(s.logScale);
      boundary_.setOutOfRangeColors(asFloat(s.belowColor), asFloat(s.aboveColor));
    }
  }
  // Section cuts in the surface view: the volume's planes and box cut the surface too.
  const std::vector<ClipPlane> cuts = s.volume.allClipPlanes();
  boundary_.setFieldInterpolation(s.volume.interpolation);
  boundary_.setRefinementLimits(limitsForElementTolerance(s.volume.elementTolerance));
  boundary_.setCuts(s.volume.shown ? std::vector<ClipPlane>{} : cuts, values.view, values.version, range);
  const VersionedView iso = scene.isoSurfaceValues();
  boundary_.setIsoSurfaces(s.volume.shown ? std::vector<optics::IsoSurface>{} : s.volume.isoSurfaces, iso.view,
                           iso.version);
  boundary_.setSlices(scene.slicePlanes(), cuts, values.view, values.version, range);
}

// Uploads the lines with the current style (a style change re-uploads, never re-traces).
void SceneDrawing::applyToStreamlines(const Scene& scene) {
  if (!scene.streamlinesDrawn()) return;
  const std::shared_ptr<const StreamlineResult> result = scene.streamlineResult();
  const std::uint64_t now = scene.revisions().streamlines;
  if (drawn_.streamlines == now && linesUploaded_ == result.get()) return;
  const StreamlineResult& r = *result;
  std::vector<std::vector<glm::dvec3>> lines;
  for (const Streamline& l : r.lines) lines.push_back(l.points);
  StreamlineStyle style = scene.shown().streamlines.style;
  const double size = scene.session()->model().bounds().diagonal();
  if (style.tubeRadius <= 0.0) style.tubeRadius = 0.003 * size;
  if (style.arrowSpacing <= 0.0) style.arrowSpacing = 0.08 * size;
  streamlineRenderer_.setLines(lines, r.values, scene.session()->origin(), style);
  streamlineRenderer_.setColorMap(ColorMap::named(scene.shown().colorMap));
  streamlineRenderer_.setRange(r.min, r.max);
  linesUploaded_ = result.get();
  linesHeld_ = result;
  drawn_.streamlines = now;  // after the upload, which throws for too many tube vertices
}

// Hands the volume renderer what changed, and only that. The GPU holds only the tets the
// clip box can show (the renderer cuts exactly at every plane, so the picture is the
// same); free planes are not culled to, so dragging one never rebuilds, and the window
// and the command line hold the same tets and draw the same pixels.
void SceneDrawing::applyToVolume(const Scene& scene) {
  const VolumeLayer& v = scene.shown().volume;
  const ModelSession& session = *scene.session();
  const ScalarView& view = *scene.view();
  const SceneRevisions& now = scene.revisions();
  if (drawn_.renderer != now.renderer || !volume_ || volumeName_ != v.renderer) {
    if (scene.volumeRenderers().drawsApart(v.renderer))
      throw std::invalid_argument(
          "the volume renderer '" + v.renderer + "' makes its pictures apart (volpost render --renderer " + v.renderer +
          "); choose one that draws here" + inParentheses(scene.volumeRenderers().namesDrawnHere()));
    if (volume_) volume_->release();
    volume_ = scene.volumeRenderers()(v.renderer);
    volumeName_.clear();
    if (!volume_) throw std::invalid_argument("no volume renderer named '" + v.renderer + "' is loaded");
    volume_->initialize();
    volume_->setAsynchronousUpdates(asynchronous_);
    volumeName_ = v.renderer;
    volumeTraits_ = volume_->traits();
    forgetVolume();  // everything goes to the new renderer
    drawn_.renderer = now.renderer;
  }
  // A grid goes to a grid renderer as a grid, except a per-cell field where the renderer
  // also draws tetrahedra (the CPU ray caster): grid renderers sample values at the points.
  auto* grid = volumeTraits_.drawsGrids ? dynamic_cast<GridVolumeRenderer*>(volume_.get()) : nullptr;
  const bool asGrid =
      grid && (!volumeTraits_.drawsMeshes || (session.model().grid && view.location == FieldLocation::Node));
  if (asGrid != volumeGivenAGrid_) {  // the other kind of data: everything goes again
    forgetVolume();
    volumeGivenAGrid_ = asGrid;
  }
  if (asGrid) {
    applyToGridVolume(scene, *grid);
    return;
  }
  if (v.transferFunction2D)
    throw std::invalid_argument(
        session.model().grid
            ? "the volume renderer '" + v.renderer + "' has no 2D transfer functions: choose one that has" +
                  inParentheses(scene.volumeRenderers().namesWhere(
                      [](const VolumeRendererTraits& t) { return t.transferFunction2D; }))
            : "2D transfer functions (over the value and its gradient) are drawn on regular grids "
              "(SEG-Y, image data); this model is a mesh");
  const std::vector<ClipPlane> cullPlanes = v.clipBox ? clipBoxPlanes(*v.clipBox) : std::vector<ClipPlane>{};
  if (!refinesElementField(scene)) refinedSkipped_.reset();
  else if (applyRefinedElementField(scene, cullPlanes)) return;
  // Where the renderer holds refined pieces the split goes again; the pieces stay alive
  // until it has (the renderer reads them when it next draws).
  const bool geometry = drawn_.geometry != now.geometry || cullPlanes != culledFor_ || refinedShown_;
  const bool values = drawn_.values != now.values;
  const Mesh& tets = session.tetrahedra().mesh;
  if (geometry) {
    requireVolumeMemory(session.model(), tets);
    const std::vector<double> tetValues = session.tetValues(view);
    if (cullPlanes.empty()) {
      culled_.reset();
      volume_->setVolume(tets, view.location, tetValues);
    } else {
      culled_ = cullToClipPlanes(tets, cullPlanes);
      volume_->setVolume(culled_->mesh, view.location, culled_->values(view.location, tetValues));
    }
    culledFor_ = cullPlanes;
    refinedShown_.reset();
  } else if (values) {
    const std::vector<double> tetValues = session.tetValues(view);
    volume_->setValues(culled_ ? culled_->values(view.location, tetValues) : tetValues);  // only the values travel
  }
  if (geometry || values || drawn_.mode != now.mode) applyElementField(scene, geometry || values);
  applyVolumeSettings(scene);
}

bool SceneDrawing::refinesElementField(const Scene& scene) const {
  return drawsCellsFieldOnPieces(volumeTraits_, scene.shown().volume.interpolation, scene.view()->location,
                                 scene.session()->model());
}

// The cells' own field for a renderer that draws tetrahedra only: the split refined to the
// tolerance, handed over as a tet mesh of its own. False while it is refined on a worker
// thread (the split's field is drawn meanwhile).
bool SceneDrawing::applyRefinedElementField(const Scene& scene, const std::vector<ClipPlane>& cullPlanes) {
  const SceneRevisions& now = scene.revisions();
  const VolumeLayer& v = scene.shown().volume;
  if (v.elementTolerance == 0.0)
    throw std::invalid_argument(
        "the volume renderer '" + v.renderer +
        "' draws the cells' own field on tetrahedra refined to a tolerance above 0; the "
        "exact field (tolerance 0) is drawn by " +
        scene.volumeRenderers().namesWhere([](const VolumeRendererTraits& t) { return t.elementInterpolation; }));
  const TransferFunction transferFunction = scene.transferFunction();
  const RefinedElementKey key{now.geometry, now.values, cullPlanes, v.elementTolerance, transferFunction};
  const auto work = [session = scene.sharedSession(), view = *scene.view(), cullPlanes, transferFunction,
                     tolerance = v.elementTolerance](const Progress& progress) {
    RefinedElementMesh out;
    out.session = session;
    out.goal.perChannel = tolerance;
    const TetMesh& split = session->tetrahedra();
    std::vector<std::uint32_t> chosen;
    if (cullPlanes.empty()) {
      chosen.resize(split.mesh.cellCount());
      for (std::size_t t = 0; t < chosen.size(); ++t) chosen[t] = std::uint32_t(t);
    } else {
      const CulledMesh culled = cullToClipPlanes(split.mesh, cullPlanes);
      chosen.assign(culled.cellOf.begin(), culled.cellOf.end());
    }
    out.chosen = chosen.size();
    // The pieces are bisected from a copy of the chosen tetrahedra; past half the budget
    // there is too little room left to cut, and the split is drawn with no copy made.
    if (2 * chosen.size() > out.goal.maxTetrahedra) {
      out.unrefined = true;
      return out;
    }
    std::vector<double> converted;
    const auto values = view.values.doubles(converted);
    out.nodeValues.assign(values.begin(), values.end());
    out.field = std::make_shared<const optics::ElementField>(session->model().mesh(), out.nodeValues, split,
                                                             split.mesh.bounds().center());
    Progress refining = progress;
    refining.setStage("refining the cells");
    VolumeRefinementGoal goal = out.goal;
    goal.transferFunction = &transferFunction;
    out.refined = refineVolumeAdaptively(*out.field, chosen, goal, refining);
    return out;
  };
  const auto refined = refinedVolume_.wanted(key, work, asynchronous_);
  if (!refined && refinedShown_ && shownKey_ && shownKey_->sameField(key)) {
    // Only the transfer function or the tolerance changed: the pieces held draw the same
    // field, refined for the other, while the new ones are made.
    applyVolumeSettings(scene);
    return true;
  }
  refinedSkipped_ = refined && refined->unrefined ? refined : nullptr;
  if (!refined || refined->unrefined) return false;
  if (refinedShown_ != refined) {
    shownKey_ = key;
    requireVolumeMemory(scene.session()->model(), refined->refined.tets.mesh);
    volume_->setVolume(refined->refined.tets.mesh, FieldLocation::Node, refined->refined.values);
    refinedShown_ = refined;
    culled_.reset();
    culledFor_.clear();
    elementField_.reset();
  }
  applyVolumeSettings(scene);
  return true;
}

std::vector<std::string> SceneDrawing::refinedVolumeNotes() const {
  if (volumeDrawn_ && refinedSkipped_) return app::refinedVolumeNotes(*refinedSkipped_);
  if (!volumeDrawn_ || !refinedShown_) return {};
  std::vector<std::string> notes = app::refinedVolumeNotes(*refinedShown_);
  for (std::string& note : elementFieldNotes(*refinedShown_->field, refinedShown_->field->mesh()))
    notes.push_back(std::move(note));
  return notes;
}

void SceneDrawing::applyElementField(const Scene& scene, bool volumeSent) {
  if (!volumeTraits_.elementInterpolation) return;
  const ModelSession& session = *scene.session();
  const ScalarView& view = *scene.view();
  // Values per cell are constant in a cell: both interpolations are the same field. A mesh
  // of tet4 cells is its own split: nothing to send.
  const Mesh& cells = session.model().mesh();
  bool wanted =
      scene.shown().volume.interpolation == FieldInterpolation::Element && view.location == FieldLocation::Node;
  if (wanted) {
    wanted = false;
    for (std::size_t c = 0; c < cells.cellCount() && !wanted; ++c) wanted = cells.cellType(c) != CellType::Tet4;
  }
  if (!wanted) {
    if (elementField_ && !volumeSent) volume_->setElementField(nullptr, {});  // setVolume and setValues drop it
    elementField_.reset();
    return;
  }
  // Another setting of the mode (the tolerance, early termination): the renderer keeps the field.
  if (elementField_ && !volumeSent) return;
  const TetMesh& split = session.tetrahedra();
  std::vector<double> converted;
  auto field = std::make_shared<const optics::ElementField>(session.model().mesh(), view.values.doubles(converted),
                                                            split, split.mesh.bounds().center());
  std::vector<std::uint32_t> cellOfTet(culled_ ? culled_->cellOf.size() : split.mesh.cellCount());
  for (std::size_t t = 0; t < cellOfTet.size(); ++t) cellOfTet[t] = split.sourceCell(culled_ ? culled_->cellOf[t] : t);
  volume_->setElementField(field, std::move(cellOfTet));
  elementField_ = std::move(field);
}

// What every volume renderer takes the same way: the transfer function, planes,
// iso-surfaces and the mode's settings.
void SceneDrawing::applyVolumeSettings(const Scene& scene) {
  const VolumeLayer& v = scene.shown().volume;
  const SceneRevisions& now = scene.revisions();
  if (drawn_.tables != now.tables) volume_->setTransferFunction(scene.transferFunction());
  if (drawn_.planes != now.planes) volume_->setClipPlanes(v.allClipPlanes());
  // A volume contours the quantity it renders: iso-surfaces of another show in the surface view.
  if (drawn_.iso != now.iso)
    volume_->setIsoSurfaces(v.isoQuantity.empty() || scene.view()->quantity.key() == v.isoQuantity
                                ? v.isoSurfaces
                                : std::vector<optics::IsoSurface>{});
  if (drawn_.mode != now.mode) {
    volume_->setIntegrationMode(v.mode);
    volume_->setSamplingStep(v.samplingStep);
    volume_->setTerminationThreshold(v.termination);
    if (volumeTraits_.elementTolerance) volume_->setElementTolerance(v.elementTolerance);
  }
  volumeCaughtUp(drawn_, now);
}

// A grid renderer samples the grid's point values itself: no tetrahedra, no culling (the
// clip box's planes cut exactly).
void SceneDrawing::applyToGridVolume(const Scene& scene, GridVolumeRenderer& renderer) {
  const Model& model = scene.session()->model();
  const VolumeLayer& v = scene.shown().volume;
  const ScalarView& view = *scene.view();
  if (!model.grid)
    throw std::invalid_argument("the volume renderer '" + v.renderer +
                                "' draws regular grids (SEG-Y, image data); this model is a mesh: choose another");
  if (view.location != FieldLocation::Node) throw std::invalid_argument(scene.perCellRefusal(v.renderer));
  const SceneRevisions& now = scene.revisions();
  const bool geometry = drawn_.geometry != now.geometry;
  const bool values = drawn_.values != now.values;
  if (geometry) {
    culled_.reset();
    culledFor_.clear();
    renderer.setGrid(*model.grid, view.values);
  } else if (values) {
    renderer.setGridValues(view.values);
  }
  if (drawn_.mode != now.mode) renderer.setShading(v.shading);
  if (drawn_.tables != now.tables) renderer.setTransferFunction2D(v.transferFunction2D);
  applyVolumeSettings(scene);
}

void SceneDrawing::render(const Scene& scene, const RenderContext& target) {
  if (!initialized_) return;
  if (drawn_.scene != scene.revisions().scene) {  // another scene's counts say nothing of this one
    forgetAll();
    drawn_.scene = scene.revisions().scene;
  }
  boundary_.background = scene.background();
  boundary_.frameStarted();
  RenderContext ctx = target;
  const double ratio = scene.devicePixelRatio();
  ctx.camera = scene.pictureCamera(ctx.width / ratio, ctx.height / ratio);
  applyToBoundary(scene);
  applyToStreamlines(scene);
  streamlineRenderer_.setClipPlanes(scene.shown().volume.allClipPlanes());
  volumeDrawn_ = scene.shown().volume.shown && scene.view() && scene.session();
  if (volumeDrawn_) renderVolume(scene, ctx);
  else renderSurface(scene, ctx);
}

void SceneDrawing::renderSurface(const Scene& scene, const RenderContext& ctx) {
  const SceneState& s = scene.shown();
  // Opaque lines first, then the surface: opaque it hides the lines inside, see-through
  // it is blended over them.
  boundary_.renderBackground(ctx);
  if (scene.streamlinesDrawn()) streamlineRenderer_.render(ctx);
  if (applyToGlyphs(scene)) drawGlyphs(scene, ctx);
  const SurfaceRepresentation r = s.representation;
  const bool lines = r == SurfaceRepresentation::FeatureEdges || r == SurfaceRepresentation::Outline;
  // Edges would cage what shows through a see-through surface; a wireframe is its edges.
  boundary_.setShowEdges(r == SurfaceRepresentation::Wireframe ||
                         (r == SurfaceRepresentation::Surface && s.edges && s.surfaceOpacity >= 1.0));
  boundary_.setShowFaces(r == SurfaceRepresentation::Surface);
  boundary_.setShowPoints(r == SurfaceRepresentation::Points, float(s.pointSize * scene.devicePixelRatio()));
  boundary_.setFadeDenseEdges(r != SurfaceRepresentation::Wireframe);
  boundary_.setColorEdgesByValue(r == SurfaceRepresentation::Wireframe);
  boundary_.setLighting(s.lighting);
  boundary_.setOpacity(float(s.surfaceOpacity));
  // Hidden, the sections, slices and iso-surfaces still show.
  boundary_.setSurfaceShown(s.surfaceShown && !lines);
  boundary_.renderOver(ctx);
  boundary_.setShowFaces(true);
  boundary_.setShowPoints(false, 1.0f);
  if (s.surfaceShown && lines) drawModelLines(scene, ctx, r);
  if (s.deformation.shown && s.deformation.undeformedOutline && scene.baseSession() &&
      scene.session() != scene.baseSession())
    drawUndeformedOutline(scene, ctx);
}

// The undeformed model's outline (its feature edges) in gray, hidden where the deformed
// surface is in front, cut by the same planes: how far each part moved, at a glance.
void SceneDrawing::drawUndeformedOutline(const Scene& scene, const RenderContext& ctx) {
  const ModelSession& base = *scene.baseSession();
  if (undeformedUploaded_ != &base) {
    undeformedEdges_.setLines(featureEdges(base.surface()), base.origin());
    undeformedUploaded_ = &base;
  }
  undeformedEdges_.setShowFaces(false);
  undeformedEdges_.setShowEdges(true);
  undeformedEdges_.edgeColor = {0.55f, 0.57f, 0.62f};
  const double tolerance = 1e-5 * std::max(base.bounds().diagonal(), 1e-300);
  undeformedEdges_.setClipPlanes(scene.shown().volume.allClipPlanes(), tolerance);
  drawDepthTested(undeformedEdges_, ctx, base.origin());
}

bool SceneDrawing::applyToGlyphs(const Scene& scene) {
  const std::shared_ptr<const GlyphGeometry> glyphs = scene.glyphs();  // throws: too many
  if (!glyphs || glyphs->glyphs == 0) return false;
  if (glyphs != glyphsUploaded_) {
    glyphRenderer_.setTriangles(glyphs->corners, scene.session()->origin());
    glyphRenderer_.setScalars(FieldLocation::Node, SampleView(glyphs->values), glyphs->min, glyphs->max);
    glyphsUploaded_ = glyphs;
  }
  return true;
}

// Lit, in the color map's colors, hidden behind what is nearer, cut by the clip planes.
void SceneDrawing::drawGlyphs(const Scene& scene, const RenderContext& ctx) {
  if (glyphColorMap_ != scene.shown().colorMap) {
    glyphRenderer_.setColorMap(ColorMap::named(scene.shown().colorMap));
    glyphColorMap_ = scene.shown().colorMap;
  }
  glyphRenderer_.setShowEdges(false);
  glyphRenderer_.setLighting(true);
  glyphRenderer_.setClipPlanes({});  // cut at their places (Scene::glyphs): a glyph kept is drawn whole
  drawDepthTested(glyphRenderer_, ctx, scene.session()->origin());
}

// The model's feature edges (creases and borders) or its bounding box's twelve edges, in
// the edge color, hidden behind what is nearer, cut by the clip planes.
void SceneDrawing::drawModelLines(const Scene& scene, const RenderContext& ctx, SurfaceRepresentation lines) {
  const ModelSession& session = *scene.session();
  if (modelLinesFor_ != std::pair(&session, lines)) {
    if (lines == SurfaceRepresentation::Outline) {
      const Bounds b = session.bounds();
      std::vector<glm::dvec3> ends;
      const auto corner = [&](int i) {
        return glm::dvec3(i & 1 ? b.max.x : b.min.x, i & 2 ? b.max.y : b.min.y, i & 4 ? b.max.z : b.min.z);
      };
      for (int i = 0; i < 8; ++i)
        for (int axis = 1; axis < 8; axis <<= 1)
          if (!(i & axis)) ends.insert(ends.end(), {corner(i), corner(i | axis)});
      modelLines_.setLines(ends, session.origin());
    } else {
      modelLines_.setLines(featureEdges(session.surface()), session.origin());
    }
    modelLinesFor_ = {&session, lines};
  }
  modelLines_.setShowFaces(false);
  modelLines_.setShowEdges(true);
  const double tolerance = 1e-5 * std::max(session.bounds().diagonal(), 1e-300);
  modelLines_.setClipPlanes(scene.shown().volume.allClipPlanes(), tolerance);
  drawDepthTested(modelLines_, ctx, session.origin());
}

// The element edges stay visible over the volume and end its rays: they are drawn into
// the target and, depth only, into a texture the volume renderer reads.
void SceneDrawing::renderVolume(const Scene& scene, const RenderContext& ctx) {
  applyToVolume(scene);
  const VolumeLayer& v = scene.shown().volume;
  RenderContext volumeCtx = ctx;
  const bool lines = scene.streamlinesDrawn();
  const bool slices = boundary_.sliceTriangles() > 0;
  const bool glyphs = applyToGlyphs(scene);
  if (v.edges || v.outline || lines || slices || glyphs) {
    // The opaque things (edges, streamlines) drawn into the target and, depth only, into a
    // texture the volume renderer reads: its rays end at them.
    if (!depthTarget_ || depthTarget_->width() != ctx.width || depthTarget_->height() != ctx.height)
      depthTarget_ = std::make_unique<OffscreenTarget>(ctx.width, ctx.height);
    boundary_.setShowFaces(false);
    boundary_.setShowPoints(false, 1.0f);
    boundary_.setFadeDenseEdges(true);
    boundary_.setColorEdgesByValue(false);  // over a volume: the volume's colors are its own
    boundary_.setSurfaceShown(true);        // its edges, that is
    boundary_.setShowEdges(v.edges);
    boundary_.setOpacity(1.0f);
    for (const GLuint target : {depthTarget_->framebuffer(), ctx.framebuffer}) {
      RenderContext pass = ctx;
      pass.framebuffer = target;
      boundary_.renderBackground(pass);
      if (slices) boundary_.renderSlices(pass);
      if (lines) streamlineRenderer_.render(pass);
      if (glyphs) drawGlyphs(scene, pass);
      if (v.edges) boundary_.renderOver(pass);
      if (v.outline) drawModelLines(scene, pass, SurfaceRepresentation::FeatureEdges);
    }
    boundary_.setShowFaces(true);
    volumeCtx.depthTexture = depthTarget_->depthTexture();
  } else {
    boundary_.renderBackground(ctx);
  }
  volume_->render(volumeCtx);
}

}  // namespace volpost::app

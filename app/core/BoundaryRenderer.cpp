// SPDX-License-Identifier: MIT
#include "BoundaryRenderer.hpp"

#include "host/IsoSurfaceExtraction.hpp"
#include "host/SectionCut.hpp"

#include <algorithm>
#include <cmath>

namespace volpost::app {

namespace {

// Three corners per triangle of `mesh` (float positions relative to `origin`), back in
// model coordinates.
std::vector<glm::dvec3> cornersOf(const SurfaceMesh& mesh, const glm::dvec3& origin) {
  std::vector<glm::dvec3> corners;
  corners.reserve(3 * mesh.n_faces());
  for (const auto face : mesh.faces())
    for (const auto vertex : mesh.fv_range(face)) {
      const auto& p = mesh.point(vertex);
      corners.push_back(origin + glm::dvec3(p[0], p[1], p[2]));
    }
  return corners;
}

}  // namespace

void BoundaryRenderer::initialize() {
  surface_.initialize();
  sections_.initialize();
  sections_.setShowEdges(false);
  slices_.initialize();
  slices_.setShowEdges(false);
  slicesFor_.reset();
  sliceTriangles_ = 0;
  cutFor_.reset();
  surfaceUploaded_ = false;
  initialized_ = true;
}

// The boundary goes to the GPU (and is extracted, when the session has not yet) the
// first time it is drawn: a volume picture never pays for it.
void BoundaryRenderer::ensureSurface() {
  if (!initialized_ || !session_) return;
  surfaceDrawn_ = true;
  // Keyed as elementField() keys the field (the iso-surfaces may have asked it for another
  // view since): the field is built only when the surface must be refined again.
  std::optional<std::uint64_t> wanted;
  if (curvedSurfaceWanted())
    wanted = scalars_ && scalars_->view->location == FieldLocation::Node ? scalars_->version : 0;
  // A refinement on a worker thread: dropped when the values it was for are no longer
  // wanted, shown when done.
  if (refining_ && refining_->key != wanted) stopRefining();
  if (refining_ && refining_->result.wait_for(std::chrono::seconds(0)) == std::future_status::ready) {
    std::future<RefinedSurface> done = std::move(refining_->result);
    refining_.reset();
    showCurved(done.get(), wanted);
  }
  if (!surfaceUploaded_ || wanted != curvedFor_) {
    if (wanted) {
      const auto field = elementField(scalars_ ? scalars_->view : nullptr, scalars_ ? scalars_->version : 0);
      const BoundarySurface& boundary = session_->surface();  // extracted here, not on the worker
      // Other node values on the same curved surface (the next step): its points stay where
      // they are unless the new field needs another level.
      std::optional<RefinedValues> revalued;
      if (surfaceUploaded_ && curvedFor_) revalued = revalueBoundary(*field, boundary, curved_, limits_);
      if (revalued) {
        curved_.values = std::move(revalued->values);
        curved_.deviation = revalued->deviation;
        curved_.toleranceReached = revalued->toleranceReached;
        curvedFor_ = wanted;
        scalarsUploaded_ = false;
      } else if (asynchronous_) {
        if (!refining_) {
          auto cancel = std::make_shared<std::atomic<bool>>(false);
          refining_ = Refining{
              wanted, cancel, std::async(std::launch::async, [field, session = session_, cancel, limits = limits_] {
                return refineBoundary(*field, session->surface(), limits,
                                      Progress([cancel](double, const std::string&) { return !*cancel; }));
              })};
        }
        // Meanwhile the model's flat faces, with the values wanted.
        if (!surfaceUploaded_ || curvedFor_) {
          surface_.setSurface(boundary);
          curved_ = RefinedSurface();
          curvedCorners_ = {};
          curvedFor_.reset();
          surfaceUploaded_ = true;
          scalarsUploaded_ = false;
        }
      } else {
        showCurved(refineBoundary(*field, boundary, limits_), wanted);
      }
    } else {
      surface_.setSurface(session_->surface());
      curved_ = RefinedSurface();
      curvedCorners_ = {};
      curvedFor_ = wanted;
      surfaceUploaded_ = true;
      scalarsUploaded_ = false;
    }
  }
  if (scalarsUploaded_) return;
  if (!scalars_) surface_.clearScalars();
  else if (curvedFor_ && scalars_->view->location == FieldLocation::Node)
    surface_.setScalars(FieldLocation::Node, SampleView(curved_.values), scalars_->range.min, scalars_->range.max);
  else surface_.setScalars(scalars_->view->location, scalars_->view->values, scalars_->range.min, scalars_->range.max);
  scalarsUploaded_ = true;
}

void BoundaryRenderer::showCurved(RefinedSurface curved, std::optional<std::uint64_t> key) {
  curved_ = std::move(curved);
  surface_.setSurface(curved_.surface);
  curvedCorners_ = cornersOf(curved_.surface.mesh, curved_.surface.origin);
  curved_.surface = BoundarySurface();  // on the GPU now; the points' values and origins stay
  curvedFor_ = key;
  surfaceUploaded_ = true;
  scalarsUploaded_ = false;
}

bool BoundaryRenderer::pending() const {
  if (!refining_) return false;
  return surfaceDrawn_ || refining_->result.wait_for(std::chrono::seconds(0)) != std::future_status::ready;
}

void BoundaryRenderer::stopRefining() {
  if (!refining_) return;
  *refining_->cancel = true;
  try {
    refining_->result.get();  // waits for the worker, which stops at its next report
  } catch (...) {
    // Cancelled, or failed: nothing of it is shown.
  }
  refining_.reset();
}

void BoundaryRenderer::setRefinementLimits(const RefinementLimits& limits) {
  if (limits == limits_) return;
  limits_ = limits;
  // Whatever followed the cells' own field is followed again to the new limits.
  stopRefining();
  if (curvedFor_) surfaceUploaded_ = false;
  curvedFor_.reset();
  curved_ = RefinedSurface();
  curvedCorners_ = {};
  if (interpolation_ == FieldInterpolation::Element) {
    cutFor_.reset();
    slicesFor_.reset();
    isoFor_.reset();
  }
}

bool BoundaryRenderer::curvedSurfaceWanted() const {
  return interpolation_ == FieldInterpolation::Element && !showPoints_ && session_->model().meshBuilt() &&
         hasNonlinearCells(session_->model().mesh());
}

void BoundaryRenderer::release() {
  stopRefining();
  surface_.release();
  sections_.release();
  slices_.release();
  slicesFor_.reset();
  sliceTriangles_ = 0;
  for (auto& r : isoRenderers_) r->release();
  isoRenderers_.clear();
  isoFor_.reset();
  isoTriangles_ = 0;  // the corners stay: a headless picture's iso-surfaces can still be picked
  cutFor_.reset();
  surfaceUploaded_ = false;
  curvedFor_.reset();
  initialized_ = false;
}

void BoundaryRenderer::setSession(std::shared_ptr<const ModelSession> session) {
  stopRefining();
  session_ = std::move(session);
  elementField_.reset();
  elementFieldFor_.reset();
  isoCorners_.clear();
  cutFor_.reset();
  slicesFor_.reset();
  sliceTriangles_ = 0;
  isoFor_.reset();
  surface_.clearScalars();
  scalars_.reset();
  scalarsUploaded_ = false;
  surfaceUploaded_ = false;
  curvedFor_.reset();
  curved_ = RefinedSurface();
  curvedCorners_ = {};
}

// Kept until the surface is next drawn (a volume picture never uploads them).
void BoundaryRenderer::setScalars(const ScalarView* view, DisplayRange range, std::uint64_t viewVersion) {
  scalars_.reset();
  if (view) scalars_ = ShownScalars{view, range, viewVersion};
  scalarsUploaded_ = false;
}

void BoundaryRenderer::setCuts(const std::vector<ClipPlane>& planes, const ScalarView* view, std::uint64_t viewVersion,
                               DisplayRange range) {
  if (!initialized_ || !session_) return;
  const CutKey key{planes, viewVersion, range, view != nullptr, interpolation_};
  if (cutFor_ == key) return;
  cutFor_ = key;
  const double tolerance = 1e-5 * std::max(session_->model().bounds().diagonal(), 1e-300);
  // What lies on a plane is kept: a section on its own plane, a face of the model on a
  // plane of the box (float rounding would otherwise speckle it).
  surface_.setClipPlanes(planes, tolerance);
  sections_.setClipPlanes(planes, tolerance);
  for (auto& r : isoRenderers_) r->setClipPlanes(planes, tolerance);
  sectionTriangles_ = uploadCrossSections(sections_, planes, view, viewVersion, range);
}

std::shared_ptr<const optics::ElementField> BoundaryRenderer::elementField(const ScalarView* view,
                                                                           std::uint64_t viewVersion) const {
  const Model& model = session_->model();
  if (interpolation_ != FieldInterpolation::Element || !model.meshBuilt() || !hasNonlinearCells(model.mesh()))
    return nullptr;
  const bool perNode = view && view->location == FieldLocation::Node;
  const std::uint64_t key = perNode ? viewVersion : 0;
  if (elementField_ && elementFieldFor_ == key) return elementField_;
  std::vector<double> converted;
  const std::span<const double> values =
      perNode ? view->values.doubles(converted)
              : std::span<const double>(converted = std::vector<double>(model.mesh().nodeCount(), 0.0));
  elementField_ =
      std::make_shared<const optics::ElementField>(model.mesh(), values, session_->tetrahedra(), glm::dvec3(0.0));
  elementFieldFor_ = key;
  return elementField_;
}

std::size_t BoundaryRenderer::uploadCrossSections(SurfaceRenderer& target, const std::vector<ClipPlane>& planes,
                                                  const ScalarView* view, std::uint64_t viewVersion,
                                                  DisplayRange range) const {
  std::vector<glm::dvec3> corners;
  std::vector<double> values;
  const Model& model = session_->model();
  if (!planes.empty() && !model.meshBuilt()) {  // a grid: cut its cells as they are, no tetrahedra
    const bool perNode = view && view->location == FieldLocation::Node;
    const SampleView gridValues = view ? view->values : SampleView();
    for (const ClipPlane& plane : planes) {
      SectionTriangles cut = cutGrid(*model.grid, gridValues, perNode, plane);
      corners.insert(corners.end(), cut.positions.begin(), cut.positions.end());
      values.insert(values.end(), cut.values.begin(), cut.values.end());
    }
  } else if (const auto field = planes.empty() ? nullptr : elementField(view, viewVersion)) {
    // The cells' own shapes, colored by their own field (or their element results).
    std::vector<double> converted;
    const bool perCell = view && view->location != FieldLocation::Node;
    const std::span<const double> cellValues = perCell ? view->values.doubles(converted) : std::span<const double>();
    for (const ClipPlane& plane : planes) {
      SectionTriangles cut = cutCells(*field, cellValues, plane, limits_);
      corners.insert(corners.end(), cut.positions.begin(), cut.positions.end());
      if (view) values.insert(values.end(), cut.values.begin(), cut.values.end());
    }
  } else if (!planes.empty()) {
    const TetMesh& tets = session_->tetrahedra();
    const std::vector<double> tetValues = view ? session_->tetValues(*view) : std::vector<double>{};
    const bool perNode = view && view->location == FieldLocation::Node;
    for (const ClipPlane& plane : planes) {
      SectionTriangles cut = cutTetrahedra(tets, tetValues, perNode, plane);
      corners.insert(corners.end(), cut.positions.begin(), cut.positions.end());
      values.insert(values.end(), cut.values.begin(), cut.values.end());
    }
  }
  target.setTriangles(corners, session_->origin());
  if (view) target.setScalars(FieldLocation::Node, values, range.min, range.max);
  else target.clearScalars();
  return corners.size() / 3;
}

void BoundaryRenderer::setSlices(const std::vector<ClipPlane>& planes, const std::vector<ClipPlane>& clipPlanes,
                                 const ScalarView* view, std::uint64_t viewVersion, DisplayRange range) {
  if (!initialized_ || !session_) return;
  // Cut by the clip planes and box as the surface and the volume are (what lies on a plane
  // of the box is kept: a slice on its face).
  slices_.setClipPlanes(clipPlanes, 1e-5 * std::max(session_->model().bounds().diagonal(), 1e-300));
  const CutKey key{planes, viewVersion, range, view != nullptr, interpolation_};
  if (slicesFor_ == key) return;
  slicesFor_ = key;
  sliceTriangles_ = uploadCrossSections(slices_, planes, view, viewVersion, range);
}

void BoundaryRenderer::renderSlices(const RenderContext& ctx) {
  if (!session_ || sliceTriangles_ == 0) return;
  glBindFramebuffer(GL_FRAMEBUFFER, ctx.framebuffer);
  glViewport(0, 0, ctx.width, ctx.height);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  RenderContext local = ctx;
  local.origin = session_->origin();
  slices_.render(local);
  glDisable(GL_DEPTH_TEST);
}

void BoundaryRenderer::setIsoSurfaces(const std::vector<optics::IsoSurface>& surfaces, const ScalarView* view,
                                      std::uint64_t viewVersion) {
  if (!initialized_ || !session_) return;
  std::vector<double> key;
  if (view && view->location == FieldLocation::Node)  // extraction needs values at the nodes
    for (const auto& iso : surfaces) key.insert(key.end(), {iso.value, iso.color.r, iso.color.g, iso.color.b, iso.opacity});
  if (!key.empty()) key.push_back(double(int(interpolation_)));
  if (isoFor_ && isoFor_->first == key && isoFor_->second == viewVersion) return;
  isoFor_ = std::pair(key, viewVersion);
  for (auto& r : isoRenderers_) r->release();
  isoRenderers_.clear();
  isoTriangles_ = 0;
  isoCorners_.clear();
  if (key.empty()) return;
  const Model& model = session_->model();
  const bool grid = !model.meshBuilt();  // a grid's cells are split on the fly, no tetrahedra built
  const auto field = grid ? nullptr : elementField(view, viewVersion);
  const std::vector<double> values = grid || field ? std::vector<double>() : session_->tetValues(*view);
  for (const auto& iso : surfaces) {
    const ExtractedSurface extracted = grid    ? extractIsoSurface(*model.grid, view->values, iso.value)
                                       : field ? extractIsoSurface(*field, iso.value, limits_)
                                               : extractIsoSurface(session_->tetrahedra(), values, iso.value);
    const std::vector<glm::dvec3> corners = cornersOf(extracted.mesh, extracted.origin);
    auto renderer = std::make_unique<SurfaceRenderer>();
    renderer->initialize();
    renderer->setShowEdges(false);
    renderer->plainColor = glm::vec3(iso.color);
    renderer->setOpacity(float(iso.opacity));
    renderer->setTriangles(corners, session_->origin());
    if (cutFor_) {
      const double tolerance = 1e-5 * std::max(session_->model().bounds().diagonal(), 1e-300);
      renderer->setClipPlanes(cutFor_->planes, tolerance);
    }
    isoTriangles_ += corners.size() / 3;
    isoCorners_.insert(isoCorners_.end(), corners.begin(), corners.end());
    isoRenderers_.push_back(std::move(renderer));
  }
}

void BoundaryRenderer::renderBackground(const RenderContext& ctx) {
  glBindFramebuffer(GL_FRAMEBUFFER, ctx.framebuffer);
  glViewport(0, 0, ctx.width, ctx.height);
  glClearColor(background.r, background.g, background.b, 1.0f);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

void BoundaryRenderer::render(const RenderContext& ctx) {
  renderBackground(ctx);
  renderOver(ctx);
}

void BoundaryRenderer::renderOver(const RenderContext& ctx) {
  glBindFramebuffer(GL_FRAMEBUFFER, ctx.framebuffer);
  glViewport(0, 0, ctx.width, ctx.height);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  if (session_) {
    RenderContext local = ctx;
    local.origin = session_->origin();
    if (surfaceShown_) ensureSurface();
    // The opaque sections and iso-surfaces first: a see-through surface blends over them.
    const bool seeThrough = opacity_ < 1.0f;
    if (surfaceShown_ && !seeThrough) surface_.render(local);
    if (sectionTriangles_ > 0) sections_.render(local);
    if (sliceTriangles_ > 0) slices_.render(local);
    for (auto& iso : isoRenderers_) iso->render(local);
    if (surfaceShown_ && seeThrough) surface_.render(local);
  }
  glDisable(GL_DEPTH_TEST);
}

}  // namespace volpost::app

// SPDX-License-Identifier: MIT
#include "Scene.hpp"

#include "Deformation.hpp"
#include "Probe.hpp"
#include "StreamlineSeeds.hpp"
#include "Threshold.hpp"
#include "VolumeDefaults.hpp"

#include <glm/geometric.hpp>

#include <QString>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace volpost::app {
namespace {

// A renderer that draws apart (its pictures made without the scene's refined tetrahedra) and
// draws the tetrahedra's field only, asked for the cells' own.
std::string elementInterpolationRefusal(const VolumeRendererFactory& factory, const std::string& renderer) {
  return "volume renderer '" + renderer + "' draws the field linear on the tetrahedra the cells are split into; " +
         "the cells' own interpolation is drawn by " + factory.namesDrawnHere() + " (or draw the tetrahedra's field)";
}

QString stepAndLocation(const ScalarView& view) {
  return QString("%1%2").arg(QString::fromStdString(view.stepLabel),
                             view.location == FieldLocation::Node ? "  per node" : "  per cell");
}

}  // namespace

Scene::Scene(VolumeRendererFactory factory) : factory_(std::move(factory)) {
  static std::atomic<std::uint64_t> scenesMade{0};
  revisions_.scene = ++scenesMade;
  camera_.setView(StandardView::Isometric);
}

Scene::~Scene() = default;

// ---- the model ----

void Scene::setSession(std::shared_ptr<const ModelSession> session) {
  session_ = session;
  baseSession_ = std::move(session);
  state_.deformation.shown = false;
  deformationScale_ = 0.0;
  view_.reset();
  ++viewVersion_;
  state_.probes.clear();
  state_.quantity.clear();
  state_.step = 0;
  state_.modelPath = session_ ? session_->model().sourcePath : std::string();
  state_.readerOptions = session_ ? session_->readerOptions() : ReaderOptions{};
  state_.formulas = session_ ? session_->formulas() : std::vector<FormulaSpec>{};
  state_.volume.shown = false;
  state_.volume.samplingStep = 0.0;  // model units: the last model's step may not suit this one
  if (!session_ || !session_->model().grid) state_.volume.shading = false;  // lighting by the gradient is for grids
  ++revisions_.mode;
  state_.volume.clipPlanes.clear();
  state_.volume.clipBox.reset();
  state_.volume.isoSurfaces.clear();
  state_.volume.isoQuantity.clear();
  state_.gridSlices = {};
  state_.slicePlanes.clear();
  state_.plotLine.reset();
  state_.views.clear();  // cameras placed about the last model
  viewHistory_.clear();
  state_.surfaceOpacity = 1.0;  // a see-through surface chosen for another model's lines would stay a ghost
  state_.surfaceShown = true;  // hidden for another model's slices, it would leave this one's view empty
  state_.volume.transferFunction.reset();
  state_.volume.transferFunction2D.reset();  // its values and gradients were the last model's
  state_.streamlines = StreamlineLayer{};
  state_.glyphs = GlyphLayer{};  // the last model's field
  state_.threshold = ThresholdLayer{};
  state_.sets = SetVisibility{};  // the last model's set names
  stepBlend_ = 0.0;
  state_.selection = Selection{};  // and its ids
  glyphs_.reset();
  streamlineResult_.reset();
  ++revisions_.streamlines;
  changeEverything();
  camera_.setView(StandardView::Isometric);
  fitCamera();
}

void Scene::setDeformation(const DeformationLayer& layer) {
  if (layer.shown && baseSession_) checkDeformationField(*baseSession_, layer.field);
  if (layer.scale && !std::isfinite(*layer.scale)) throw std::invalid_argument("the deformation scale must be finite");
  state_.deformation = layer;
  rebuildDeformation();
}

// The drawn model follows the deformation: everything that holds geometry is rebuilt, the
// result and the state stay.
void Scene::rebuildDeformation() {
  if (!baseSession_) return;
  const DeformationLayer& d = state_.deformation;
  std::shared_ptr<const ModelSession> next = baseSession_;
  if (d.shown) {
    deformationScale_ = d.scale ? *d.scale : automaticDeformationScale(*baseSession_, d.field, state_.step);
    next = deformedSession(*baseSession_, d.field, state_.step, deformationScale_, stepBlend_);
  } else {
    deformationScale_ = 0.0;
  }
  // The shown sets' cells, and of those the ones whose values lie in the threshold's range.
  next = setVisibleSession(next, state_.sets);
  if (state_.threshold.shown) next = thresholdedSession(*next, state_.threshold, state_.step);
  if (next == session_) return;
  session_ = std::move(next);
  // Per-element values are the kept cells' now: the shown values are taken again.
  if (view_) view_ = evaluateShown(*session_, view_->quantity, state_.step);
  deformedStep_ = state_.step;
  ++viewVersion_;
  streamlineResult_.reset();
  ++revisions_.streamlines;
  changeEverything();
}

void Scene::fitCamera() {
  if (session_) camera_.fit(session_->model().bounds());
}

// ---- what is shown ----

ScalarView Scene::evaluateShown(const ModelSession& session, const Quantity& q, std::size_t step) const {
  ScalarView a = session.evaluate(q, step);
  if (!(stepBlend_ > 0.0) || step + 1 >= session.fieldOf(q).stepCount()) return a;
  const ScalarView b = session.evaluate(q, step + 1);
  std::vector<double> values(std::min(a.values.size(), b.values.size()));
  for (std::size_t i = 0; i < values.size(); ++i)
    values[i] = (1.0 - stepBlend_) * a.values[i] + stepBlend_ * b.values[i];
  ScalarView out = a;
  out.setValues(std::move(values));
  out.range = rangeOf(out.values);
  out.stepLabel =
      a.stepLabel + " to " + b.stepLabel + " (" + std::to_string(int(std::lround(100.0 * stepBlend_))) + " %)";
  return out;
}

void Scene::setStepBlend(double t) {
  if (!(t >= 0.0 && t < 1.0)) throw std::invalid_argument("an in-between frame lies from 0 to below 1 of the way");
  if (t == stepBlend_) return;
  stepBlend_ = t;
  if (state_.deformation.shown) {
    deformedStep_ = ~std::size_t(0);  // the shape moves with the blend
    rebuildDeformation();
    return;
  }
  if (view_ && session_) view_ = evaluateShown(*session_, view_->quantity, state_.step);
  ++viewVersion_;
  ++revisions_.scalars;
  ++revisions_.values;
  if (!state_.volume.transferFunction) ++revisions_.tables;
}

void Scene::setResult(const std::string& quantity, std::size_t step) {
  ++viewVersion_;
  if (quantity.empty() || !session_) {
    stepBlend_ = 0.0;
    view_.reset();
    state_.quantity.clear();
    state_.step = 0;
    state_.volume.shown = false;
  } else {
    ScalarView view = session_->evaluate(session_->findQuantity(quantity), step);  // throws, changing nothing
    if (stepBlend_ > 0.0) deformedStep_ = ~std::size_t(0);  // a shape moved between steps is moved back
    stepBlend_ = 0.0;
    if (!view_ || view_->location != view.location) ++revisions_.geometry;
    view_ = std::move(view);
    state_.quantity = quantity;
    state_.step = step;
    // The step's displacement, the step's cells within the threshold.
    if ((state_.deformation.shown || state_.threshold.shown) && step != deformedStep_) rebuildDeformation();
    // (the shown sets do not change with the step)
  }
  ++revisions_.scalars;
  ++revisions_.values;
  if (!state_.volume.transferFunction) ++revisions_.tables;  // the default follows the range
}

void Scene::setColorMap(const std::string& name) {
  (void)ColorMap::named(name);  // throws for an unknown name
  const DisplayRange before = displayRange();
  state_.colorMap = name;
  ++revisions_.colorMap;
  if (displayRange() != before) ++revisions_.scalars;  // an automatic symmetric range follows the map
  ++revisions_.streamlines;
  if (!state_.volume.transferFunction) ++revisions_.tables;  // the default takes the map's colors
}

void Scene::setFixedRange(std::optional<DisplayRange> range) {
  if (range && !(range->max > range->min && std::isfinite(range->min) && std::isfinite(range->max)))
    throw std::invalid_argument("a color range needs finite min < max");
  if (range && state_.logScale && !(range->min > 0.0))
    throw std::invalid_argument("a log scale needs a positive color range: " +
                                QString::number(range->min, 'g', 6).toStdString() + " is not above 0");
  state_.fixedRange = range;
  if (range) state_.rangeOverSteps = false;
  ++revisions_.scalars;
  if (!state_.volume.transferFunction) ++revisions_.tables;  // the default spans the range
}

void Scene::setRangeOverSteps(bool on) {
  state_.rangeOverSteps = on;
  state_.fixedRange.reset();  // either way, the values' own range: over all steps or per step
  ++revisions_.scalars;
  if (!state_.volume.transferFunction) ++revisions_.tables;
}

void Scene::setSymmetricRange(bool on) {
  state_.symmetricRange = on;
  state_.symmetricAuto = false;
  ++revisions_.scalars;
  if (!state_.volume.transferFunction) ++revisions_.tables;
}

void Scene::setSymmetricRangeAutomatic() {
  state_.symmetricAuto = true;
  ++revisions_.scalars;
  if (!state_.volume.transferFunction) ++revisions_.tables;
}

bool Scene::symmetricRangeShown() const {
  if (state_.fixedRange || state_.logScale) return false;
  if (!state_.symmetricAuto) return state_.symmetricRange;
  if (!divergingMap() || !view_ || !view_->range.valid()) return false;
  return view_->range.min < 0.0 && view_->range.max > 0.0;  // signed values: zero in the middle
}

bool Scene::divergingMap() const {
  const std::string base =
      ColorMap::isReversed(state_.colorMap) ? ColorMap::reversedName(state_.colorMap) : state_.colorMap;
  return base == "cool-warm" || base == "seismic";
}

void Scene::setColorBands(int bands) {
  if (bands < 0 || bands == 1 || bands > kMaxColorBands)
    throw std::invalid_argument(std::to_string(bands) + " color bands: 0 (continuous) or 2 to " +
                                std::to_string(kMaxColorBands));
  state_.colorBands = bands;
  ++revisions_.colorMap;
}

void Scene::setLogScale(bool on) {
  if (on && state_.fixedRange && !(state_.fixedRange->min > 0.0))
    throw std::invalid_argument("a log scale needs a positive color range; the typed one starts at " +
                                QString::number(state_.fixedRange->min, 'g', 6).toStdString());
  state_.logScale = on;
  ++revisions_.scalars;  // the range may change
  ++revisions_.colorMap;
}

void Scene::setOutOfRangeColors(std::optional<glm::dvec3> below, std::optional<glm::dvec3> above) {
  for (const auto& c : {below, above})
    if (c && !(c->r >= 0.0 && c->r <= 1.0 && c->g >= 0.0 && c->g <= 1.0 && c->b >= 0.0 && c->b <= 1.0))
      throw std::invalid_argument("a color outside the range needs r, g, b each from 0 to 1");
  state_.belowColor = below;
  state_.aboveColor = above;
  ++revisions_.colorMap;
}

void Scene::setShowEdges(bool show) { state_.edges = show; }

namespace {
void setOrErase(std::map<std::string, std::string>& map, const std::string& key, const std::string& text,
                const char* what) {
  if (text.size() > 200) throw std::invalid_argument(std::string(what) + " longer than 200 bytes");
  if (text.empty()) map.erase(key);
  else map[key] = text;
}
}  // namespace

void Scene::setTitle(const std::string& title) {
  if (title.size() > 200) throw std::invalid_argument("a picture title longer than 200 bytes");
  if (title.find_first_of("\r\n") != std::string::npos) throw std::invalid_argument("a picture title is one line");
  state_.title = title;
}

void Scene::setLegendTitle(const std::string& quantity, const std::string& title) {
  setOrErase(state_.legendTitles, quantity, title, "a legend title");
}

void Scene::setUnits(const std::string& field, const std::string& units) {
  setOrErase(state_.units, field, units, "units");
}

std::string Scene::unitsOf(const std::string& field) const {
  if (const auto typed = state_.units.find(field); typed != state_.units.end()) return typed->second;
  const Field* f = session_ ? session_->model().findField(field) : nullptr;
  return f ? f->units() : std::string();
}

std::map<std::string, std::string> Scene::unitsByField() const {
  std::map<std::string, std::string> out = state_.units;
  if (session_)
    for (const auto& f : session_->model().fields)
      if (!f->units().empty()) out.emplace(f->name(), f->units());  // a typed one stays
  return out;
}

void Scene::setLegendNumbers(const std::string& style) {
  const auto numbers = LegendNumbers::parse(style);
  if (!numbers)
    throw std::invalid_argument("legend numbers '" + style +
                                "': auto[:DIGITS], fixed[:DIGITS] or scientific[:DIGITS] (DIGITS up to 12)");
  state_.legendNumbers = numbers->written();
}

void Scene::setLegendLabels(int labels) {
  if (labels < 2 || labels > 20) throw std::invalid_argument(std::to_string(labels) + " legend labels: 2 to 20");
  state_.legendLabels = labels;
}

void Scene::setVolumeShown(bool shown) {
  if (shown && !view_) throw std::invalid_argument("choose a result to render as a volume");
  state_.volume.shown = shown;
}

void Scene::setVolumeRenderer(const std::string& name) {
  const std::optional<VolumeRendererTraits> traits = factory_.traitsOf(name);
  if (!traits) throw std::invalid_argument("no volume renderer named '" + name + "' is loaded");
  const bool gridsOnly = !traits->drawsMeshes;
  if (gridsOnly && session_ && !session_->model().grid)
    throw std::invalid_argument("the volume renderer '" + name +
                                "' draws regular grids (SEG-Y, image data); this model is a mesh: choose another");
  if (gridsOnly && view_ && view_->location != FieldLocation::Node) throw std::invalid_argument(perCellRefusal(name));
  if (state_.volume.interpolation == FieldInterpolation::Element && !traits->elementInterpolation &&
      factory_.drawsApart(name))
    throw std::invalid_argument("the " + elementInterpolationRefusal(factory_, name));
  if (name == state_.volume.renderer) return;
  state_.volume.renderer = name;
  ++revisions_.renderer;
}

void Scene::setShading(bool on) {
  if (on && session_ && !session_->model().grid)
    throw std::invalid_argument("shading by the gradient applies to regular grids (SEG-Y, image data); this model is a "
                                "mesh");
  state_.volume.shading = on;
  ++revisions_.mode;
}

void Scene::setIntegrationMode(IntegrationMode mode) {
  state_.volume.mode = mode;
  ++revisions_.mode;
}

void Scene::setTransferFunction(std::optional<TransferFunction> tf) {
  state_.volume.transferFunction = std::move(tf);
  ++revisions_.tables;
}

void Scene::setTransferFunction2D(std::optional<TransferFunction2D> tf) {
  state_.volume.transferFunction2D = std::move(tf);
  ++revisions_.tables;
}

void Scene::setClipPlanes(std::vector<ClipPlane> planes) {
  VolumeLayer next = state_.volume;
  next.clipPlanes = std::move(planes);
  checkClipPlanes(next.allClipPlanes());
  state_.volume.clipPlanes = std::move(next.clipPlanes);
  ++revisions_.planes;
}

void Scene::setClipBox(std::optional<ClipBox> box) {
  VolumeLayer next = state_.volume;
  next.clipBox = box;
  checkClipPlanes(next.allClipPlanes());
  state_.volume.clipBox = box;
  ++revisions_.planes;
}

void Scene::setIsoSurfaces(std::vector<optics::IsoSurface> surfaces) {
  checkIsoSurfaces(surfaces);
  state_.volume.isoSurfaces = std::move(surfaces);
  ++revisions_.iso;
}

void Scene::setGridSlices(const std::array<std::optional<double>, 3>& labels) {
  checkGridSlices(session_ ? session_->model().grid : std::nullopt, labels);
  state_.gridSlices = labels;
}

std::vector<ClipPlane> Scene::gridSlicePlanes() const {
  if (!session_ || !session_->model().grid) return {};
  return gridSlicePlanesAt(*session_->model().grid, state_.gridSlices);
}

namespace {

void checkSlicePlanes(const std::vector<ClipPlane>& planes) {
  if (planes.size() > kMaxSlicePlanes)
    throw std::invalid_argument(std::to_string(planes.size()) + " slice planes; at most " +
                                std::to_string(kMaxSlicePlanes));
  for (const ClipPlane& p : planes) {
    const double n = glm::length(p.normal);
    if (!std::isfinite(p.point.x + p.point.y + p.point.z) || !std::isfinite(n) || !(n > 0.0))
      throw std::invalid_argument("a slice plane needs a finite point and a finite, non-zero normal");
  }
}

}  // namespace

void Scene::setSlicePlanes(std::vector<ClipPlane> planes) {
  checkSlicePlanes(planes);
  state_.slicePlanes = std::move(planes);
}

std::vector<ClipPlane> Scene::slicePlanes() const {
  std::vector<ClipPlane> planes = gridSlicePlanes();
  planes.insert(planes.end(), state_.slicePlanes.begin(), state_.slicePlanes.end());
  return planes;
}

void Scene::setGlyphs(GlyphLayer layer) {
  if (layer.shown) {
    if (!session_) throw std::invalid_argument("no model is open to draw glyphs on");
    checkGlyphLayer(*session_, layer);
    // Built now: too many glyphs is said here, not by the next frame.
    const std::vector<ClipPlane> cuts = state_.volume.allClipPlanes();
    auto built =
        std::make_shared<const GlyphGeometry>(buildGlyphs(*session_, layer, state_.step, cuts, !state_.volume.shown));
    glyphs_ = std::move(built);
    glyphsFor_ = std::make_tuple(session_.get(), state_.step, layer, cuts, !state_.volume.shown);
  }
  state_.glyphs = std::move(layer);
}

std::shared_ptr<const GlyphGeometry> Scene::glyphs() const {
  if (!session_ || !state_.glyphs.shown) return nullptr;
  // Clip planes cut the glyphs at their places, not through them; the cut faces carry glyphs too.
  const auto key =
      std::make_tuple(session_.get(), state_.step, state_.glyphs, state_.volume.allClipPlanes(), !state_.volume.shown);
  if (!glyphs_ || glyphsFor_ != key) {
    glyphs_.reset();
    glyphs_ = std::make_shared<const GlyphGeometry>(
        buildGlyphs(*session_, state_.glyphs, state_.step, std::get<3>(key), std::get<4>(key)));
    glyphsFor_ = key;
  }
  return glyphs_;
}

void Scene::setBackground(const glm::dvec3& rgb) {
  for (int k = 0; k < 3; ++k)
    if (!(rgb[k] >= 0.0 && rgb[k] <= 1.0)) throw std::invalid_argument("a background color's components lie in 0..1");
  state_.background = rgb;
}

void Scene::setTextScale(double scale) {
  if (!(scale >= kMinTextScale && scale <= kMaxTextScale))
    throw std::invalid_argument("the text scale must lie in 0.25..8");
  state_.textScale = scale;
}

void Scene::setPointSize(double pixels) {
  if (!(pixels >= 1.0 && pixels <= kMaxPointSize))
    throw std::invalid_argument("the point size must lie in 1.." + std::to_string(int(kMaxPointSize)) + " pixels");
  state_.pointSize = pixels;
}

// A step so short that a ray would take millions of samples would hold the picture for
// hours: at most kMaxSamplesAcross along the model's diagonal.
void Scene::checkSamplingStep(double step) const {
  if (!(step >= 0.0) || !std::isfinite(step))
    throw std::invalid_argument("the sampling step must be >= 0 (0: automatic)");
  if (step == 0.0 || !session_) return;
  const Bounds b = session_->model().bounds();
  const double across = b.valid ? b.diagonal() : 0.0;
  if (across / step > kMaxSamplesAcross) {
    char text[256];
    std::snprintf(
        text, sizeof text,
        "the sampling step %g (--sampling-step, or \"volume\": {\"samplingStep\"} in a state file) would take "
        "more than %.0f samples across the model (%g long): use at least %.3g, or 0 for the automatic step",
        step, kMaxSamplesAcross, across, across / kMaxSamplesAcross);
    throw std::invalid_argument(text);
  }
}

void Scene::setSamplingStep(double step) {
  checkSamplingStep(step);
  state_.volume.samplingStep = step;
  ++revisions_.mode;
}

void Scene::setTermination(double transmittance) {
  if (!(transmittance >= 0.0 && transmittance < 1.0)) {
    char value[32];
    std::snprintf(value, sizeof value, "%g", transmittance);
    throw std::invalid_argument(std::string("the early-termination transmittance must lie in [0, 1), not ") + value);
  }
  state_.volume.termination = transmittance;
  ++revisions_.mode;
}

void Scene::setInterpolation(FieldInterpolation interpolation) {
  if (interpolation == state_.volume.interpolation) return;
  state_.volume.interpolation = interpolation;
  ++revisions_.mode;
}

void Scene::setElementTolerance(double tolerance) {
  if (!validElementTolerance(tolerance)) {
    char value[32];
    std::snprintf(value, sizeof value, "%g", tolerance);
    throw std::invalid_argument(std::string("the tolerance of the cells' own field ") + kElementToleranceRule +
                                "; not " + value);
  }
  if (tolerance == state_.volume.elementTolerance) return;
  state_.volume.elementTolerance = tolerance;
  ++revisions_.mode;
}

void Scene::setVolumeEdges(bool show) { state_.volume.edges = show; }

// ---- the whole state ----

CameraState Scene::cameraState() const {
  CameraState c;
  c.eye = camera_.eye();
  c.target = camera_.target();
  c.up = camera_.up();
  c.fieldOfView = camera_.fieldOfView();
  c.orthographic = camera_.projection() == Camera::Projection::Orthographic;
  c.rotation = camera_.rotation();
  c.distance = camera_.distance();
  return c;
}

SceneState Scene::state() const {
  SceneState s = state_;
  s.camera = cameraState();
  return s;
}

Camera Scene::cameraAt(const CameraState& c) const {
  Camera camera = camera_;
  if (session_) camera.fit(session_->model().bounds());
  camera.setProjection(c.orthographic ? Camera::Projection::Orthographic : Camera::Projection::Perspective);
  camera.setFieldOfView(c.fieldOfView);
  camera.lookAt(c.eye, c.target, c.up);  // checks them
  // The camera as it was held, when that agrees with the eye and up (to their coordinates'
  // rounding); otherwise the eye and up as typed.
  if (c.rotation && c.distance) {
    Camera held = camera;
    held.place(c.target, *c.rotation, *c.distance);
    const double scale = glm::length(c.eye) + glm::length(c.target) + *c.distance;
    if (glm::length(held.eye() - c.eye) <= 1e-12 * scale && glm::length(held.up() - glm::normalize(c.up)) <= 1e-12)
      camera = held;
  }
  return camera;
}

// ---- saved views and the views before ----

void Scene::saveView(const std::string& name) {
  if (const std::string why = viewNameProblem(name); !why.empty())
    throw std::invalid_argument("the view's name " + why);
  for (NamedView& v : state_.views)
    if (v.name == name) {
      v.camera = cameraState();
      return;
    }
  if (state_.views.size() >= kMaxViews)
    throw std::invalid_argument("at most " + std::to_string(kMaxViews) + " saved views: remove one first");
  state_.views.push_back({name, cameraState()});
}

void Scene::showView(const std::string& name) {
  for (const NamedView& v : state_.views)
    if (v.name == name) {
      const Camera camera = cameraAt(v.camera);  // throws before anything changes
      rememberView();
      camera_ = camera;
      return;
    }
  std::string names;
  for (const NamedView& v : state_.views) names += (names.empty() ? "" : ", ") + ("\"" + v.name + "\"");
  throw std::invalid_argument("no view is saved as \"" + name + "\"" +
                              (names.empty() ? std::string(": none is saved") : "; the saved views: " + names));
}

void Scene::removeView(const std::string& name) {
  std::erase_if(state_.views, [&](const NamedView& v) { return v.name == name; });
}

void Scene::rememberView() {
  const CameraState now = cameraState();
  if (!viewHistory_.empty() && viewHistory_.back() == now) return;
  viewHistory_.push_back(now);
  if (viewHistory_.size() > kViewHistory) viewHistory_.erase(viewHistory_.begin());
}

bool Scene::previousView() {
  const CameraState now = cameraState();
  while (!viewHistory_.empty()) {
    const CameraState before = viewHistory_.back();
    viewHistory_.pop_back();
    if (before == now) continue;
    camera_ = cameraAt(before);
    return true;
  }
  return false;
}

void Scene::applyState(const SceneState& s) {
  if (!session_) throw std::invalid_argument("no model is open to apply the state to");
  if (s.formulas.size() > kMaxFormulas)
    throw std::invalid_argument("the state has " + std::to_string(s.formulas.size()) + " formulas; at most " +
                                std::to_string(kMaxFormulas));
  applyState(s, s.formulas == state_.formulas ? nullptr : ModelSession::withFormulas(*baseSession_, s.formulas));
}

void Scene::setFormulas(std::vector<FormulaSpec> formulas) {
  if (!baseSession_) throw std::invalid_argument("no model is open to compute formulas on");
  if (formulas.size() > kMaxFormulas)
    throw std::invalid_argument(std::to_string(formulas.size()) + " formulas; at most " + std::to_string(kMaxFormulas));
  std::shared_ptr<const ModelSession> next = ModelSession::withFormulas(*baseSession_, formulas);  // throws
  // What showed a formula that is gone (or changed its steps) falls back instead of failing.
  SceneState s = state();
  s.formulas = std::move(formulas);
  const auto offers = [&](const std::string& key, std::size_t step) {
    try {
      return step < next->fieldOf(next->findQuantity(key)).stepCount();
    } catch (const std::invalid_argument&) {
      return false;
    }
  };
  if (!s.quantity.empty() && !offers(s.quantity, s.step)) {
    const std::optional<Quantity> fallback = next->defaultQuantity();
    s.quantity = fallback ? fallback->key() : std::string();
    s.step = 0;
    if (!fallback) s.volume.shown = false;
  }
  if (!s.volume.isoQuantity.empty() && !offers(s.volume.isoQuantity, 0)) {
    s.volume.isoQuantity.clear();
    s.volume.isoSurfaces.clear();
  }
  if (s.deformation.shown && !next->model().findField(s.deformation.field)) s.deformation.shown = false;
  if (s.streamlines.shown && !next->model().findField(s.streamlines.field)) s.streamlines.shown = false;
  if (s.threshold.shown) try {
      checkThreshold(*next, s.threshold);
    } catch (const std::invalid_argument&) {
      s.threshold.shown = false;  // a formula it used is gone
    }
  try {
    checkSetVisibility(*next, s.sets);
  } catch (const std::invalid_argument&) {
    s.sets = SetVisibility{};  // the other model's sets
  }
  if (s.glyphs.shown) try {
      checkGlyphLayer(*next, s.glyphs);
    } catch (const std::invalid_argument&) {
      s.glyphs.shown = false;  // a formula they showed is gone
    }
  applyState(s, next);
}

void Scene::applyState(const SceneState& s, std::shared_ptr<const ModelSession> withFormulas) {
  // The state's selection joins the model's sets before the choices naming them are checked.
  if (baseSession_ && (withFormulas || s.selection != state_.selection)) {
    const ModelSession& from = withFormulas ? *withFormulas : *baseSession_;
    withFormulas = ModelSession::withSets(from, kSelectionOrigin, selectionSets(from, s.selection));  // throws
  }
  // Check everything before changing anything, on the model with the state's formulas.
  const ModelSession& checked = withFormulas ? *withFormulas : *session_;
  std::optional<ScalarView> view;
  if (!s.quantity.empty()) {
    const Quantity q = checked.findQuantity(s.quantity);
    if (const std::size_t steps = checked.fieldOf(q).stepCount(); s.step >= steps)
      throw std::invalid_argument("the state's result step (\"result\": {\"step\": " + std::to_string(s.step + 1) +
                                  "}) does not exist: " + s.quantity + " has " + std::to_string(steps) + " step" +
                                  (steps == 1 ? "" : "s"));
    view = checked.evaluate(q, s.step);
  }
  checkSamplingStep(s.volume.samplingStep);
  if (!s.volume.isoQuantity.empty() &&
      checked.fieldOf(checked.findQuantity(s.volume.isoQuantity)).location() != FieldLocation::Node)
    throw std::invalid_argument("the state's iso-surfaces are of " + s.volume.isoQuantity +
                                ", which is given per element; iso-surfaces need values at the nodes");
  (void)ColorMap::named(s.colorMap);
  if (s.volume.shown && !view) throw std::invalid_argument("the state shows a volume but names no result");
  if (s.volume.shown && !factory_.traitsOf(s.volume.renderer))
    throw std::invalid_argument("no volume renderer named '" + s.volume.renderer + "' is loaded");
  if (s.volume.shown && s.volume.interpolation == FieldInterpolation::Element &&
      !factory_.traitsOf(s.volume.renderer)->elementInterpolation && factory_.drawsApart(s.volume.renderer))
    throw std::invalid_argument("the state's " + elementInterpolationRefusal(factory_, s.volume.renderer));
  checkStreamlines(s.streamlines, checked);
  checkGlyphLayer(checked, s.glyphs);
  checkThreshold(checked, s.threshold);
  checkSetVisibility(checked, s.sets);
  checkProbes(s.probes);
  checkMeasure(s.measure, s.probes.size());
  if (s.deformation.shown) checkDeformationField(withFormulas ? *withFormulas : *baseSession_, s.deformation.field);
  if (!(s.surfaceOpacity >= 0.0 && s.surfaceOpacity <= 1.0)) throw std::invalid_argument("surface opacity outside 0..1");
  checkGridSlices(checked.model().grid, s.gridSlices);
  checkSlicePlanes(s.slicePlanes);
  if (s.logScale && s.fixedRange && !(s.fixedRange->min > 0.0))
    throw std::invalid_argument("the state's log scale needs a positive color range (colors.range)");
  for (int k = 0; k < 3; ++k)
    if (!(s.background[k] >= 0.0 && s.background[k] <= 1.0))
      throw std::invalid_argument("the state's background color lies outside 0..1");
  if (!(s.textScale >= kMinTextScale && s.textScale <= kMaxTextScale))
    throw std::invalid_argument("the state's text scale lies outside 0.25..8");
  if (!(s.pointSize >= 1.0 && s.pointSize <= kMaxPointSize))
    throw std::invalid_argument("the state's point size lies outside 1.." + std::to_string(int(kMaxPointSize)));
  checkClipPlanes(s.volume.allClipPlanes());
  checkIsoSurfaces(s.volume.isoSurfaces);
  Camera camera = camera_;
  if (s.camera) {
    camera = cameraAt(*s.camera);
  } else {
    camera.setView(StandardView::Isometric);
    camera.fit(checked.model().bounds());
  }
  if (s.views.size() > kMaxViews)
    throw std::invalid_argument("the state saves more than " + std::to_string(kMaxViews) + " views");
  for (std::size_t i = 0; i < s.views.size(); ++i) {
    if (const std::string why = viewNameProblem(s.views[i].name); !why.empty())
      throw std::invalid_argument("the state's view " + std::to_string(i + 1) + ": its name " + why);
    (void)cameraAt(s.views[i].camera);  // checks it
  }

  const bool locationChanged = !view_ || !view || view_->location != view->location;
  const bool rendererChanged = s.volume.renderer != state_.volume.renderer;
  const std::string keptModel = state_.modelPath;
  const ReaderOptions keptOptions = state_.readerOptions;
  if (s.volume.shading && session_ && !session_->model().grid)
    throw std::invalid_argument("the state lights the volume by its gradient (volume.shading), which applies to regular "
                                "grids; this model is a mesh");
  state_ = s;
  state_.modelPath = keptModel;
  state_.readerOptions = keptOptions;
  state_.camera.reset();  // the live camera holds it
  ++revisions_.streamlines;
  view_ = std::move(view);
  ++viewVersion_;
  camera_ = camera;
  for (std::uint64_t* r : {&revisions_.scalars, &revisions_.colorMap, &revisions_.values, &revisions_.tables,
                           &revisions_.planes, &revisions_.iso, &revisions_.mode})
    ++*r;
  if (locationChanged) ++revisions_.geometry;
  if (rendererChanged) ++revisions_.renderer;
  if (withFormulas) {
    baseSession_ = std::move(withFormulas);
    session_ = baseSession_;
    deformedStep_ = state_.step;
    changeEverything();
  }
  if (state_.deformation.shown || state_.threshold.shown || state_.sets.active() || session_ != baseSession_)
    rebuildDeformation();
}

void Scene::setSetVisibility(const SetVisibility& sets) {
  if (sets.active() || !sets.marked.empty() || sets.colors) {
    if (!baseSession_) throw std::invalid_argument("no model is open to show sets of");
    checkSetVisibility(*baseSession_, sets);
    if (sets.active() && !sets.drawsTheSame(state_.sets) && state_.threshold.shown &&
        thresholdedSession(*setVisibleSession(baseSession_, sets), state_.threshold, state_.step)
                ->model()
                .cellCount() == 0)
      throw std::invalid_argument("no cell of these sets has " + state_.threshold.quantity +
                                  " within the threshold's range at this step");
  }
  const bool sameCells = sets.drawsTheSame(state_.sets);
  const bool recolored = sets.colors != state_.sets.colors;
  state_.sets = sets;
  if (recolored) {  // the surface's values and colors are the sets' or the result's again
    ++viewVersion_;
    ++revisions_.scalars;
    ++revisions_.colorMap;
  }
  if (!sameCells) rebuildDeformation();  // marking another set draws the same cells
}

namespace {

// Forgets the names of the selection's sets that `selection` no longer makes.
void forgetSelectionSets(SetVisibility& v, const Selection& selection) {
  const auto gone = [&](const std::string& name) {
    const auto is = [&](const char* set) {
      return name.size() == std::string_view(set).size() &&
             std::equal(name.begin(), name.end(), set, [](char a, char b) {
               return std::tolower(static_cast<unsigned char>(a)) == std::tolower(static_cast<unsigned char>(b));
             });
    };
    return (is(kSelectedElements) && selection.elements.empty()) || (is(kSelectedNodes) && selection.nodes.empty());
  };
  std::erase_if(v.shown, gone);
  std::erase_if(v.hidden, gone);
  if (gone(v.marked)) {
    v.marked.clear();
    v.numbers = false;
  }
}

}  // namespace

void Scene::setSelection(Selection selection) {
  if (!baseSession_) throw std::invalid_argument("no model is open to select in");
  normalizeIds(selection.elements);
  normalizeIds(selection.nodes);
  std::shared_ptr<const ModelSession> next =
      ModelSession::withSets(*baseSession_, kSelectionOrigin, selectionSets(*baseSession_, selection));  // throws
  SetVisibility sets = state_.sets;
  forgetSelectionSets(sets, selection);
  checkSetVisibility(*next, sets);  // throws (hiding what is left of the sets leaves nothing): nothing changed
  baseSession_ = std::move(next);
  state_.selection = std::move(selection);
  state_.sets = sets;
  rebuildDeformation();
}

const SetColoring* Scene::setColoring() const {
  if (!state_.sets.colors || !session_ || !baseSession_) return nullptr;
  if (coloring_ && !coloringFor_.expired() && coloringFor_.lock() == session_) return &*coloring_;
  coloring_ = volpost::app::setColoring(*session_, *baseSession_);
  coloringFor_ = session_;
  return &*coloring_;
}

VersionedView Scene::surfaceValues() const {
  // viewVersion_ counts the coloring's changes too (turning it on or off, a new part).
  if (const SetColoring* c = setColoring()) return {&c->view, viewVersion_};
  return shownValues();
}

DisplayRange Scene::surfaceRange() const {
  if (setColoring()) return {0.0, double(kSetPaletteSize)};
  return displayRange();
}

const Scene::MarkedSet& Scene::markedSet() const {
  const std::string& name = state_.sets.marked;
  const bool numbers = state_.sets.numbers;
  if (!markedFor_.expired() && markedFor_.lock() == session_ && markedName_ == name && markedNumbers_ == numbers)
    return marked_;
  markedFor_ = session_;
  markedName_ = name;
  markedNumbers_ = numbers;
  marked_ = MarkedSet{};
  if (name.empty() || !session_) return marked_;
  MarkedMembers members;
  try {
    members = markedMembers(*session_, name);
  } catch (const std::invalid_argument&) {
    return marked_;  // checked when it was set: a part made since may lack it
  }
  const Model& model = session_->model();
  marked_.nodeCount = members.nodes.size();
  const std::size_t stride = members.nodes.size() / kMaxMarkedNodes + 1;
  for (std::size_t i = 0; i < members.nodes.size(); i += stride)
    marked_.nodes.push_back(model.nodePosition(members.nodes[i]));
  if (!numbers) return marked_;
  const bool ofCells = members.kind == SetKind::Cells;
  marked_.numbered = ofCells ? members.cells.size() : members.nodes.size();
  if (marked_.numbered > kMaxNumbers) return marked_;
  if (ofCells) {
    const Mesh& mesh = model.mesh();
    for (const std::uint32_t c : members.cells) {
      const auto nodes = mesh.cellNodes(c);
      const int corners = topology(mesh.cellType(c)).cornerCount;
      glm::dvec3 centre(0.0);
      for (int k = 0; k < corners; ++k) centre += model.nodePosition(nodes[std::size_t(k)]);
      marked_.numbers.push_back({centre / double(corners), mesh.cellId(c)});
    }
  } else {
    for (const std::uint32_t n : members.nodes)
      marked_.numbers.push_back({model.nodePosition(n), model.mesh().nodeId(n)});
  }
  return marked_;
}

void Scene::setThreshold(const ThresholdLayer& layer) {
  if (layer.shown) {
    if (!baseSession_) throw std::invalid_argument("no model is open to threshold");
    checkThreshold(*baseSession_, layer);
    const auto kept = thresholdedSession(*setVisibleSession(baseSession_, state_.sets), layer, state_.step);
    if (kept->model().mesh().cellCount() == 0) {
      const Quantity q = baseSession_->findQuantity(layer.quantity);
      const ScalarView v = baseSession_->evaluate(q, std::min(state_.step, baseSession_->fieldOf(q).stepCount() - 1));
      const auto number = [](double x) { return QString::number(x, 'g', 6).toStdString(); };
      throw std::invalid_argument("no cell has " + layer.quantity + " within " + number(layer.min) + " .. " +
                                  number(layer.max) + " at this step (its values: " + number(v.range.min) + " .. " +
                                  number(v.range.max) + ")");
    }
  }
  state_.threshold = layer;
  rebuildDeformation();
}

// ---- probed points and markers ----

void Scene::checkProbes(const std::vector<glm::dvec3>& points) const {
  if (points.size() > kMaxProbes)
    throw std::invalid_argument(std::to_string(points.size()) + " probed points: at most " + std::to_string(kMaxProbes));
  for (const glm::dvec3& p : points)
    if (!std::isfinite(p.x + p.y + p.z)) throw std::invalid_argument("a probed point is not a finite X, Y, Z");
}

void Scene::setProbes(std::vector<glm::dvec3> points) {
  checkProbes(points);
  state_.probes = std::move(points);
  for (const std::size_t i : state_.measure)
    if (i >= state_.probes.size()) state_.measure.clear();  // a measured probe is gone
}

void Scene::checkMeasure(const std::vector<std::size_t>& measure, std::size_t probes) {
  if (measure.empty()) return;
  if (measure.size() != 2 && measure.size() != 3)
    throw std::invalid_argument("a measure names two probes, or three for an angle (" + std::to_string(measure.size()) +
                                " given)");
  for (std::size_t i = 0; i < measure.size(); ++i) {
    if (measure[i] >= probes)
      throw std::invalid_argument("probe " + std::to_string(measure[i] + 1) + " is not there to measure (" +
                                  std::to_string(probes) + " probes)");
    for (std::size_t j = 0; j < i; ++j)
      if (measure[j] == measure[i])
        throw std::invalid_argument("probe " + std::to_string(measure[i] + 1) + " is named twice in the measure");
  }
}

void Scene::setHighlight(std::optional<Highlight> h) {
  if (h &&
      (!session_ || h->cell >= session_->model().cellCount() || (h->node && *h->node >= session_->model().nodeCount())))
    h.reset();
  highlight_ = h;
  highlightOn_ = session_;
}

std::optional<Scene::Highlight> Scene::highlight() const {
  if (!highlight_ || highlightOn_.expired() || highlightOn_.lock() != session_) return std::nullopt;
  return highlight_;
}

void Scene::setMeasure(std::vector<std::size_t> probes) {
  checkMeasure(probes, state_.probes.size());
  state_.measure = std::move(probes);
}

const std::vector<std::optional<double>>& Scene::probedValues() const {
  if (probedVersion_ == viewVersion_ && probedPoints_ == state_.probes) return probedValues_;
  probedVersion_ = viewVersion_;
  probedPoints_ = state_.probes;
  probedValues_.assign(state_.probes.size(), std::nullopt);
  if (!session_ || !view_) return probedValues_;
  const std::string key = view_->quantity.key();
  for (std::size_t i = 0; i < state_.probes.size(); ++i) {
    const ProbeResult r = probeAt(*session_, state_.probes[i], state_.step);
    if (r.inside()) probedValues_[i] = r.value(key);
  }
  return probedValues_;
}

std::optional<Scene::Extremes> Scene::extremes() const {
  if (extremesVersion_ == viewVersion_) return extremes_;
  extremesVersion_ = viewVersion_;
  extremes_.reset();
  if (!view_ || !session_ || !view_->range.valid()) return extremes_;
  const Model& model = session_->model();
  const SampleView& v = view_->values;
  std::size_t lo = v.size(), hi = v.size();
  std::vector<bool> used;
  // A grid without its cells built has every point used, its point and cell numbers in
  // grid order: its hexahedra (57 bytes a point) are not built to find two values.
  const bool gridOnly = model.grid && !model.meshBuilt();
  if (view_->location == FieldLocation::Node && !gridOnly) {  // unused nodes are not part of the model
    used.assign(model.mesh().nodeCount(), false);
    for (NodeIndex n : model.mesh().connectivity()) used[n] = true;
  }
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (!std::isfinite(v[i]) || (!used.empty() && !used[i])) continue;
    if (lo == v.size() || v[i] < v[lo]) lo = i;
    if (hi == v.size() || v[i] > v[hi]) hi = i;
  }
  if (lo == v.size()) return extremes_;
  const auto where = [&](std::size_t i) {
    if (view_->location == FieldLocation::Node) return model.nodePosition(i);
    if (gridOnly) {
      const RegularGrid& g = *model.grid;
      const std::size_t cx = g.dims[0] - 1, cy = g.dims[1] - 1;
      return g.position(double(i % cx) + 0.5, double(i / cx % cy) + 0.5, double(i / (cx * cy)) + 0.5);
    }
    const Mesh& mesh = model.mesh();
    const CellTopology& topo = topology(mesh.cellType(i));
    const auto nodes = mesh.cellNodes(i);
    glm::dvec3 c(0.0);
    for (int k = 0; k < topo.cornerCount; ++k) c += mesh.nodes[nodes[std::size_t(k)]];
    return c / double(topo.cornerCount);
  };
  const auto idOf = [&](std::size_t i) {
    if (gridOnly) return std::int64_t(i) + 1;  // as hexahedraOfGrid numbers them
    return view_->location == FieldLocation::Node ? model.mesh().nodeId(i) : model.mesh().cellId(i);
  };
  extremes_ = Extremes{where(lo), where(hi), v[lo], v[hi], idOf(lo), idOf(hi)};
  return extremes_;
}

// ---- derived ----

DisplayRange Scene::displayRange() const {
  if (state_.fixedRange) return *state_.fixedRange;
  if (!view_) return DisplayRange{};
  DisplayRange range = autoRange(*view_);
  if (state_.rangeOverSteps && session_) {
    const ValueRange all = session_->rangeOverSteps(view_->quantity);
    if (all.valid() && all.max > all.min) range = {all.min, all.max};
  }
  if (state_.logScale) {
    if (!(range.min > 0.0)) {
      // The values reach 0 or below: the range starts at the smallest positive one.
      if (smallestPositiveVersion_ != viewVersion_) {
        smallestPositiveVersion_ = viewVersion_;
        double smallest = std::numeric_limits<double>::infinity();
        for (std::size_t i = 0; i < view_->values.size(); ++i)
          if (const double v = view_->values[i]; v > 0.0 && v < smallest) smallest = v;
        smallestPositive_ = std::isfinite(smallest) ? std::optional(smallest) : std::nullopt;
      }
      if (smallestPositive_ && *smallestPositive_ < range.max) range.min = *smallestPositive_;
    }
    return range;  // no symmetric range on a log scale
  }
  if (state_.symmetricAuto ? divergingMap() && range.min < 0.0 && range.max > 0.0 : state_.symmetricRange) {
    const double m = std::max(std::abs(range.min), std::abs(range.max));
    if (m > 0.0 && std::isfinite(m)) range = {-m, m};
  }
  return range;
}

TransferFunction Scene::transferFunction() const {
  if (state_.volume.transferFunction) return *state_.volume.transferFunction;
  if (!view_ || !session_) return {};
  // The default follows the color range the user chose (fixed, over all steps or per step).
  const auto chosen = state_.fixedRange || state_.rangeOverSteps ? std::optional(displayRange()) : std::nullopt;
  return defaultTransferFunction(*view_, session_->model().bounds().diagonal(), state_.colorMap, chosen);
}

std::optional<LegendPicture> Scene::legend() const {
  auto all = legends();
  if (all.empty()) return std::nullopt;
  return std::move(all.front());
}

std::vector<LegendPicture> Scene::legends() const {
  std::vector<LegendPicture> out;
  if (!state_.legend) return out;
  if (const SetColoring* coloring = state_.volume.shown ? nullptr : setColoring()) {
    LegendContent key;  // the surface's colors name sets: their key replaces the result's bar
    key.title = "Element sets";
    key.subtitle = coloring->entries.size() == 1 ? QString("1 set") : QString("%1 sets").arg(coloring->entries.size());
    for (const SetColoring::Entry& e : coloring->entries)
      key.swatches.push_back({QString::fromStdString(e.name), e.rgb});
    if (coloring->cellsInNoSet > 0)
      key.swatches.push_back({QString("in no set (%1)").arg(coloring->cellsInNoSet), glm::dvec3(0.55)});
    out.push_back({setPaletteMap(), key});
  } else if (view_) {
    LegendContent content;
    const auto title = state_.legendTitles.find(view_->quantity.key());
    content.title =
        QString::fromStdString(title != state_.legendTitles.end() ? title->second : view_->quantity.displayName());
    const QString written = quantityUnits(view_->quantity, QString::fromStdString(unitsOf(view_->quantity.field)));
    if (!written.isEmpty()) content.title += QString(" [%1]").arg(written);
    content.numbers = LegendNumbers::parse(state_.legendNumbers).value_or(LegendNumbers{});
    content.labels = state_.legendLabels;
    content.subtitle = stepAndLocation(*view_);
    content.noValueCount = view_->range.nanCount;
    if (view_->range.valid()) content.dataMin = view_->range.min, content.dataMax = view_->range.max;
    if (state_.volume.shown) content.noValueShown = "left out of the volume";
    if (state_.volume.shown && state_.volume.transferFunction2D) {
      // A 2D transfer function's colors depend on the gradient too: no bar over the values
      // could say what a color means; the legend says where they come from.
      content.subtitle = "volume  " + content.subtitle.trimmed();
      content.noBarNote = "colors: 2D transfer function (value and gradient)";
      out.push_back({ColorMap::named(state_.colorMap), content});
    } else if (state_.volume.shown) {
      const TransferFunction tf = transferFunction();
      content.subtitle = "volume  " + content.subtitle.trimmed();
      content.min = tf.minValue();
      content.max = tf.maxValue();
      out.push_back({colorMapOf(tf), content});
    } else {
      const DisplayRange range = displayRange();
      content.min = range.min;
      content.max = range.max;
      content.bands = state_.colorBands;
      content.logScale = state_.logScale && range.min > 0.0;
      content.belowColor = state_.belowColor;
      content.aboveColor = state_.aboveColor;
      out.push_back({ColorMap::named(state_.colorMap), content});
    }
  }
  // Streamlines have a key of their own, beside the result's (it replaced it before).
  if (!state_.volume.shown && streamlinesDrawn()) {
    const StreamlineResult& r = *streamlineResult_;
    LegendContent lines;
    lines.title = QString::fromStdString(r.valueName);
    lines.subtitle = QString("%1 streamlines").arg(r.lines.size());
    lines.min = r.min;
    lines.max = r.max;
    lines.dataMin = r.min;
    lines.dataMax = r.max;
    out.push_back({ColorMap::named(state_.colorMap), lines});
  }
  if (state_.glyphs.shown) {
    try {
      if (const auto g = glyphs(); g && g->glyphs > 0) {
        LegendContent key;
        key.title = QString::fromStdString(g->valueName);
        key.subtitle = QString("%1 glyphs").arg(g->glyphs);
        if (g->every > 1) key.subtitle += QString(", one node in %1").arg(g->every);
        key.min = g->min;
        key.dataMin = g->dataMin;
        key.max = g->max;
        key.dataMax = g->dataMax;
        out.push_back({ColorMap::named(state_.colorMap), key});
      }
    } catch (const std::invalid_argument&) {
      // too many glyphs: the drawing says why; no key for what is not drawn
    }
  }
  for (LegendPicture& legend : out) {
    legend.content.textScale = state_.textScale;
    legend.content.onDark = isDarkBackground(state_.background);
  }
  return out;
}

Camera Scene::pictureCamera(double width, double height) const {
  Camera camera = camera_;
  if (!legend() || !(width > 0.0) || !(height > 0.0)) return camera;
  const QRect area(0, 0, int(std::lround(width)), int(std::lround(height)));
  LegendContent content = legend()->content;  // the strip as wide as its numbers' style, or its names
  content.numbers = LegendNumbers::parse(state_.legendNumbers).value_or(LegendNumbers{});
  content.textScale = state_.textScale;
  camera.setRightMargin(std::min(0.4, legendWidth(area, content) / width));
  return camera;
}

// The values of another quantity are evaluated once per quantity, step and model.
VersionedView Scene::isoSurfaceValues() const {
  const std::string& key = state_.volume.isoQuantity;
  if (key.empty() || (view_ && view_->quantity.key() == key)) return shownValues();
  if (!session_) return {};
  const std::string id = key + "@" + std::to_string(state_.step) + "@" + std::to_string(viewVersion_);
  if (isoViewFor_ != id) {
    try {
      isoView_ = session_->evaluate(session_->findQuantity(key), std::min(state_.step, stepCountOf(key) - 1));
    } catch (const std::exception&) {
      isoView_.reset();  // checked when set: a failure here is a damaged lazy read, drawn as none
    }
    isoViewFor_ = id;
    ++isoViewVersion_;
  }
  return {isoView_ ? &*isoView_ : nullptr, isoViewVersion_};
}

std::size_t Scene::stepCountOf(const std::string& key) const {
  return std::max<std::size_t>(1, session_->fieldOf(session_->findQuantity(key)).stepCount());
}

void Scene::setIsoQuantity(const std::string& key) {
  if (!key.empty()) {
    if (!session_) throw std::invalid_argument("open a model first");
    const Quantity q = session_->findQuantity(key);  // invalid_argument naming the choices
    if (session_->fieldOf(q).location() != FieldLocation::Node)
      throw std::invalid_argument("iso-surfaces need values at the nodes; " + q.displayName() +
                                  " is given per element");
  }
  state_.volume.isoQuantity = key;
  ++revisions_.iso;
}

void Scene::setPlotLine(std::optional<std::array<glm::dvec3, 2>> line) {
  if (line && !std::isfinite((*line)[0].x + (*line)[0].y + (*line)[0].z + (*line)[1].x + (*line)[1].y + (*line)[1].z))
    throw std::invalid_argument("the plotted line's ends must be finite X, Y, Z");
  state_.plotLine = line;
}

void Scene::setSurfaceOpacity(double opacity) {
  if (!(opacity >= 0.0 && opacity <= 1.0)) throw std::invalid_argument("the surface opacity must lie in 0..1");
  state_.surfaceOpacity = opacity;
}

void Scene::setStreamlines(StreamlineLayer layer) {
  checkStreamlines(layer);
  state_.streamlines = std::move(layer);
  ++revisions_.streamlines;
}

void Scene::checkStreamlines(const StreamlineLayer& layer) const {
  if (!session_) {
    if (layer.shown) throw std::invalid_argument("open a model first");
    return;
  }
  checkStreamlines(layer, *session_);
}

void Scene::checkStreamlines(const StreamlineLayer& layer, const ModelSession& session) const {
  if (layer.shown) {
    const Field* f = session.model().findField(layer.field);
    if (!f) throw std::invalid_argument("no field named '" + layer.field + "' to trace streamlines in");
    if (f->components() != 3)
      throw std::invalid_argument("streamlines follow a vector field; " + layer.field + " has " +
                                  std::to_string(f->components()) + " components");
    if (f->location() == FieldLocation::Cell && !layer.averageCellVectors)
      throw std::invalid_argument(layer.field + " is given per element: streamlines need it at the nodes (average it "
                                                "there, an approximation, with --average-cell-vectors)");
    if (layer.seeds.empty()) throw std::invalid_argument("streamlines need seeds (where the lines start)");
    (void)seedPoints(layer.seeds, session);  // throws saying what is wrong with a spec
    if (!layer.colorBy.empty()) (void)session.findQuantity(layer.colorBy);
    if (!(layer.settings.tolerance > 0.0)) throw std::invalid_argument("the streamline tolerance must be positive");
    if (layer.style.tubes && layer.style.tubeRadius < 0.0) throw std::invalid_argument("the tube radius must be >= 0");
  }
}

bool Scene::streamlinesNeedTracing() const {
  const StreamlineLayer& l = state_.streamlines;
  if (!l.shown || !session_) return false;
  return !streamlineResult_ || streamlineResult_->session != session_.get() || streamlineResult_->step != state_.step ||
         streamlineResult_->interpolation != state_.volume.interpolation || !streamlineResult_->layer.sameLinesAs(l);
}

bool Scene::streamlinesDrawn() const {
  return state_.streamlines.shown && streamlineResult_ && !streamlinesNeedTracing();
}

std::shared_ptr<const StreamlineResult> Scene::traceStreamlines(const Progress& progress) const {
  if (!session_) throw std::invalid_argument("open a model first");
  return traceStreamlineLayer(*session_, state_.streamlines, state_.step, state_.volume.interpolation, progress);
}

void Scene::setStreamlineResult(std::shared_ptr<const StreamlineResult> result) {
  streamlineResult_ = std::move(result);
  ++revisions_.streamlines;
}

std::string Scene::perCellRefusal(const std::string& renderer) const {
  return "the volume renderer '" + renderer + "' draws values at the grid's points; '" + view_->quantity.displayName() +
         "' is given per cell: choose a renderer that draws meshes" +
         inParentheses(factory_.namesWhere([](const VolumeRendererTraits& t) { return t.drawsMeshes; }));
}

// ---- streamlines ----

void Scene::updateStreamlines() {
  if (streamlinesNeedTracing()) setStreamlineResult(traceStreamlines());
}

void Scene::changeEverything() {
  for (std::uint64_t* r : {&revisions_.model, &revisions_.scalars, &revisions_.colorMap, &revisions_.renderer,
                           &revisions_.geometry, &revisions_.values, &revisions_.tables, &revisions_.planes,
                           &revisions_.iso, &revisions_.mode, &revisions_.streamlines})
    ++*r;
}

}  // namespace volpost::app

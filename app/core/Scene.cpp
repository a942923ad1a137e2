// SPDX-License-Identifier: MIT
#include "Scene.hpp"

#include "VolumeDefaults.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace volpost::app {
namespace {

QString stepAndLocation(const ScalarView& view) {
  return QString("%1%2").arg(QString::fromStdString(view.stepLabel),
                             view.location == FieldLocation::Node ? "  per node" : "  per cell");
}

}  // namespace

Scene::Scene(VolumeRendererFactory factory) : factory_(std::move(factory)) { camera_.setView(StandardView::Isometric); }

Scene::~Scene() = default;

// ---- the model ----

void Scene::setSession(std::shared_ptr<const ModelSession> session) {
  session_ = std::move(session);
  view_.reset();
  state_.quantity.clear();
  state_.step = 0;
  state_.modelPath = session_ ? session_->model().sourcePath : std::string();
  state_.volume.shown = false;
  state_.volume.clipPlanes.clear();
  state_.volume.clipBox.reset();
  state_.volume.isoSurfaces.clear();
  state_.volume.transferFunction.reset();
  culled_.reset();
  culledFor_.clear();
  changed_ = Changes{};
  camera_.setView(StandardView::Isometric);
  fitCamera();
}

void Scene::fitCamera() {
  if (session_) camera_.fit(session_->model().mesh.bounds());
}

// ---- what is shown ----

void Scene::setResult(const std::string& quantity, std::size_t step) {
  if (quantity.empty() || !session_) {
    view_.reset();
    state_.quantity.clear();
    state_.step = 0;
    state_.volume.shown = false;
  } else {
    ScalarView view = session_->evaluate(session_->findQuantity(quantity), step);  // throws, changing nothing
    if (!view_ || view_->location != view.location) changed_.geometry = true;
    view_ = std::move(view);
    state_.quantity = quantity;
    state_.step = step;
  }
  changed_.scalars = changed_.values = true;
  if (!state_.volume.transferFunction) changed_.tables = true;  // the default follows the range
}

void Scene::setColorMap(const std::string& name) {
  (void)ColorMap::named(name);  // throws for an unknown name
  state_.colorMap = name;
  changed_.colorMap = true;
  if (!state_.volume.transferFunction) changed_.tables = true;  // the default takes the map's colors
}

void Scene::setFixedRange(std::optional<DisplayRange> range) {
  if (range && !(range->max > range->min && std::isfinite(range->min) && std::isfinite(range->max)))
    throw std::invalid_argument("a color range needs finite min < max");
  state_.fixedRange = range;
  changed_.scalars = true;
  if (!state_.volume.transferFunction) changed_.tables = true;  // the default spans the range
}

void Scene::setShowEdges(bool show) { state_.edges = show; }

void Scene::setVolumeShown(bool shown) {
  if (shown && !view_) throw std::invalid_argument("choose a result to render as a volume");
  state_.volume.shown = shown;
}

void Scene::setVolumeRenderer(const std::string& name) {
  if (!factory_(name)) throw std::invalid_argument("no volume renderer named '" + name + "' is loaded");
  if (name == state_.volume.renderer) return;
  state_.volume.renderer = name;
  changed_.renderer = true;
}

void Scene::setIntegrationMode(IntegrationMode mode) {
  state_.volume.mode = mode;
  changed_.mode = true;
}

void Scene::setTransferFunction(std::optional<TransferFunction> tf) {
  state_.volume.transferFunction = std::move(tf);
  changed_.tables = true;
}

void Scene::setClipPlanes(std::vector<ClipPlane> planes) {
  for (const ClipPlane& p : planes) {
    const double scale = std::max({std::abs(p.normal.x), std::abs(p.normal.y), std::abs(p.normal.z)});
    if (!(scale > 0.0) || !std::isfinite(scale) || !std::isfinite(glm::length(p.point)))
      throw std::invalid_argument("a clip plane needs a finite point and a finite, non-zero normal");
  }
  VolumeLayer next = state_.volume;
  next.clipPlanes = std::move(planes);
  if (next.allClipPlanes().size() > std::size_t(kMaxClipPlanes))
    throw std::invalid_argument("at most " + std::to_string(kMaxClipPlanes) + " clip planes, the box's six included");
  state_.volume.clipPlanes = std::move(next.clipPlanes);
  changed_.planes = true;
}

void Scene::setClipBox(std::optional<ClipBox> box) {
  VolumeLayer next = state_.volume;
  next.clipBox = box;
  if (next.allClipPlanes().size() > std::size_t(kMaxClipPlanes))
    throw std::invalid_argument("at most " + std::to_string(kMaxClipPlanes) + " clip planes, the box's six included");
  state_.volume.clipBox = box;
  changed_.planes = true;
}

void Scene::setIsoSurfaces(std::vector<optics::IsoSurface> surfaces) {
  if (surfaces.size() > std::size_t(kMaxIsoSurfaces))
    throw std::invalid_argument("at most " + std::to_string(kMaxIsoSurfaces) + " iso-surfaces");
  for (const optics::IsoSurface& s : surfaces)
    if (!std::isfinite(s.value) || !(s.opacity >= 0.0 && s.opacity <= 1.0))
      throw std::invalid_argument("an iso-surface needs a finite value and an opacity in 0..1");
  state_.volume.isoSurfaces = std::move(surfaces);
  changed_.iso = true;
}

void Scene::setSamplingStep(double step) {
  if (!(step >= 0.0) || !std::isfinite(step)) throw std::invalid_argument("the sampling step must be >= 0 (0: automatic)");
  state_.volume.samplingStep = step;
  changed_.mode = true;
}

void Scene::setTermination(double transmittance) {
  if (!(transmittance >= 0.0 && transmittance < 1.0))
    throw std::invalid_argument("the early-termination transmittance must lie in [0, 1)");
  state_.volume.termination = transmittance;
  changed_.mode = true;
}

void Scene::setVolumeEdges(bool show) { state_.volume.edges = show; }

// ---- the whole state ----

SceneState Scene::state() const {
  SceneState s = state_;
  CameraState c;
  c.eye = camera_.eye();
  c.target = camera_.target();
  c.up = camera_.up();
  c.fieldOfView = camera_.fieldOfView();
  c.orthographic = camera_.projection() == Camera::Projection::Orthographic;
  s.camera = c;
  return s;
}

void Scene::applyState(const SceneState& s) {
  if (!session_) throw std::invalid_argument("no model is open to apply the state to");
  // Check everything before changing anything.
  std::optional<ScalarView> view;
  if (!s.quantity.empty()) view = session_->evaluate(session_->findQuantity(s.quantity), s.step);
  (void)ColorMap::named(s.colorMap);
  if (s.volume.shown && !view) throw std::invalid_argument("the state shows a volume but names no result");
  if (s.volume.shown && !factory_(s.volume.renderer))
    throw std::invalid_argument("no volume renderer named '" + s.volume.renderer + "' is loaded");
  if (s.volume.allClipPlanes().size() > std::size_t(kMaxClipPlanes) ||
      s.volume.isoSurfaces.size() > std::size_t(kMaxIsoSurfaces))
    throw std::invalid_argument("too many clip planes or iso-surfaces");
  Camera camera = camera_;
  camera.fit(session_->model().mesh.bounds());
  if (s.camera) {
    camera.setProjection(s.camera->orthographic ? Camera::Projection::Orthographic : Camera::Projection::Perspective);
    camera.setFieldOfView(s.camera->fieldOfView);
    camera.lookAt(s.camera->eye, s.camera->target, s.camera->up);
  } else {
    camera.setView(StandardView::Isometric);
    camera.fit(session_->model().mesh.bounds());
  }

  const bool locationChanged = !view_ || !view || view_->location != view->location;
  const std::string keptModel = state_.modelPath;
  state_ = s;
  state_.modelPath = keptModel;
  state_.camera.reset();  // the live camera holds it
  view_ = std::move(view);
  camera_ = camera;
  changed_.scalars = changed_.colorMap = changed_.edges = true;
  changed_.values = changed_.tables = changed_.planes = changed_.iso = changed_.mode = true;
  if (locationChanged) changed_.geometry = true;
  if (volumeName_ != state_.volume.renderer) changed_.renderer = true;
}

// ---- derived ----

DisplayRange Scene::displayRange() const {
  if (state_.fixedRange) return *state_.fixedRange;
  return view_ ? autoRange(*view_) : DisplayRange{};
}

TransferFunction Scene::transferFunction() const {
  if (state_.volume.transferFunction) return *state_.volume.transferFunction;
  if (!view_ || !session_) return {};
  return defaultTransferFunction(*view_, session_->model().mesh.bounds().diagonal(), state_.colorMap, state_.fixedRange);
}

std::optional<LegendPicture> Scene::legend() const {
  if (!view_ || !state_.legend) return std::nullopt;
  LegendContent content{QString::fromStdString(view_->quantity.displayName()), stepAndLocation(*view_), 0.0, 1.0,
                        view_->range.nanCount};
  if (state_.volume.shown) {
    const TransferFunction tf = transferFunction();
    content.subtitle = "volume  " + content.subtitle.trimmed();
    content.min = tf.minValue();
    content.max = tf.maxValue();
    return LegendPicture{colorMapOf(tf), content};
  }
  const DisplayRange range = displayRange();
  content.min = range.min;
  content.max = range.max;
  return LegendPicture{ColorMap::named(state_.colorMap), content};
}

std::vector<double> Scene::tetValues() const { return session_->tetValues(*view_); }

// ---- GL ----

void Scene::initialize() {
  boundary_.initialize();
  initialized_ = true;
  changed_ = Changes{};  // a fresh context holds nothing
}

void Scene::release() {
  if (!initialized_) return;
  if (volume_) volume_->release();
  volume_.reset();
  volumeName_.clear();
  culled_.reset();
  culledFor_.clear();
  depthTarget_.reset();
  boundary_.release();
  initialized_ = false;
  changed_ = Changes{};
}

VolumeStats Scene::volumeStats() const { return volume_ ? volume_->stats() : VolumeStats{}; }

std::vector<float> Scene::readVolumeImage() const {
  return volume_ && state_.volume.shown ? volume_->readImage() : std::vector<float>{};
}

void Scene::applyToBoundary() {
  if (changed_.model) boundary_.setSession(session_);
  if (changed_.model || changed_.scalars) boundary_.setScalars(view_ ? &*view_ : nullptr, displayRange());
  if (changed_.colorMap) boundary_.setColorMap(ColorMap::named(state_.colorMap));
  changed_.model = changed_.scalars = changed_.colorMap = changed_.edges = false;
}

// Hands the volume renderer what changed, and only that. The GPU holds only the tets the
// clip box can show (the renderer cuts exactly at every plane, so the picture is the
// same); free planes are not culled to, so dragging one never rebuilds, and the window
// and the command line hold the same tets and draw the same pixels.
void Scene::applyToVolume() {
  const VolumeLayer& v = state_.volume;
  if (changed_.renderer || !volume_ || volumeName_ != v.renderer) {
    if (volume_) volume_->release();
    volume_ = factory_(v.renderer);
    volumeName_.clear();
    if (!volume_) throw std::invalid_argument("no volume renderer named '" + v.renderer + "' is loaded");
    volume_->initialize();
    volume_->setAsynchronousUpdates(interactive_);
    volumeName_ = v.renderer;
    changed_.volumeAll();
    culledFor_.clear();
  }
  const std::vector<ClipPlane> planes = v.allClipPlanes();
  const std::vector<ClipPlane> cullPlanes = v.clipBox ? clipBoxPlanes(*v.clipBox) : std::vector<ClipPlane>{};
  if (cullPlanes != culledFor_) changed_.geometry = true;
  const Mesh& tets = session_->tetrahedra().mesh;
  if (changed_.geometry) {
    const std::vector<double> values = tetValues();
    if (cullPlanes.empty()) {
      culled_.reset();
      volume_->setVolume(tets, view_->location, values);
    } else {
      culled_ = cullToClipPlanes(tets, cullPlanes);
      volume_->setVolume(culled_->mesh, view_->location, culled_->values(view_->location, values));
    }
    culledFor_ = cullPlanes;
  } else if (changed_.values) {
    const std::vector<double> values = tetValues();
    volume_->setValues(culled_ ? culled_->values(view_->location, values) : values);  // only the values travel
  }
  if (changed_.tables) volume_->setTransferFunction(transferFunction());
  if (changed_.planes) volume_->setClipPlanes(planes);
  if (changed_.iso) volume_->setIsoSurfaces(v.isoSurfaces);
  if (changed_.mode) {
    volume_->setIntegrationMode(v.mode);
    volume_->setSamplingStep(v.samplingStep);
    volume_->setTerminationThreshold(v.termination);
  }
  changed_.renderer = changed_.geometry = changed_.values = changed_.tables = false;
  changed_.planes = changed_.iso = changed_.mode = false;
}

void Scene::render(const RenderContext& target) {
  if (!initialized_) return;
  RenderContext ctx = target;
  ctx.camera = camera_;
  applyToBoundary();
  if (state_.volume.shown && view_ && session_) {
    renderVolume(ctx);
  } else {
    boundary_.setShowEdges(state_.edges);
    boundary_.setLighting(state_.lighting);
    boundary_.render(ctx);
  }
}

// The element edges stay visible over the volume and end its rays: they are drawn into
// the target and, depth only, into a texture the volume renderer reads.
void Scene::renderVolume(const RenderContext& ctx) {
  applyToVolume();
  RenderContext volumeCtx = ctx;
  if (state_.volume.edges) {
    if (!depthTarget_ || depthTarget_->width() != ctx.width || depthTarget_->height() != ctx.height)
      depthTarget_ = std::make_unique<OffscreenTarget>(ctx.width, ctx.height);
    boundary_.setShowFaces(false);
    boundary_.setShowEdges(true);
    RenderContext depthCtx = ctx;
    depthCtx.framebuffer = depthTarget_->framebuffer();
    boundary_.render(depthCtx);
    boundary_.render(ctx);
    boundary_.setShowFaces(true);
    volumeCtx.depthTexture = depthTarget_->depthTexture();
  } else {
    boundary_.renderBackground(ctx);
  }
  volume_->render(volumeCtx);
}

}  // namespace volpost::app

// SPDX-License-Identifier: MIT
#include "CpuVolumeRenderer.hpp"



#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

namespace volpost::volume {

void CpuVolumeRenderer::initialize() {
  composite_.initialize();
  textureWidth_ = textureHeight_ = 0;
  meshUploads_ = valueUploads_ = 0;
}

CpuVolumeRenderer::~CpuVolumeRenderer() { cancelJob(); }

void CpuVolumeRenderer::release() {
  cancelJob();
  shownKey_ = {};
  texture_.reset();
  uploaded_ = false;
  composite_.release();
  textureWidth_ = textureHeight_ = 0;
}

void CpuVolumeRenderer::setVolume(const Mesh& mesh, FieldLocation location, std::span<const double> values) {
  walkMesh_ = std::make_shared<const TetWalkMesh>(mesh, location, values);  // throws before anything changes
  grid_.reset();
  mesh_ = &mesh;
  location_ = location;
  settings_.element.reset();
  ++meshUploads_;
  ++revision_;
  visible_.reset();
}

void CpuVolumeRenderer::setElementField(std::shared_ptr<const optics::ElementField> field,
                                        std::vector<std::uint32_t> cellOfTet) {
  if (!field) {
    if (settings_.element) ++revision_, visible_.reset();
    settings_.element.reset();
    return;
  }
  if (!walkMesh_ || !mesh_) throw std::logic_error("CpuVolumeRenderer::setElementField before setVolume");
  if (location_ != FieldLocation::Node)
    throw std::invalid_argument("the cells' own interpolation needs values at the nodes, not per cell");
  if (cellOfTet.size() != mesh_->cellCount())
    throw std::invalid_argument("the element field names the cells of " + std::to_string(cellOfTet.size()) +
                                " tetrahedra; the volume has " + std::to_string(mesh_->cellCount()));
  auto element = std::make_shared<CpuElementField>();
  element->field = std::move(field);
  element->cellOfTet.resize(walkMesh_->tetCount());  // the walk leaves degenerate tets out
  for (std::size_t t = 0; t < element->cellOfTet.size(); ++t) element->cellOfTet[t] = cellOfTet[walkMesh_->meshTet(t)];
  settings_.element = std::move(element);
  ++revision_;
  visible_.reset();
}

void CpuVolumeRenderer::setElementTolerance(double tolerance) {
  if (!(tolerance >= 0.0 && tolerance <= 1.0))
    throw std::invalid_argument("the tolerance of the cells' own field must lie in [0, 1], not " +
                                std::to_string(tolerance));
  if (tolerance == settings_.elementTolerance) return;
  settings_.elementTolerance = tolerance;
  ++revision_;
}

void CpuVolumeRenderer::setGrid(const RegularGrid& grid, SampleView values) {
  grid_ = std::make_shared<const GridSamples>(grid, values);  // throws before anything changes
  walkMesh_.reset();
  mesh_ = nullptr;
  location_ = FieldLocation::Node;
  settings_.element.reset();
  ++meshUploads_;
  ++revision_;
  visible_.reset();
}

void CpuVolumeRenderer::setShading(bool on) {
  if (settings_.shading != on) ++revision_;
  settings_.shading = on;
}

void CpuVolumeRenderer::setTransferFunction2D(const std::optional<TransferFunction2D>& tf) {
  if (settings_.transferFunction2D != tf) ++revision_;
  settings_.transferFunction2D = tf;
}

void CpuVolumeRenderer::setSamplingStep(double step) {
  if (!(step >= 0.0) || !std::isfinite(step))
    throw std::invalid_argument("the sampling step must be a length >= 0, not " + std::to_string(step));
  if (step != gridStep_) ++revision_;
  gridStep_ = step;
}

void CpuVolumeRenderer::setGridValues(SampleView values) {
  if (!grid_) throw std::logic_error("CpuVolumeRenderer::setGridValues before setGrid");
  grid_ = std::make_shared<const GridSamples>(grid_->grid(), values);
  ++valueUploads_;
  ++revision_;
}

void CpuVolumeRenderer::setValues(std::span<const double> values) {
  if (grid_) {
    setGridValues(values);
    return;
  }
  if (!mesh_) throw std::logic_error("CpuVolumeRenderer::setValues before setVolume");
  walkMesh_ = TetWalkMesh::withValues(walkMesh_, *mesh_, values);
  settings_.element.reset();
  ++valueUploads_;
  ++revision_;
  visible_.reset();
}

void CpuVolumeRenderer::setClipPlanes(const std::vector<ClipPlane>& planes) {
  checkClipPlanes(planes);
  settings_.clipPlanes = planes;
  ++revision_;
}

void CpuVolumeRenderer::setIsoSurfaces(const std::vector<optics::IsoSurface>& surfaces) {
  checkIsoSurfaces(surfaces);
  settings_.isoSurfaces = surfaces;
  ++revision_;
  visible_.reset();
}

void CpuVolumeRenderer::setTerminationThreshold(double transmittance) {
  if (!(transmittance >= 0.0 && transmittance < 1.0))
    throw std::invalid_argument("the early-termination transmittance must lie in [0, 1), not " + std::to_string(transmittance));
  if (settings_.terminationTransmittance != transmittance) ++revision_;
  settings_.terminationTransmittance = transmittance;
}

void CpuVolumeRenderer::setAsynchronousUpdates(bool on) {
  if (!on) cancelJob();
  asynchronous_ = on;
}

void CpuVolumeRenderer::cancelJob() {
  if (!job_.valid()) return;
  *jobCancelled_ = true;
  try {
    job_.get();  // it stops at its next tile
  } catch (...) {  // Cancelled, or a failure nobody waits for any more
  }
}

std::shared_ptr<const VisiblePart> CpuVolumeRenderer::visiblePart() {
  if (!visible_)
    visible_ = std::make_shared<const VisiblePart>(
        findVisiblePart(*walkMesh_, tf_, settings_.isoSurfaces, threads_, settings_.element.get()));
  return visible_;
}

std::function<CpuImage(const Camera&, int, int, const CpuRaySettings&, const Progress&)> CpuVolumeRenderer::frameMaker() {
  if (grid_)
    return [grid = grid_, tf = tf_, step = gridStep_, threads = threads_](const Camera& camera, int w, int h,
                                                                          const CpuRaySettings& s, const Progress& p) {
      return renderCpuGrid(*grid, tf, camera, w, h, s, step, p, threads);
    };
  if (settings_.transferFunction2D)
    throw std::invalid_argument("2D transfer functions (over the value and its gradient) are drawn on regular grids "
                                "only, not on meshes of tetrahedra");
  return [mesh = walkMesh_, part = visiblePart(), tf = tf_, threads = threads_](const Camera& camera, int w, int h,
                                                                               const CpuRaySettings& s, const Progress& p) {
    return renderCpu(*mesh, *part, tf, camera, w, h, s, p, threads);
  };
}

int CpuVolumeRenderer::reductionFor(int width, int height) const {
  if (msPerRay_ <= 0.0) return 4;  // nothing measured yet: a cautious first guess
  const double fullMs = msPerRay_ * double(width) * double(height);
  return std::clamp(int(std::ceil(std::sqrt(fullMs / quickFrameMs_))), 1, 16);
}

void CpuVolumeRenderer::render(const RenderContext& ctx) {
  if ((!walkMesh_ && !grid_) || ctx.width <= 0 || ctx.height <= 0) return;
  FrameKey key;
  key.viewProjection = ctx.camera.projectionMatrix(ctx.aspect()) * ctx.camera.viewMatrix();
  key.width = ctx.width;
  key.height = ctx.height;
  key.revision = revision_;
  if (ctx.depthTexture) {  // rays end at the opaque geometry already drawn
    key.depth.resize(std::size_t(ctx.width) * std::size_t(ctx.height));
    glGetTextureImage(ctx.depthTexture, 0, GL_DEPTH_COMPONENT, GL_FLOAT, GLsizei(key.depth.size() * sizeof(float)),
                      key.depth.data());
  }
  const auto measured = [this](const CpuImage& frame) {
    uploaded_ = false;  // a new image
    const double rays = double(frame.width) * double(frame.height);
    if (rays > 0.0) msPerRay_ = (frame.stats.entryMs + frame.stats.walkMs) / rays;
  };
  CpuRaySettings settings = settings_;
  settings.sceneDepth = key.depth;
  if (!asynchronous_) {
    image_ = frameMaker()(ctx.camera, ctx.width, ctx.height, settings, {});
    measured(image_);
    shownKey_ = key;
    shownReduction_ = 1;
    show(ctx);
    return;
  }
  if (job_.valid() && jobKey_ == key) {  // the full frame of this very view is on its way
    if (job_.wait_for(std::chrono::seconds(0)) == std::future_status::ready) {
      image_ = job_.get();  // a failure surfaces here, in the GUI thread
      measured(image_);
      shownKey_ = key;
      shownReduction_ = 1;
    }
    show(ctx);
    return;
  }
  if (!(shownKey_ == key && shownReduction_ == 1)) {
    cancelJob();
    const int reduction = reductionFor(ctx.width, ctx.height);
    const auto frame = frameMaker();
    if (reduction == 1) {
      image_ = frame(ctx.camera, ctx.width, ctx.height, settings, {});
      measured(image_);
    } else {
      // A quick frame now (same camera, fewer rays), the full one on worker threads.
      const int w = std::max(1, ctx.width / reduction), h = std::max(1, ctx.height / reduction);
      CpuRaySettings quick = settings;
      quick.sceneDepth.clear();  // one depth per full-size pixel: not for the reduced rays
      image_ = frame(ctx.camera, w, h, quick, {});
      measured(image_);
      jobCancelled_ = std::make_shared<std::atomic<bool>>(false);
      jobKey_ = key;
      job_ = std::async(std::launch::async, [frame, camera = ctx.camera, width = ctx.width, height = ctx.height,
                                             settings, cancelled = jobCancelled_] {
        return frame(camera, width, height, settings,
                     Progress([cancelled](double, const std::string&) { return !*cancelled; }));
      });
    }
    shownKey_ = key;
    shownReduction_ = reduction;
  }
  show(ctx);
}

void CpuVolumeRenderer::show(const RenderContext& ctx) {
  if (image_.width <= 0 || image_.height <= 0) return;
  if (!texture_ || textureWidth_ != image_.width || textureHeight_ != image_.height) {
    texture_ = floatImageTexture(image_.width, image_.height);
    textureWidth_ = image_.width;
    textureHeight_ = image_.height;
    uploaded_ = false;
  }
  if (!uploaded_)
    glTextureSubImage2D(texture_.id(), 0, 0, 0, image_.width, image_.height, GL_RGBA, GL_FLOAT, image_.rgba.data());
  uploaded_ = true;
  composite_.draw(ctx, texture_.id());  // as the GPU renderers do
}

VolumeStats CpuVolumeRenderer::stats() const {
  VolumeStats s;
  s.tetrahedra = walkMesh_ ? walkMesh_->tetCount() : 0;  // a grid is marched: none
  s.gpuBytes = std::size_t(textureWidth_) * std::size_t(textureHeight_) * 16;  // the image only: the mesh stays in host memory
  s.meshBytes = 0;
  s.meshUploads = meshUploads_;
  s.valueUploads = valueUploads_;
  return s;
}

}  // namespace volpost::volume

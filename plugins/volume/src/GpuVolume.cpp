// SPDX-License-Identifier: MIT
#include "GpuVolume.hpp"

#include "PiecewiseIntegrator.hpp"

#include "GpuLimits.hpp"
#include "StorageUpload.hpp"

#include "VolumeBindings.hpp"
#include "VolumeShaders.hpp"
#include "VolumeTextures.hpp"

#include <volpost/core/optics/IsoTables.hpp>
#include <volpost/core/optics/OpticalDepth.hpp>
#include <volpost/core/optics/PreintegrationTable.hpp>
#include <volpost/core/optics/PsiTable.hpp>
#include <volpost/core/optics/ThickPsi.hpp>
#include <volpost/render/ShaderLibrary.hpp>

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <tuple>
#include <utility>

namespace volpost::volume {
namespace {

constexpr int kTransferFunction2DMode = 4;  // INTEGRATION_MODE of common/volume_segment.glsl

int modeIndex(IntegrationMode mode) {
  switch (mode) {
    case IntegrationMode::LinearSegments: return 0;
    case IntegrationMode::PreIntegrated: return 1;
    case IntegrationMode::Sampling: return 2;
    case IntegrationMode::LinearSegmentsIsoTable: return 3;
  }
  return 0;
}

// A plane's unit normal, also for normals whose squared length overflows (1e308) or
// underflows; throws for a zero or non-finite one.
glm::dvec3 unitNormal(const ClipPlane& c) {
  const double scale = std::max({std::abs(c.normal.x), std::abs(c.normal.y), std::abs(c.normal.z)});
  if (!(scale > 0.0) || !std::isfinite(scale) || !std::isfinite(c.point.x) || !std::isfinite(c.point.y) ||
      !std::isfinite(c.point.z))
    throw std::invalid_argument("a clip plane needs a finite point and a finite, non-zero normal");
  return glm::normalize(c.normal / scale);
}

}  // namespace

// ---- state ---------------------------------------------------------------------------

void GpuVolume::setVolume(const Mesh& mesh, FieldLocation location, std::span<const double> values) {
  gpu_ = buildTetMeshGpu(mesh, location, values);  // CPU only; throws for cells that are not tets
  tetrahedraOnlyOnGpu_ = false;
  mesh_ = &mesh;
  grid_.clear();
  location_ = location;
  ++meshRevision_;
  ++revision_;
  meshDirty_ = visibleDirty_ = true;
}

void GpuVolume::setGrid(const RegularGrid& grid, SampleView values) {
  TetMeshGpu frame;
  frame.origin = grid.bounds().center();
  // The shortest step between grid points: the tables' segment length and the march's unit.
  frame.maxEdge = std::min({glm::length(grid.axes[0]), glm::length(grid.axes[1]), glm::length(grid.axes[2])});
  grid_.set(grid, values, frame);  // throws for a defect or a wrong count, changing nothing
  gpu_ = std::move(frame);
  tetrahedraOnlyOnGpu_ = false;
  mesh_ = nullptr;
  location_ = FieldLocation::Node;
  ++meshRevision_;
  ++revision_;
  meshDirty_ = true;
}

void GpuVolume::setGridValues(SampleView values) {
  if (!grid_.has()) throw std::logic_error("GpuVolume::setGridValues before setGrid");
  grid_.setValues(values, gpu_);
  valuesDirty_ = true;
  ++revision_;
}

void GpuVolume::setValues(SampleView values) {
  if (grid_.has()) {
    setGridValues(values);
    return;
  }
  if (!mesh_) return;
  std::vector<double> converted;
  const std::span<const double> doubles = values.doubles(converted);
  if (!replaceValues(gpu_, *mesh_, location_, doubles)) {
    setVolume(*mesh_, location_, doubles);  // the set of renderable tets changed
    return;
  }
  valuesDirty_ = visibleDirty_ = true;  // other values show other tets
  ++revision_;
}

void GpuVolume::setTransferFunction(const TransferFunction& tf) {
  if (tf == tf_) return;
  tf_ = tf;
  tablesDirty_ = visibleDirty_ = true;
  ++revision_;
}

void GpuVolume::setTransferFunction2D(const std::optional<TransferFunction2D>& tf) {
  if (tf == tf2d_) return;
  tf2d_ = tf;
  tf2dDirty_ = true;
  ++revision_;
}

void GpuVolume::setClipPlanes(const std::vector<ClipPlane>& planes) {
  checkClipPlanes(planes);
  clipPlanes_ = planes;
  ++revision_;
}

void GpuVolume::setIsoSurfaces(const std::vector<optics::IsoSurface>& surfaces) {
  checkIsoSurfaces(surfaces);
  // Tets an iso-surface passes through show: a new value changes what rays skip.
  const auto valuesOf = [](const std::vector<optics::IsoSurface>& list) {
    std::vector<double> v;
    for (const optics::IsoSurface& s : list) v.push_back(s.value);
    return v;
  };
  if (valuesOf(surfaces) != valuesOf(isoSurfaces_)) visibleDirty_ = true;
  isoSurfaces_ = surfaces;
  ++revision_;
}

void GpuVolume::setIntegrationMode(IntegrationMode mode) {
  if (mode == mode_) return;
  mode_ = mode;
  tablesDirty_ = true;
  ++revision_;
}

// ---- GL ------------------------------------------------------------------------------

void GpuVolume::initialize() {
  registerVolumeShaders();
  composite_.initialize();
  tables_.initialize();
  initialized_ = true;
  meshDirty_ = tablesDirty_ = visibleDirty_ = true;  // a fresh context holds nothing yet
  meshUploads_ = valueUploads_ = 0;
  gl::check("GpuVolume::initialize");
}

void GpuVolume::release() {
  tables_.release();
  for (gl::Buffer* b : {&nodes_, &tets_, &neighbors_, &cellValues_, &bvh_, &boundary_}) b->reset();
  image_.reset();
  tf2dDirty_ = tf2d_.has_value();
  grid_.release();
  visible_.release();
  programs_.clear();
  composite_.release();
  imageWidth_ = imageHeight_ = 0;
  initialized_ = false;
}

void GpuVolume::prepare(const RenderContext& ctx) {
  if (meshDirty_) {
    uploadMesh();
    meshDirty_ = valuesDirty_ = false;
  } else if (valuesDirty_) {
    uploadValues();
    valuesDirty_ = false;
  }
  if (grid_.has()) grid_.layOut();  // the budget may have changed since
  if (tf2dDirty_) {
    tables_.upload2D(tf2d_);
    tf2dDirty_ = false;
  }
  if (tablesDirty_ || !tables_.spanTheRangeOf(gpu_)) {
    // The tables depend on the transfer function, the mode and the values' range (they span
    // it, and control points travel in the values' frame). The mesh is not touched.
    if (tables_.rebuild(tf_, mode_, gpu_, asynchronous_)) ++revision_;
    tablesDirty_ = false;
  }
  if (visibleDirty_ && hasTets()) findVisibleTets(ctx);
  // A table finished since the last frame goes up now; with none uploaded yet, wait.
  if (tables_.collect(!asynchronous_ || (mode_ == IntegrationMode::PreIntegrated && !tables_.hasPreintegrationTable())))
    ++revision_;  // frames drawn with the previous table are outdated
  ensureImage(ctx.width, ctx.height);
}

// After the tables: the test reads the control points' zero-extinction runs.
void GpuVolume::findVisibleTets(const RenderContext& ctx) {
  visibleDirty_ = false;
  if (!emptySpaceSkipping_) {
    visible_.release();
    return;
  }
  const GLuint p = program({"volume/visible_tets.comp"});
  setSegmentUniforms(p, ctx);
  bindSegmentResources(ctx);
  visible_.update(p, gpu_);
  gl::check("GpuVolume::findVisibleTets");
}

void GpuVolume::uploadMesh() {
  if (tetrahedraOnlyOnGpu_)
    throw std::logic_error("the volume renderer was released after its tetrahedra went to the GPU: set the volume again");
  if (grid_.has()) uploadGrid();
  else grid_.release();
  // Checked before anything is uploaded: a buffer past the device's limit would read as
  // zeros (or fault) on drivers that enforce it.
  GLint64 limit = 0;
  glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &limit);
  // Mesa's llvmpipe states 128 MiB but binds and addresses whole buffers of any size
  // (reported working on a 2-core llvmpipe machine up to 48M tets, 768 MiB of tetrahedra).
  const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  if (renderer && std::strstr(renderer, "llvmpipe")) limit = 0;
  requireStorageBlockFits("nodes", gpu_.nodes.size() * sizeof(glm::vec4), limit);
  requireStorageBlockFits("tetrahedra", gpu_.tetCount * sizeof(glm::uvec4), limit);
  requireStorageBlockFits("face neighbours", gpu_.neighbors.size() * sizeof(std::uint32_t), limit);
  requireStorageBlockFits("cell values", gpu_.cellValues.size() * sizeof(float), limit);
  requireStorageBlockFits("boundary faces", gpu_.boundaryFaces.size() * sizeof(std::uint32_t), limit);
  requireStorageBlockFits("boundary hierarchy", gpu_.bvh.size() * sizeof(glm::vec4), limit);
  // Each array let go as soon as it is up (unless kept), so that a driver whose "GPU" copy
  // is host memory too (llvmpipe) never holds both whole structures at once.
  const bool letGo = !keepsTetrahedraOnHost_ && gpu_.holdsTets();
  upload(nodes_, gpu_.nodes);
  uploadBytes(tets_, gpu_.tetData(), gpu_.tetCount * sizeof(glm::uvec4));
  if (letGo) gpu_.letGoOfTets();
  upload(neighbors_, gpu_.neighbors);
  if (letGo) std::vector<std::uint32_t>().swap(gpu_.neighbors);
  tetrahedraOnlyOnGpu_ = letGo;
  upload(cellValues_, gpu_.cellValues);
  upload(bvh_, gpu_.bvh);
  upload(boundary_, gpu_.boundaryFaces);
  builtRevision_ = meshRevision_;
  ++meshUploads_;
  gl::check("GpuVolume::uploadMesh");
}

// Only the values travel: 16 B per node (position and value share a vec4) or 4 B per tet.
void GpuVolume::uploadValues() {
  if (grid_.has()) uploadGrid();
  else if (location_ == FieldLocation::Node) upload(nodes_, gpu_.nodes);
  else upload(cellValues_, gpu_.cellValues);
  ++valueUploads_;
}

// The grid's values go up as textures (GridTexture); a second upload of the same grid is
// a value upload.
void GpuVolume::uploadGrid() {
  const bool sameGrid = grid_.bricks().count() > 0 && builtRevision_ == meshRevision_;
  grid_.upload();
  if (sameGrid) ++valueUploads_;
  gl::check("GpuVolume::uploadGrid");
}

std::vector<std::size_t> GpuVolume::gridBricksInOrder(const RenderContext& ctx, bool backToFront) const {
  return grid_.inOrder(ctx, backToFront);
}

std::pair<glm::vec2, glm::vec2> GpuVolume::gridBrickOnScreen(const RenderContext& ctx, std::size_t b) const {
  return grid_.brickOnScreen(ctx, b, imageViewProjection(ctx), gpu_.origin);
}

void GpuVolume::bindGridBrick(GLuint program, std::size_t b) { grid_.bind(program, binding::kGrid, b); }

void GpuVolume::ensureImage(int width, int height) {
  if (image_ && width == imageWidth_ && height == imageHeight_) return;
  image_ = texture2D(GL_RGBA32F, width, height);
  setFilter(image_.id(), GL_NEAREST);
  imageWidth_ = width;
  imageHeight_ = height;
}

GLuint GpuVolume::program(const std::vector<std::string>& stageFiles) {
  const int mode = tf2d_ && grid_.has() ? kTransferFunction2DMode : modeIndex(mode_);
  std::string key = std::to_string(mode);
  for (const std::string& f : stageFiles) key += " " + f;
  gl::Program& p = programs_[key];
  if (!p)
    p = gl::buildProgram(stageFiles, volumeLimitDefines() + binding::glslDefines() + "#define INTEGRATION_MODE " +
                                         std::to_string(mode) + "\n");
  return p.id();
}

void GpuVolume::setSegmentUniforms(GLuint p, const RenderContext& ctx) const {
  const glm::dmat4 vp = ctx.camera.projectionMatrix(ctx.aspect()) * ctx.camera.viewMatrix(gpu_.origin);
  const glm::mat4 inv(glm::inverse(vp));
  const glm::vec3 eye(ctx.camera.eye() - gpu_.origin);
  const auto u = [&](const char* n) { return glGetUniformLocation(p, n); };
  glProgramUniformMatrix4fv(p, u("inverseViewProjection"), 1, GL_FALSE, glm::value_ptr(inv));
  glProgramUniform3fv(p, u("eye"), 1, glm::value_ptr(eye));
  glProgramUniform1i(p, u("orthographic"), ctx.camera.projection() == Camera::Projection::Orthographic);
  glProgramUniform2i(p, u("imageSize_"), ctx.width, ctx.height);
  glProgramUniform1i(p, u("cellField"), location_ == FieldLocation::Cell);
  glProgramUniform1i(p, u("skipsHiddenTets"), skipsHiddenTets());
  const double meanEdge = gpu_.maxEdge * 0.5;
  glProgramUniform1f(p, u("samplingStep"), float(samplingStep_ > 0.0 ? samplingStep_ : 0.25 * meanEdge));
  glProgramUniform1f(p, u("terminationTransmittance"), float(termination_));
  tables_.setUniforms(p, gpu_);
  std::vector<glm::vec4> planes;
  for (const ClipPlane& c : clipPlanes_) {
    const glm::dvec3 n = unitNormal(c);
    planes.push_back(glm::vec4(glm::vec3(n), float(-glm::dot(n, c.point - gpu_.origin))));
  }
  std::vector<float> isoValues;
  std::vector<glm::vec4> isoColors;
  for (const optics::IsoSurface& iso : isoSurfaces_) {
    isoValues.push_back(gpu_.gpuValue(iso.value));
    isoColors.push_back(glm::vec4(glm::vec3(iso.color), float(iso.opacity)));
  }
  glProgramUniform1i(p, u("isoCount"), int(isoValues.size()));
  if (!isoValues.empty()) {
    glProgramUniform1fv(p, u("isoValue"), GLsizei(isoValues.size()), isoValues.data());
    glProgramUniform4fv(p, u("isoColor"), GLsizei(isoColors.size()), glm::value_ptr(isoColors[0]));
  }
  glProgramUniform1i(p, u("clipCount"), int(planes.size()));
  if (!planes.empty()) glProgramUniform4fv(p, u("clipPlanes"), GLsizei(planes.size()), glm::value_ptr(planes[0]));
  glProgramUniform1i(p, u("hasSceneDepth"), ctx.depthTexture != 0);
  glProgramUniform1i(p, u("shading"), shading_ && grid_.has());
  if (tf2d_) {
    // In the values' frame: gpuValue scales the values, and so their gradient.
    glProgramUniform1f(p, u("tf2dValueLow"), gpu_.gpuValue(tf2d_->valueLow()));
    glProgramUniform1f(p, u("tf2dValueHigh"), gpu_.gpuValue(tf2d_->valueHigh()));
    glProgramUniform1f(p, u("tf2dGradientHigh"), float(tf2d_->gradientHigh() * gpu_.valueScale));
  }
  if (grid_.has()) {
    const RegularGrid& grid = grid_.grid();
    const glm::dmat3 toIndex = glm::inverse(grid.indexToWorld());
    glm::mat4 worldToIndex{glm::mat3(toIndex)};
    worldToIndex[3] = glm::vec4(glm::vec3(toIndex * (gpu_.origin - grid.origin)), 1.0f);
    glProgramUniformMatrix4fv(p, u("worldToIndex"), 1, GL_FALSE, glm::value_ptr(worldToIndex));
    glProgramUniform3i(p, u("gridSize"), GLint(grid.dims[0]), GLint(grid.dims[1]), GLint(grid.dims[2]));
    // The whole grid as one brick until bindGridBrick says which.
    glProgramUniform3i(p, u("brickFirst"), 0, 0, 0);
    glProgramUniform3i(p, u("brickPoints"), GLint(grid.dims[0]), GLint(grid.dims[1]), GLint(grid.dims[2]));
    glProgramUniform2f(p, u("texelToValue"), grid_.texels().scale, grid_.texels().offset);
  }
}

void GpuVolume::beginDrawingIntoImage(gl::Framebuffer& framebuffer, GLuint& attachedImage, GLuint image,
                                      const RenderContext& ctx, bool clear) {
  if (attachedImage != image) {
    glNamedFramebufferTexture(framebuffer.id(), GL_COLOR_ATTACHMENT0, image, 0);
    attachedImage = image;
  }
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.id());
  glViewport(0, 0, ctx.width, ctx.height);
  if (clear) {
    const float transparent[4] = {0, 0, 0, 0};
    glClearNamedFramebufferfv(framebuffer.id(), GL_COLOR, 0, transparent);
  }
}

glm::mat4 GpuVolume::imageViewProjection(const RenderContext& ctx) const {
  const glm::dmat4 flip(glm::dvec4(1, 0, 0, 0), glm::dvec4(0, -1, 0, 0), glm::dvec4(0, 0, 1, 0), glm::dvec4(0, 0, 0, 1));
  return glm::mat4(flip * ctx.camera.projectionMatrix(ctx.aspect()) * ctx.camera.viewMatrix(gpu_.origin));
}

void GpuVolume::bindSegmentResources(const RenderContext& ctx) const {
  glBindTextureUnit(binding::kSceneDepth, ctx.depthTexture);
  tables_.bind();
  glBindTextureUnit(binding::kGrid, 0);  // bindGridBrick binds each brick's
  const std::pair<GLuint, const gl::Buffer*> buffers[] = {
      {binding::kNodes, &nodes_},           {binding::kTets, &tets_}, {binding::kNeighbors, &neighbors_},
      {binding::kCellValues, &cellValues_}, {binding::kBvh, &bvh_},   {binding::kBoundaryFaces, &boundary_}};
  for (const auto& [index, buffer] : buffers) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, index, buffer->id());
  if (skipsHiddenTets()) visible_.bind();
}

void GpuVolume::compositeOver(const RenderContext& ctx, GLuint image) const {
  glBindTextureUnit(binding::kSceneDepth, 0);  // the depth texture may be attached to the target: no feedback
  glBindTextureUnit(binding::kGrid, 0);
  composite_.draw(ctx, image);
}

VolumeStats GpuVolume::stats() const {
  VolumeStats s;
  s.tetrahedra = gpu_.tetCount;
  s.meshBytes = gpu_.bytes() + grid_.residentBytes();
  s.gpuBytes = s.meshBytes + visible_.bytes() + tables_.bytes() + std::size_t(imageWidth_) * imageHeight_ * 16;
  s.lastTransferFunctionMs = tables_.lastChangeMs();
  s.meshUploads = meshUploads_;
  s.valueUploads = valueUploads_;
  s.tableBuilds = tables_.builds();
  return s;
}

std::vector<float> GpuVolume::readImage() const {
  std::vector<float> pixels(std::size_t(imageWidth_) * std::size_t(imageHeight_) * 4);
  if (!image_) return pixels;
  glGetTextureImage(image_.id(), 0, GL_RGBA, GL_FLOAT, GLsizei(pixels.size() * sizeof(float)), pixels.data());
  return pixels;  // row 0 is the top already (the shaders write y from the top)
}

}  // namespace volpost::volume

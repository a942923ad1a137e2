// SPDX-License-Identifier: MIT
#include "RayCaster.hpp"

#include <volpost/core/optics/IsoTables.hpp>
#include <volpost/core/optics/PreintegrationTable.hpp>
#include <volpost/core/optics/PsiTable.hpp>
#include <volpost/render/ShaderLibrary.hpp>

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>

namespace volpost {

const char* toString(IntegrationMode mode) {
  switch (mode) {
    case IntegrationMode::LinearSegments: return "linear-segments";
    case IntegrationMode::PreIntegrated: return "pre-integrated";
    case IntegrationMode::Sampling: return "sampling";
    case IntegrationMode::LinearSegmentsIsoTable: return "linear-segments-iso-table";
  }
  return "?";
}

namespace volume {
namespace {

template <typename T>
void upload(gl::Buffer& buffer, const std::vector<T>& data) {
  if (!buffer) buffer = gl::createBuffer();
  // Zero-size SSBOs cannot be bound: keep one element.
  const std::size_t bytes = std::max<std::size_t>(data.size() * sizeof(T), 16);
  glNamedBufferData(buffer.id(), GLsizeiptr(bytes), nullptr, GL_STATIC_DRAW);
  if (!data.empty()) glNamedBufferSubData(buffer.id(), 0, GLsizeiptr(data.size() * sizeof(T)), data.data());
}

gl::Texture texture2D(GLenum format, int w, int h) {
  gl::Texture t = gl::createTexture(GL_TEXTURE_2D);
  glTextureStorage2D(t.id(), 1, format, w, h);
  glTextureParameteri(t.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(t.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return t;
}

void setFilter(GLuint tex, GLint filter) {
  glTextureParameteri(tex, GL_TEXTURE_MIN_FILTER, filter);
  glTextureParameteri(tex, GL_TEXTURE_MAG_FILTER, filter);
}

}  // namespace

void RayCaster::initialize() {
  compositeProgram_ = gl::buildProgram({"overlay.vert", "overlay.frag"});
  quad_ = gl::createVertexArray();
  const optics::PsiTable psi(psiResolution);
  psiTable_ = texture2D(GL_R32F, psiResolution, psiResolution);
  setFilter(psiTable_.id(), GL_LINEAR);
  glTextureSubImage2D(psiTable_.id(), 0, 0, 0, psiResolution, psiResolution, GL_RED, GL_FLOAT, psi.values().data());
  initialized_ = true;
  if (mesh_) uploadMesh();
  rebuildTables();
  gl::check("RayCaster::initialize");
}

void RayCaster::release() {
  if (preFuture_.valid()) preFuture_.wait();
  preFuture_ = {};
  preOutdated_ = false;
  for (gl::Buffer* b : {&nodes_, &tets_, &neighbors_, &cellValues_, &bvh_, &boundary_, &tfColorTau_, &tfValues_}) b->reset();
  for (gl::Texture* t : {&psiTable_, &isoTable_, &preTable_, &image_}) t->reset();
  for (gl::Program& program : programs_) program.reset();
  compositeProgram_.reset();
  quad_.reset();
  imageWidth_ = imageHeight_ = 0;
  initialized_ = false;
}

void RayCaster::setVolume(const Mesh& mesh, FieldLocation location, std::span<const double> values) {
  gpu_ = buildTetMeshGpu(mesh, location, values);
  mesh_ = &mesh;
  location_ = location;
  if (initialized_) {
    uploadMesh();
    rebuildTables();  // table ranges follow the values
  }
}

void RayCaster::setValues(std::span<const double> values) {
  if (!mesh_) return;
  if (!replaceValues(gpu_, *mesh_, location_, values)) {
    setVolume(*mesh_, location_, values);  // the set of renderable tets changed
    return;
  }
  if (initialized_) {  // only the values travel: 16 B per node (position and value share a vec4) or 4 B per tet
    if (location_ == FieldLocation::Node) upload(nodes_, gpu_.nodes);
    else upload(cellValues_, gpu_.cellValues);
    rebuildTables();
  }
}

void RayCaster::uploadMesh() {
  upload(nodes_, gpu_.nodes);
  upload(tets_, gpu_.tets);
  upload(neighbors_, gpu_.neighbors);
  upload(cellValues_, gpu_.cellValues);
  upload(bvh_, gpu_.bvh);
  upload(boundary_, gpu_.boundaryFaces);
  gl::check("RayCaster::uploadMesh");
}

void RayCaster::setTransferFunction(const TransferFunction& tf) {
  tf_ = tf;
  if (initialized_) rebuildTables();
}

void RayCaster::setClipPlanes(const std::vector<ClipPlane>& planes) {
  clipPlanes_ = planes;
  if (clipPlanes_.size() > 6) clipPlanes_.resize(6);
}

void RayCaster::setIsoSurfaces(const std::vector<optics::IsoSurface>& surfaces) {
  isoSurfaces_ = surfaces;
  if (isoSurfaces_.size() > 8) isoSurfaces_.resize(8);
}

void RayCaster::setIntegrationMode(IntegrationMode mode) {
  mode_ = mode;
  if (initialized_) rebuildTables();
}

// What a TF edit costs: the control points, the iso-detection table and (in that mode)
// the pre-integration table. The mesh is not touched.
void RayCaster::rebuildTables() {
  const auto start = std::chrono::steady_clock::now();
  std::vector<glm::vec4> colorTau;
  std::vector<float> values;
  for (const ControlPoint& p : tf_.points()) {
    colorTau.push_back(glm::vec4(glm::vec3(p.color), float(p.extinction)));
    values.push_back(gpu_.gpuValue(p.value));
  }
  upload(tfColorTau_, colorTau);
  upload(tfValues_, values);
  // Table ranges follow the values (their range is kept with the GPU structure).
  tableLo_ = std::min(gpu_.valueMin, tf_.empty() ? gpu_.valueMin : tf_.minValue());
  tableHi_ = std::max(gpu_.valueMax, tf_.empty() ? gpu_.valueMax : tf_.maxValue());
  if (!(tableHi_ > tableLo_)) tableHi_ = tableLo_ + 1.0;
  const optics::IsoDetectionTable iso(tf_, tableLo_, tableHi_, isoResolution);
  if (!isoTable_) {
    isoTable_ = texture2D(GL_RG32F, isoResolution, isoResolution);
    setFilter(isoTable_.id(), GL_NEAREST);
  }
  glTextureSubImage2D(isoTable_.id(), 0, 0, 0, isoResolution, isoResolution, GL_RG, GL_FLOAT, iso.values.data());
  if (mode_ == IntegrationMode::PreIntegrated && !tf_.empty()) {
    if (preFuture_.valid()) preOutdated_ = true;  // the running build finishes, then the latest TF goes
    else launchPreintegration();
    if (!asynchronous_) collectPreintegration(true);
  }
  glFinish();
  if (!preFuture_.valid())
    lastTfMs_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  tfChanged_ = start;
  gl::check("RayCaster::rebuildTables");
}

// The pre-integrated table (seconds at 128^3) is computed off the GL thread from a copy of
// the TF and the table's range.
void RayCaster::launchPreintegration() {
  preMaxLength_ = std::max(gpu_.maxEdge, 1e-30);
  preFuture_ = std::async(std::launch::async, [tf = tf_, lo = tableLo_, hi = tableHi_, length = preMaxLength_,
                                               n = preResolution] {
    return optics::PreintegrationTable(tf, lo, hi, n, length, n).values();
  });
}

void RayCaster::collectPreintegration(bool wait) {
  if (!preFuture_.valid()) return;
  if (!wait && preFuture_.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return;
  uploadPreintegration(preFuture_.get());
  if (preOutdated_) {
    preOutdated_ = false;
    launchPreintegration();
    if (wait) collectPreintegration(true);
    return;
  }
  lastTfMs_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - tfChanged_).count();
}

void RayCaster::uploadPreintegration(const std::vector<float>& values) {
  if (!preTable_) {
    preTable_ = gl::createTexture(GL_TEXTURE_3D);
    glTextureStorage3D(preTable_.id(), 1, GL_RGBA32F, preResolution, preResolution, preResolution);
    setFilter(preTable_.id(), GL_LINEAR);
    for (GLenum w : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R})
      glTextureParameteri(preTable_.id(), w, GL_CLAMP_TO_EDGE);
  }
  glTextureSubImage3D(preTable_.id(), 0, 0, 0, 0, preResolution, preResolution, preResolution, GL_RGBA, GL_FLOAT,
                      values.data());
}

void RayCaster::ensureImage(int width, int height) {
  if (image_ && width == imageWidth_ && height == imageHeight_) return;
  image_ = texture2D(GL_RGBA32F, width, height);
  setFilter(image_.id(), GL_NEAREST);
  imageWidth_ = width;
  imageHeight_ = height;
}

void RayCaster::render(const RenderContext& ctx) {
  if (!initialized_ || gpu_.tets.empty() || ctx.width <= 0 || ctx.height <= 0) return;
  prepareFrame(ctx);
  const GLuint p = programForMode(programs_, {"raycast.comp"});
  glUseProgram(p);
  setSegmentUniforms(p, ctx);
  glProgramUniform1i(p, glGetUniformLocation(p, "maxSteps"), int(std::min<std::size_t>(gpu_.tets.size() + 16, 1u << 20)));
  bindSegmentResources(ctx);
  glBindImageTexture(0, image_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  glDispatchCompute(GLuint((ctx.width + 7) / 8), GLuint((ctx.height + 7) / 8), 1);
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
  glBindTextureUnit(3, 0);  // the depth texture may be attached to the target: no feedback
  compositeOver(ctx);
  gl::check("RayCaster::render");
}

GLuint RayCaster::programForMode(ModePrograms& programs, const std::vector<std::string>& stageFiles) const {
  const bool linear = mode_ == IntegrationMode::LinearSegments || mode_ == IntegrationMode::LinearSegmentsIsoTable;
  const int index = linear ? 0 : mode_ == IntegrationMode::PreIntegrated ? 1 : 2;
  gl::Program& program = programs[std::size_t(index)];
  if (!program) program = gl::buildProgram(stageFiles, "#define INTEGRATION_MODE " + std::to_string(index));
  return program.id();
}

void RayCaster::prepareFrame(const RenderContext& ctx) {
  // A table finished since the last frame goes up now; with none uploaded yet, wait.
  collectPreintegration(!asynchronous_ || (mode_ == IntegrationMode::PreIntegrated && !preTable_));
  ensureImage(ctx.width, ctx.height);
}

// The uniforms of common/tet_segment.glsl: camera, mode, tables' range, clip planes,
// iso-surfaces, scene depth. Shared by every program that integrates tet segments.
void RayCaster::setSegmentUniforms(GLuint p, const RenderContext& ctx) const {
  const glm::dmat4 vp = ctx.camera.projectionMatrix(ctx.aspect()) * ctx.camera.viewMatrix(gpu_.origin);
  const glm::mat4 inv(glm::inverse(vp));
  const glm::vec3 eye(ctx.camera.eye() - gpu_.origin);
  const auto u = [&](const char* n) { return glGetUniformLocation(p, n); };
  glProgramUniformMatrix4fv(p, u("inverseViewProjection"), 1, GL_FALSE, glm::value_ptr(inv));
  glProgramUniform3fv(p, u("eye"), 1, glm::value_ptr(eye));
  glProgramUniform1i(p, u("orthographic"), ctx.camera.projection() == Camera::Projection::Orthographic);
  glProgramUniform2i(p, u("imageSize_"), ctx.width, ctx.height);
  glProgramUniform1i(p, u("cellField"), location_ == FieldLocation::Cell);
  glProgramUniform1i(p, u("exactCuts"), mode_ == IntegrationMode::LinearSegments);
  const double meanEdge = gpu_.maxEdge * 0.5;
  glProgramUniform1f(p, u("samplingStep"), float(samplingStep_ > 0.0 ? samplingStep_ : 0.25 * meanEdge));
  glProgramUniform1f(p, u("terminationTransmittance"), float(termination_));
  glProgramUniform1i(p, u("tfCount"), int(tf_.points().size()));
  glProgramUniform1f(p, u("sLo"), gpu_.gpuValue(tableLo_));
  glProgramUniform1f(p, u("sHi"), gpu_.gpuValue(tableHi_));
  glProgramUniform1f(p, u("preMaxLength"), float(preMaxLength_));
  std::vector<glm::vec4> planes;
  for (const ClipPlane& c : clipPlanes_) {
    const glm::dvec3 n = glm::normalize(c.normal);
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
  glProgramUniform1i(p, u("sceneDepth"), 3);
  glProgramUniform1i(p, u("psiTable"), 0);
  glProgramUniform1i(p, u("isoTable"), 1);
  glProgramUniform1i(p, u("preTable"), 2);
}

void RayCaster::bindSegmentResources(const RenderContext& ctx) const {
  glBindTextureUnit(3, ctx.depthTexture);
  glBindTextureUnit(0, psiTable_.id());
  glBindTextureUnit(1, isoTable_.id());
  glBindTextureUnit(2, preTable_ ? preTable_.id() : 0);
  const gl::Buffer* buffers[] = {&nodes_, &tets_, &neighbors_, &cellValues_, &bvh_, &boundary_, &tfColorTau_, &tfValues_};
  for (GLuint i = 0; i < 8; ++i) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, i, buffers[i]->id());
}

// Composites the premultiplied float image over what the target already holds.
void RayCaster::compositeOver(const RenderContext& ctx) const {
  glBindFramebuffer(GL_FRAMEBUFFER, ctx.framebuffer);
  glViewport(0, 0, ctx.width, ctx.height);
  glUseProgram(compositeProgram_.id());
  glProgramUniform1i(compositeProgram_.id(), glGetUniformLocation(compositeProgram_.id(), "image"), 0);
  glBindTextureUnit(0, image_.id());
  glBindVertexArray(quad_.id());
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
  glDisable(GL_BLEND);
  glBindVertexArray(0);
  glUseProgram(0);
}

VolumeStats RayCaster::stats() const {
  VolumeStats s;
  s.tetrahedra = gpu_.tets.size();
  s.meshBytes = gpu_.bytes();
  s.gpuBytes = gpu_.bytes() + tf_.points().size() * 20 + std::size_t(psiResolution) * psiResolution * 4 +
               std::size_t(isoResolution) * isoResolution * 8 +
               (preTable_ ? std::size_t(preResolution) * preResolution * preResolution * 16 : 0) +
               std::size_t(imageWidth_) * imageHeight_ * 16;
  s.lastTransferFunctionMs = lastTfMs_;
  return s;
}

std::vector<float> RayCaster::readImage() const {
  std::vector<float> pixels(std::size_t(imageWidth_) * std::size_t(imageHeight_) * 4);
  if (!image_) return pixels;
  glGetTextureImage(image_.id(), 0, GL_RGBA, GL_FLOAT, GLsizei(pixels.size() * sizeof(float)), pixels.data());
  // The compute shader wrote row 0 at the top of the image already (y from the top).
  return pixels;
}

}  // namespace volume
}  // namespace volpost

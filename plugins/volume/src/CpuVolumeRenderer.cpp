// SPDX-License-Identifier: MIT
#include "CpuVolumeRenderer.hpp"

#include "VolumeBindings.hpp"
#include "VolumeShaders.hpp"

#include <volpost/render/ShaderLibrary.hpp>

#include <cmath>
#include <stdexcept>
#include <string>

namespace volpost::volume {

void CpuVolumeRenderer::initialize() {
  registerVolumeShaders();
  composite_ = gl::buildProgram({"volume/composite.vert", "volume/composite.frag"}, binding::glslDefines());
  quad_ = gl::createVertexArray();
  textureWidth_ = textureHeight_ = 0;
  meshUploads_ = valueUploads_ = 0;
}

void CpuVolumeRenderer::release() {
  texture_.reset();
  composite_.reset();
  quad_.reset();
  textureWidth_ = textureHeight_ = 0;
}

void CpuVolumeRenderer::setVolume(const Mesh& mesh, FieldLocation location, std::span<const double> values) {
  walkMesh_ = std::make_unique<TetWalkMesh>(mesh, location, values);  // throws before anything changes
  mesh_ = &mesh;
  location_ = location;
  ++meshUploads_;
}

void CpuVolumeRenderer::setValues(std::span<const double> values) {
  if (!mesh_) throw std::logic_error("CpuVolumeRenderer::setValues before setVolume");
  walkMesh_ = std::make_unique<TetWalkMesh>(*mesh_, location_, values);
  ++valueUploads_;
}

void CpuVolumeRenderer::setClipPlanes(const std::vector<ClipPlane>& planes) {
  if (planes.size() > std::size_t(kMaxClipPlanes))
    throw std::invalid_argument(std::to_string(planes.size()) + " clip planes: a volume takes at most " +
                                std::to_string(kMaxClipPlanes));
  settings_.clipPlanes = planes;
}

void CpuVolumeRenderer::setIsoSurfaces(const std::vector<optics::IsoSurface>& surfaces) {
  if (surfaces.size() > std::size_t(kMaxIsoSurfaces))
    throw std::invalid_argument(std::to_string(surfaces.size()) + " iso-surfaces: a volume takes at most " +
                                std::to_string(kMaxIsoSurfaces));
  for (const optics::IsoSurface& s : surfaces)
    if (!std::isfinite(s.value) || !(s.opacity >= 0.0 && s.opacity <= 1.0))
      throw std::invalid_argument("an iso-surface needs a finite value and an opacity in 0..1");
  settings_.isoSurfaces = surfaces;
}

void CpuVolumeRenderer::setTerminationThreshold(double transmittance) {
  if (!(transmittance >= 0.0 && transmittance < 1.0))
    throw std::invalid_argument("the early-termination transmittance must lie in [0, 1), not " + std::to_string(transmittance));
  settings_.terminationTransmittance = transmittance;
}

void CpuVolumeRenderer::render(const RenderContext& ctx) {
  if (!walkMesh_ || ctx.width <= 0 || ctx.height <= 0) return;
  settings_.sceneDepth.clear();
  if (ctx.depthTexture) {  // rays end at the opaque geometry already drawn
    settings_.sceneDepth.resize(std::size_t(ctx.width) * std::size_t(ctx.height));
    glGetTextureImage(ctx.depthTexture, 0, GL_DEPTH_COMPONENT, GL_FLOAT,
                      GLsizei(settings_.sceneDepth.size() * sizeof(float)), settings_.sceneDepth.data());
  }
  image_ = renderCpu(*walkMesh_, tf_, ctx.camera, ctx.width, ctx.height, settings_, {}, threads_);
  if (!texture_ || textureWidth_ != ctx.width || textureHeight_ != ctx.height) {
    texture_ = gl::createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(texture_.id(), 1, GL_RGBA32F, ctx.width, ctx.height);
    glTextureParameteri(texture_.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(texture_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    textureWidth_ = ctx.width;
    textureHeight_ = ctx.height;
  }
  glTextureSubImage2D(texture_.id(), 0, 0, 0, ctx.width, ctx.height, GL_RGBA, GL_FLOAT, image_.rgba.data());
  // Blended over the target as the GPU renderers do (the image's first row is the top).
  glBindFramebuffer(GL_FRAMEBUFFER, ctx.framebuffer);
  glViewport(0, 0, ctx.width, ctx.height);
  glUseProgram(composite_.id());
  glBindTextureUnit(binding::kImage, texture_.id());
  glBindVertexArray(quad_.id());
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
  glDisable(GL_BLEND);
  glEnable(GL_DEPTH_TEST);
  glBindVertexArray(0);
  glUseProgram(0);
}

VolumeStats CpuVolumeRenderer::stats() const {
  VolumeStats s;
  s.tetrahedra = walkMesh_ ? walkMesh_->tetCount() : 0;
  s.gpuBytes = std::size_t(textureWidth_) * std::size_t(textureHeight_) * 16;  // the image only: the mesh stays in host memory
  s.meshBytes = 0;
  s.meshUploads = meshUploads_;
  s.valueUploads = valueUploads_;
  return s;
}

}  // namespace volpost::volume

// SPDX-License-Identifier: MIT
#include "TransferFunctionTables.hpp"

#include "GpuLimits.hpp"
#include "PiecewiseIntegrator.hpp"
#include "StorageUpload.hpp"
#include "VolumeBindings.hpp"
#include "VolumeTextures.hpp"

#include <volpost/core/optics/IsoTables.hpp>
#include <volpost/core/optics/OpticalDepth.hpp>
#include <volpost/core/optics/PreintegrationTable.hpp>
#include <volpost/core/optics/PsiTable.hpp>
#include <volpost/core/optics/TableWarp.hpp>
#include <volpost/core/optics/ThickPsi.hpp>

#include <glm/vec4.hpp>

#include <algorithm>
#include <tuple>

namespace volpost::volume {
namespace {

// The shaders compute in float: extinctions go there capped (kMaxFloatExtinction).
double gpuExtinction(double extinction) { return std::min(extinction, kMaxFloatExtinction); }

// The running integrals of the extinction matter between control points inside the values'
// range only (0..1 on the GPU); points far outside it (a function spanning 1e30 times the
// field's range) are moved in to here, so the integrals inside stay small and finite.
constexpr double kIntegralValueMargin = 1.0;

}  // namespace

void TransferFunctionTables::initialize() {
  const optics::PsiTable psi(psiResolution);
  psiTable_ = texture2D(GL_R32F, psiResolution, psiResolution);
  setFilter(psiTable_.id(), GL_LINEAR);
  glTextureSubImage2D(psiTable_.id(), 0, 0, 0, psiResolution, psiResolution, GL_RED, GL_FLOAT, psi.values().data());
  const optics::ThickPsiTable thick(thickPsiResolution);
  thickPsiTable_ = gl::createTexture(GL_TEXTURE_1D);
  glTextureStorage1D(thickPsiTable_.id(), 1, GL_RG32F, thickPsiResolution);
  setFilter(thickPsiTable_.id(), GL_NEAREST);  // read with texelFetch, interpolated in the shader
  glTextureSubImage1D(thickPsiTable_.id(), 0, 0, thickPsiResolution, GL_RG, GL_FLOAT, thick.values().data());
  builds_ = 0;
}

void TransferFunctionTables::release() {
  if (future_.valid()) future_.wait();
  future_ = {};
  outdated_ = false;
  for (gl::Buffer* b : {&colorTau_, &values_, &knots_}) b->reset();
  for (gl::Texture* t : {&psiTable_, &thickPsiTable_, &isoTable_, &preTable_, &table2D_}) t->reset();
}

// A function reaching far beyond the field (a preset over a fixed range, a point at -1e30)
// would otherwise leave the field's values a few texels (0.018 off).
std::pair<double, double> TransferFunctionTables::rangeFor(const TetMeshGpu& mesh) {
  const double lo = mesh.valueMin, hi = mesh.valueMax;
  return {lo, hi > lo ? hi : lo + 1.0};
}

bool TransferFunctionTables::rebuild(const TransferFunction& tf, IntegrationMode mode, const TetMeshGpu& mesh,
                                     bool asynchronous) {
  const auto start = std::chrono::steady_clock::now();
  tf_ = tf;
  std::vector<glm::vec4> colorTau;
  std::vector<float> values;
  for (const ControlPoint& p : tf_.points()) {
    colorTau.push_back(glm::vec4(glm::vec3(p.color), float(gpuExtinction(p.extinction))));
    values.push_back(mesh.gpuValue(p.value));
  }
  upload(colorTau_, colorTau);
  upload(values_, values);
  std::tie(lo_, hi_) = rangeFor(mesh);
  uploadKnots(values);  // after the range: the table coordinates span it
  if (mode == IntegrationMode::LinearSegmentsIsoTable) {
    const optics::IsoDetectionTable iso(tf_, lo_, hi_, isoResolution);
    if (!isoTable_) {
      isoTable_ = texture2D(GL_RG32F, isoResolution, isoResolution);
      setFilter(isoTable_.id(), GL_NEAREST);
    }
    glTextureSubImage2D(isoTable_.id(), 0, 0, 0, isoResolution, isoResolution, GL_RG, GL_FLOAT, iso.values.data());
  }
  bool uploaded = false;
  if (mode == IntegrationMode::PreIntegrated && !tf_.empty()) {
    if (future_.valid()) outdated_ = true;  // the running build finishes, then the latest function goes
    else launchPreintegration();
    if (!asynchronous) uploaded = collect(true);
  }
  glFinish();  // the cost reported is the whole change, upload included
  if (!future_.valid())
    lastMs_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  changed_ = start;
  ++builds_;
  gl::check("TransferFunctionTables::rebuild");
  return uploaded;
}

// The pre-integrated table (0.04 s at 256^2 x 9 for a function of ten pieces, 0.4 s for
// 255) is computed off the GL thread from a copy of the function and the table's range.
void TransferFunctionTables::launchPreintegration() {
  future_ =
      std::async(std::launch::async, [tf = tf_, lo = lo_, hi = hi_, n = preResolution, depths = preDepthResolution] {
        return PreintegrationBuild{optics::PreintegrationTable(tf, lo, hi, n, depths).values()};
      });
}

// Per control point: where it lies in the pre-integration table (optics::TableWarp, the
// table's own), the extinction's running integral over the values as the GPU holds them
// (gpuValue) in double split into two floats (the shader's difference of two of them keeps
// double accuracy), and up to which value the extinction stays zero from inside the piece
// that starts there (-inf where it does not: PiecewiseIntegrator's empty-space test).
void TransferFunctionTables::uploadKnots(const std::vector<float>& gpuValues) {
  const optics::TableWarp warp(tf_, lo_, hi_, preResolution);
  const std::size_t n = gpuValues.size();
  std::vector<double> values, taus, integralValues;
  for (std::size_t i = 0; i < n; ++i) {
    values.push_back(gpuValues[i]);
    taus.push_back(gpuExtinction(tf_.points()[i].extinction));
    integralValues.push_back(std::clamp(values.back(), -kIntegralValueMargin, 1.0 + kIntegralValueMargin));
  }
  const std::vector<double> zeroUntil = zeroExtinctionRuns(values, taus);  // in the GPU's frame
  zeroBelow_ = float(zeroUntil[0]);
  // gpuValue rounds to float: equal values stay equal, the order stays.
  const optics::OpticalDepth depth(std::move(integralValues), std::move(taus));
  std::vector<glm::vec4> knots;
  for (std::size_t i = 0; i < n; ++i) {
    const double integral = depth.runningIntegrals()[i];
    const float high = float(integral);
    knots.push_back(glm::vec4(float(warp.toTable(std::clamp(tf_.points()[i].value, lo_, hi_))), high,
                              float(integral - double(high)), float(zeroUntil[i + 1])));
  }
  upload(knots_, knots);
}

bool TransferFunctionTables::collect(bool wait) {
  if (!future_.valid()) return false;
  if (!wait && future_.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return false;
  uploadPreintegration(future_.get());
  if (outdated_) {
    outdated_ = false;
    launchPreintegration();
    if (wait) collect(true);
    return true;
  }
  lastMs_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - changed_).count();
  return true;
}

void TransferFunctionTables::uploadPreintegration(const PreintegrationBuild& build) {
  if (!preTable_) {
    preTable_ = gl::createTexture(GL_TEXTURE_3D);
    glTextureStorage3D(preTable_.id(), 1, GL_RGB32F, preResolution, preResolution, preDepthResolution);
    setFilter(preTable_.id(), GL_LINEAR);
    for (GLenum w : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R})
      glTextureParameteri(preTable_.id(), w, GL_CLAMP_TO_EDGE);
  }
  glTextureSubImage3D(preTable_.id(), 0, 0, 0, 0, preResolution, preResolution, preDepthResolution, GL_RGB, GL_FLOAT,
                      build.values.data());
}

// The 2D transfer function's nodes, interpolated bilinearly by the texture unit as
// TransferFunction2D::evaluate does (emission and extinction, the color their quotient).
void TransferFunctionTables::upload2D(const std::optional<TransferFunction2D>& tf) {
  if (!tf) {
    table2D_.reset();
    return;
  }
  if (!table2D_) {
    table2D_ = texture2D(GL_RGBA32F, TransferFunction2D::kValueNodes, TransferFunction2D::kGradientNodes);
    setFilter(table2D_.id(), GL_LINEAR);
  }
  glTextureSubImage2D(table2D_.id(), 0, 0, 0, TransferFunction2D::kValueNodes, TransferFunction2D::kGradientNodes,
                      GL_RGBA, GL_FLOAT, tf->table().data());
  ++builds_;
  gl::check("TransferFunctionTables::upload2D");
}

void TransferFunctionTables::bind() const {
  glBindTextureUnit(binding::kPsiTable, psiTable_.id());
  glBindTextureUnit(binding::kThickPsi, thickPsiTable_.id());
  glBindTextureUnit(binding::kIsoTable, isoTable_ ? isoTable_.id() : 0);
  glBindTextureUnit(binding::kPreTable, preTable_ ? preTable_.id() : 0);
  glBindTextureUnit(binding::kTf2d, table2D_ ? table2D_.id() : 0);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kTfColorTau, colorTau_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kTfValues, values_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kTfKnots, knots_.id());
}

void TransferFunctionTables::setUniforms(GLuint p, const TetMeshGpu& mesh) const {
  const auto u = [&](const char* n) { return glGetUniformLocation(p, n); };
  glProgramUniform1i(p, u("tfCount"), int(tf_.points().size()));
  glProgramUniform1f(p, u("tfZeroBelow"), zeroBelow_);
  glProgramUniform1f(p, u("sLo"), mesh.gpuValue(lo_));
  glProgramUniform1f(p, u("sHi"), mesh.gpuValue(hi_));
  glProgramUniform1f(p, u("preMaxDepth"), float(optics::PreintegrationTable::kMaxDepth));
}

std::size_t TransferFunctionTables::bytes() const {
  return tf_.points().size() * 20 + std::size_t(psiResolution) * psiResolution * 4 +
         (isoTable_ ? std::size_t(isoResolution) * isoResolution * 8 : 0) +
         (preTable_ ? std::size_t(preResolution) * preResolution * preDepthResolution * 12 + tf_.points().size() * 16
                    : 0);
}

}  // namespace volpost::volume

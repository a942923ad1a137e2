// SPDX-License-Identifier: MIT
// The transfer function as the volume shaders read it: its control points (color and
// extinction, values in the GPU's frame, the knots of the exact opacity and the
// zero-extinction runs of the empty-space test) and each mode's tables (psi and thick psi
// for the exact cuts, the iso-detection table, the pre-integration table built off the GL
// thread, the 2D function's nodes). GpuVolume keeps the state and says when to rebuild;
// this holds what the GPU has of it. Every call but the resolutions needs a current context.
#pragma once

#include "TetMeshGpu.hpp"

#include <volpost/core/TransferFunction.hpp>
#include <volpost/core/TransferFunction2D.hpp>
#include <volpost/render/GlObjects.hpp>
#include <volpost/render/IntegrationMode.hpp>

#include <chrono>
#include <cstddef>
#include <future>
#include <optional>
#include <vector>

namespace volpost::volume {

class TransferFunctionTables {
 public:
  /// Texture sizes (set before initialize): psi table N^2, iso table N^2, pre-integration
  /// N^2 values x preDepthResolution depths.
  int psiResolution = 512, thickPsiResolution = 1024, isoResolution = 256, preResolution = 256, preDepthResolution = 9;

  /// The psi tables, which depend on nothing; the counts start again.
  void initialize();
  /// Frees everything (waiting for a table being built).
  void release();

  /// The value range the tables span for `mesh`'s values: the values' own, not the
  /// function's (no value outside it is ever looked up).
  static std::pair<double, double> rangeFor(const TetMeshGpu& mesh);
  /// True when the last build spans the range `mesh`'s values need.
  bool spanTheRangeOf(const TetMeshGpu& mesh) const { return rangeFor(mesh) == std::pair(lo_, hi_); }
  /// What a transfer-function edit costs: the control points and the table `mode` uses. A
  /// pre-integration table is built on a worker thread; `asynchronous` false waits for it.
  /// True when a pre-integration table went up (frames drawn before are outdated).
  bool rebuild(const TransferFunction& tf, IntegrationMode mode, const TetMeshGpu& mesh, bool asynchronous);
  /// Uploads a finished pre-integration table (waiting for it when `wait`); true when one
  /// went up, so frames drawn before are outdated.
  bool collect(bool wait);
  /// True while a pre-integration table is being built.
  bool pending() const { return future_.valid(); }
  bool hasPreintegrationTable() const { return bool(preTable_); }
  /// The 2D function's nodes (nullopt frees them).
  void upload2D(const std::optional<TransferFunction2D>& tf);

  /// Binds the tables and the control points' buffers at their binding points.
  void bind() const;
  /// tfCount, tfZeroBelow, sLo, sHi, preMaxDepth of common/volume_segment.glsl.
  void setUniforms(GLuint program, const TetMeshGpu& mesh) const;

  std::size_t bytes() const;
  double lastChangeMs() const { return lastMs_; }
  std::size_t builds() const { return builds_; }

 private:
  struct PreintegrationBuild {
    std::vector<float> values;  ///< the table's mean colors (optics::PreintegrationTable::values)
  };
  void launchPreintegration();
  void uploadPreintegration(const PreintegrationBuild& build);
  void uploadKnots(const std::vector<float>& gpuValues);

  TransferFunction tf_;  ///< the function the tables were built for
  double lo_ = 0.0, hi_ = 1.0;
  float zeroBelow_ = 0.0f;                   ///< the extinction is zero from below the first point up to this value
  std::future<PreintegrationBuild> future_;  ///< the pre-integration table being built
  bool outdated_ = false;                    ///< the function changed again while it was built
  std::chrono::steady_clock::time_point changed_;
  double lastMs_ = 0.0;
  std::size_t builds_ = 0;
  gl::Buffer colorTau_, values_, knots_;
  gl::Texture psiTable_, thickPsiTable_, isoTable_, preTable_, table2D_;
};

}  // namespace volpost::volume

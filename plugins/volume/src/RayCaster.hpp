// SPDX-License-Identifier: MIT
// GPU ray casting through tetrahedra (compute shader, one invocation per pixel): rays enter
// at boundary faces found in a BVH, walk tet to tet through face adjacency, integrate each
// segment, and the float image is composited over the target.
//
// A frame is a series of dispatches, each taking every unfinished ray a bounded number of
// tets further (raycast.comp keeps where each ray stopped): no single dispatch runs long
// enough for a GPU's watchdog, the shader's loops stay under drivers' iteration limits,
// and the window can slice a long frame. Where the device's storage blocks cannot hold a
// state per pixel, the frame goes in bands of rows. With asynchronous updates (the window), a changed view or scene first gets a
// quick frame at reduced resolution (sized from the measured cost per ray to take ~40 ms);
// the full-resolution frame then advances by dispatches of ~30 ms per render() call and is
// shown once complete (hasPendingWork() says to draw again meanwhile). It is the same
// image the synchronous path draws.
#pragma once

#include "QuickFrames.hpp"
#include "TetRayDispatch.hpp"
#include "TetVolumeRenderer.hpp"

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <cstdint>

namespace volpost::volume {

class RayCaster final : public TetVolumeRenderer {
 public:
  static constexpr int kStepsPerPass = TetRayDispatch::kStepsPerPass;

  std::string name() const override { return "raycast"; }
  VolumeRendererTraits traits() const override {
    VolumeRendererTraits t;
    t.label = "Ray casting";
    t.modes = allIntegrationModes();
    return t;
  }
  void initialize() override;
  void release() override;
  void render(const RenderContext& ctx) override;
  bool hasPendingWork() const override { return volume_.hasPendingWork() || quick_.refining(); }
  VolumeStats stats() const override;

  const RayFrameReport& lastFrame() const { return lastFrame_; }
  /// The shown image's reduction (1: full resolution; n: one ray per n x n pixels).
  int shownReduction() const { return quick_.shownReduction(); }
  /// Tets per dispatch (tests force small ones to exercise resumption); clamped to
  /// 1..kStepsPerPass.
  void setStepsPerPass(int steps);
  /// Tests: at most this many rows of rays per band, as on a device whose storage blocks
  /// hold little (0: as the device allows).
  void setBandRowsLimit(int rows) { rays_.setBandRowsLimit(rows); }
  /// Tests and benches: without the entry maps (TetRayDispatch::drawEntryMaps) every ray
  /// searches the BVH for where it enters; the picture is the same.
  void setEntryMaps(bool on) { rays_.setEntryMaps(on); }
  /// What a quick frame and one slice of the full frame may take (asynchronous updates).
  void setFrameBudget(double quickMs, double sliceMs) { quick_.setBudget(quickMs, sliceMs); }

 private:
  /// The whole frame into `image`, band by band, dispatching until every ray is done;
  /// returns its milliseconds.
  double renderWhole(const RenderContext& ctx, GLuint image);
  /// Starts the full frame of ctx (asynchronous path); refine() advances it for about the
  /// slice's time and says true when it is complete.
  void beginRefining(const RenderContext& ctx);
  void beginRefiningBand(const RenderContext& ctx, int firstRow);
  bool refine(const RenderContext& ctx);
  /// Part of the entry maps (TetRayDispatch::drawEntryMapFaces) within the slice that began
  /// at sliceStart; true once they are done and the slice has time left for rays.
  bool drawMapsPart(const RenderContext& ctx, std::chrono::steady_clock::time_point sliceStart);

  TetRayDispatch rays_;
  int stepsPerPass_ = kStepsPerPass;
  RayFrameReport lastFrame_, building_;
  QuickFrames quick_;      ///< asynchronous updates: the quick frame and the refinement's state
  int refineFirstRow_ = 0, refineRows_ = 0;  ///< the band being refined
  double bandMs_ = 0.0;    ///< its dispatches' time so far
  double msPerRow_ = 0.0;  ///< the last finished band's time per row (0: none yet this frame)
  int sliceSteps_ = 256;   ///< tets per dispatch while refining, adapted to the slice's time
  bool mapsPending_ = false;  ///< the full frame being refined has no entry maps yet
  bool mapsBegun_ = false;    ///< its maps are cleared and partly drawn
  std::size_t mapFacesPerPart_ = 1024;  ///< faces a part of the maps, adapted to the slice's time
};

}  // namespace volpost::volume

// SPDX-License-Identifier: MIT
// Dispatching raycast.comp over a GpuVolume's tets: the per-pixel ray states, the counters
// the shader reports through, and the frame in dispatches and bands (raycast.comp keeps
// where each ray stopped, so every dispatch takes each unfinished ray a bounded number of
// tets further). The ray caster draws its frames with it; cell projection its quick frames
// (the same picture, and, unlike cell projection's, a cost that shrinks with the
// resolution).
#pragma once

#include "GpuVolume.hpp"

#include <volpost/render/GlObjects.hpp>
#include <volpost/render/RenderContext.hpp>

#include <cstddef>

namespace volpost::volume {

/// What a frame took.
struct RayFrameReport {
  int dispatches = 0;          ///< passes over the image (1 unless rays crossed many tets or the frame was sliced)
  std::size_t cappedRays = 0;  ///< rays stopped at the step cap (rayStepCap) before leaving the mesh
  double milliseconds = 0.0;   ///< GPU work of the frame, summed over its dispatches (asynchronous path)
  bool entryMaps = false;      ///< rays started from the entry maps (drawEntryMaps), not BVH searches
  int entryMapParts = 0;       ///< draws the maps took (asynchronous path: in parts, within the slices)
  int refinedBands = 0;        ///< bands of rows the window's refinement took (each sized to a slice)
};

class TetRayDispatch {
 public:
  /// Tets a ray advances per dispatch when the frame need not be sliced: below the 65535
  /// loop iterations llvmpipe documents as its limit.
  static constexpr int kStepsPerPass = 32768;

  void initialize();
  void release();

  /// Rows of rays per band: all of them unless the device's storage blocks cannot hold a
  /// state per pixel (16 bytes each) or a test set a limit.
  int bandRows(int width, int height) const;
  void setBandRowsLimit(int rows);
  /// Clears the state of a band's `rows` rows of rays for a new frame.
  void beginBand(int width, int rows);
  /// Draws each pixel's nearest and farthest entry for ctx's frame (entry_faces.vert/.frag:
  /// the faces rays enter by, each pixel tested exactly as the entry search does): the
  /// frame's rays start at the nearest without searching the BVH, and a ray that has left
  /// the mesh searches for a re-entry only where an entry lies beyond it. Read by every
  /// dispatch until the next call. Not drawn where the image has fewer than two pixels per
  /// face (the searches are then cheaper than the maps).
  void drawEntryMaps(GpuVolume& volume, const RenderContext& ctx);
  /// The same maps in parts, so that a window's refinement slice stays within its time:
  /// beginEntryMaps clears them (false where none are drawn, as above); each
  /// drawEntryMapFaces draws the next `count` faces and says true once every face is drawn
  /// (the maps are then used). Faces go in the order of one draw: the same maps bit for bit.
  bool beginEntryMaps(GpuVolume& volume, const RenderContext& ctx);
  bool drawEntryMapFaces(GpuVolume& volume, const RenderContext& ctx, std::size_t count);
  /// Tests and benches: without entry maps every ray searches the BVH (the same picture).
  void setEntryMaps(bool on) { entryMaps_ = on; }

  /// One dispatch advancing every unfinished ray of rows [firstRow, firstRow + rows) by up
  /// to `steps` tets; returns the rays still unfinished and adds to `report`.
  std::size_t dispatch(GpuVolume& volume, const RenderContext& ctx, GLuint image, int firstRow, int rows, int steps,
                       RayFrameReport& report);
  /// The whole frame into `image`, band by band, up to `stepsPerPass` tets a dispatch
  /// until every ray is done.
  RayFrameReport renderWhole(GpuVolume& volume, const RenderContext& ctx, GLuint image, int stepsPerPass);

  std::size_t bytes() const;

 private:
  /// The maps' images and framebuffer at this size (made again when it changes).
  void sizeMaps(int width, int height);

  gl::Buffer rayState_, counters_;
  std::size_t rayStateBytes_ = 0;
  gl::Texture nearest_, farthest_, mapsDepth_;  ///< the entry maps (RG32UI: parameter bits, face code)
  gl::Framebuffer mapsFramebuffer_;
  gl::VertexArray emptyVertexArray_;
  int mapsWidth_ = 0, mapsHeight_ = 0;
  bool hasMaps_ = false;                         ///< drawn for the frame being dispatched
  std::size_t mapsFaces_ = 0, mapsNextFace_ = 0; ///< maps being drawn in parts: faces, the next one
  bool entryMaps_ = true;
  int bandRowsLimit_ = 0;  ///< tests: at most this many rows per band (0: as the device allows)
};

}  // namespace volpost::volume

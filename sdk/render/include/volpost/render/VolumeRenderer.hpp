// SPDX-License-Identifier: MIT
// The interface of GPU volume renderers (ray casting, cell projection), provided by
// renderer plugins. The host hands it the mesh and one result; transfer-function and
// clip-plane changes never re-upload the mesh.
#pragma once

#include <volpost/core/ClipPlane.hpp>
#include <volpost/core/Field.hpp>
#include <volpost/core/Mesh.hpp>
#include <volpost/core/TransferFunction.hpp>
#include <volpost/core/optics/IsoTables.hpp>
#include <volpost/render/Renderer.hpp>

#include <span>
#include <string>
#include <vector>

namespace volpost {

/// How a renderer integrates the transfer function along a ray segment.
enum class IntegrationMode {
  LinearSegments,          ///< cut exactly at every control point crossed, psi table
  PreIntegrated,           ///< 3D (s_front, s_back, length) table
  Sampling,                ///< fixed step, the baseline users know from other tools
  LinearSegmentsIsoTable,  ///< the seed's 4.2: cuts looked up in the 2D iso-detection texture
};
const char* toString(IntegrationMode mode);

struct VolumeStats {
  std::size_t gpuBytes = 0;        ///< buffers and textures this renderer holds
  std::size_t meshBytes = 0;       ///< of which the mesh structure (per-tet, per-node, BVH)
  std::size_t tetrahedra = 0;
  double lastTransferFunctionMs = 0.0;  ///< CPU+upload time of the last TF change
  double lastSortMs = 0.0;              ///< cell projection: the last frame's visibility sort
};

class VolumeRenderer : public Renderer {
 public:
  /// Mesh of tetrahedra (tet4, tet10 corners) and one value per node or per cell.
  /// Throws std::invalid_argument for other cells (tetrahedralize first).
  virtual void setVolume(const Mesh& mesh, FieldLocation location, std::span<const double> values) = 0;
  /// Only the values change (another result or step on the same mesh).
  virtual void setValues(std::span<const double> values) = 0;
  virtual void setTransferFunction(const TransferFunction& tf) = 0;
  virtual void setClipPlanes(const std::vector<ClipPlane>& planes) = 0;
  /// Iso-surfaces (up to 8) drawn where rays cross their values, opaque or translucent,
  /// shaded by the cell gradient and composited in order with the volume.
  virtual void setIsoSurfaces(const std::vector<optics::IsoSurface>& surfaces) = 0;
  virtual void setIntegrationMode(IntegrationMode mode) = 0;
  /// Sampling mode's step, model length units.
  virtual void setSamplingStep(double step) = 0;
  /// Rays stop when what is behind would count less than this (0: never).
  virtual void setTerminationThreshold(double transmittance) = 0;
  virtual VolumeStats stats() const = 0;
  /// The last frame as premultiplied RGBA floats, top row first (for tests and benches).
  virtual std::vector<float> readImage() const = 0;
  /// Interactive use: slow transfer-function tables (the pre-integrated one) are built on
  /// a worker thread while frames keep using the previous table; rapid changes coalesce to
  /// the latest. Off (the default, for the command line, tests and benches): render()
  /// waits for them.
  virtual void setAsynchronousUpdates(bool) {}
  /// True while such a table is being built: the caller should render again soon.
  virtual bool hasPendingWork() const { return false; }
};

}  // namespace volpost

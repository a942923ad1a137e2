// SPDX-License-Identifier: MIT
// The interface of GPU volume renderers (ray casting, cell projection), provided by
// renderer plugins, and the contract every one of them honours: how many clip planes and
// iso-surfaces (VolumeLimits.hpp), the integration modes (IntegrationMode.hpp), and what it
// says of itself (VolumeRendererTraits.hpp).
//
// Setters only record state: they make no GL call and may be called without a context.
// render() (a context current) uploads and rebuilds what changed since the last frame,
// once: moving a clip plane costs only the frame, a transfer-function edit rebuilds the
// tables only, a new result or step uploads only the values.
#pragma once

#include <volpost/core/ClipPlane.hpp>
#include <volpost/core/Field.hpp>
#include <volpost/core/Mesh.hpp>
#include <volpost/core/TransferFunction.hpp>
#include <volpost/core/optics/ElementField.hpp>
#include <volpost/core/optics/IsoTables.hpp>
#include <volpost/render/IntegrationMode.hpp>
#include <volpost/render/Renderer.hpp>
#include <volpost/render/VolumeLimits.hpp>
#include <volpost/render/VolumeRendererTraits.hpp>

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace volpost {

struct VolumeStats {
  std::size_t gpuBytes = 0;        ///< buffers and textures this renderer holds
  std::size_t meshBytes = 0;       ///< of which the mesh structure (per-tet, per-node, BVH)
  std::size_t tetrahedra = 0;
  double lastTransferFunctionMs = 0.0;  ///< CPU+upload time of the last TF change
  double lastSortMs = 0.0;              ///< cell projection: the last frame's visibility sort
  // What render() has done so far (counts since initialize()): the cost of an interaction
  // is visible in tests, e.g. a dragged plane must leave all three unchanged.
  std::size_t meshUploads = 0;     ///< the whole mesh structure went to the GPU
  std::size_t valueUploads = 0;    ///< only the values went
  std::size_t tableBuilds = 0;     ///< transfer-function tables were rebuilt
};

class VolumeRenderer : public Renderer {
 public:
  /// What it draws and which settings it takes (the host derives its menus and refusals
  /// from these); the same for every instance of one renderer.
  virtual VolumeRendererTraits traits() const = 0;
  /// Mesh of tetrahedra (tet4, tet10 corners) and one value per node or per cell. The mesh
  /// must outlive the renderer's use of it (until the next setVolume or release); the
  /// values are copied. Throws std::invalid_argument for other cells (tetrahedralize
  /// first) or a wrong value count.
  virtual void setVolume(const Mesh& mesh, FieldLocation location, std::span<const double> values) = 0;
  /// Only the values change (another result or step on the same mesh).
  virtual void setValues(std::span<const double> values) = 0;
  /// The cells' own field, for renderers whose traits() say elementInterpolation: node
  /// values through each cell's shape functions (trilinear, quadratic) instead of linear on
  /// setVolume's tetrahedra, which still give the geometry. `cellOfTet[t]` is the cell of
  /// `field` that tet t of setVolume's mesh was split from. Null: the tetrahedra's field
  /// again. Call after setVolume or setValues (they drop it). Renderers that draw the
  /// tetrahedra's field only throw std::invalid_argument for a field.
  virtual void setElementField(std::shared_ptr<const optics::ElementField> field,
                               std::vector<std::uint32_t> cellOfTet) {
    (void)cellOfTet;
    if (field) throw std::invalid_argument("this volume renderer draws the field linear on the tetrahedra only");
  }
  /// For renderers whose traits() say elementTolerance: the most each pixel channel (0..1)
  /// may differ from the exact picture of the cells' own field (0: exact). The host sends
  /// it to no other renderer; their default refuses anything but 0.
  virtual void setElementTolerance(double tolerance) {
    if (tolerance != 0.0) throw std::invalid_argument("this volume renderer draws the cells' own field exactly");
  }
  virtual void setTransferFunction(const TransferFunction& tf) = 0;
  /// Throws std::invalid_argument where checkClipPlanes does (VolumeLimits.hpp).
  virtual void setClipPlanes(const std::vector<ClipPlane>& planes) = 0;
  /// Iso-surfaces drawn where rays cross their values, opaque or translucent, shaded by
  /// the cell gradient and composited in order with the volume. Throws
  /// std::invalid_argument where checkIsoSurfaces does.
  virtual void setIsoSurfaces(const std::vector<optics::IsoSurface>& surfaces) = 0;
  virtual void setIntegrationMode(IntegrationMode mode) = 0;
  /// Sampling mode's step, model length units.
  virtual void setSamplingStep(double step) = 0;
  /// Rays stop when what is behind would count less than this (0: never).
  virtual void setTerminationThreshold(double transmittance) = 0;
  virtual VolumeStats stats() const = 0;
  /// The last frame as premultiplied RGBA floats, top row first (for tests and benches).
  /// A context is current.
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

// SPDX-License-Identifier: MIT
// The production CPU volume renderer: one ray per pixel walked tet to tet through face
// adjacency, in float, on all cores in tiles, with exact linear-segment integration.
//
// Watertight by construction. Every decision (where a ray enters the mesh, through which
// face it leaves a tet) is made from the signs of Plucker products of the ray with the
// tets' edges, and each edge's product is computed once per ray from its two vertex ids in
// ascending order, so the two tets sharing a face see bit-identical numbers (zero counts
// as positive for the ascending direction): a ray can neither slip between two tets nor be
// claimed by both, and where it crosses a face (point, parameter, value) is the same for
// both sides. Rays leave a non-convex mesh through a boundary face and re-enter through
// the next boundary face along them.
#pragma once

#include <volpost/core/TransferFunction2D.hpp>

#include <optional>

#include <volpost/core/Camera.hpp>
#include <volpost/core/ClipPlane.hpp>
#include <volpost/core/Progress.hpp>
#include <volpost/core/TransferFunction.hpp>
#include <volpost/core/optics/ElementField.hpp>
#include <volpost/core/optics/IsoTables.hpp>
#include "TetWalkMesh.hpp"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace volpost::volume {

/// The cells' own field for the walk (docs/methods/element_field.md): `field` through each
/// cell's inverse map, `cellOfTet[t]` the field's cell that walk tet t was split from.
struct CpuElementField {
  std::shared_ptr<const optics::ElementField> field;
  std::vector<std::uint32_t> cellOfTet;
};

struct CpuRaySettings {
  std::vector<ClipPlane> clipPlanes;    ///< in model coordinates
  std::vector<optics::IsoSurface> isoSurfaces;  ///< composited where the ray meets them (as the reference)
  /// A ray stops when what lies behind would count less than this (0: never); the default
  /// is the GPU renderers'. It is also the bound of the error it makes, per channel: the
  /// frame reports the largest as maxStopTransmittance.
  double terminationTransmittance = 0.002;
  /// Window depth (0..1, bottom row first, one per pixel) of opaque geometry already drawn:
  /// rays end there. Empty: none.
  std::vector<float> sceneDepth;
  /// Regular grids: the emission shaded by the trilinear gradient, light at the eye
  /// (volpost/core/optics/Headlight.hpp). The tetrahedral walk ignores it.
  bool shading = false;
  /// Regular grids: a 2D transfer function over the value and its gradient magnitude, used
  /// instead of the 1D one. The tetrahedral walk refuses it.
  std::optional<TransferFunction2D> transferFunction2D;
  /// Meshes: the cells' own field instead of the tetrahedra's linear one (null: the latter).
  /// Each ray's stretch through one such cell is fitted and integrated in double.
  std::shared_ptr<const CpuElementField> element;
  /// The most each pixel channel may differ from the exact picture of the cells' own field,
  /// on top of early termination's bound (0: integrated to rounding, as the reference).
  double elementTolerance = 0.0;
};

struct CpuRenderStats {
  std::size_t rays = 0;             ///< pixels whose ray meets the mesh
  std::size_t visibleTets = 0;      ///< tets the transfer function can see: the only ones walked
  std::size_t steps = 0;            ///< tets crossed, all rays together
  std::size_t stoppedRays = 0;      ///< stopped early (nearly opaque)
  double maxStopTransmittance = 0;  ///< the most any stopped ray left behind: its error bound
  std::size_t ambiguousExits = 0;   ///< float signs that named no exit face (resolved by the largest margin)
  std::size_t cappedRays = 0;       ///< walks cut at the step limit (a corrupt mesh)
  double entryMs = 0, walkMs = 0;   ///< finding entries, walking rays
  unsigned threads = 0;
};

struct CpuImage {
  int width = 0, height = 0;
  std::vector<float> rgba;  ///< premultiplied RGBA, top row first
  CpuRenderStats stats;
};

/// The part of the mesh a transfer function can show: the tets whose values do not all map
/// to zero extinction or that hold an iso-surface, and that part's boundary faces (where rays
/// enter and leave it). Rays are walked only there (empty-space skipping). It depends on
/// the values, the transfer function and the iso-surfaces, not on the view: kept between
/// frames.
struct VisiblePart {
  std::vector<std::uint8_t> tets;   ///< one flag per tet
  std::vector<BoundaryFace> faces;  ///< listed outward
};
/// With an element field, a cell's tets show together, by the bound of the cell's field
/// (ElementField::valueBound; always where it has none).
VisiblePart findVisiblePart(const TetWalkMesh& mesh, const TransferFunction& tf,
                            const std::vector<optics::IsoSurface>& isoSurfaces, int threads = 0,
                            const CpuElementField* element = nullptr);

/// Renders the volume as seen by the camera, with the same rays as the other renderers
/// (through pixel centres, perspective or orthographic). threads = 0: all cores. Throws
/// Cancelled if progress says so.
CpuImage renderCpu(const TetWalkMesh& mesh, const TransferFunction& tf, const Camera& camera, int width, int height,
                   const CpuRaySettings& settings = {}, const Progress& progress = {}, int threads = 0);
/// The same with the visible part found already (findVisiblePart with the same transfer
/// function and settings.isoSurfaces).
CpuImage renderCpu(const TetWalkMesh& mesh, const VisiblePart& part, const TransferFunction& tf, const Camera& camera,
                   int width, int height, const CpuRaySettings& settings = {}, const Progress& progress = {},
                   int threads = 0);

}  // namespace volpost::volume

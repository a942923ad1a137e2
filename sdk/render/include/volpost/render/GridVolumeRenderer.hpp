// SPDX-License-Identifier: MIT
// Volume renderers of regular grids (seismic cubes, image data): the values of a
// RegularGrid's points sampled as a 3D texture. The rest of the contract (transfer
// function, clip planes, iso-surfaces, modes, the float image) is VolumeRenderer's. Its
// traits() say drawsGrids; a renderer that draws only grids says drawsMeshes false and its
// setVolume() throws std::invalid_argument; one that draws both is given grids as grids,
// and the grid's tetrahedra where the field is given per cell.
#pragma once

#include <volpost/core/RegularGrid.hpp>
#include <volpost/core/SampleView.hpp>
#include <volpost/core/TransferFunction2D.hpp>
#include <volpost/render/VolumeRenderer.hpp>

#include <optional>

namespace volpost {

class GridVolumeRenderer : public VolumeRenderer {
 public:
  /// One value per grid point (RegularGrid::pointIndex order), in the type that holds them
  /// (a 16-bit cube's samples as stored: a renderer reads them in their type and keeps what
  /// it draws, never a copy in doubles); the grid is copied. Throws std::invalid_argument
  /// for a wrong count or a grid with a defect().
  virtual void setGrid(const RegularGrid& grid, SampleView pointValues) = 0;
  /// Replaces the values only (another step or quantity on the same grid); the same rules.
  virtual void setGridValues(SampleView pointValues) = 0;
  /// Shading of the emission by the trilinear gradient with the light at the eye
  /// (volpost/core/optics/Headlight.hpp); off by default.
  virtual void setShading(bool on) = 0;
  /// A 2D transfer function over the value and its gradient magnitude (the trilinear
  /// field's, in model units), used instead of the 1D one while set; nullopt goes back to
  /// the 1D one. Throws std::invalid_argument where the renderer cannot draw it.
  virtual void setTransferFunction2D(const std::optional<TransferFunction2D>& tf) = 0;
};

}  // namespace volpost

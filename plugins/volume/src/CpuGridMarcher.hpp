// SPDX-License-Identifier: MIT
// Ray marching through a regular grid on the CPU's cores: the same rays, lattice of steps,
// trilinear values and linear-segment integration of each piece as the GPU texture ray
// marcher (exact psi, as the CPU ray caster), with clip planes, iso-surfaces, opaque
// scene depth and early termination. Empty space is skipped a brick at a time: the grid is
// cut into bricks of 8^3 cells, and a ray crosses a brick whose whole value range the
// transfer function maps to zero extinction (and holds no iso-value) in one step. Used by
// the "cpu" renderer for grid models, where OpenGL is a software rasterizer.
#pragma once

#include "CpuRayCaster.hpp"
#include "PiecewiseIntegrator.hpp"

#include <volpost/core/RegularGrid.hpp>
#include <volpost/core/SampleView.hpp>

#include <glm/mat3x3.hpp>

#include <span>

namespace volpost::volume {

/// A grid's values prepared for marching: float values relative to their mid-range (float
/// resolves the range, not the magnitude), scaled down where that range is beyond a float's,
/// and each brick's value range.
class GridSamples {
 public:
  /// Throws std::invalid_argument for a grid with a defect or a wrong value count.
  GridSamples(const RegularGrid& grid, SampleView values);

  const RegularGrid& grid() const { return grid_; }
  double valueOffset() const { return valueOffset_; }
  /// A stored (relative, scaled) value as the field's value, and back.
  double valueOf(double relative) const { return valueOffset_ + relative / scale_; }
  float relativeOf(double value) const { return float((value - valueOffset_) * scale_); }
  /// A difference of stored values (a gradient) in the field's units.
  double unscaled(double storedDifference) const { return storedDifference / scale_; }
  double shortestSpacing() const { return shortestSpacing_; }
  const glm::dmat3& toIndex() const { return toIndex_; }
  /// The value (relative to valueOffset) at a continuous index, trilinear.
  float at(const glm::dvec3& index) const;
  /// The value there and d value / d index: the cell's own trilinear gradient (as the GPU
  /// marchers and the reference).
  float at(const glm::dvec3& index, glm::dvec3& indexGradient) const;
  /// The same with the polynomial of the cell holding `inCellOf` (at a cell face: the
  /// side a piece lies on).
  float at(const glm::dvec3& index, const glm::dvec3& inCellOf, glm::dvec3& indexGradient) const;

  static constexpr std::size_t kBrickCells = 8;
  const std::array<std::size_t, 3>& bricks() const { return bricks_; }
  std::size_t brickIndex(std::size_t bi, std::size_t bj, std::size_t bk) const {
    return bi + bricks_[0] * (bj + bricks_[1] * bk);
  }
  float brickMin(std::size_t brick) const { return brickMin_[brick]; }
  float brickMax(std::size_t brick) const { return brickMax_[brick]; }

 private:
  RegularGrid grid_;
  std::vector<float> values_;
  double valueOffset_ = 0.0, shortestSpacing_ = 1.0;
  double scale_ = 1.0;  ///< stored = (value - offset) * scale; below 1 only for ranges beyond float
  glm::dmat3 toIndex_{1.0};
  std::array<std::size_t, 3> bricks_{1, 1, 1};
  std::vector<float> brickMin_, brickMax_;
};

/// Renders the grid as seen by the camera (the same rays as every renderer: pixel
/// centres, perspective or orthographic), marching `step` model units (0: half the
/// shortest grid spacing). threads = 0: all cores. Throws Cancelled if progress says so.
CpuImage renderCpuGrid(const GridSamples& grid, const TransferFunction& tf, const Camera& camera, int width,
                       int height, const CpuRaySettings& settings = {}, double step = 0.0,
                       const Progress& progress = {}, int threads = 0);

}  // namespace volpost::volume

// SPDX-License-Identifier: MIT
// A regular grid's point values on the GPU for the grid renderers: texels in the values'
// frame (or, for integers of 8 or 16 bits such as seismic samples, those integers in
// signed normalized texels), laid out in bricks that fit the GPU memory budget and the
// device's largest 3D texture, each uploaded when it is drawn (GridBricks).
#pragma once

#include "GridBricks.hpp"
#include "TetMeshGpu.hpp"

#include <volpost/core/RegularGrid.hpp>
#include <volpost/core/SampleView.hpp>
#include <volpost/render/RenderContext.hpp>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>

#include <optional>
#include <utility>
#include <vector>

namespace volpost::volume {

class GridTexture {
 public:
  /// The grid and its point values; sets `frame`'s value frame (the tables' too) from their
  /// range. Throws std::invalid_argument for a grid with a defect or a wrong count,
  /// changing nothing.
  void set(const RegularGrid& grid, SampleView values, TetMeshGpu& frame);
  /// New values on the same grid (std::logic_error without one).
  void setValues(SampleView values, TetMeshGpu& frame);
  /// No grid (tetrahedra are drawn instead).
  void clear();
  bool has() const { return grid_.has_value(); }
  const RegularGrid& grid() const { return *grid_; }
  /// How a texel reads back in the values' frame: value = texel * scale + offset.
  const GridTexels& texels() const { return texels_; }

  // ---- GL (a context current) ----
  /// Lays out the bricks and uploads the single one when the grid fits (what the next
  /// frame draws anyway); the others go up as they are drawn.
  void upload();
  /// Lays out the bricks for the present budget (nothing changes when it is the same).
  void layOut();
  void release() { bricks_.release(); }
  const GridBricks& bricks() const { return bricks_; }
  std::size_t residentBytes() const { return bricks_.residentBytes(); }
  /// The bricks' order for ctx's camera: back to front, or front to back.
  std::vector<std::size_t> inOrder(const RenderContext& ctx, bool backToFront) const;
  /// Where brick b can cover the picture (normalized device coordinates, a pixel of slack):
  /// the rectangle round its projected corners, or the whole picture when a corner lies
  /// behind the eye. `origin` is the point GPU positions are relative to.
  std::pair<glm::vec2, glm::vec2> brickOnScreen(const RenderContext& ctx, std::size_t b,
                                                const glm::mat4& viewProjection, const glm::dvec3& origin) const;
  /// Makes brick b resident, binds its texture at `unit` and sets its place in the grid
  /// (brickFirst, brickPoints of common/grid_sampling.glsl).
  void bind(GLuint program, GLuint unit, std::size_t b);

 private:
  void makeTexels(SampleView values, TetMeshGpu& frame);

  std::optional<RegularGrid> grid_;
  GridTexels texels_;  ///< the points' values as the textures hold them
  GridBricks bricks_;
};

}  // namespace volpost::volume

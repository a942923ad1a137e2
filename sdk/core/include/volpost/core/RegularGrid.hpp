// SPDX-License-Identifier: MIT
// A regular grid of points (a seismic cube, VTK image data): dims, the world position of
// the first point and the step along each index axis, which may be rotated and of any
// length (a rotated survey, anisotropic spacing). A Model carries one when its mesh is
// this grid's hexahedra: then grid renderers sample its point values as a 3D texture and
// everything else (probing, surfaces, sections, the tetrahedral renderers) uses the mesh.
#pragma once

#include <volpost/core/Mesh.hpp>

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <cstddef>
#include <string>

namespace volpost {

struct RegularGrid {
  /// Points along i, j, k (each >= 2 for a grid with volume). Point (i, j, k) is entry
  /// i + dims[0] * (j + dims[1] * k) of the mesh's nodes and of every point field.
  std::array<std::size_t, 3> dims{0, 0, 0};
  glm::dvec3 origin{0.0};  ///< world position of point (0, 0, 0), model units
  /// World step from point (i, j, k) to (i+1, j, k), (i, j+1, k), (i, j, k+1): any three
  /// linearly independent vectors.
  std::array<glm::dvec3, 3> axes{glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0), glm::dvec3(0, 0, 1)};
  /// What each index axis is to the user ("inline", "crossline", "time (ms)") and the label
  /// of its first point and its step in those words (inline 111, 112, ...): for probes,
  /// slices and `info`. Default: "i", "j", "k" from 0 by 1.
  std::array<std::string, 3> axisNames{"i", "j", "k"};
  std::array<double, 3> firstLabel{0.0, 0.0, 0.0};
  std::array<double, 3> labelStep{1.0, 1.0, 1.0};
  /// How the file stored the samples ("16-bit integer", "IBM float"), for `info`.
  std::string sampleStorage;

  std::size_t pointCount() const { return dims[0] * dims[1] * dims[2]; }
  std::size_t cellCount() const;
  std::size_t pointIndex(std::size_t i, std::size_t j, std::size_t k) const { return i + dims[0] * (j + dims[1] * k); }
  /// (i, j, k) of point `point` (the inverse of pointIndex).
  std::array<std::size_t, 3> pointIndices(std::size_t point) const {
    return {point % dims[0], (point / dims[0]) % dims[1], point / (dims[0] * dims[1])};
  }
  /// World position of point `point` (a node of the grid's hexahedra, without them).
  glm::dvec3 pointPosition(std::size_t point) const {
    const auto [i, j, k] = pointIndices(point);
    return position(double(i), double(j), double(k));
  }
  glm::dvec3 position(double i, double j, double k) const { return origin + i * axes[0] + j * axes[1] + k * axes[2]; }
  /// Columns are the three axes: world = origin + indexToWorld() * (i, j, k).
  glm::dmat3 indexToWorld() const { return glm::dmat3(axes[0], axes[1], axes[2]); }
  /// Continuous index (i, j, k) of a world point (may lie outside 0..dims-1).
  glm::dvec3 indexOf(const glm::dvec3& world) const;
  /// The user's label of index `index` along `axis` (inline 111 for i = 0).
  double label(int axis, double index) const { return firstLabel[axis] + index * labelStep[axis]; }
  Bounds bounds() const;
  /// Empty when the grid is usable; otherwise what is wrong ("dims 1 x 5 x 5: ...").
  std::string defect() const;
};

/// The corners of cell (i, j, k) in VTK order (point indices), positive volume whatever the
/// handedness of the axes: the hexahedron hexahedraOfGrid lists for that cell.
std::array<NodeIndex, 8> gridHexahedron(const RegularGrid& grid, std::size_t i, std::size_t j, std::size_t k);

/// The grid's points and hexahedra (VTK order, positive volume whatever the handedness of
/// the axes), cell (i, j, k) at i + (dims[0]-1) * (j + (dims[1]-1) * k). Throws
/// std::length_error for a grid of more points than 32-bit node indices number.
Mesh hexahedraOfGrid(const RegularGrid& grid);

/// Host bytes per point that drawing a grid takes besides its samples: a renderer's copy of
/// them (float texels or the CPU marcher's floats, at most 4 bytes). Readers check the
/// samples plus this against the memory budget; the hexahedra (kGridHexahedraBytesPerPoint)
/// are checked when something first needs them as a mesh.
inline constexpr double kGridDrawingBytesPerPoint = 4.0;
/// A grid's explicit points and hexahedra (hexahedraOfGrid): 24 bytes a point, ~33 a cell.
inline constexpr double kGridHexahedraBytesPerPoint = 57.0;

/// Trilinear interpolation of point values at a continuous index (clamped to the grid).
double trilinear(const RegularGrid& grid, const float* values, const glm::dvec3& index);
double trilinear(const RegularGrid& grid, const double* values, const glm::dvec3& index);

}  // namespace volpost

// SPDX-License-Identifier: MIT
// A regular grid's values on the GPU under a memory budget. A grid that fits the budget
// (and the device's largest 3D texture) is one texture, as before. A larger one is split
// into bricks of at most a quarter of the budget each that share their border points with
// each neighbour (brick k along an axis holds points k * (side - 1) .. k * (side - 1) +
// side - 1), so the trilinear cell around any point inside a brick lies in that brick's
// texture and neighbouring bricks give the same values on their common face: no seams.
// The renderers draw the bricks one after another in visibility order; as many as the
// budget holds stay resident, the rest are uploaded when drawn (least recently drawn out
// first), so a volume far larger than the budget is rendered by streaming it.
#pragma once

#include <volpost/render/GlObjects.hpp>

#include <glm/vec3.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <list>
#include <vector>

namespace volpost::volume {

/// A grid's values as the GPU stores them: 32-bit floats in the values' frame or, when the
/// values are all integers that fit (8- and 16-bit seismic samples), those integers as
/// signed normalized 8- or 16-bit texels: a quarter or half of the memory, exactly the
/// same values. The shader maps a fetched texel t back: value = scale * t + offset.
struct GridTexels {
  enum class Format { Float32, Snorm16, Snorm8 };
  Format format = Format::Float32;
  std::vector<float> floats;
  std::vector<std::int16_t> shorts;
  std::vector<std::int8_t> bytes;
  float scale = 1.0f, offset = 0.0f;
  std::size_t bytesPerTexel() const { return format == Format::Float32 ? 4 : format == Format::Snorm16 ? 2 : 1; }
  std::size_t count() const { return floats.size() + shorts.size() + bytes.size(); }
};

struct GridBrick {
  std::array<std::size_t, 3> first{};   ///< the grid index of its first point
  std::array<std::size_t, 3> points{};  ///< points per axis (its texture's size)
  std::size_t texels() const { return points[0] * points[1] * points[2]; }
};

/// Bricks of at most `side` points per axis covering a grid of `dims` points, sharing
/// their border points, in x-fastest order. `side` >= 2.
std::vector<GridBrick> splitIntoBricks(const std::array<std::size_t, 3>& dims, std::size_t side);

/// The points per side of the bricks for a grid of `dims` values of `texelBytes` each under
/// `budget` bytes and textures of at most `largestTexture` points per side: the whole grid
/// when it fits both; else the largest side whose brick takes at most a quarter of the
/// budget. Throws std::invalid_argument, naming the figures, when not even a brick of 2^3
/// points fits.
std::size_t brickSideFor(const std::array<std::size_t, 3>& dims, std::size_t budget, std::size_t largestTexture,
                         std::size_t texelBytes = sizeof(float));

/// The bricks' order from back to front for rays from `eye` (index space), or, when
/// `orthographic`, along `direction`: a ray moves away from the eye's slab on every axis,
/// so a brick it meets later lies at least as far (in slabs) on each axis and farther on
/// one; sorting by the summed distance, farthest first, puts every brick behind those
/// that can hide it.
std::vector<std::size_t> bricksBackToFront(const std::vector<GridBrick>& bricks, const glm::dvec3& eye,
                                           const glm::dvec3& direction, bool orthographic);

class GridBricks {
 public:
  /// Lays out bricks for a grid of `dims` texels of `format` under `budget` bytes (0: no
  /// budget) and the device's largest texture side; keeps the textures when nothing changes.
  void configure(const std::array<std::size_t, 3>& dims, GridTexels::Format format, std::size_t texelBytes,
                 std::size_t budget, std::size_t largestTexture);
  /// The values changed: every resident brick is uploaded again when next drawn.
  void valuesChanged();
  /// Brick b's texture (nearest), uploaded from `texels` (the whole grid, x fastest) if it is
  /// not resident; evicts the least recently used brick when the budget is full.
  GLuint resident(std::size_t b, const GridTexels& texels);
  void release();

  const std::vector<GridBrick>& bricks() const { return bricks_; }
  std::size_t count() const { return bricks_.size(); }
  /// Bricks the budget lets stay on the GPU at once.
  std::size_t capacity() const { return capacity_; }
  std::size_t residentBytes() const;
  /// Brick uploads since configure(): equal to count() when the budget holds them all.
  std::size_t uploads() const { return uploads_; }
  /// Bytes those uploads sent.
  std::size_t uploadedBytes() const { return uploadedBytes_; }

 private:
  struct Slot {
    gl::Texture texture;
    std::size_t brick = 0;
    bool current = false;  ///< holds this brick's present values
  };
  void upload(Slot& slot, std::size_t b, const GridTexels& texels);
  std::size_t brickBytes(const GridBrick& b) const { return b.texels() * texelBytes_; }

  std::array<std::size_t, 3> dims_{};
  GridTexels::Format format_ = GridTexels::Format::Float32;
  std::size_t texelBytes_ = sizeof(float);
  std::size_t budget_ = 0, largest_ = 0, side_ = 0, capacity_ = 0, uploads_ = 0, uploadedBytes_ = 0;
  std::vector<GridBrick> bricks_;
  std::list<Slot> slots_;  ///< most recently used first
};

}  // namespace volpost::volume

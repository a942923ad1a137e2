// SPDX-License-Identifier: MIT
#include "GridBricks.hpp"

#include <volpost/core/ResourceLimits.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

namespace volpost::volume {

namespace {

// The bricks along one axis of n points: (first point, points) each.
std::vector<std::pair<std::size_t, std::size_t>> axisBricks(std::size_t n, std::size_t side) {
  if (n <= side) return {{0, n}};
  std::vector<std::pair<std::size_t, std::size_t>> out;
  for (std::size_t first = 0; first + 1 < n; first += side - 1) out.emplace_back(first, std::min(side, n - first));
  return out;
}

std::string dimsText(const std::array<std::size_t, 3>& dims) {
  return std::to_string(dims[0]) + " x " + std::to_string(dims[1]) + " x " + std::to_string(dims[2]);
}

}  // namespace

std::vector<GridBrick> splitIntoBricks(const std::array<std::size_t, 3>& dims, std::size_t side) {
  if (side < 2) throw std::invalid_argument("bricks need at least 2 points per side");
  const auto xs = axisBricks(dims[0], side), ys = axisBricks(dims[1], side), zs = axisBricks(dims[2], side);
  std::vector<GridBrick> bricks;
  bricks.reserve(xs.size() * ys.size() * zs.size());
  for (const auto& [fz, nz] : zs)
    for (const auto& [fy, ny] : ys)
      for (const auto& [fx, nx] : xs) bricks.push_back(GridBrick{{fx, fy, fz}, {nx, ny, nz}});
  return bricks;
}

std::size_t brickSideFor(const std::array<std::size_t, 3>& dims, std::size_t budget, std::size_t largestTexture,
                         std::size_t texelBytes) {
  const std::size_t longest = std::max({dims[0], dims[1], dims[2]});
  const double perTexel = double(texelBytes);
  const double bytes = double(dims[0]) * double(dims[1]) * double(dims[2]) * perTexel;
  if ((budget == 0 || bytes <= double(budget)) && longest <= largestTexture) return longest;
  std::size_t side = largestTexture;
  if (budget > 0) side = std::min(side, std::size_t(std::cbrt(double(budget) / 4.0 / perTexel)));
  while (side > 2 && double(side) * double(side) * double(side) * perTexel * 4.0 > double(budget) && budget > 0)
    --side;  // cbrt's rounding
  if (side < 2)
    throw std::invalid_argument("a GPU memory budget of " + byteSizeText(double(budget)) +
                                " cannot hold the bricks of a grid of " + dimsText(dims) + " points (each brick needs " +
                                "at least " + std::to_string(8 * texelBytes) + " bytes, four of them resident)");
  return std::min(side, longest);
}

std::vector<std::size_t> bricksBackToFront(const std::vector<GridBrick>& bricks, const glm::dvec3& eye,
                                           const glm::dvec3& direction, bool orthographic) {
  std::vector<double> key(bricks.size());
  for (std::size_t b = 0; b < bricks.size(); ++b) {
    double k = 0.0;
    for (int a = 0; a < 3; ++a) {
      const double lo = double(bricks[b].first[std::size_t(a)]);
      const double hi = lo + double(bricks[b].points[std::size_t(a)] - 1);
      if (orthographic) k += direction[a] > 0.0 ? lo : direction[a] < 0.0 ? -lo : 0.0;
      else k += std::max({0.0, lo - eye[a], eye[a] - hi});
    }
    key[b] = k;
  }
  std::vector<std::size_t> order(bricks.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return key[a] > key[b]; });
  return order;
}

void GridBricks::configure(const std::array<std::size_t, 3>& dims, GridTexels::Format format, std::size_t texelBytes,
                           std::size_t budget, std::size_t largestTexture) {
  if (dims == dims_ && format == format_ && budget == budget_ && largestTexture == largest_ && !bricks_.empty()) return;
  const std::size_t side = brickSideFor(dims, budget, largestTexture, texelBytes);
  dims_ = dims;
  format_ = format;
  texelBytes_ = texelBytes;
  budget_ = budget;
  largest_ = largestTexture;
  side_ = side;
  bricks_ = splitIntoBricks(dims, side);
  std::size_t largestBrick = 0;
  for (const GridBrick& b : bricks_) largestBrick = std::max(largestBrick, brickBytes(b));
  capacity_ = budget > 0 ? std::clamp<std::size_t>(budget / std::max<std::size_t>(largestBrick, 1), 1, bricks_.size())
                         : bricks_.size();
  slots_.clear();
  uploads_ = uploadedBytes_ = 0;
}

void GridBricks::valuesChanged() {
  for (Slot& s : slots_) s.current = false;
}

GLuint GridBricks::resident(std::size_t b, const GridTexels& values) {
  auto hit = std::find_if(slots_.begin(), slots_.end(), [b](const Slot& s) { return s.brick == b && s.texture; });
  if (hit == slots_.end()) {
    if (slots_.size() < capacity_) slots_.emplace_back();
    hit = std::prev(slots_.end());  // the least recently used, or the new one
    hit->current = false;
  }
  slots_.splice(slots_.begin(), slots_, hit);  // most recently used first
  Slot& slot = slots_.front();
  if (!slot.current || slot.brick != b) upload(slot, b, values);
  return slot.texture.id();
}

void GridBricks::upload(Slot& slot, std::size_t b, const GridTexels& texels) {
  const GridBrick& brick = bricks_[b];
  const bool sameSize = slot.texture && bricks_[slot.brick].points == brick.points;
  using Format = GridTexels::Format;
  if (!sameSize) {
    slot.texture = gl::createTexture(GL_TEXTURE_3D);
    const GLenum internal = format_ == Format::Float32 ? GL_R32F : format_ == Format::Snorm16 ? GL_R16_SNORM : GL_R8_SNORM;
    glTextureStorage3D(slot.texture.id(), 1, internal, GLsizei(brick.points[0]), GLsizei(brick.points[1]),
                       GLsizei(brick.points[2]));
    glTextureParameteri(slot.texture.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(slot.texture.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  }
  // The brick's points straight from the grid's array: rows of the grid's length, slices of
  // its rows (the start computed here in 64 bits, not by the driver from skip counts).
  const std::size_t start = (brick.first[2] * dims_[1] + brick.first[1]) * dims_[0] + brick.first[0];
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);  // rows of 1- and 2-byte texels need not be 4-aligned
  glPixelStorei(GL_UNPACK_ROW_LENGTH, GLint(dims_[0]));
  glPixelStorei(GL_UNPACK_IMAGE_HEIGHT, GLint(dims_[1]));
  const GLsizei w = GLsizei(brick.points[0]), h = GLsizei(brick.points[1]), d = GLsizei(brick.points[2]);
  if (format_ == Format::Float32)
    glTextureSubImage3D(slot.texture.id(), 0, 0, 0, 0, w, h, d, GL_RED, GL_FLOAT, texels.floats.data() + start);
  else if (format_ == Format::Snorm16)
    glTextureSubImage3D(slot.texture.id(), 0, 0, 0, 0, w, h, d, GL_RED, GL_SHORT, texels.shorts.data() + start);
  else
    glTextureSubImage3D(slot.texture.id(), 0, 0, 0, 0, w, h, d, GL_RED, GL_BYTE, texels.bytes.data() + start);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glPixelStorei(GL_UNPACK_IMAGE_HEIGHT, 0);
  slot.brick = b;
  slot.current = true;
  ++uploads_;
  uploadedBytes_ += brickBytes(brick);
  gl::check("GridBricks::upload");
}

void GridBricks::release() {
  slots_.clear();
  uploads_ = uploadedBytes_ = 0;
}

std::size_t GridBricks::residentBytes() const {
  std::size_t bytes = 0;
  for (const Slot& s : slots_)
    if (s.texture) bytes += brickBytes(bricks_[s.brick]);
  return bytes;
}

}  // namespace volpost::volume

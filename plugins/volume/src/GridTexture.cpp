// SPDX-License-Identifier: MIT
#include "GridTexture.hpp"

#include <volpost/core/ResourceLimits.hpp>

#include <glm/gtc/matrix_inverse.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace volpost::volume {
namespace {

// Whether every finite value is a whole number (always, for an integer type).
template <typename T>
bool finiteValuesAreIntegers(std::span<const T> values) {
  if constexpr (!std::is_integral_v<T>) {
    for (const T value : values)
      if (std::isfinite(value) && value != std::nearbyint(value)) return false;
  }
  return true;
}

template <typename Texel, typename T>
std::vector<Texel> integerTexels(std::span<const T> values, double minimum) {
  std::vector<Texel> out(values.size());
  for (std::size_t i = 0; i < values.size(); ++i) {
    const double v = double(values[i]);
    out[i] = Texel(std::isfinite(v) ? v : minimum);
  }
  return out;
}

void requireCount(const RegularGrid& grid, SampleView values) {
  if (values.size() != grid.pointCount())
    throw std::invalid_argument(std::to_string(values.size()) + " values for a grid of " +
                                std::to_string(grid.pointCount()) + " points");
}

// The GPU memory budget for the grid's textures: the setting, else 3/4 of what an NVIDIA
// device reports as its dedicated memory, else none.
std::size_t textureBudget() {
  if (const std::size_t set = gpuMemoryBudget()) return set;
  if (epoxy_has_gl_extension("GL_NVX_gpu_memory_info")) {
    GLint kilobytes = 0;
    glGetIntegerv(0x9047, &kilobytes);  // GPU_MEMORY_INFO_DEDICATED_VIDMEM_NVX
    if (kilobytes > 0) return std::size_t(kilobytes) * 1024 / 4 * 3;
  }
  return 0;
}

}  // namespace

void GridTexture::set(const RegularGrid& grid, SampleView values, TetMeshGpu& frame) {
  if (const std::string defect = grid.defect(); !defect.empty()) throw std::invalid_argument(defect);
  requireCount(grid, values);
  grid_ = grid;
  makeTexels(values, frame);
}

void GridTexture::setValues(SampleView values, TetMeshGpu& frame) {
  if (!grid_) throw std::logic_error("GridTexture::setValues before set");
  requireCount(*grid_, values);
  makeTexels(values, frame);
}

void GridTexture::clear() {
  grid_.reset();
  texels_ = GridTexels{};
}

// Values go to the texture in their own frame (see TetMeshGpu::valueOffset), or, when they
// are all integers of 8 or 16 bits (seismic samples as stored), as those integers in signed
// normalized texels the shader maps back into the frame. A value that is not a finite
// number is drawn as the field's minimum. Each type's values are read in that type, never
// copied to doubles first.
void GridTexture::makeTexels(SampleView values, TetMeshGpu& frame) {
  const ValueRange range = rangeOf(values);
  setValueFrame(frame, range);
  using Format = GridTexels::Format;
  GridTexels t;
  const double minimum = range.min, largest = std::max(std::abs(range.min), std::abs(range.max));
  const bool integers = range.valid() && values.visit([](auto typed) { return finiteValuesAreIntegers(typed); });
  t.format = !integers || largest > 32767.0 ? Format::Float32 : largest <= 127.0 ? Format::Snorm8 : Format::Snorm16;
  if (t.format == Format::Float32) {
    t.floats.resize(values.size());
    values.visit([&](auto typed) {
      for (std::size_t i = 0; i < typed.size(); ++i) {
        const double v = double(typed[i]);
        t.floats[i] = std::isfinite(v) ? frame.gpuValue(v) : 0.0f;
      }
    });
  } else {
    // A texel t is the integer / 127 (or 32767); the frame's value is (integer - valueOffset) * valueScale.
    const double unit = t.format == Format::Snorm8 ? 127.0 : 32767.0;
    t.scale = float(unit * frame.valueScale);
    t.offset = float(-frame.valueOffset * frame.valueScale);
    values.visit([&](auto typed) {
      if (t.format == Format::Snorm8) t.bytes = integerTexels<std::int8_t>(typed, minimum);
      else t.shorts = integerTexels<std::int16_t>(typed, minimum);
    });
  }
  texels_ = std::move(t);
}

// The grid's values as 3D float textures, fetched texel by texel (the shader interpolates
// in float itself: hardware filtering weighs with as few as 8 bits on some GPUs): one
// texture when the grid fits the GPU memory budget and the device's largest texture,
// else bricks, uploaded as they are drawn.
void GridTexture::upload() {
  layOut();
  bricks_.valuesChanged();
  if (bricks_.count() == 1) bricks_.resident(0, texels_);
}

void GridTexture::layOut() {
  GLint largest = 0;
  glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &largest);
  bricks_.configure(grid_->dims, texels_.format, texels_.bytesPerTexel(), textureBudget(),
                    std::size_t(std::max(largest, 2)));
}

std::vector<std::size_t> GridTexture::inOrder(const RenderContext& ctx, bool backToFront) const {
  const glm::dmat3 toIndex = glm::inverse(grid_->indexToWorld());
  const bool ortho = ctx.camera.projection() == Camera::Projection::Orthographic;
  std::vector<std::size_t> order = bricksBackToFront(bricks_.bricks(), toIndex * (ctx.camera.eye() - grid_->origin),
                                                     toIndex * ctx.camera.viewDirection(), ortho);
  if (!backToFront) std::reverse(order.begin(), order.end());
  return order;
}

std::pair<glm::vec2, glm::vec2> GridTexture::brickOnScreen(const RenderContext& ctx, std::size_t b,
                                                           const glm::mat4& viewProjection,
                                                           const glm::dvec3& origin) const {
  const GridBrick& brick = bricks_.bricks()[b];
  glm::vec2 lo(1e30f), hi(-1e30f);
  for (int c = 0; c < 8; ++c) {
    glm::dvec3 index;
    for (int a = 0; a < 3; ++a)
      index[a] = double(brick.first[std::size_t(a)] + ((c >> a) & 1) * (brick.points[std::size_t(a)] - 1));
    const glm::dvec3 p = grid_->origin + grid_->indexToWorld() * index - origin;
    const glm::vec4 clip = viewProjection * glm::vec4(glm::vec3(p), 1.0f);
    if (!(clip.w > 0.0f)) return {glm::vec2(-1.0f), glm::vec2(1.0f)};
    lo = glm::min(lo, glm::vec2(clip) / clip.w);
    hi = glm::max(hi, glm::vec2(clip) / clip.w);
  }
  const glm::vec2 pixel(2.0f / float(ctx.width), 2.0f / float(ctx.height));
  return {glm::clamp(lo - pixel, glm::vec2(-1.0f), glm::vec2(1.0f)),
          glm::clamp(hi + pixel, glm::vec2(-1.0f), glm::vec2(1.0f))};
}

void GridTexture::bind(GLuint program, GLuint unit, std::size_t b) {
  glBindTextureUnit(unit, bricks_.resident(b, texels_));
  const GridBrick& brick = bricks_.bricks()[b];
  glProgramUniform3i(program, glGetUniformLocation(program, "brickFirst"), GLint(brick.first[0]), GLint(brick.first[1]),
                     GLint(brick.first[2]));
  glProgramUniform3i(program, glGetUniformLocation(program, "brickPoints"), GLint(brick.points[0]),
                     GLint(brick.points[1]), GLint(brick.points[2]));
}

}  // namespace volpost::volume

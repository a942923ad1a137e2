// SPDX-License-Identifier: MIT
#include "CpuGridMarcher.hpp"

#include <volpost/core/Quantity.hpp>
#include <volpost/core/WorkerThreads.hpp>
#include <volpost/core/optics/Headlight.hpp>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <mutex>
#include <stdexcept>
#include <thread>

namespace volpost::volume {

GridSamples::GridSamples(const RegularGrid& grid, SampleView values) : grid_(grid) {
  if (const std::string defect = grid.defect(); !defect.empty()) throw std::invalid_argument(defect);
  if (values.size() != grid.pointCount())
    throw std::invalid_argument(std::to_string(values.size()) + " values for a grid of " +
                                std::to_string(grid.pointCount()) + " points");
  const ValueRange range = rangeOf(values);
  const double lo = range.min, hi = range.max;  // 0, 0 without a finite value
  valueOffset_ = 0.5 * lo + 0.5 * hi;
  // Values reaching beyond a float's range from the mid-range (a junk sample of 1e39 in a
  // double file, an IBM float of 7e75) are scaled by a power of two: trilinear sums and
  // differences of them must stay finite (inf - inf is NaN).
  const double halfRange = 0.5 * hi - 0.5 * lo;
  while (halfRange * scale_ > 1e37) scale_ *= 0x1p-32;
  values_.resize(values.size());
  values.visit([&](auto typed) {  // not a finite number: drawn as the lowest value
    forEachChunk(typed.size(), 1 << 16, [&](std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i) {
        const double v = double(typed[i]);
        values_[i] = float(((std::isfinite(v) ? v : lo) - valueOffset_) * scale_);
      }
    });
  });
  toIndex_ = glm::inverse(grid.indexToWorld());
  shortestSpacing_ = std::min({glm::length(grid.axes[0]), glm::length(grid.axes[1]), glm::length(grid.axes[2])});
  for (int a = 0; a < 3; ++a) bricks_[a] = (grid.dims[a] - 2) / kBrickCells + 1;
  const std::size_t count = bricks_[0] * bricks_[1] * bricks_[2];
  brickMin_.assign(count, INFINITY);
  brickMax_.assign(count, -INFINITY);
  // A brick holds cells b*8 .. b*8+7: the points b*8 .. b*8+8 bound its trilinear values.
  for (std::size_t k = 0; k < grid.dims[2]; ++k)
    for (std::size_t j = 0; j < grid.dims[1]; ++j)
      for (std::size_t i = 0; i < grid.dims[0]; ++i) {
        const float v = values_[grid.pointIndex(i, j, k)];
        const std::size_t p[3] = {i, j, k};
        std::size_t first[3], last[3];
        for (int a = 0; a < 3; ++a) {  // the bricks this point belongs to (two on a border between them)
          const std::size_t owner = p[a] / kBrickCells;
          last[a] = std::min(owner, bricks_[a] - 1);
          first[a] = std::min(p[a] % kBrickCells == 0 && p[a] > 0 ? owner - 1 : last[a], last[a]);
        }
        for (std::size_t bk = first[2]; bk <= last[2]; ++bk)
          for (std::size_t bj = first[1]; bj <= last[1]; ++bj)
            for (std::size_t bi = first[0]; bi <= last[0]; ++bi) {
              const std::size_t b = brickIndex(bi, bj, bk);
              brickMin_[b] = std::min(brickMin_[b], v);
              brickMax_[b] = std::max(brickMax_[b], v);
            }
      }
}

float GridSamples::at(const glm::dvec3& index) const {
  glm::dvec3 unused;
  return at(index, unused);
}

float GridSamples::at(const glm::dvec3& index, glm::dvec3& gradient) const { return at(index, index, gradient); }

float GridSamples::at(const glm::dvec3& index, const glm::dvec3& inCellOf, glm::dvec3& gradient) const {
  std::size_t base[3];
  float w[3];
  for (int a = 0; a < 3; ++a) {
    const double top = double(grid_.dims[a] - 1);
    const double x = std::clamp(index[a], 0.0, top);
    const double cell = std::min(std::floor(std::clamp(inCellOf[a], 0.0, top)), top - 1.0);
    base[a] = std::size_t(cell);
    w[a] = float(x - cell);
  }
  const std::size_t dj = grid_.dims[0], dk = grid_.dims[0] * grid_.dims[1];
  const float* v = values_.data() + grid_.pointIndex(base[0], base[1], base[2]);
  const float y0 = v[0] + w[0] * (v[1] - v[0]), y1 = v[dj] + w[0] * (v[dj + 1] - v[dj]);
  const float y2 = v[dk] + w[0] * (v[dk + 1] - v[dk]), y3 = v[dk + dj] + w[0] * (v[dk + dj + 1] - v[dk + dj]);
  const float a = y0 + w[1] * (y1 - y0), b = y2 + w[1] * (y3 - y2);
  const auto lerp = [](float p, float q, float t) { return p + t * (q - p); };
  gradient = {lerp(lerp(v[1] - v[0], v[dj + 1] - v[dj], w[1]), lerp(v[dk + 1] - v[dk], v[dk + dj + 1] - v[dk + dj], w[1]), w[2]),
              lerp(y1 - y0, y3 - y2, w[2]), b - a};
  return a + w[2] * (b - a);
}

namespace {

using Clock = std::chrono::steady_clock;

struct GridRay {
  glm::dvec3 start, dir;  // model units, unit direction
  double t0 = 0, t1 = 0;  // the part to integrate
};

// Restricts [t0, t1] to where dot(n, p - point) >= 0; false when nothing is left.
bool clipToPlane(const ClipPlane& c, const GridRay& r, double& t0, double& t1) {
  const double a = glm::dot(c.normal, r.start - c.point), b = glm::dot(c.normal, r.dir);
  if (b == 0.0) return a >= 0.0;
  if (b > 0.0) t0 = std::max(t0, -a / b);
  else t1 = std::min(t1, -a / b);
  return t0 < t1;
}

struct Marcher {
  const GridSamples& grid;
  const PiecewiseIntegrator& integrator;
  const CpuRaySettings& settings;
  const std::vector<std::uint8_t>& clearBricks;  // 1: the ray crosses it without integrating
  std::vector<float> isoValues;                  // relative to the grid's value offset
  double step;
  // Shading and 2D transfer functions read the gradient, which jumps across cell faces:
  // pieces are then cut there too (second order, as the GPU ray marcher).
  bool readsGradient = false;

  // The shading of a sample (its index gradient), or unlit.
  glm::dvec2 shadeOf(const glm::dvec3& indexGradient, const GridRay& r) const {
    return settings.shading ? optics::headlight(glm::transpose(grid.toIndex()) * indexGradient, r.dir) : glm::dvec2(1.0, 0.0);
  }

  // Where the ray (index space: o + t e) next crosses a grid plane after t.
  static double nextCellFace(const glm::dvec3& o, const glm::dvec3& e, double t) {
    double best = 1e300;
    for (int a = 0; a < 3; ++a) {
      if (e[a] == 0.0) continue;
      const double p = o[a] + t * e[a];
      double plane = e[a] > 0.0 ? std::floor(p) + 1.0 : std::ceil(p) - 1.0;
      double at = (plane - o[a]) / e[a];
      if (!(at > t)) at = (plane + (e[a] > 0.0 ? 1.0 : -1.0) - o[a]) / e[a];
      best = std::min(best, at);
    }
    return best;
  }

  // The gradient magnitude of a sample (its index gradient) in model units, for a 2D
  // transfer function.
  double gradientOf(const glm::dvec3& indexGradient) const {
    return settings.transferFunction2D ? grid.unscaled(glm::length(glm::transpose(grid.toIndex()) * indexGradient))
                                       : 0.0;
  }

  // A piece over which the scalar is linear, cut at the iso-surfaces it crosses; with a 2D
  // transfer function its gradient magnitude goes linearly from gradients.x to .y.
  void piece(const GridRay& r, const glm::dvec3& o, const glm::dvec3& e, double ta, double tb, float sa, float sb,
             const EmissionShade& shade, const glm::dvec2& gradients, optics::SegmentLight& light) const {
    const double length = tb - ta;
    double x0 = 0.0;
    for (std::size_t n = 0; n < isoValues.size() && sa != sb; ++n) {
      double best = 2.0;
      std::size_t which = isoValues.size();
      for (std::size_t i = 0; i < isoValues.size(); ++i) {
        const float v = isoValues[i];
        if ((sb > sa && v > sa && v <= sb) || (sb < sa && v < sa && v >= sb)) {
          const double x = double(v - sa) / double(sb - sa);
          if (x > x0 && x < best) best = x, which = i;
        }
      }
      if (which == isoValues.size()) break;
      integratePart(sa, sb, x0, best, length, shade, gradients, light);
      const optics::IsoSurface& s = settings.isoSurfaces[which];
      glm::dvec3 indexGradient;
      (void)grid.at(o + (ta + best * length) * e, indexGradient);
      const glm::dvec3 g = glm::transpose(grid.toIndex()) * indexGradient;
      const double gl = glm::length(g);
      const double isoShade = gl > 0.0 ? 0.3 + 0.7 * std::abs(glm::dot(g / gl, r.dir)) : 1.0;
      optics::compositeBehind(light, {s.color * isoShade * s.opacity, 1.0 - s.opacity});
      x0 = best;
    }
    integratePart(sa, sb, x0, 1.0, length, shade, gradients, light);
  }

  // The part [x0, x1] of a piece, its shading interpolated from the piece's ends.
  void integratePart(float sa, float sb, double x0, double x1, double length, const EmissionShade& shade,
                     const glm::dvec2& gradients, optics::SegmentLight& light) const {
    if (!(x1 > x0)) return;
    const double a = grid.valueOf(double(sa) + x0 * (double(sb) - double(sa))),
                 b = grid.valueOf(double(sa) + x1 * (double(sb) - double(sa)));
    if (const auto& tf2d = settings.transferFunction2D) {
      // Color and extinction at both ends from the table, linear between (as the GPU).
      glm::dvec4 front = tf2d->evaluate(a, gradients.x + x0 * (gradients.y - gradients.x));
      glm::dvec4 back = tf2d->evaluate(b, gradients.x + x1 * (gradients.y - gradients.x));
      if (!(front.a > 0.0) && !(back.a > 0.0)) return;
      if (settings.shading) {
        const glm::dvec2 kf = shade.front + x0 * (shade.back - shade.front), kb = shade.front + x1 * (shade.back - shade.front);
        front = glm::dvec4(glm::dvec3(front) * kf.x + kf.y, front.a);
        back = glm::dvec4(glm::dvec3(back) * kb.x + kb.y, back.a);
      }
      optics::compositeBehind(light, optics::linearSegment(glm::dvec3(front), front.a, glm::dvec3(back), back.a,
                                                           (x1 - x0) * length));
      return;
    }
    if (integrator.transparent(a, b)) return;
    const EmissionShade part{shade.front + x0 * (shade.back - shade.front), shade.front + x1 * (shade.back - shade.front)};
    optics::compositeBehind(light, integrator.integrate(a, b, (x1 - x0) * length, settings.shading ? &part : nullptr));
  }

  // The brick holding index point p (clamped to the grid).
  std::size_t brickAt(const glm::dvec3& p, std::size_t b[3]) const {
    for (int a = 0; a < 3; ++a) {
      const double cells = double(grid.grid().dims[a] - 1);
      const double x = std::clamp(p[a], 0.0, cells);
      b[a] = std::min(std::size_t(x / double(GridSamples::kBrickCells)), grid.bricks()[a] - 1);
    }
    return grid.brickIndex(b[0], b[1], b[2]);
  }

  // Where the ray leaves brick b (index space), as a parameter beyond t.
  static double brickExit(const glm::dvec3& o, const glm::dvec3& e, const std::size_t b[3], double t) {
    double exit = std::numeric_limits<double>::infinity();
    for (int a = 0; a < 3; ++a) {
      if (e[a] == 0.0) continue;
      const double face = double(GridSamples::kBrickCells) * double(e[a] > 0.0 ? b[a] + 1 : b[a]);
      exit = std::min(exit, (face - o[a]) / e[a]);
    }
    return std::max(exit, t);
  }

  // Returns the steps taken; `light` accumulates front to back.
  std::size_t march(const GridRay& r, optics::SegmentLight& light, bool& stopped) const {
    const glm::dvec3 o = grid.toIndex() * (r.start - grid.grid().origin), e = grid.toIndex() * r.dir;
    double t0 = r.t0, t1 = r.t1;
    for (int a = 0; a < 3; ++a) {  // the grid's box
      const double top = double(grid.grid().dims[a] - 1);
      if (e[a] == 0.0) {
        if (o[a] < 0.0 || o[a] > top) return 0;
        continue;
      }
      const double ta = -o[a] / e[a], tb = (top - o[a]) / e[a];
      t0 = std::max(t0, std::min(ta, tb));
      t1 = std::min(t1, std::max(ta, tb));
    }
    for (const ClipPlane& c : settings.clipPlanes)
      if (!clipToPlane(c, r, t0, t1)) return 0;
    if (!(t0 < t1)) return 0;
    std::size_t steps = 0;
    double t = t0;
    glm::dvec3 g;
    float sf = grid.at(o + t * e, g);
    glm::dvec2 frontShade = shadeOf(g, r);
    double frontGradient = gradientOf(g);
    const double nudge = 1e-9 * (std::abs(t1) + step);
    while (t < t1) {
      ++steps;
      std::size_t b[3];
      const std::size_t brick = brickAt(o + (t + nudge) * e, b);
      if (clearBricks[brick]) {  // nothing to see in it: across in one step
        const double exit = std::min(brickExit(o, e, b, t), t1);
        t = exit > t ? exit : std::min(t + step, t1);
        sf = grid.at(o + t * e, g);
        frontShade = shadeOf(g, r);
        frontGradient = gradientOf(g);
        continue;
      }
      double next = std::min((std::floor(t / step) + 1.0) * step, t1);
      if (!(next > t)) next = std::min(t + step, t1);
      if (!(next > t)) break;
      if (readsGradient) {  // cut at cell faces too; both ends in the piece's own cell
        next = std::min(next, nextCellFace(o, e, t));
        const glm::dvec3 middle = o + (0.5 * (t + next)) * e;
        sf = grid.at(o + t * e, middle, g);
        frontShade = shadeOf(g, r);
        frontGradient = gradientOf(g);
      }
      const float sb = readsGradient ? grid.at(o + next * e, o + (0.5 * (t + next)) * e, g) : grid.at(o + next * e, g);
      const glm::dvec2 backShade = shadeOf(g, r);
      const double backGradient = gradientOf(g);
      piece(r, o, e, t, next, sf, sb, {frontShade, backShade}, {frontGradient, backGradient}, light);
      t = next;
      sf = sb;
      frontShade = backShade;
      frontGradient = backGradient;
      if (light.transmittance < settings.terminationTransmittance) {
        stopped = t < t1;
        break;
      }
    }
    return steps;
  }
};

// Bricks the transfer function shows nothing of (and no iso-surface crosses).
std::vector<std::uint8_t> clearBricks(const GridSamples& grid, const PiecewiseIntegrator& integrator,
                                      const std::vector<optics::IsoSurface>& isoSurfaces,
                                      const std::optional<TransferFunction2D>& tf2d) {
  const std::size_t count = grid.bricks()[0] * grid.bricks()[1] * grid.bricks()[2];
  std::vector<std::uint8_t> clear(count, 0);
  for (std::size_t b = 0; b < count; ++b) {
    const double lo = grid.valueOf(grid.brickMin(b)), hi = grid.valueOf(grid.brickMax(b));
    // A 2D transfer function is zero outside its table's values, whatever the gradient.
    bool clearHere = tf2d ? (tf2d->empty() || hi < tf2d->valueLow() || lo > tf2d->valueHigh())
                          : integrator.transparent(lo, hi);
    for (const optics::IsoSurface& s : isoSurfaces) clearHere = clearHere && !(s.value >= lo && s.value <= hi);
    clear[b] = clearHere;
  }
  return clear;
}

}  // namespace

CpuImage renderCpuGrid(const GridSamples& grid, const TransferFunction& tf, const Camera& camera, int width, int height,
                       const CpuRaySettings& settings, double step, const Progress& progress, int threadCount) {
  CpuImage image;
  image.width = width;
  image.height = height;
  image.rgba.assign(std::size_t(width) * std::size_t(height) * 4, 0.0f);
  if (width <= 0 || height <= 0) return image;
  const unsigned threads = threadCount > 0 ? unsigned(threadCount) : usableCores();
  const auto start = Clock::now();
  const PiecewiseIntegrator integrator(tf);
  const std::vector<std::uint8_t> clear = clearBricks(grid, integrator, settings.isoSurfaces, settings.transferFunction2D);
  Marcher marcher{grid, integrator, settings, clear, {}, step > 0.0 ? step : 0.5 * grid.shortestSpacing()};
  for (const optics::IsoSurface& s : settings.isoSurfaces) marcher.isoValues.push_back(grid.relativeOf(s.value));
  marcher.readsGradient = settings.shading || settings.transferFunction2D.has_value();

  const glm::dmat4 toModel = glm::inverse(camera.projectionMatrix(double(width) / height) * camera.viewMatrix());
  const bool ortho = camera.projection() == Camera::Projection::Orthographic;
  const auto unproject = [&](double x, double y, double z) {
    const glm::dvec4 p = toModel * glm::dvec4(x, y, z, 1.0);
    return glm::dvec3(p) / p.w;
  };
  constexpr int kTile = 16;
  const int tilesX = (width + kTile - 1) / kTile, tilesY = (height + kTile - 1) / kTile;
  std::atomic<int> nextTile{0}, tilesDone{0};
  std::atomic<bool> stop{false};
  std::mutex totalsMutex;
  std::size_t rays = 0, steps = 0, stopped = 0;
  const unsigned ran = runOnThreads(threads, [&](unsigned worker) {
    std::size_t myRays = 0, mySteps = 0, myStopped = 0;
    try {
      for (int tile; !stop && (tile = nextTile++) < tilesX * tilesY;) {
        const int tx = tile % tilesX, ty = tile / tilesX;
        for (int y = ty * kTile; y < std::min(height, (ty + 1) * kTile); ++y)
          for (int x = tx * kTile; x < std::min(width, (tx + 1) * kTile); ++x) {
            const double nx = 2.0 * (x + 0.5) / width - 1.0, ny = 1.0 - 2.0 * (y + 0.5) / height;
            const glm::dvec3 nearPoint = unproject(nx, ny, -1.0), farPoint = unproject(nx, ny, 1.0);
            GridRay r;
            r.start = ortho ? nearPoint : camera.eye();
            const double length = glm::length(farPoint - r.start);
            r.dir = (farPoint - r.start) / length;
            r.t0 = ortho ? 0.0 : glm::length(nearPoint - r.start);
            r.t1 = length;
            const std::size_t pixel = std::size_t(y) * std::size_t(width) + std::size_t(x);
            if (settings.sceneDepth.size() == std::size_t(width) * std::size_t(height)) {
              const double z = settings.sceneDepth[std::size_t(height - 1 - y) * std::size_t(width) + std::size_t(x)];
              if (z < 1.0) r.t1 = std::min(r.t1, glm::dot(unproject(nx, ny, 2.0 * z - 1.0) - r.start, r.dir));
            }
            optics::SegmentLight light;
            bool stoppedEarly = false;
            const std::size_t taken = marcher.march(r, light, stoppedEarly);
            if (taken == 0) continue;
            ++myRays;
            mySteps += taken;
            myStopped += stoppedEarly;
            float* out = &image.rgba[4 * pixel];
            out[0] = float(light.color.r), out[1] = float(light.color.g), out[2] = float(light.color.b);
            out[3] = float(1.0 - light.transmittance);
          }
        const int done = ++tilesDone;
        if (worker == 0) progress.report(double(done) / (tilesX * tilesY));
      }
    } catch (...) {
      stop = true;
      throw;
    }
    const std::lock_guard lock(totalsMutex);
    rays += myRays, steps += mySteps, stopped += myStopped;
  });
  image.stats.rays = rays;
  image.stats.steps = steps;
  image.stats.stoppedRays = stopped;
  image.stats.maxStopTransmittance = stopped ? settings.terminationTransmittance : 0.0;
  image.stats.walkMs = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
  image.stats.threads = ran;
  return image;
}

}  // namespace volpost::volume

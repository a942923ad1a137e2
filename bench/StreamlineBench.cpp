// SPDX-License-Identifier: MIT
// Streamlines: error against the step tolerance and steps per second for each integrator,
// on fields whose trajectories are known (a solid-body rotation: the closure error of a
// circle; the ABC flow on a tetrahedralized box: the distance to the exact trajectory,
// which also holds the interpolation error), then lines per second traced on all cores
// and drawn as lit lines. Prints Markdown tables.
//   volpost_streamline_bench [--cubes N] [--lines N] [--size N]
#include "BenchUsage.hpp"

#include "support/TetGrid.hpp"

#include "host/Streamlines.hpp"
#include "host/render/StreamlineRenderer.hpp"

#include <volpost/render/HeadlessContext.hpp>
#include <volpost/render/OffscreenTarget.hpp>

#include <glm/geometric.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <random>
#include <string>

using namespace volpost;
using Clock = std::chrono::steady_clock;

namespace {

double msSince(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }

std::vector<glm::dvec3> sample(const TetMesh& tets, const std::function<glm::dvec3(glm::dvec3)>& f) {
  std::vector<glm::dvec3> v;
  for (const glm::dvec3& p : tets.mesh.nodes) v.push_back(f(p));
  return v;
}

glm::dvec3 exactAfterLength(const std::function<glm::dvec3(glm::dvec3)>& field, glm::dvec3 x, double length) {
  const auto unit = [&](glm::dvec3 p) { return glm::normalize(field(p)); };
  const int steps = 40000;
  const double h = length / steps;
  for (int i = 0; i < steps; ++i) {
    const glm::dvec3 k1 = unit(x), k2 = unit(x + 0.5 * h * k1), k3 = unit(x + 0.5 * h * k2), k4 = unit(x + h * k3);
    x += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
  }
  return x;
}

glm::dvec3 atLength(const std::vector<glm::dvec3>& points, double length) {
  double walked = 0.0;
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    const double d = glm::length(points[i + 1] - points[i]);
    if (walked + d >= length) return points[i] + (length - walked) / d * (points[i + 1] - points[i]);
    walked += d;
  }
  return points.back();
}

}  // namespace

int main(int argc, char** argv) {
  int cubes = 24, lineCount = 2000, size = 512;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--cubes") && i + 1 < argc) cubes = std::max(4, std::atoi(argv[++i]));
    else if (!std::strcmp(argv[i], "--lines") && i + 1 < argc) lineCount = std::max(1, std::atoi(argv[++i]));
    else if (!std::strcmp(argv[i], "--size") && i + 1 < argc) size = std::max(16, std::atoi(argv[++i]));
    else
      return volpost::bench::usageFor(argv[i], "volpost_streamline_bench: streamline accuracy and speed\n"
                                               "usage: volpost_streamline_bench [--cubes N] [--lines N] [--size N]\n");
  }
  const StreamlineMethod methods[] = {StreamlineMethod::RK2, StreamlineMethod::RK4, StreamlineMethod::RK45};

  // Solid-body rotation on a 2 x 2 x 0.25 slab: linear, so only the integrator errs.
  const TetMesh slab = tetrahedralize(test::tetGrid(cubes, cubes, 2, {-1, -1, 0}, 2.0 / cubes));
  const StreamlineTracer rotation(slab, sample(slab, [](glm::dvec3 p) { return glm::dvec3(-p.y, p.x, 0.0); }));
  std::printf("## Solid-body rotation (%zu tets): closure error of a circle of radius 0.6\n\n", slab.mesh.cellCount());
  std::printf("| integrator | tolerance | closure error | steps | rejected | steps/s |\n|---|---:|---:|---:|---:|---:|\n");
  for (StreamlineMethod m : methods)
    for (double tol : {1e-3, 1e-5, 1e-7}) {
      StreamlineSettings s;
      s.method = m;
      s.direction = StreamlineDirection::Forward;
      s.tolerance = tol;
      const auto t0 = Clock::now();
      Streamline line;
      int repeats = 0;
      do {
        line = rotation.trace({0.6, 0.0, 0.1}, s);
        ++repeats;
      } while (msSince(t0) < 200.0);
      const double ms = msSince(t0) / repeats;
      std::printf("| %s | %.0e | %.3g | %zu | %zu | %.3g |\n", toString(m), tol, line.closureError, line.steps,
                  line.rejected, double(line.steps + line.rejected) / (ms / 1e3));
    }

  // ABC flow: the interpolation error too.
  const double A = 1.0, B = std::sqrt(2.0 / 3.0), C = std::sqrt(1.0 / 3.0);
  const auto abc = [&](glm::dvec3 p) {
    return glm::dvec3(A * std::sin(p.z) + C * std::cos(p.y), B * std::sin(p.x) + A * std::cos(p.z),
                      C * std::sin(p.y) + B * std::cos(p.x));
  };
  const TetMesh box = tetrahedralize(test::tetGrid(cubes, cubes, cubes, {0, 0, 0}, 2.0 * M_PI / cubes));
  const StreamlineTracer flow(box, sample(box, abc));
  const glm::dvec3 seed(M_PI, 2.0, 3.0);
  const glm::dvec3 exact = exactAfterLength(abc, seed, 2.0);
  std::printf("\n## ABC flow on %d^3 cubes (%zu tets, cell %.3f): distance to the exact trajectory after length 2\n\n",
              cubes, box.mesh.cellCount(), 2.0 * M_PI / cubes);
  std::printf("| integrator | tolerance | error | steps | rejected | steps/s |\n|---|---:|---:|---:|---:|---:|\n");
  for (StreamlineMethod m : methods)
    for (double tol : {1e-3, 1e-5, 1e-7}) {
      StreamlineSettings s;
      s.method = m;
      s.direction = StreamlineDirection::Forward;
      s.tolerance = tol;
      s.maxLength = 2.5;
      // Points every 0.02 units (each integrated like a step end): the length along the
      // written polyline is then the line's own, not the chords' of long steps.
      s.pointSpacing = 0.02;
      const auto t0 = Clock::now();
      Streamline line;
      int repeats = 0;
      do {
        line = flow.trace(seed, s);
        ++repeats;
      } while (msSince(t0) < 200.0);
      const double ms = msSince(t0) / repeats;
      std::printf("| %s | %.0e | %.3g | %zu | %zu | %.3g |\n", toString(m), tol,
                  glm::length(atLength(line.points, 2.0) - exact), line.steps, line.rejected,
                  double(line.steps + line.rejected) / (ms / 1e3));
    }

  // Many lines: traced on all cores, then drawn as lit lines.
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(0.2, 2.0 * M_PI - 0.2);
  std::vector<glm::dvec3> seeds;
  for (int i = 0; i < lineCount; ++i) seeds.push_back({unit(rng), unit(rng), unit(rng)});
  StreamlineSettings s;
  s.maxLength = 3.0;
  s.direction = StreamlineDirection::Both;
  const auto t0 = Clock::now();
  const auto lines = flow.traceAll(seeds, s);
  const double traceMs = msSince(t0);
  std::size_t points = 0;
  std::vector<std::vector<glm::dvec3>> polylines;
  std::vector<std::vector<double>> values;
  for (const auto& l : lines) {
    points += l.points.size();
    polylines.push_back(l.points);
    std::vector<double> v;
    for (const auto& u : l.velocity) v.push_back(glm::length(u));
    values.push_back(v);
  }
  HeadlessContext context;
  OffscreenTarget target(size, size);
  StreamlineRenderer renderer;
  renderer.initialize();
  renderer.setLines(polylines, values, glm::dvec3(M_PI), StreamlineStyle{});
  renderer.setRange(0.0, 2.0);
  Camera camera;
  camera.setView(StandardView::Isometric);
  Bounds b;
  b.valid = true;
  b.min = glm::dvec3(0.0);
  b.max = glm::dvec3(2.0 * M_PI);
  camera.fit(b);
  RenderContext ctx;
  ctx.camera = camera;
  ctx.width = ctx.height = size;
  ctx.framebuffer = target.framebuffer();
  renderer.render(ctx);
  glFinish();
  const int frames = 10;
  const auto r0 = Clock::now();
  for (int f = 0; f < frames; ++f) {
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    renderer.render(ctx);
    glFinish();
  }
  const double frameMs = msSince(r0) / frames;
  renderer.release();
  std::printf("\n## %zu lines of the ABC flow (rk2, tolerance 1e-5, length 3 each way)\n\n", lines.size());
  std::printf("| traced in | lines/s | points | drawn (lit, %dx%d) | lines/s drawn |\n|---:|---:|---:|---:|---:|\n", size, size);
  std::printf("| %.0f ms | %.3g | %zu | %.1f ms | %.3g |\n", traceMs, double(lines.size()) / (traceMs / 1e3), points,
              frameMs, double(lines.size()) / (frameMs / 1e3));
  std::printf("\ndevice: %s\n", gl::describeContext().c_str());
  return 0;
}

// SPDX-License-Identifier: MIT
// volpost_grid_bench: regular-grid volume rendering, speed against error. A synthetic seismic
// cube (convolution model) is drawn by the texture ray marcher and the texture slicer on the
// GPU and by the CPU marcher, at several steps (slice spacings) per grid spacing, against
// the exact trilinear reference; one table row per renderer and step.
#include "BenchUsage.hpp"

#include "CpuVolumeRenderer.hpp"
#include "GridRayMarcher.hpp"
#include "GridSlicer.hpp"
#include "SegyReader.hpp"
#include "SyntheticSeismic.hpp"
#include "host/optics/GridReference.hpp"

#include <volpost/core/ResourceLimits.hpp>
#include <volpost/render/GL.hpp>
#include <volpost/render/HeadlessContext.hpp>
#include <volpost/render/OffscreenTarget.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <memory>
#include <string>
#include <vector>

using namespace volpost;
using Clock = std::chrono::steady_clock;

namespace {

const char* kUsage =
    "volpost_grid_bench: regular-grid volume rendering (a synthetic seismic cube), speed against\n"
    "error: texture ray marching, texture slicing and the CPU marcher at several steps per grid\n"
    "spacing, against the exact trilinear reference. Prints a Markdown table.\n"
    "  --grid N        points per axis of the cube (default 128; 64 quick, 256 big)\n"
    "  --segy FILE     a real post-stack SEG-Y cube instead (its amplitude, the same transfer\n"
    "                  function over its own range), e.g. ../shared/data/seismic/segyio/f3.sgy\n"
    "  --size N        image size in pixels (default 512)\n"
    "  --frames N      timed frames per row (default 3; the median is shown)\n"
    "  --steps A,B,..  steps as fractions of the grid spacing (default 1,0.5,0.25)\n"
    "  --cpu-only      only the CPU marcher (no GL rows)\n"
    "  --shading       lit by the gradient (headlight), the reference too\n"
    "  --interactive   also the renderers as the window drives them: 1024x768, the view turning\n"
    "                  5 degrees per frame, quick reduced frames (frames per second)\n"
    "  --gpu-budget SIZE  also the GPU renderers in bricks streamed through a GPU memory budget\n"
    "                  of SIZE (256M, 1G), against the same renderer from one texture\n"
    "  --bricks-only   only those rows (no reference, no table by step): for grids too large\n"
    "                  for the reference, such as --grid 645 (1 GB of floats)\n";

// Opaque where the amplitude is strong, either sign: reflectors show, the quiet rock is clear.
TransferFunction seismicTf(double extinction) {
  return TransferFunction({{-1.0, {0.1, 0.2, 0.9}, extinction},
                           {-0.35, {0.5, 0.6, 1.0}, 0.0},
                           {0.35, {1.0, 0.6, 0.5}, 0.0},
                           {1.0, {0.9, 0.1, 0.1}, extinction}});
}

struct Errors {
  double rmse = 0, max = 0;
};
Errors compare(const std::vector<float>& image, const optics::ReferenceImage& ref) {
  Errors e;
  double sum = 0;
  for (std::size_t i = 0; i < ref.pixels.size(); ++i)
    for (int c = 0; c < 4; ++c) {
      const double d = double(image[4 * i + std::size_t(c)]) - ref.pixels[i][c];
      sum += d * d;
      e.max = std::max(e.max, std::abs(d));
    }
  e.rmse = std::sqrt(sum / double(ref.pixels.size() * 4));
  return e;
}

}  // namespace

int main(int argc, char** argv) {
  std::size_t n = 128;
  int size = 512, frames = 3;
  bool cpuOnly = false, interactive = false, shading = false, bricksOnly = false;
  std::size_t gpuBudget = 0;
  std::string segy;
  std::vector<double> steps = {1.0, 0.5, 0.25};
  for (int a = 1; a < argc; ++a) {
    const bool more = a + 1 < argc;
    if (!std::strcmp(argv[a], "--grid") && more) n = std::size_t(std::atoi(argv[++a]));
    else if (!std::strcmp(argv[a], "--size") && more) size = std::atoi(argv[++a]);
    else if (!std::strcmp(argv[a], "--frames") && more) frames = std::atoi(argv[++a]);
    else if (!std::strcmp(argv[a], "--cpu-only")) cpuOnly = true;
    else if (!std::strcmp(argv[a], "--interactive")) interactive = true;
    else if (!std::strcmp(argv[a], "--shading")) shading = true;
    else if (!std::strcmp(argv[a], "--bricks-only")) bricksOnly = true;
    else if (!std::strcmp(argv[a], "--segy") && more) segy = argv[++a];
    else if (!std::strcmp(argv[a], "--gpu-budget") && more) {
      if (!(gpuBudget = parseByteSize(argv[++a]))) return bench::usageFor(argv[a], kUsage);
    }
    else if (!std::strcmp(argv[a], "--steps") && more) {
      steps.clear();
      for (char* s = std::strtok(argv[++a], ","); s; s = std::strtok(nullptr, ",")) steps.push_back(std::atof(s));
    } else
      return bench::usageFor(argv[a], kUsage);
  }
  if (n < 4 || size < 8 || frames < 1 || steps.empty()) return bench::usageFor("(a value out of range)", kUsage);
  if (bricksOnly && !gpuBudget) return bench::usageFor("--bricks-only without --gpu-budget", kUsage);

  seismic::SyntheticVolume cube;
  std::string title;
  double amplitudePeak = 0.0;
  if (segy.empty()) {
    seismic::SyntheticSurvey survey;
    survey.inlines = survey.crosslines = survey.samples = n;
    survey.binSize = 4.0;  // the cube is about as wide as it is deep in model units
    cube = seismic::makeSyntheticSeismic(survey);
    title = "Synthetic seismic cube " + std::to_string(n) + "^3";
  } else {
    try {
      const std::unique_ptr<Model> model = seismic::readSegy(segy, {});
      const Field* amplitude = model->findField("amplitude");
      if (!model->grid || !amplitude) throw std::runtime_error("no grid with an amplitude");
      cube.grid = *model->grid;
      cube.values = amplitude->values(0);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "volpost_grid_bench: %s: %s\n", segy.c_str(), e.what());
      return 1;
    }
    // The transfer function is made for amplitudes in -1 .. 1: stretched to the cube's peak
    // (the values stay as read: integer samples stay integers on the GPU).
    for (const double v : cube.values) amplitudePeak = std::max(amplitudePeak, std::abs(v));
    n = std::max({cube.grid.dims[0], cube.grid.dims[1], cube.grid.dims[2]});
    title = segy + " (" + std::to_string(cube.grid.dims[0]) + " x " + std::to_string(cube.grid.dims[1]) + " x " +
            std::to_string(cube.grid.dims[2]) + ")";
  }
  const RegularGrid& grid = cube.grid;
  const double spacing = std::min({glm::length(grid.axes[0]), glm::length(grid.axes[1]), glm::length(grid.axes[2])});
  TransferFunction tf = seismicTf(4.0 / (double(n) * spacing));
  if (amplitudePeak > 0.0) {
    std::vector<ControlPoint> points = tf.points();
    for (ControlPoint& p : points) p.value *= amplitudePeak;
    tf = TransferFunction(points);
  }
  Camera camera;
  camera.setView(StandardView::Isometric);
  camera.fit(grid.bounds());
  camera.orbit(20.0, -8.0);

  optics::ReferenceImage reference;
  double refMs = 0.0;
  if (!bricksOnly) {
    std::fprintf(stderr, "reference (exact trilinear) at %dx%d...\n", size, size);
    const auto refStart = Clock::now();
    optics::RaySettings referenceSettings;
    referenceSettings.shading = shading;
    reference = optics::renderGridReference(grid, cube.values, tf, camera, size, size, referenceSettings);
    refMs = std::chrono::duration<double, std::milli>(Clock::now() - refStart).count();
  }

  std::printf("%s (%.1f M points, %.0f MB of floats), %dx%d, early termination off, %s; "
              "reference %.0f ms\n\n",
              title.c_str(), double(grid.pointCount()) / 1e6, double(grid.pointCount()) * 4.0 / 1048576.0, size, size,
              shading ? "lit by the gradient" : "unlit", refMs);

  const auto row = [&](const char* name, double fraction, GridVolumeRenderer& r, const std::function<void()>& frame) {
    // Frames after the first: the grid and tables are on the GPU, only the frame is timed.
    r.setTransferFunction(tf);
    r.setTerminationThreshold(0.0);
    r.setSamplingStep(fraction * spacing);
    r.setShading(shading);
    frame();  // not timed: shader compilation, the upload
    std::vector<double> times;
    for (int f = 0; f < frames; ++f) {
      const auto start = Clock::now();
      frame();
      times.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
    }
    std::sort(times.begin(), times.end());
    const Errors e = compare(r.readImage(), reference);
    std::printf("| %s | %g | %.0f | %.2g | %.2g |\n", name, fraction, times[times.size() / 2], e.rmse, e.max);
    std::fflush(stdout);
  };

  HeadlessContext context;
  OffscreenTarget target(size, size);
  RenderContext ctx;
  ctx.camera = camera;
  ctx.width = ctx.height = size;
  ctx.framebuffer = target.framebuffer();
  const auto draw = [&](VolumeRenderer& r) {
    return [&] {
      glBindFramebuffer(GL_FRAMEBUFFER, ctx.framebuffer);
      glClearColor(0, 0, 0, 0);
      glClear(GL_COLOR_BUFFER_BIT);
      r.render(ctx);
      glFinish();
    };
  };
  if (gpuBudget) {
    std::printf("GPU renderers from one texture and in bricks streamed through a GPU memory budget of %s (default "
                "step, median of %d frames):\n\n| renderer | textures | ms/frame | uploads/frame | MB sent/frame | "
                "GPU MB held | max difference |\n|---|---|---:|---:|---:|---:|---:|\n",
                byteSizeText(double(gpuBudget)).c_str(), frames);
    const auto bricked = [&](auto& r) {
      std::vector<float> whole;
      for (const std::size_t budget : {std::size_t(0), gpuBudget}) {
        setGpuMemoryBudget(budget);
        r.initialize();
        r.setGrid(grid, cube.values);
        r.setTransferFunction(tf);
        r.setTerminationThreshold(0.0);
        r.setShading(shading);
        draw(r)();  // not timed: shader compilation, the first upload
        const std::size_t uploadsBefore = r.brickUploads(), bytesBefore = r.brickUploadedBytes();
        std::vector<double> times;
        for (int f = 0; f < frames; ++f) {
          const auto start = Clock::now();
          draw(r)();
          times.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
        }
        std::sort(times.begin(), times.end());
        const std::vector<float> image = r.readImage();
        double difference = 0.0;
        char differenceText[32] = "-";
        if (budget == 0) whole = image;
        else {
          for (std::size_t i = 0; i < image.size(); ++i)
            difference = std::max(difference, double(std::abs(image[i] - whole[i])));
          std::snprintf(differenceText, sizeof differenceText, "%.2g", difference);
        }
        const double uploads = double(r.brickUploads() - uploadsBefore) / double(frames);
        const double sentMb = double(r.brickUploadedBytes() - bytesBefore) / double(frames) / 1048576.0;
        std::printf("| %s | %s | %.0f | %.1f | %.3g | %.3g | %s |\n", r.name().c_str(),
                    r.brickCount() == 1 ? "one" : (std::to_string(r.brickCount()) + " bricks").c_str(),
                    times[times.size() / 2], uploads, sentMb, double(r.stats().meshBytes) / 1048576.0,
                    differenceText);
        std::fflush(stdout);
        r.release();
      }
      setGpuMemoryBudget(0);
    };
    if (!cpuOnly) {
      volume::GridRayMarcher marcher;
      bricked(marcher);
      volume::GridSlicer slicer;
      bricked(slicer);
    }
    std::printf("\n");
    if (bricksOnly) {
      std::printf("OpenGL: %s\n", reinterpret_cast<const char*>(glGetString(GL_RENDERER)));
      return 0;
    }
  }
  std::printf("| renderer | step / spacing | ms/frame (median of %d) | RMSE | max error |\n|---|---:|---:|---:|---:|\n",
              frames);
  volume::CpuVolumeRenderer cpu;
  cpu.initialize();
  cpu.setGrid(grid, cube.values);
  for (double s : steps) row("cpu (march)", s, cpu, draw(cpu));
  cpu.release();
  if (!cpuOnly) {
    volume::GridRayMarcher marcher;
    marcher.initialize();
    marcher.setGrid(grid, cube.values);
    for (double s : steps) row("texture-raymarch", s, marcher, draw(marcher));
    marcher.release();
    volume::GridSlicer slicer;
    slicer.initialize();
    slicer.setGrid(grid, cube.values);
    for (double s : steps) row("texture-slices", s, slicer, draw(slicer));
    slicer.release();
  }
  if (interactive) {
    // As in the window: every frame a new view, so a quick frame is drawn and the full one
    // started (the CPU's on worker threads, the GPU renderers' in slices when the view
    // rests). What the user sees: frames per second, at the default step.
    std::printf("\nIn the window (1024x768, the view turning 5 degrees per frame, default step):\n\n"
                "| renderer | quick frames | ms/frame (median of 35) | frames/s |\n|---|---|---:|---:|\n");
    const auto turning = [&](GridVolumeRenderer& r, const char* name, const std::function<int()>& reductionShown) {
      r.initialize();
      r.setGrid(grid, cube.values);
      r.setTransferFunction(tf);
      r.setAsynchronousUpdates(true);
      OffscreenTarget window(1024, 768);
      RenderContext w = ctx;
      w.width = 1024;
      w.height = 768;
      w.framebuffer = window.framebuffer();
      std::vector<double> times;
      int reduction = 1;
      for (int f = 0; f < 40; ++f) {
        w.camera.orbit(5.0, 0.0);
        const auto start = Clock::now();
        r.render(w);
        glFinish();
        times.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
        reduction = reductionShown();
      }
      r.release();
      std::sort(times.begin() + 5, times.end());  // the first frames measure the cost per pixel
      const double median = times[5 + (times.size() - 5) / 2];
      std::printf("| %s | 1 pixel per %dx%d | %.0f | %.1f |\n", name, reduction, reduction, median, 1000.0 / median);
      std::fflush(stdout);
    };
    volume::CpuVolumeRenderer cpuWindow;
    turning(cpuWindow, "cpu (march)", [&] { return cpuWindow.shownReduction(); });
    if (!cpuOnly) {
      volume::GridRayMarcher marcher;
      turning(marcher, "texture-raymarch", [&] { return marcher.shownReduction(); });
      volume::GridSlicer slicer;
      turning(slicer, "texture-slices", [&] { return slicer.shownReduction(); });
    }
  }
  std::printf("\nOpenGL: %s\n", reinterpret_cast<const char*>(glGetString(GL_RENDERER)));
  return 0;
}

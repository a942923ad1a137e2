// SPDX-License-Identifier: MIT
// Speed against error of the GPU volume renderers: for each mesh and integration mode,
// ms per frame along an orbit, tetrahedra per second, the time from a transfer-function
// change to the new frame, GPU memory, and the image error against the exact CPU
// reference renderer (same camera, same transfer function). Prints a Markdown table and
// writes a CSV for the speed-versus-error plot.
//   volpost_volume_bench [--size N|WxH] [--frames N] [--csv FILE] [--quick] [--mesh SUBSTRING]
//                        [--error-images DIR]  (one PGM per row: white = off by 0.05 or more)
#include "AllReaders.hpp"
#include "CellProjector.hpp"
#include "KuhnGrid.hpp"
#include "RayCaster.hpp"
#include "TetVolumeRenderer.hpp"
#include "VtkLegacyReader.hpp"
#include "VtuReader.hpp"

#include <volpost/core/MeshChecks.hpp>
#include <volpost/core/Tetrahedralize.hpp>
#include "CpuRayCaster.hpp"
#include "CpuVolumeRenderer.hpp"
#include "core/FloatImageFile.hpp"
#include "host/VtuWriter.hpp"
#include "host/optics/ReferenceRenderer.hpp"
#include <volpost/render/HeadlessContext.hpp>
#include <volpost/render/OffscreenTarget.hpp>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <optional>
#include <thread>
#include <tuple>

using namespace volpost;
using Clock = std::chrono::steady_clock;
using volpost::bench::kuhnGrid;

namespace {

// Where a renderer is off, as a picture: |error| (the worst channel) scaled so that 0.05
// and above is white. Binary PGM needs no image library.
void writeErrorImage(const std::filesystem::path& path, const std::vector<double>& errors, int width, int height) {
  FILE* f = std::fopen(path.string().c_str(), "wb");
  if (!f) {
    std::fprintf(stderr, "cannot write %s\n", path.string().c_str());
    return;
  }
  std::fprintf(f, "P5\n%d %d\n255\n", width, height);
  for (double e : errors) std::fputc(int(std::lround(std::min(1.0, e / 0.05) * 255.0)), f);
  std::fclose(f);
}

double msSince(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }

// CPU time of the whole process (every thread: the ray caster's workers and llvmpipe's
// rasterizer threads alike), in ms: what a frame costs the machine, beside its wall time.
double processCpuMs() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

struct Case {
  std::string name;
  Mesh mesh;
  FieldLocation location = FieldLocation::Node;
  std::vector<double> values;
  bool sharpPeak = false;  ///< the transfer function: a narrow opacity peak instead of a ramp
  bool fog = false;        ///< and a thin extinction everywhere else: no tet can be skipped
};

// --model FILE --field NAME [--tf FILE]: any model the readers know, one scalar field (the
// first step), hexahedra and others tetrahedralized.
Case modelCase(const std::string& path, const std::string& field) {
  auto model = meshio::allReadersRegistry().load(path);
  checkModel(*model);
  const Field* f = model->findField(field);
  if (!f) throw std::runtime_error(path + " has no field '" + field + "'");
  if (f->components() != 1) throw std::runtime_error("'" + field + "' has " + std::to_string(f->components()) +
                                                     " components: choose a scalar field");
  const TetMesh tets = tetrahedralize(model->mesh());
  return {std::filesystem::path(path).stem().string(), tets.mesh, f->location(),
          f->location() == FieldLocation::Node ? tets.nodeValues(model->mesh(), f->values(0)) : tets.cellValues(f->values(0))};
}

bool parseVec3(const char* text, glm::dvec3& v) {
  char tail = 0;
  return std::sscanf(text, "%lf,%lf,%lf%c", &v.x, &v.y, &v.z, &tail) == 3 && std::isfinite(v.x) && std::isfinite(v.y) &&
         std::isfinite(v.z);
}

std::vector<Case> cases(bool quick) {
  std::vector<Case> out;
  for (int n : {16, 32}) {
    if (quick && n == 32) continue;
    Case c{"grid " + std::to_string(n) + "^3", kuhnGrid(n), FieldLocation::Node, {}};
    for (const auto& p : c.mesh.nodes) c.values.push_back(p.x);  // s varies along x (Espinha 2005, 5.1)
    out.push_back(std::move(c));
  }
  {
    // A wave field seen through a sharp opacity peak: most of the range transparent, one
    // narrow iso-band opaque (what fast approximate renderers blur or miss).
    const int n = quick ? 16 : 32;
    Case c{"grid " + std::to_string(n) + "^3 wave, sharp peak", kuhnGrid(n), FieldLocation::Node, {}, true};
    for (const auto& p : c.mesh.nodes)
      c.values.push_back(std::sin(6.0 * p.x / n) * std::cos(5.0 * p.y / n) + 0.5 * std::sin(7.0 * p.z / n));
    // The same peak in a thin fog: every tet is visible, none skipped (the scene where
    // renderers that project every tet anyway lose nothing against a skipping ray caster).
    Case fogged = c;
    fogged.name = "grid " + std::to_string(n) + "^3 wave, sharp peak in fog (no tet skippable)";
    fogged.fog = true;
    out.push_back(std::move(c));
    out.push_back(std::move(fogged));
  }
  const std::string shared = VOLPOST_SHARED_DATA;
  if (!std::filesystem::exists(shared)) {
    std::fprintf(stderr, "../shared/data is absent: the real meshes are not measured\n");
    return out;
  }
  meshio::VtuReader vtu;
  const std::pair<const char*, const char*> files[] = {
      {"bar/tet4/bar_tet4.vtu", "S_Mises"}, {"bar/hex8/bar_hex8.vtu", "S_Mises"},
      {"wheel/tet4/wheel_tet4.vtu", "S_Mises"}, {"wheel/mixed/wheel_mixed.vtu", "S_Mises"},
      {"post/coarse/post_coarse.vtu", "oxygen_fraction"}, {"post/fine/post_fine.vtu", "oxygen_fraction"}};
  for (const auto& [file, field] : files) {
    if (quick && std::strstr(file, "fine")) continue;
    auto model = vtu.read(shared + "/" + file, {});
    checkModel(*model);
    const Field* f = model->findField(field);
    // Hexahedra, wedges and pyramids go through the conforming tetrahedralization.
    const TetMesh tets = tetrahedralize(model->mesh());
    Case c{std::filesystem::path(file).stem().string(), tets.mesh, f->location(),
           f->location() == FieldLocation::Node ? tets.nodeValues(model->mesh(), f->values(0)) : tets.cellValues(f->values(0))};
    out.push_back(std::move(c));
  }
  return out;
}

// What another program needs to render a case as this bench does and compare with its
// reference (docs/scripts/vtk_side_by_side.py): the mesh and field (.vtu), the transfer
// function (.tf.json), the camera (.camera.json) and the exact reference image (.npy).
void exportCase(const std::filesystem::path& dir, const Case& c, const TransferFunction& tf, const Camera& camera,
                const optics::ReferenceImage& reference) {
  std::string slug = c.name;
  std::replace_if(slug.begin(), slug.end(), [](char ch) { return !std::isalnum(static_cast<unsigned char>(ch)); }, '_');
  std::filesystem::create_directories(dir);
  Model model;
  model.mesh() = c.mesh;
  model.fields.push_back(Field::fromValues("s", c.location, 1, {c.values}));
  // Inline: what VTK 9.2 reads where the XML parser defers parsing (VtuWriter.hpp).
  writeVtu(model, (dir / (slug + ".vtu")).string(), {}, VtuLayout::Inline);
  std::ofstream(dir / (slug + ".tf.json")) << tf.toJson();
  const glm::dvec3 e = camera.eye(), t = camera.target(), u = camera.up();
  std::ofstream(dir / (slug + ".camera.json"))
      << "{\"eye\": [" << e.x << ", " << e.y << ", " << e.z << "], \"target\": [" << t.x << ", " << t.y << ", " << t.z
      << "], \"up\": [" << u.x << ", " << u.y << ", " << u.z << "], \"viewAngle\": " << camera.fieldOfView()
      << ", \"size\": [" << reference.width << ", " << reference.height << "]}\n";
  std::vector<float> rgba;
  for (const glm::dvec4& p : reference.pixels)
    for (int k = 0; k < 4; ++k) rgba.push_back(float(p[k]));
  app::writeFloatImage((dir / (slug + ".reference.npy")).string(), reference.width, reference.height, rgba, glm::dvec3(0.0));
}

// `fog`: a floor of extinction (0.5 per diagonal) under the peak, so no tet is transparent.
TransferFunction sharpPeakTf(const std::vector<double>& values, double diagonal, bool fog) {
  double lo = INFINITY, hi = -INFINITY;
  for (double v : values) lo = std::min(lo, v), hi = std::max(hi, v);
  const double mid = lo + 0.6 * (hi - lo), half = 0.015 * (hi - lo), tau = 60.0 / diagonal;
  const double floor = fog ? 0.5 / diagonal : 0.0;
  return TransferFunction({{lo, {0.2, 0.3, 0.9}, floor},
                           {mid - half, {0.2, 0.3, 0.9}, floor},
                           {mid, {1.0, 0.6, 0.1}, tau},
                           {mid + half, {0.9, 0.2, 0.1}, floor},
                           {hi, {0.9, 0.2, 0.1}, floor}});
}

TransferFunction benchTf(const std::vector<double>& values, double diagonal) {
  // 10 linear segments (Espinha 2005's "10 segments" rows), cool-warm, extinction as the
  // default TF: a light fog rising to dense color at the top of the range.
  double lo = INFINITY, hi = -INFINITY;
  for (double v : values) lo = std::min(lo, v), hi = std::max(hi, v);
  std::vector<ControlPoint> p = TransferFunction::ramp(lo, hi, "cool-warm", 1.0, 11).points();
  const double tauMax = 24.0 / diagonal;
  for (std::size_t i = 0; i < p.size(); ++i) p[i].extinction = tauMax * (0.1 + 0.9 * double(i) / 10.0) * (i % 2 ? 0.5 : 1.0);
  return TransferFunction(p);
}

}  // namespace

int main(int argc, char** argv) {
  int width = 512, height = 512, frames = 5;
  const char* csvPath = nullptr;
  bool quick = false;
  const char* only = nullptr;  // --mesh SUBSTRING: just the meshes whose name contains it
  const char* errorImages = nullptr;
  const char* exportDir = nullptr;
  bool cpuOnly = false;  // --cpu-only: leave out the GPU renderers
  std::vector<IntegrationMode> onlyModes;  // --modes LIST: just these integration modes of the GPU renderers
  bool interactive = false;  // --interactive: the window's quick frames while the view turns
  const char* modelPath = nullptr;  // --model FILE --field NAME: that model instead of the built-in cases
  const char* fieldName = nullptr;
  const char* tfPath = nullptr;     // --tf FILE: a volpost transfer function instead of the bench's
  std::optional<glm::dvec3> eye, lookAt, up;  // --eye/--target/--up X,Y,Z: an explicit camera
  double viewAngle = 0.0;  // --export DIR: each case's mesh, TF, camera and reference for other programs
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--size") && i + 1 < argc) {
      // N (square) or WxH
      const char* text = argv[++i];
      char tail = 0;
      if (std::sscanf(text, "%dx%d%c", &width, &height, &tail) != 2) {
        if (std::sscanf(text, "%d%c", &width, &tail) != 1) width = 0;
        height = width;
      }
    } else if (!std::strcmp(argv[i], "--frames") && i + 1 < argc) frames = std::max(1, std::atoi(argv[++i]));
    else if (!std::strcmp(argv[i], "--csv") && i + 1 < argc) csvPath = argv[++i];
    else if (!std::strcmp(argv[i], "--quick")) quick = true;
    else if (!std::strcmp(argv[i], "--mesh") && i + 1 < argc) only = argv[++i];
    else if (!std::strcmp(argv[i], "--error-images") && i + 1 < argc) errorImages = argv[++i];
    else if (!std::strcmp(argv[i], "--export") && i + 1 < argc) exportDir = argv[++i];
    else if (!std::strcmp(argv[i], "--cpu-only")) cpuOnly = true;
    else if (!std::strcmp(argv[i], "--modes") && i + 1 < argc) {
      const std::string list = argv[++i];
      for (std::size_t at = 0; at <= list.size();) {
        const std::size_t end = std::min(list.find(',', at), list.size());
        const auto mode = integrationModeFromString(list.substr(at, end - at));
        if (!mode) {
          std::fprintf(stderr, "volpost_volume_bench: --modes: '%s' is not one of %s\n", list.substr(at, end - at).c_str(),
                       integrationModeChoices().c_str());
          return 2;
        }
        onlyModes.push_back(*mode);
        at = end + 1;
      }
    }
    else if (!std::strcmp(argv[i], "--interactive")) interactive = true;
    else if (!std::strcmp(argv[i], "--model") && i + 1 < argc) modelPath = argv[++i];
    else if (!std::strcmp(argv[i], "--field") && i + 1 < argc) fieldName = argv[++i];
    else if (!std::strcmp(argv[i], "--tf") && i + 1 < argc) tfPath = argv[++i];
    else if (!std::strcmp(argv[i], "--view-angle") && i + 1 < argc) viewAngle = std::atof(argv[++i]);
    else if ((!std::strcmp(argv[i], "--eye") || !std::strcmp(argv[i], "--target") || !std::strcmp(argv[i], "--up")) &&
             i + 1 < argc) {
      glm::dvec3 v;
      if (!parseVec3(argv[i + 1], v)) {
        std::fprintf(stderr, "volpost_volume_bench: %s wants X,Y,Z (finite numbers), not '%s'\n", argv[i], argv[i + 1]);
        return 2;
      }
      (!std::strcmp(argv[i], "--eye") ? eye : !std::strcmp(argv[i], "--target") ? lookAt : up) = v;
      ++i;
    }
    else {
      const bool help = !std::strcmp(argv[i], "--help") || !std::strcmp(argv[i], "-h");
      std::fprintf(help ? stdout : stderr,
                   "%svolpost_volume_bench: speed against error of every volume renderer and integration mode\n"
                   "usage: volpost_volume_bench [--size N|WxH] [--frames N] [--csv FILE] [--quick] [--mesh SUBSTRING]\n"
                   "                            [--error-images DIR] [--export DIR] [--cpu-only] [--modes LIST]\n"
                   "                            [--interactive]\n"
                   "                            [--model FILE --field NAME] [--tf FILE]\n"
                   "                            [--eye X,Y,Z --target X,Y,Z [--up X,Y,Z] [--view-angle DEG]]\n"
                   "  --size N|WxH        image N x N or W x H pixels (default 512)\n"
                   "  --frames N          frames along the orbit (default 5)\n"
                   "  --csv FILE          also write mesh, mode, median ms, RMSE, max error (for the plot)\n"
                   "  --quick             leave out the largest meshes\n"
                   "  --mesh SUBSTRING    only the meshes whose name contains it\n"
                   "  --error-images DIR  one PGM per row: where the renderer is off (white = 0.05 or more)\n"
                   "  --export DIR        each case's mesh (.vtu), transfer function, camera and reference image\n"
                   "                      (.npy), for docs/scripts/vtk_side_by_side.py\n"
                   "  --cpu-only          the reference and the CPU ray caster only (no GPU renderer)\n"
                   "  --modes LIST        only these integration modes of the GPU renderers, e.g.\n"
                   "                      pre-integrated,iso-table (of linear, iso-table, pre-integrated, sampling)\n"
                   "  --model FILE        this model instead of the built-in cases (any format volpost reads),\n"
                   "  --field NAME        with this scalar field (first step)\n"
                   "  --tf FILE           this transfer function (volpost TF JSON) instead of the bench's\n"
                   "  --eye, --target, --up, --view-angle   an explicit camera instead of the isometric fit\n"
                   "  --interactive       also the renderers as the window drives them: 1024x768, the view\n"
                   "                      turning 5 degrees per frame, quick frames while the full one is\n"
                   "                      computed and cancelled (frames per second, rays per pixel)\n",
                   help ? "" : ("unknown argument '" + std::string(argv[i]) + "'\n").c_str());
      return help ? 0 : 2;
    }
  }
  if (bool(modelPath) != bool(fieldName)) {
    std::fprintf(stderr, "volpost_volume_bench: --model and --field go together\n");
    return 2;
  }
  if (bool(eye) != bool(lookAt) || viewAngle < 0.0 || viewAngle >= 180.0) {
    std::fprintf(stderr, "volpost_volume_bench: an explicit camera needs --eye and --target (and a view angle in (0, 180))\n");
    return 2;
  }
  std::optional<TransferFunction> fileTf;
  std::vector<Case> chosen;
  try {
    if (tfPath) {
      std::ifstream in(tfPath);
      if (!in) throw std::runtime_error(std::string("cannot open ") + tfPath);
      fileTf = TransferFunction::fromJson(std::string(std::istreambuf_iterator<char>(in), {}));
    }
    if (modelPath) chosen.push_back(modelCase(modelPath, fieldName));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "volpost_volume_bench: %s\n", e.what());
    return 1;
  }
  if (width < 8 || width > 8192 || height < 8 || height > 8192 || frames < 1) {
    std::fprintf(stderr, "volpost_volume_bench: --size must be N or WxH, each in 8..8192, and --frames at least 1\n");
    return 2;
  }
  HeadlessContext context;
  std::printf(
      "device: %s\nimage %dx%d, %d frames orbiting 360 degrees; errors against the CPU reference, "
      "premultiplied RGBA in 0..1\n\n",
      gl::describeContext().c_str(), width, height, frames);
  std::printf(
      "| mesh | tets | renderer / mode | ms/frame min / median / max | CPU ms/frame | sort ms | tets/s | TF update ms "
      "| GPU MB (mesh B/tet) | RMSE | max error |\n");
  std::printf("|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  FILE* csv = csvPath ? std::fopen(csvPath, "w") : nullptr;
  if (csv) std::fprintf(csv, "mesh,mode,median_ms,rmse,max_error\n");
  OffscreenTarget target(width, height);
  for (Case& c : modelPath ? std::move(chosen) : cases(quick)) {
    if (only && c.name.find(only) == std::string::npos) continue;
    const double diagonal = c.mesh.bounds().diagonal();
    const TransferFunction tf = fileTf        ? *fileTf
                                : c.sharpPeak ? sharpPeakTf(c.values, diagonal, c.fog)
                                              : benchTf(c.values, diagonal);
    Camera camera;
    camera.setView(StandardView::Isometric);
    camera.fit(c.mesh.bounds());
    if (eye) camera.lookAt(*eye, *lookAt, up.value_or(glm::dvec3(0.0, 0.0, 1.0)));
    if (viewAngle > 0.0) camera.setFieldOfView(viewAngle);
    const auto refStart = Clock::now();
    const double refCpuStart = processCpuMs();
    const optics::TetVolume volume(c.mesh, c.location, c.values);
    const optics::ReferenceImage reference = optics::renderReference(volume, tf, camera, width, height);
    const double refMs = msSince(refStart), refCpuMs = processCpuMs() - refCpuStart;
    if (exportDir) exportCase(exportDir, c, tf, camera, reference);
    std::printf("| %s | %zu | CPU reference (exact, %u threads) | %.0f | %.0f | - | %.3g | - | - | 0 | 0 |\n",
                c.name.c_str(), volume.tetCount(), std::thread::hardware_concurrency(), refMs, refCpuMs,
                double(volume.tetCount()) / (refMs / 1e3));
    // The CPU renderer: without early termination (like with like), then with its default.
    {
      const auto prepStart = Clock::now();
      const volume::TetWalkMesh walkMesh(c.mesh, c.location, c.values);
      const double prepMs = msSince(prepStart);
      for (double stopAt : {0.0, 1e-4, volume::CpuRaySettings{}.terminationTransmittance}) {
        volume::CpuRaySettings settings;
        settings.terminationTransmittance = stopAt;
        const volume::CpuImage first = volume::renderCpu(walkMesh, tf, camera, width, height, settings);
        double sum = 0.0, worst = 0.0;
        for (std::size_t i = 0; i < reference.pixels.size(); ++i)
          for (int k = 0; k < 4; ++k) {
            const double d = double(first.rgba[4 * i + std::size_t(k)]) - reference.pixels[i][k];
            sum += d * d;
            worst = std::max(worst, std::abs(d));
          }
        const double rmse = std::sqrt(sum / double(reference.pixels.size() * 4));
        std::vector<double> times, cpuTimes;
        Camera orbit = camera;
        for (int f = 0; f < frames; ++f) {
          const auto t0 = Clock::now();
          const double cpu0 = processCpuMs();
          (void)volume::renderCpu(walkMesh, tf, orbit, width, height, settings);
          times.push_back(msSince(t0));
          cpuTimes.push_back(processCpuMs() - cpu0);
          orbit.orbit(360.0 / frames, 0.0);
        }
        std::sort(times.begin(), times.end());
        std::sort(cpuTimes.begin(), cpuTimes.end());
        const double median = times[times.size() / 2];
        char label[160];
        std::snprintf(label, sizeof label, "cpu (%u threads, stop at %g; entries %.0f ms, walk %.0f ms, prepare %.0f ms)",
                      first.stats.threads, stopAt, first.stats.entryMs, first.stats.walkMs, prepMs);
        std::printf("| %s | %zu | %s | %.0f / %.0f / %.0f | %.0f | - | %.3g | - | host %.1f (%.0f) | %.2g | %.2g |\n",
                    c.name.c_str(), walkMesh.tetCount(), label, times.front(), median, times.back(),
                    cpuTimes[cpuTimes.size() / 2], double(walkMesh.tetCount()) / (median / 1e3),
                    walkMesh.bytes() / 1048576.0, double(walkMesh.bytes()) / double(walkMesh.tetCount()), rmse, worst);
        std::fflush(stdout);
        if (csv) std::fprintf(csv, "%s,cpu stop %g,%.3f,%.6g,%.6g\n", c.name.c_str(), stopAt, median, rmse, worst);
      }
    }
    if (interactive) {
      // As in the window: every frame a new view, so a quick frame is drawn and the full one
      // started (the CPU's on worker threads, cancelled by the next frame; the GPU
      // renderers' in slices when the view rests). What the user sees: frames per second.
      const auto turning = [&](VolumeRenderer& renderer, const char* name, const std::function<int()>& reductionShown) {
        renderer.initialize();
        renderer.setVolume(c.mesh, c.location, c.values);
        renderer.setTransferFunction(tf);
        renderer.setAsynchronousUpdates(true);
        OffscreenTarget window(1024, 768);
        RenderContext ctx;
        ctx.width = 1024;
        ctx.height = 768;
        ctx.framebuffer = window.framebuffer();
        ctx.camera = camera;
        std::vector<double> times;
        int reduction = 1;
        for (int f = 0; f < 40; ++f) {
          ctx.camera.orbit(5.0, 0.0);
          const auto t0 = Clock::now();
          renderer.render(ctx);
          glFinish();
          times.push_back(msSince(t0));
          reduction = reductionShown();
        }
        // Then the view rests: each call refines for about its slice; the longest is how long
        // the window's thread is held, the sum how long until the full picture.
        std::vector<double> slices;
        const auto restStart = Clock::now();
        do {
          const auto t0 = Clock::now();
          renderer.render(ctx);
          glFinish();
          slices.push_back(msSince(t0));
        } while (renderer.hasPendingWork() && slices.size() < 100000);
        const double restMs = msSince(restStart);
        renderer.release();
        std::sort(times.begin() + 5, times.end());  // the first frames measure the cost per ray
        const double median = times[5 + (times.size() - 5) / 2];
        // Every tet renderer's quick frames are ray cast (cell projection's too).
        std::printf(
            "| %s | %zu | %s, window 1024x768 turning: quick frames (1 ray per %dx%d pixels) | %.0f / %.0f / %.0f | - "
            "| - | "
            "%.1f frames/s | - | - | - | - |\n",
            c.name.c_str(), c.mesh.cellCount(), name, reduction, reduction, times[5], median, times.back(),
            1000.0 / median);
        std::sort(slices.begin(), slices.end());
        std::printf(
            "| %s | %zu | %s, window 1024x768 at rest: %zu calls to the full picture | %.0f / %.0f / %.0f | - | - | "
            "full in %.0f ms | - | - | - | - |\n",
            c.name.c_str(), c.mesh.cellCount(), name, slices.size(), slices.front(), slices[slices.size() / 2],
            slices.back(), restMs);
        std::fflush(stdout);
      };
      volume::CpuVolumeRenderer cpu;
      turning(cpu, "cpu", [&] { return cpu.shownReduction(); });
      if (!cpuOnly) {
        volume::RayCaster raycaster;
        turning(raycaster, "raycast", [&] { return raycaster.shownReduction(); });
        volume::CellProjector projector(volume::OrderMethod::Mpvonc);
        turning(projector, "vicp (MPVONC)", [&] { return projector.shownReduction(); });
      }
    }
    if (cpuOnly) continue;
    // The ray caster in every mode; cell projection (MPVONC and image-space orders) in the
    // exact, pre-integrated and sampling modes, with its sort time per frame.
    volume::RayCaster raycaster;
    volume::CellProjector vicp(volume::OrderMethod::Mpvonc), vicpExact(volume::OrderMethod::ImageSpace);
    const std::vector<IntegrationMode> allModes = {IntegrationMode::LinearSegments, IntegrationMode::LinearSegmentsIsoTable,
                                                   IntegrationMode::PreIntegrated, IntegrationMode::Sampling};
    const std::vector<IntegrationMode> projectionModes = {IntegrationMode::LinearSegments, IntegrationMode::PreIntegrated,
                                                          IntegrationMode::Sampling};
    for (auto [caster, label, modes] : {std::tuple<volume::TetVolumeRenderer*, const char*, const std::vector<IntegrationMode>*>{&raycaster, "raycast", &allModes},
                                        {&vicp, "vicp (MPVONC)", &projectionModes},
                                        {&vicpExact, "vicp (image-space order)", &projectionModes}}) {
    caster->initialize();
    caster->setVolume(c.mesh, c.location, c.values);
    caster->setTerminationThreshold(0.0);  // compare like with like
    for (IntegrationMode mode : *modes) {
      if (!onlyModes.empty() && std::find(onlyModes.begin(), onlyModes.end(), mode) == onlyModes.end()) continue;
      caster->setIntegrationMode(mode);
      const auto tfStart = Clock::now();
      caster->setTransferFunction(tf);
      RenderContext ctx;
      ctx.width = width;
      ctx.height = height;
      ctx.framebuffer = target.framebuffer();
      ctx.camera = camera;
      caster->render(ctx);
      glFinish();
      const double tfMs = msSince(tfStart);  // TF change to the new frame
      const auto image = caster->readImage();
      double sum = 0.0, worst = 0.0;
      std::size_t bad = 0, worstPixel = 0;
      std::vector<double> pixelErrors(reference.pixels.size());
      for (std::size_t i = 0; i < reference.pixels.size(); ++i) {
        double pixelError = 0.0;
        for (int k = 0; k < 4; ++k) {
          const double d = double(image[4 * i + std::size_t(k)]) - reference.pixels[i][k];
          sum += d * d;
          pixelError = std::max(pixelError, std::abs(d));
        }
        pixelErrors[i] = pixelError;
        bad += pixelError > 0.05;
        if (pixelError > worst) worst = pixelError, worstPixel = i;
      }
      // Pixels far from the reference (a lost ray would show here), for the record.
      if (bad)
        std::fprintf(stderr, "%s %s %s: %zu pixel(s) off by > 0.05, worst at (%zu, %zu)\n", c.name.c_str(), label,
                     toString(mode).data(), bad, worstPixel % std::size_t(width), worstPixel / std::size_t(width));
      if (errorImages) {
        std::string name = c.name + " " + (caster == &raycaster ? "raycast" : caster == &vicp ? "vicp" : "vicp-exact") + " " + std::string(toString(mode));
        std::replace_if(name.begin(), name.end(), [](char ch) { return !std::isalnum(static_cast<unsigned char>(ch)) && ch != '-'; }, '_');
        std::filesystem::create_directories(errorImages);
        writeErrorImage(std::filesystem::path(errorImages) / (name + ".pgm"), pixelErrors, width, height);
      }
      const double rmse = std::sqrt(sum / double(reference.pixels.size() * 4));
      std::vector<double> times, sorts, cpuTimes;
      Camera orbit = camera;
      for (int f = 0; f < frames; ++f) {
        ctx.camera = orbit;
        const auto t0 = Clock::now();
        const double cpu0 = processCpuMs();
        caster->render(ctx);
        glFinish();
        times.push_back(msSince(t0));
        cpuTimes.push_back(processCpuMs() - cpu0);
        sorts.push_back(caster->stats().lastSortMs);
        orbit.orbit(360.0 / frames, 0.0);
      }
      std::sort(times.begin(), times.end());
      std::sort(sorts.begin(), sorts.end());
      std::sort(cpuTimes.begin(), cpuTimes.end());
      const double median = times[times.size() / 2];
      const VolumeStats st = caster->stats();
      const std::string sortMs = caster == &raycaster ? "-" : std::to_string(int(std::lround(sorts[sorts.size() / 2])));
      std::printf("| %s | %zu | %s / %s | %.0f / %.0f / %.0f | %.0f | %s | %.3g | %.0f | %.1f (%.0f) | %.2g | %.2g |\n",
                  c.name.c_str(), st.tetrahedra, label, toString(mode).data(), times.front(), median, times.back(),
                  cpuTimes[cpuTimes.size() / 2], sortMs.c_str(), double(st.tetrahedra) / (median / 1e3), tfMs,
                  st.gpuBytes / 1048576.0, double(st.meshBytes) / double(st.tetrahedra), rmse, worst);
      std::fflush(stdout);
      if (csv)
        std::fprintf(csv, "%s,%s%s,%.3f,%.6g,%.6g\n", c.name.c_str(), caster == &raycaster ? "" : (caster == &vicp ? "vicp " : "vicp-exact "),
                     toString(mode).data(), median, rmse, worst);
    }
    caster->release();
    }
  }
  if (csv) std::fclose(csv);
  return 0;
}

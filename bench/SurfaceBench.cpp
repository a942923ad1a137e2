// SPDX-License-Identifier: MIT
// Loading and surface rendering on the real meshes: read, check, boundary extraction,
// and frame time of the boundary view at 512x512 along an orbit. Prints a Markdown table,
// then one of the boundary drawn in the cells' own shapes and field as the quantity shown
// changes (refined again, or recolored where the level stays).
//   volpost_bench [--frames N] [--size N]
#include "BenchUsage.hpp"

#include "core/ModelSession.hpp"
#include "core/BoundaryRenderer.hpp"

#include "VtkLegacyReader.hpp"
#include "VtuReader.hpp"

#include <volpost/core/MeshChecks.hpp>
#include <volpost/render/HeadlessContext.hpp>
#include <volpost/render/OffscreenTarget.hpp>

#include <sys/resource.h>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <vector>

using namespace volpost;
using Clock = std::chrono::steady_clock;

namespace {

double ms(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double, std::milli>(b - a).count(); }

struct Case {
  const char* name;
  const char* file;  // relative to ../shared/data, or tests/data when shared is absent
  const char* quantity;
};

const Case kCases[] = {
    {"bar tet4", "bar/tet4/bar_tet4.vtu", "S.mises"},       {"bar hex8", "bar/hex8/bar_hex8.vtu", "S.mises"},
    {"bar wedge6", "bar/wedge6/bar_wedge6.vtu", "S.mises"}, {"bar tet10", "bar/tet10/bar_tet10.vtu", "S.mises"},
    {"wheel tet4", "wheel/tet4/wheel_tet4.vtu", "S.mises"}, {"wheel mixed", "wheel/mixed/wheel_mixed.vtu", "S.mises"},
    {"bracket tet10", "bracket/tet10/bracket_tet10.vtu", "T"},
    {"post coarse", "post/coarse/post_coarse.vtu", "pressure"}, {"post fine", "post/fine/post_fine.vtu", "pressure"},
};

// The quantities shown one after another on a model of quadratic or mixed cells.
struct CurvedCase {
  const char* name;
  const char* file;
  std::vector<const char*> quantities;
};

const CurvedCase kCurvedCases[] = {
    {"bracket tet10", "bracket/tet10/bracket_tet10.vtu", {"S.mises", "T", "U.magnitude", "S.mises", "T"}},
    {"wheel mixed", "wheel/mixed/wheel_mixed.vtu", {"S.mises", "U.magnitude", "U.x", "S.mises"}},
    {"bar tet10", "bar/tet10/bar_tet10.vtu", {"S.mises", "U.magnitude", "S.mises"}},
};

// The first draw after each change of quantity, with the cells' own interpolation: the
// boundary refined for it or recolored, then drawn (synchronously, as a picture is).
void curvedBoundaryTable(const ReaderRegistry& readers, int size) {
  std::printf(
      "\nThe boundary in the cells' own shapes and field, %dx%d, the first draw after each change of "
      "quantity:\n\n| mesh | quantity | draw ms | triangles |\n|---|---|---:|---:|\n",
      size, size);
  for (const CurvedCase& c : kCurvedCases) {
    const std::string path = std::string(VOLPOST_SHARED_DATA) + "/" + c.file;
    const auto session = app::ModelSession::load(readers, path);
    OffscreenTarget target(size, size);
    app::BoundaryRenderer scene;
    scene.initialize();
    scene.setSession(session);
    scene.setFieldInterpolation(FieldInterpolation::Element);
    Camera camera;
    camera.setView(StandardView::Isometric);
    camera.fit(session->model().mesh().bounds());
    std::uint64_t version = 0;
    for (const char* quantity : c.quantities) {
      const app::ScalarView view = session->evaluate(session->findQuantity(quantity), 0);
      RenderContext ctx;
      ctx.camera = camera;
      ctx.width = ctx.height = size;
      ctx.framebuffer = target.framebuffer();
      const auto a = Clock::now();
      scene.setScalars(&view, app::autoRange(view), ++version);
      scene.render(ctx);
      glFinish();
      std::printf("| %s | %s | %.0f | %zu |\n", c.name, quantity, ms(a, Clock::now()),
                  scene.curvedCorners().size() / 3);
      scene.setScalars(nullptr, {}, 0);  // the view goes out of scope
    }
    scene.release();
  }
}

}  // namespace

int main(int argc, char** argv) {
  int frames = 30, size = 512;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--frames") && i + 1 < argc) frames = std::max(3, std::atoi(argv[++i]));
    else if (!std::strcmp(argv[i], "--size") && i + 1 < argc) size = std::max(16, std::atoi(argv[++i]));
    else
      return volpost::bench::usageFor(argv[i], "volpost_bench: surface rendering frame times while orbiting\n"
                                               "usage: volpost_bench [--frames N] [--size N]\n");
  }
  meshio::VtuReader vtu;
  meshio::VtkLegacyReader legacy;
  ReaderRegistry readers;
  readers.add(&vtu);
  readers.add(&legacy);

  HeadlessContext context;
  std::printf("device: %s\nframes: %d at %dx%d, orbiting 360 degrees\n\n", gl::describeContext().c_str(), frames, size, size);
  std::printf("| mesh | cells | boundary tris | read ms | checks ms | boundary ms | frame ms min / median / max | Mtri/s |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|\n");
  const bool shared = std::filesystem::exists(VOLPOST_SHARED_DATA);
  if (!shared) std::fprintf(stderr, "../shared/data is absent: only the bundled bar is measured\n");
  for (const Case& c : kCases) {
    std::string path = std::string(VOLPOST_SHARED_DATA) + "/" + c.file;
    if (!shared) {
      if (std::strcmp(c.name, "bar tet4")) continue;
      path = std::string(VOLPOST_TEST_DATA) + "/bar/bar_tet4.vtu";
    }
    const auto t0 = Clock::now();
    auto model = readers.choose(path).read(path, {});
    const auto t1 = Clock::now();
    checkModel(*model);
    const auto t2 = Clock::now();
    std::shared_ptr<Model> sharedModel(std::move(model));
    const BoundarySurface surface = extractBoundary(sharedModel->mesh());
    const auto t3 = Clock::now();

    const auto session = app::ModelSession::load(readers, path);
    const app::ScalarView view = session->evaluate(session->findQuantity(c.quantity), 0);
    OffscreenTarget target(size, size);
    app::BoundaryRenderer scene;
    scene.initialize();
    scene.setSession(session);
    scene.setScalars(&view, app::autoRange(view), 1);
    Camera camera;
    camera.setView(StandardView::Isometric);
    camera.fit(session->model().mesh().bounds());
    std::vector<double> times;
    for (int f = 0; f < frames; ++f) {
      RenderContext ctx;
      ctx.camera = camera;
      ctx.width = ctx.height = size;
      ctx.framebuffer = target.framebuffer();
      const auto a = Clock::now();
      scene.render(ctx);
      glFinish();
      times.push_back(ms(a, Clock::now()));
      camera.orbit(360.0 / frames, 0.0);
    }
    scene.release();
    std::sort(times.begin(), times.end());
    const double median = times[times.size() / 2];
    std::printf("| %s | %zu | %zu | %.1f | %.1f | %.1f | %.2f / %.2f / %.2f | %.1f |\n", c.name,
                sharedModel->mesh().cellCount(), std::size_t(surface.mesh.n_faces()), ms(t0, t1), ms(t1, t2), ms(t2, t3),
                times.front(), median, times.back(), double(surface.mesh.n_faces()) / median / 1e3);
  }
  if (shared) curvedBoundaryTable(readers, size);
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  std::printf("\npeak resident memory: %.0f MiB\n", usage.ru_maxrss / 1024.0);
  return 0;
}

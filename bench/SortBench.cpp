// SPDX-License-Identifier: MIT
// Visibility sorting for cell projection (issue 5's CPU half): MPVO, MPVONC and the
// image-space order on the real meshes, per frame along an orbit. Prints a Markdown table.
//   volpost_sort_bench [--size N] [--frames N]
#include "BenchUsage.hpp"

#include "VisibilityOrder.hpp"

#include "AbaqusInputReader.hpp"
#include "VtuReader.hpp"

#include <volpost/core/Tetrahedralize.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>

using namespace volpost;

int main(int argc, char** argv) {
  int size = 512, frames = 3;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--size") && i + 1 < argc) size = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--frames") && i + 1 < argc) frames = std::atoi(argv[++i]);
    else
      return volpost::bench::usageFor(argv[i], "volpost_sort_bench: visibility sorting for cell projection\n"
                                               "usage: volpost_sort_bench [--size N] [--frames N]\n");
  }
  const std::filesystem::path shared = VOLPOST_SHARED_DATA;
  meshio::VtuReader reader;
  std::printf("| mesh | tets | method | sort ms min / median / max | image relations | cycle breaks |\n|---|---:|---|---:|---:|---:|\n");
  for (const char* file : {"bar/tet4/bar_tet4.vtu", "wheel/tet4/wheel_tet4.vtu", "wheel/mixed/wheel_mixed.vtu",
                           "post/coarse/post_coarse.vtu", "post/fine/post_fine.vtu"}) {
    if (!std::filesystem::exists(shared / file)) continue;
    const auto model = reader.read((shared / file).string(), {});
    const TetMesh tets = tetrahedralize(model->mesh());
    const volume::VisibilitySorter sorter(tets.mesh);
    for (const auto& [method, name] : {std::pair{volume::OrderMethod::Mpvo, "MPVO"}, std::pair{volume::OrderMethod::Mpvonc, "MPVONC"},
                                       std::pair{volume::OrderMethod::ImageSpace, "image-space"}}) {
      std::vector<double> ms;
      volume::VisibilityOrder last;
      for (int f = 0; f < frames; ++f) {
        Camera camera;
        camera.fit(tets.mesh.bounds());
        camera.setView(StandardView::Isometric);
        camera.orbit(360.0 * f / frames, 0.0);
        last = sorter.order(camera, method, size, size);
        ms.push_back(last.milliseconds);
      }
      std::sort(ms.begin(), ms.end());
      std::printf("| %s | %zu | %s%s | %.0f / %.0f / %.0f | %zu | %zu |\n", std::filesystem::path(file).stem().c_str(),
                  tets.mesh.cellCount(), name, method == volume::OrderMethod::ImageSpace ? (" " + std::to_string(size) + "^2").c_str() : "",
                  ms.front(), ms[ms.size() / 2], ms.back(), last.imageRelations, last.cycleBreaks);
      std::fflush(stdout);
    }
  }
  return 0;
}

// SPDX-License-Identifier: MIT
// Build time and error of the optical tables against the exact integration.
//   volpost_optics_bench [--csv FILE]   (the CSV holds psi-table error versus resolution)
#include "BenchUsage.hpp"

#include <volpost/core/optics/IsoTables.hpp>
#include "host/optics/IsoSurfaceTable.hpp"
#include <volpost/core/optics/OpticalDepth.hpp>
#include <volpost/core/optics/PreintegrationTable.hpp>
#include <volpost/core/optics/PsiTable.hpp>
#include <volpost/core/optics/SegmentIntegral.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <thread>

using namespace volpost;
using namespace volpost::optics;
using Clock = std::chrono::steady_clock;

namespace {

double msSince(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }

TransferFunction segments(int n) {
  std::vector<ControlPoint> p;
  for (int i = 0; i <= n; ++i) {
    const double t = double(i) / n;
    p.push_back({t, {t, 1.0 - t, 0.5 + 0.5 * (i % 2)}, (i % 3) * 2.0});
  }
  return TransferFunction(p);
}

}  // namespace

int main(int argc, char** argv) {
  const char* csv = nullptr;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--csv") && i + 1 < argc) csv = argv[++i];
    else
      return volpost::bench::usageFor(argv[i], "volpost_optics_bench: accuracy and build time of the optics tables\n"
                                               "usage: volpost_optics_bench [--csv FILE]\n");
  }
  FILE* out = csv ? std::fopen(csv, "w") : nullptr;
  if (out) std::fprintf(out, "resolution,max_abs_error,rms_error,build_ms\n");
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> e(-4.0, 3.0), u(0.0, 1.0);
  std::printf("threads: %u\n\n## psi table (float, gamma = tD/(tD+1)), error over depths 1e-4..1e3\n\n", std::thread::hardware_concurrency());
  std::printf("| N x N | build ms | max abs error | RMS error |\n|---:|---:|---:|---:|\n");
  for (int n : {64, 128, 256, 512, 1024}) {
    const auto t0 = Clock::now();
    const PsiTable table(n);
    const double build = msSince(t0);
    double worst = 0.0, sum = 0.0;
    const int samples = 200000;
    for (int i = 0; i < samples; ++i) {
      const double tf = std::pow(10.0, e(rng)), tb = std::pow(10.0, e(rng));
      const double err = std::abs(table.lookup(tf, tb) - psi(tf, tb));
      worst = std::max(worst, err);
      sum += err * err;
    }
    std::printf("| %d | %.1f | %.3g | %.3g |\n", n, build, worst, std::sqrt(sum / samples));
    if (out) std::fprintf(out, "%d,%.6g,%.6g,%.3f\n", n, worst, std::sqrt(sum / samples), build);
  }
  if (out) std::fclose(out);

  std::printf("\n## pre-integrated table: exact opacity, mean color from a (s_f, s_b, depth) table where the "
              "segment is thin (optical depth <= %.2g), exact integration where it is thick\n\n",
              PreintegrationTable::kMaxDepth);
  std::printf("| table | transfer function | build ms | segments from the table | max alpha error | max color error | "
              "RMS color error |\n|---|---|---:|---:|---:|---:|---:|\n");
  const TransferFunction peak({{0.0, {0.2, 0.2, 1.0}, 0.0}, {0.495, {1, 1, 1}, 0.0}, {0.5, {1, 0, 0}, 60.0},
                               {0.505, {1, 1, 1}, 0.0}, {1.0, {0.2, 0.2, 1.0}, 0.0}});
  for (int segs : {10, 32, 255, 0})
    for (int n : {64, 128, 256}) {
      const TransferFunction tf = segs ? segments(segs) : peak;
      const OpticalDepth depth(tf);
      const auto t0 = Clock::now();
      const PreintegrationTable table(tf, 0.0, 1.0, n, 9);
      const double build = msSince(t0);
      double worstAlpha = 0.0, worst = 0.0, sum = 0.0;
      int thin = 0;
      const int samples = 20000;
      for (int i = 0; i < samples; ++i) {
        // Lengths 0.001 to 10 (optical depths up to ~40 for the segments, ~60 through the peak).
        double sf = u(rng), sb = u(rng);
        if (!segs) sf = 0.5 + 0.1 * (sf - 0.5), sb = 0.5 + 0.1 * (sb - 0.5);
        const double len = std::pow(10.0, 4.0 * u(rng) - 3.0);
        thin += depth.depth(sf, sb, len) <= PreintegrationTable::kMaxDepth;
        const SegmentLight exact = integrateSegment(tf, sf, sb, len);
        const glm::dvec4 t = table.lookup(sf, sb, len);
        worstAlpha = std::max(worstAlpha, std::abs(t.a - (1.0 - exact.transmittance)));
        for (int c = 0; c < 3; ++c) {
          const double err = std::abs(t[c] - exact.color[c]);
          worst = std::max(worst, err);
          sum += err * err;
        }
      }
      const std::string name = segs ? std::to_string(segs) + " segments" : "peak 1/100 of the range wide";
      std::printf("| %d^2 x 9 | %s | %.0f | %.0f %% | %.2g | %.3g | %.3g |\n", n, name.c_str(), build,
                  100.0 * thin / samples, worstAlpha, worst, std::sqrt(sum / (3.0 * samples)));
    }

  std::printf("\n## 2D tables (rebuilt on every transfer-function edit)\n\n| table | TF points | build ms |\n|---|---:|---:|\n");
  for (int segs : {10, 255}) {
    const TransferFunction tf = segments(segs);
    auto t0 = Clock::now();
    const IsoDetectionTable iso(tf, 0.0, 1.0, 256);
    std::printf("| iso-detection 256^2 | %d | %.2f |\n", segs + 1, msSince(t0));
    std::vector<IsoSurface> surfaces;
    for (const auto& p : tf.points()) surfaces.push_back({p.value, p.color, 0.5});
    t0 = Clock::now();
    const IsoSurfaceTable roettger(surfaces, 0.0, 1.0, 256);
    std::printf("| Roettger iso-surface 256^2 | %d | %.2f |\n", segs + 1, msSince(t0));
  }
  return 0;
}

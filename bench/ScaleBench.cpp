// SPDX-License-Identifier: MIT
// How volpost scales with the mesh: for Kuhn grids of n^3 cubes x 6 tets (n = 64 is 1.6M
// tets, 128 is 12.6M, 256 is 100M), the time of each stage from a file to the first
// volume picture, the frame after it, and the host memory each stage needs. Each n runs in
// a process of its own (--measure), so one size's peak memory does not hide the next's.
//   volpost_scale_bench [--n 64,128,200,256] [--dir DIR] [--keep] [--size N] [--renderer raycast|cpu]
// The .vtu files are generated into DIR (default: the system's temporary folder) and
// removed afterwards unless --keep; at n = 256 the file is 4.4 GB.
#include "AllReaders.hpp"
#include "CpuVolumeRenderer.hpp"
#include "RayCaster.hpp"
#include "core/ModelSession.hpp"

#include <volpost/core/MeshChecks.hpp>
#include <volpost/render/HeadlessContext.hpp>
#include <volpost/render/OffscreenTarget.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

using namespace volpost;
using Clock = std::chrono::steady_clock;

namespace {

double secondsSince(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// Host memory from the kernel: what the process holds now and its peak since the last reset.
std::size_t statusBytes(const char* key) {
  std::ifstream in("/proc/self/status");
  std::string line;
  const std::size_t length = std::strlen(key);
  while (std::getline(in, line))
    if (line.compare(0, length, key) == 0) return std::size_t(std::stoull(line.substr(length + 1))) * 1024;
  return 0;
}
std::size_t residentBytes() { return statusBytes("VmRSS"); }
std::size_t peakBytes() { return statusBytes("VmHWM"); }
void resetPeak() { std::ofstream("/proc/self/clear_refs") << "5"; }  // VmHWM := VmRSS

// The Kuhn grid written straight to a .vtu (appended raw, UInt64 headers), never held in
// memory: points Float64, connectivity and offsets Int64 as VTK writes them, a nodal field
// "wave" in Float32.
void writeKuhnGrid(const std::filesystem::path& path, int n) {
  const std::uint64_t side = std::uint64_t(n) + 1, nodes = side * side * side, tets = std::uint64_t(n) * n * n * 6;
  const std::uint64_t pointBytes = nodes * 24, connBytes = tets * 32, offBytes = tets * 8, typeBytes = tets,
                      waveBytes = nodes * 4;
  std::ofstream out(path, std::ios::binary);
  std::uint64_t at = 0;
  const auto next = [&at](std::uint64_t bytes) {
    const std::uint64_t here = at;
    at += 8 + bytes;
    return here;
  };
  const std::uint64_t pointsAt = next(pointBytes), connAt = next(connBytes), offAt = next(offBytes), typeAt = next(typeBytes),
                      waveAt = next(waveBytes);
  out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
         "header_type=\"UInt64\">\n<UnstructuredGrid>\n<Piece NumberOfPoints=\"" << nodes << "\" NumberOfCells=\"" << tets
      << "\">\n<PointData Scalars=\"wave\">\n<DataArray type=\"Float32\" Name=\"wave\" format=\"appended\" offset=\"" << waveAt
      << "\"/>\n</PointData>\n<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"appended\" offset=\""
      << pointsAt << "\"/>\n</Points>\n<Cells>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"appended\" offset=\""
      << connAt << "\"/>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"appended\" offset=\"" << offAt
      << "\"/>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"appended\" offset=\"" << typeAt
      << "\"/>\n</Cells>\n</Piece>\n</UnstructuredGrid>\n<AppendedData encoding=\"raw\">\n_";
  const auto id = [side](std::uint64_t i, std::uint64_t j, std::uint64_t k) { return std::int64_t((k * side + j) * side + i); };
  std::vector<char> chunk;
  const auto put = [&](const auto& value) {
    const char* bytes = reinterpret_cast<const char*>(&value);
    chunk.insert(chunk.end(), bytes, bytes + sizeof value);
    if (chunk.size() > (8u << 20)) {
      out.write(chunk.data(), std::streamsize(chunk.size()));
      chunk.clear();
    }
  };
  put(pointBytes);
  for (std::uint64_t k = 0; k < side; ++k)
    for (std::uint64_t j = 0; j < side; ++j)
      for (std::uint64_t i = 0; i < side; ++i) put(glm::dvec3(double(i), double(j), double(k)));
  put(connBytes);
  for (std::uint64_t k = 0; k < std::uint64_t(n); ++k)
    for (std::uint64_t j = 0; j < std::uint64_t(n); ++j)
      for (std::uint64_t i = 0; i < std::uint64_t(n); ++i) {
        int axes[3] = {0, 1, 2};
        do {  // one tet per path from corner (i,j,k) to the opposite corner
          std::uint64_t c[3] = {i, j, k};
          std::int64_t t[4];
          t[0] = id(c[0], c[1], c[2]);
          for (int s = 0; s < 3; ++s) {
            ++c[axes[s]];
            t[s + 1] = id(c[0], c[1], c[2]);
          }
          const bool odd = (axes[0] == 1 && axes[1] == 0) || (axes[0] == 0 && axes[1] == 2) || (axes[0] == 2 && axes[1] == 1);
          if (odd) std::swap(t[2], t[3]);  // mirrored paths: swap two nodes for a positive volume
          for (std::int64_t v : t) put(v);
        } while (std::next_permutation(axes, axes + 3));
      }
  put(offBytes);
  for (std::uint64_t c = 1; c <= tets; ++c) put(std::int64_t(4 * c));
  put(typeBytes);
  for (std::uint64_t c = 0; c < tets; ++c) put(std::uint8_t(10));
  put(waveBytes);
  for (std::uint64_t k = 0; k < side; ++k)
    for (std::uint64_t j = 0; j < side; ++j)
      for (std::uint64_t i = 0; i < side; ++i)
        put(float(std::sin(6.0 * double(i) / n) * std::cos(5.0 * double(j) / n) + 0.5 * std::sin(7.0 * double(k) / n)));
  out.write(chunk.data(), std::streamsize(chunk.size()));
  out << "\n</AppendedData>\n</VTKFile>\n";
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

std::unique_ptr<VolumeRenderer> makeRenderer(const std::string& name) {
  if (name == "raycast") return std::make_unique<volume::RayCaster>();
  if (name == "cpu") return std::make_unique<volume::CpuVolumeRenderer>();
  throw std::invalid_argument("--renderer " + name + " is not raycast or cpu");
}

// One size, in this process: each stage's seconds and the peak host memory above the
// starting point, printed as KEY=VALUE for the parent.
int measure(const std::string& path, const std::string& rendererName, int size) {
  HeadlessContext context;
  OffscreenTarget target(size, size);
  std::map<std::string, double> out;
  const std::size_t base = residentBytes();
  resetPeak();
  auto t = Clock::now();
  const auto& registry = meshio::allReadersRegistry();
  std::shared_ptr<Model> model = registry.choose(path).read(path, {});
  out["read_s"] = secondsSince(t);
  out["read_peak"] = double(peakBytes() - base);
  out["read_kept"] = double(residentBytes() - base);
  t = Clock::now();
  checkModel(*model);
  out["checks_s"] = secondsSince(t);
  out["checks_peak"] = double(peakBytes() - base);
  out["checks_kept"] = double(residentBytes() - base);
  t = Clock::now();
  const auto session = app::ModelSession::fromModel(model);
  out["session_s"] = secondsSince(t);
  const double tets = double(model->mesh().cellCount());
  out["tets"] = tets;
  t = Clock::now();
  const TetMesh& tetMesh = session->tetrahedra();
  out["tetrahedra_s"] = secondsSince(t);
  out["tetrahedra_kept"] = double(residentBytes() - base);
  t = Clock::now();
  const app::ScalarView view = session->evaluate(session->findQuantity("wave"), 0);
  const std::vector<double> values = session->tetValues(view);
  out["values_s"] = secondsSince(t);
  out["values_peak"] = double(peakBytes() - base);
  out["values_kept"] = double(residentBytes() - base);
  auto renderer = makeRenderer(rendererName);
  renderer->initialize();
  t = Clock::now();
  renderer->setVolume(tetMesh.mesh, view.location, values);
  renderer->setTransferFunction(TransferFunction::ramp(view.range.min, view.range.max, "cool-warm", 4.0 / std::cbrt(tets / 6.0), 11));
  out["build_s"] = secondsSince(t);
  out["build_peak"] = double(peakBytes() - base);
  out["build_kept"] = double(residentBytes() - base);
  RenderContext ctx;
  ctx.width = ctx.height = size;
  ctx.framebuffer = target.framebuffer();
  ctx.camera.setView(StandardView::Isometric);
  ctx.camera.fit(model->mesh().bounds());
  t = Clock::now();
  renderer->render(ctx);
  glFinish();
  out["first_frame_s"] = secondsSince(t);
  ctx.camera.orbit(30.0, 10.0);
  t = Clock::now();
  renderer->render(ctx);
  glFinish();
  out["frame_s"] = secondsSince(t);
  out["volume_peak"] = double(peakBytes() - base);
  out["volume_kept"] = double(residentBytes() - base);
  out["gpu_bytes"] = double(renderer->stats().gpuBytes);
  renderer->release();
  // The boundary surface: what the surface view needs, not a volume picture.
  resetPeak();
  const std::size_t before = residentBytes();
  t = Clock::now();
  (void)session->surface();
  out["boundary_s"] = secondsSince(t);
  out["boundary_peak"] = double(peakBytes() - before);
  std::printf("MEASURE");
  for (const auto& [key, value] : out) std::printf(" %s=%.17g", key.c_str(), value);
  std::printf("\n");
  return 0;
}

std::map<std::string, double> runChild(const char* self, const std::filesystem::path& file, const std::string& renderer,
                                       int size) {
  const std::string command = "'" + std::string(self) + "' --measure '" + file.string() + "' --renderer " + renderer +
                              " --size " + std::to_string(size);
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) throw std::runtime_error("cannot run " + command);
  std::map<std::string, double> result;
  char line[4096];
  while (std::fgets(line, sizeof line, pipe)) {
    if (std::strncmp(line, "MEASURE", 7) != 0) continue;
    std::istringstream words(line + 7);
    std::string word;
    while (words >> word)
      if (const auto eq = word.find('='); eq != std::string::npos) result[word.substr(0, eq)] = std::stod(word.substr(eq + 1));
  }
  const int status = pclose(pipe);
  if (status != 0 || result.empty()) throw std::runtime_error("the measurement of " + file.string() + " failed");
  return result;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<int> sizes = {64, 128};
  std::filesystem::path dir = std::filesystem::temp_directory_path();
  bool keep = false;
  int size = 512;
  std::string renderer = "raycast";
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--measure" && i + 1 < argc) {
      const std::string path = argv[++i];
      for (int j = i + 1; j + 1 < argc; j += 2) {
        if (!std::strcmp(argv[j], "--renderer")) renderer = argv[j + 1];
        if (!std::strcmp(argv[j], "--size")) size = std::atoi(argv[j + 1]);
      }
      try {
        return measure(path, renderer, size);
      } catch (const std::exception& e) {
        std::fprintf(stderr, "volpost_scale_bench: %s\n", e.what());
        return 1;
      }
    } else if (a == "--n" && i + 1 < argc) {
      sizes.clear();
      std::istringstream list(argv[++i]);
      std::string item;
      while (std::getline(list, item, ',')) sizes.push_back(std::atoi(item.c_str()));
    } else if (a == "--dir" && i + 1 < argc) {
      dir = argv[++i];
    } else if (a == "--keep") {
      keep = true;
    } else if (a == "--size" && i + 1 < argc) {
      size = std::atoi(argv[++i]);
    } else if (a == "--renderer" && i + 1 < argc) {
      renderer = argv[++i];
    } else {
      const bool help = a == "--help" || a == "-h";
      std::fprintf(help ? stdout : stderr,
                   "volpost_scale_bench: time and host memory of each stage from a file to the first volume picture\n"
                   "usage: volpost_scale_bench [--n 64,128,200,256] [--dir DIR] [--keep] [--size N] [--renderer raycast|cpu]\n"
                   "  --n LIST        grid sizes: n^3 cubes of 6 tetrahedra each (default 64,128)\n"
                   "  --dir DIR       where the generated .vtu files go (default: the temporary folder)\n"
                   "  --keep          keep them (a later run reuses them)\n"
                   "  --size N        picture N x N (default 512)\n"
                   "  --renderer R    raycast (GPU, default) or cpu\n");
      return help ? 0 : 2;
    }
  }
  for (int n : sizes)
    if (n < 1 || n > 1000) {
      std::fprintf(stderr, "volpost_scale_bench: --n takes sizes from 1 to 1000\n");
      return 2;
    }
  std::printf("renderer %s, picture %dx%d; host peak = the process's largest resident size above its start, per tet; "
              "host kept = what it holds after the frames; the boundary (surface view only) measured after the "
              "picture\n\n", renderer.c_str(), size, size);
  std::printf("| n | tets | file MB | write s | read s | checks s | tetrahedra s | values s | renderer build s | first frame s | "
              "to first picture s | frame ms | host peak B/tet | host kept B/tet | read peak B/tet | GPU B/tet | boundary s (B/tet) |\n");
  std::printf("|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (int n : sizes) {
    const std::filesystem::path file = dir / ("volpost_kuhn_" + std::to_string(n) + ".vtu");
    double writeS = 0.0;
    try {
      if (!std::filesystem::exists(file)) {
        const auto t = Clock::now();
        writeKuhnGrid(file, n);
        writeS = secondsSince(t);
      }
      const double mb = double(std::filesystem::file_size(file)) / 1048576.0;
      auto r = runChild(argv[0], file, renderer, size);
      const double tets = r["tets"];
      const double toPicture = r["read_s"] + r["checks_s"] + r["session_s"] + r["tetrahedra_s"] + r["values_s"] + r["build_s"] +
                               r["first_frame_s"];
      std::printf("| %d | %.0f | %.0f | %.1f | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %.1f | %.0f | %.0f | %.0f | %.0f | %.1f | %.2f (%.0f) |\n",
                  n, tets, mb, writeS, r["read_s"], r["checks_s"], r["tetrahedra_s"], r["values_s"], r["build_s"],
                  r["first_frame_s"], toPicture, 1e3 * r["frame_s"], r["volume_peak"] / tets, r["volume_kept"] / tets,
                  r["read_peak"] / tets,
                  r["gpu_bytes"] / tets, r["boundary_s"], r["boundary_peak"] / tets);
      if (r["session_s"] > 0.05) std::printf("(the session itself took %.2f s)\n", r["session_s"]);
      std::fflush(stdout);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "volpost_scale_bench: n = %d: %s\n", n, e.what());
    }
    if (!keep) std::filesystem::remove(file);
  }
  return 0;
}

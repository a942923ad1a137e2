// SPDX-License-Identifier: MIT
// Reading and tetrahedralizing large models: the biggest files of ../shared/data in every
// format, and a generated 1M-cell hexahedral block written as Gmsh (ASCII and binary),
// Abaqus deck and VTU. Each case runs in its own child process so its peak memory (max
// RSS) is its own. Prints a Markdown table.
//   volpost_read_bench [--cells-per-axis N] [--keep DIR]
#include "BenchUsage.hpp"

#include "AllReaders.hpp"

#include <volpost/core/ReaderRegistry.hpp>
#include <volpost/core/Tetrahedralize.hpp>
#include "host/VtuWriter.hpp"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

using namespace volpost;
using Clock = std::chrono::steady_clock;

namespace {

double ms(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double, std::milli>(b - a).count(); }

const ReaderRegistry& readers() { return meshio::allReadersRegistry(); }

// n^3 unit hexahedra with a nodal field, in four files.
std::vector<std::string> writeHexBlock(int n, const std::string& dir) {
  const int p = n + 1;
  const auto id = [p](int i, int j, int k) { return std::int64_t(k) * p * p + std::int64_t(j) * p + i + 1; };
  const std::string msh = dir + "/hex_block.msh", mshBinary = dir + "/hex_block_binary.msh", inp = dir + "/hex_block.inp",
                    vtu = dir + "/hex_block.vtu";
  const std::int64_t nodes = std::int64_t(p) * p * p, cells = std::int64_t(n) * n * n;
  {
    std::ofstream out(msh);
    std::ofstream bin(mshBinary, std::ios::binary);
    std::ofstream deck(inp);
    out << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 " << nodes << " 1 " << nodes << "\n3 1 0 " << nodes << "\n";
    bin << "$MeshFormat\n4.1 1 8\n";
    const std::int32_t one = 1;
    bin.write(reinterpret_cast<const char*>(&one), 4);
    bin << "\n$EndMeshFormat\n$Nodes\n";
    const auto put = [&](auto v) { bin.write(reinterpret_cast<const char*>(&v), sizeof v); };
    put(std::uint64_t(1)), put(std::uint64_t(nodes)), put(std::uint64_t(1)), put(std::uint64_t(nodes));
    put(std::int32_t(3)), put(std::int32_t(1)), put(std::int32_t(0)), put(std::uint64_t(nodes));
    deck << "*HEADING\nhex block\n*NODE\n";
    for (std::int64_t i = 1; i <= nodes; ++i) out << i << "\n", put(std::uint64_t(i));
    for (int k = 0; k < p; ++k)
      for (int j = 0; j < p; ++j)
        for (int i = 0; i < p; ++i) {
          out << i << " " << j << " " << k << "\n";
          put(double(i)), put(double(j)), put(double(k));
          deck << id(i, j, k) << ", " << i << ", " << j << ", " << k << "\n";
        }
    out << "$EndNodes\n$Elements\n1 " << cells << " 1 " << cells << "\n3 1 5 " << cells << "\n";
    bin << "\n$EndNodes\n$Elements\n";
    put(std::uint64_t(1)), put(std::uint64_t(cells)), put(std::uint64_t(1)), put(std::uint64_t(cells));
    put(std::int32_t(3)), put(std::int32_t(1)), put(std::int32_t(5)), put(std::uint64_t(cells));
    deck << "*ELEMENT, TYPE=C3D8, ELSET=BLOCK\n";
    std::int64_t e = 1;
    for (int k = 0; k < n; ++k)
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i, ++e) {
          const std::int64_t c[8] = {id(i, j, k),         id(i + 1, j, k),         id(i + 1, j + 1, k),         id(i, j + 1, k),
                                     id(i, j, k + 1),     id(i + 1, j, k + 1),     id(i + 1, j + 1, k + 1),     id(i, j + 1, k + 1)};
          out << e;
          deck << e;
          put(std::uint64_t(e));
          for (std::int64_t v : c) out << " " << v, deck << ", " << v, put(std::uint64_t(v));
          out << "\n";
          deck << "\n";
        }
    out << "$EndElements\n";
    bin << "\n$EndElements\n";
  }
  const auto model = readers().load(msh);
  writeVtu(*model, vtu);
  return {msh, mshBinary, inp, vtu};
}

// Runs in the child: read, tetrahedralize, print one row (without the memory column).
void measure(const std::string& path) {
  const auto t0 = Clock::now();
  const auto model = readers().load(path);
  const auto t1 = Clock::now();
  const TetMesh tets = tetrahedralize(model->mesh());
  const auto t2 = Clock::now();
  std::printf("| %s | %s | %zu | %zu | %.0f | %.0f | %zu | %zu |", std::filesystem::path(path).filename().c_str(),
              model->formatName.c_str(), model->mesh().cellCount(), std::size_t(std::filesystem::file_size(path) >> 20),
              ms(t0, t1), ms(t1, t2), tets.mesh.cellCount(), tets.steinerCell.size());
  std::fflush(stdout);
}

void runIsolated(const std::string& path) {
  std::fflush(stdout);  // or the child would print the parent's buffered text again
  const pid_t child = fork();
  if (child == 0) {
    try {
      measure(path);
    } catch (const std::exception& e) {
      std::printf("| %s | error: %s |", path.c_str(), e.what());
    }
    std::fflush(stdout);
    _exit(0);
  }
  int status = 0;
  rusage usage{};
  wait4(child, &status, 0, &usage);
  std::printf(" %.0f |\n", double(usage.ru_maxrss) / 1024.0);
}

}  // namespace

int main(int argc, char** argv) {
  int n = 100;
  std::string keep;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--cells-per-axis") && i + 1 < argc) n = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--keep") && i + 1 < argc) keep = argv[++i];
    else
      return volpost::bench::usageFor(argv[i], "volpost_read_bench: reading speed and memory of every format\n"
                                               "usage: volpost_read_bench [--cells-per-axis N] [--keep DIR]\n");
  }
  std::vector<std::string> files;
  const std::filesystem::path shared = VOLPOST_SHARED_DATA;
  for (const char* f : {"post/fine/post_fine.vtu", "post/fine/post_fine.vtk", "post/fine/post_fine.msh",
                        "post/fine/post_fine_v22.msh", "post/fine/post_fine.exo", "wheel/mixed/wheel_mixed.inp",
                        "wheel/mixed/wheel_mixed.frd", "bracket/tet10/bracket_tet10.frd"})
    if (std::filesystem::exists(shared / f)) files.push_back((shared / f).string());
  const std::string dir = keep.empty() ? (std::filesystem::temp_directory_path() / "volpost_read_bench").string() : keep;
  std::filesystem::create_directories(dir);
  std::fprintf(stderr, "writing a %d^3 hexahedral block to %s ...\n", n, dir.c_str());
  const auto t0 = Clock::now();
  // Written by a child, so the parent (whose memory every measured child starts with)
  // stays small.
  std::fflush(stdout);
  if (const pid_t writer = fork(); writer == 0) {
    writeHexBlock(n, dir);
    _exit(0);
  } else {
    int status = 0;
    waitpid(writer, &status, 0);
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
      std::fprintf(stderr, "writing the hexahedral block failed\n");
      return 1;
    }
  }
  for (const char* name : {"hex_block.msh", "hex_block_binary.msh", "hex_block.inp", "hex_block.vtu"})
    files.push_back(dir + "/" + name);
  std::fprintf(stderr, "written in %.1f s\n", ms(t0, Clock::now()) / 1000.0);
  std::printf("| file | format | cells | MiB | read ms | tetrahedralize ms | tets | Steiner points | peak RSS MiB |\n");
  std::printf("|---|---|---:|---:|---:|---:|---:|---:|---:|\n");
  std::fflush(stdout);
  for (const auto& f : files) runIsolated(f);
  if (keep.empty()) std::filesystem::remove_all(dir);
  return 0;
}

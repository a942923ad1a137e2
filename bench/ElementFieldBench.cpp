// SPDX-License-Identifier: MIT
// What the cells' own field costs the CPU ray caster, and what drawing the split's field
// instead is off by: for each cell type on [0,1]^3 (n^3 cubes; tetrahedra, wedges and
// pyramids cut from them), the CPU renderer's ms per frame (wall and CPU) and memory with
// the tetrahedra's field and with the cells' own, and each picture's error against the
// reference drawing the cells' own field (same camera, transfer function and image size).
// Prints a Markdown table.
// The own field is drawn at each tolerance asked for (0: integrated to rounding).
//   volpost_element_field_bench [--size N] [--frames N] [--cubes N,N,...] [--threads N] [--cells TYPE]
//                               [--tolerances E,E,...] [--refined] [--bent]
// --refined adds a table of the other path: the split refined in the cells' natural
// coordinates to the tolerance (what the renderers of tetrahedra are given), its pieces
// drawn linear by the CPU ray caster, against the same reference.
#include "BenchUsage.hpp"
#include "CpuRayCaster.hpp"
#include "host/AdaptiveElementRefinement.hpp"
#include "host/ElementRefinement.hpp"
#include "host/optics/ReferenceRenderer.hpp"

#include <volpost/core/CellShape.hpp>
#include <volpost/core/Tetrahedralize.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <map>
#include <memory>
#include <string>
#include <vector>

using namespace volpost;
using Clock = std::chrono::steady_clock;

namespace {

using Lattice = std::array<int, 3>;  // position in half-cube steps

// The corners of the cells cut from the cube at 2 (i, j, k), in each type's corner order.
std::vector<std::vector<Lattice>> cellsOfCube(CellType type) {
  const Lattice c000{0, 0, 0}, c200{2, 0, 0}, c220{2, 2, 0}, c020{0, 2, 0}, c002{0, 0, 2}, c202{2, 0, 2}, c222{2, 2, 2},
      c022{0, 2, 2}, centre{1, 1, 1};
  switch (type) {
    case CellType::Hex8:
    case CellType::Hex20:
      return {{c000, c200, c220, c020, c002, c202, c222, c022}};
    case CellType::Wedge6:
    case CellType::Wedge15:
      return {{c000, c200, c020, c002, c202, c022}, {c200, c220, c020, c202, c222, c022}};
    case CellType::Pyramid5:
      return {{c000, c020, c220, c200, centre}, {c002, c202, c222, c022, centre}, {c000, c200, c202, c002, centre},
              {c020, c022, c222, c220, centre}, {c000, c002, c022, c020, centre}, {c200, c220, c222, c202, centre}};
    case CellType::Tet4:
    case CellType::Tet10: {
      std::vector<std::vector<Lattice>> tets;  // one per path from (0,0,0) to (2,2,2) along the axes
      int axes[3] = {0, 1, 2};
      do {
        Lattice p{0, 0, 0};
        std::vector<Lattice> t{p};
        for (int a : axes) p[std::size_t(a)] += 2, t.push_back(p);
        tets.push_back(t);
      } while (std::next_permutation(axes, axes + 3));
      return tets;
    }
  }
  return {};
}

// Swaps corners so that a cell generated with the other handedness becomes positive.
void turnOver(CellType type, std::vector<Lattice>& corners) {
  switch (type) {
    case CellType::Tet4:
    case CellType::Tet10:
      std::swap(corners[1], corners[2]);
      break;
    case CellType::Wedge6:
    case CellType::Wedge15:
      std::swap(corners[1], corners[2]), std::swap(corners[4], corners[5]);
      break;
    case CellType::Pyramid5:
      std::swap(corners[1], corners[3]);
      break;
    case CellType::Hex8:
    case CellType::Hex20:
      std::swap(corners[1], corners[3]), std::swap(corners[5], corners[7]);
      break;
  }
}

double wave(const glm::dvec3& x) {
  return std::sin(3.0 * x.x) * std::cos(2.0 * x.y) + 0.5 * std::sin(4.0 * x.z + 2.0 * x.x);
}

struct Model {
  Mesh mesh;
  std::vector<double> values;
};

// The cube [0,1]^3 bent into a quarter of an annulus (radii 1 to 2 about the z axis): every
// node, midside nodes too, goes through it, so quadratic cells follow the arcs with their
// curved edges and faces, and the corners of linear cells lie on them.
glm::dvec3 bent(const glm::dvec3& p) {
  const double r = 1.0 + p.x, angle = 0.5 * std::acos(-1.0) * p.y;
  return {r * std::cos(angle), r * std::sin(angle), p.z};
}

Model modelOf(CellType type, int n, bool bend) {
  Model m;
  std::map<Lattice, NodeIndex> index;
  const auto node = [&](const Lattice& l) {
    const auto [it, fresh] = index.emplace(l, NodeIndex(m.mesh.nodes.size()));
    if (fresh) m.mesh.nodes.push_back(glm::dvec3(l[0], l[1], l[2]) / (2.0 * n));
    return it->second;
  };
  const CellTopology& topo = topology(type);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k)
        for (std::vector<Lattice> corners : cellsOfCube(type)) {
          for (Lattice& l : corners) l = {l[0] + 2 * i, l[1] + 2 * j, l[2] + 2 * k};
          for (int attempt = 0; attempt < 2; ++attempt) {
            std::vector<Lattice> all = corners;
            all.resize(std::size_t(topo.nodeCount));
            for (const CellEdge& e : topo.edges)
              if (e.mid >= 0)
                for (int a = 0; a < 3; ++a)
                  all[std::size_t(e.mid)][std::size_t(a)] =
                      (corners[e.a][std::size_t(a)] + corners[e.b][std::size_t(a)]) / 2;
            std::vector<glm::dvec3> at;
            for (const Lattice& l : all) at.push_back(glm::dvec3(l[0], l[1], l[2]));
            if (attempt == 0 && !mapInvertible(type, at)) {
              turnOver(type, corners);
              continue;
            }
            std::vector<NodeIndex> ids;
            for (const Lattice& l : all) ids.push_back(node(l));
            m.mesh.addCell(type, ids);
            break;
          }
        }
  if (bend)
    for (glm::dvec3& p : m.mesh.nodes) p = bent(p);
  for (const glm::dvec3& p : m.mesh.nodes) m.values.push_back(wave(p));
  return m;
}

TransferFunction sharpPeak() {
  return TransferFunction({{-1.6, {0.2, 0.3, 0.9}, 0.0},
                           {0.30, {0.2, 0.6, 0.9}, 0.0},
                           {0.40, {1.0, 0.7, 0.2}, 40.0},
                           {0.50, {0.9, 0.2, 0.1}, 0.0},
                           {1.6, {0.9, 0.2, 0.1}, 0.0}});
}

double rmse(const std::vector<float>& image, const optics::ReferenceImage& ref) {
  double sum = 0.0;
  for (std::size_t i = 0; i < ref.pixels.size(); ++i)
    for (int k = 0; k < 4; ++k) {
      const double d = double(image[4 * i + std::size_t(k)]) - ref.pixels[i][k];
      sum += d * d;
    }
  return std::sqrt(sum / double(4 * ref.pixels.size()));
}

double largestError(const std::vector<float>& image, const optics::ReferenceImage& ref) {
  double most = 0.0;
  for (std::size_t i = 0; i < ref.pixels.size(); ++i)
    for (int k = 0; k < 4; ++k)
      most = std::max(most, std::abs(double(image[4 * i + std::size_t(k)]) - ref.pixels[i][k]));
  return most;
}

// "1e-3,0" -> {1e-3, 0}; empty where a number does not read.
std::vector<double> numbersIn(const char* list) {
  std::vector<double> out;
  for (const char* p = list; *p;) {
    char* end = nullptr;
    const double v = std::strtod(p, &end);
    if (end == p || !(v >= 0.0)) return {};
    out.push_back(v);
    p = *end == ',' ? end + 1 : end;
    if (*end && *end != ',') return {};
  }
  return out;
}

struct Timing {
  double wallMs = 0.0, cpuMs = 0.0;
  std::vector<float> first;
};

// Frames along a quarter orbit: the median wall and CPU ms per frame, and the first frame.
Timing timeFrames(const volume::TetWalkMesh& walk, const volume::VisiblePart& part, const TransferFunction& tf,
                  const Camera& camera, int size, const volume::CpuRaySettings& settings, int frames, int threads) {
  std::vector<double> wall, cpu;
  Timing t;
  for (int f = 0; f < frames; ++f) {
    Camera orbit = camera;
    orbit.orbit(90.0 * f / std::max(1, frames), 0.0);
    const auto start = Clock::now();
    const std::clock_t startCpu = std::clock();
    volume::CpuImage image = volume::renderCpu(walk, part, tf, orbit, size, size, settings, {}, threads);
    cpu.push_back(1000.0 * double(std::clock() - startCpu) / CLOCKS_PER_SEC);
    wall.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
    if (f == 0) t.first = std::move(image.rgba);
  }
  std::sort(wall.begin(), wall.end());
  std::sort(cpu.begin(), cpu.end());
  t.wallMs = wall[wall.size() / 2];
  t.cpuMs = cpu[cpu.size() / 2];
  return t;
}

struct RefinedRow {
  std::string cells, method;
  int n = 0;
  std::size_t count = 0, tets = 0;
  double tolerance = 0.0;
  int level = 1;
  std::size_t pieces = 0;
  double refineMs = 0.0, wallMs = 0.0, cpuMs = 0.0;
  std::size_t bytes = 0;
  double rmse = 0.0, largest = 0.0, deviation = 0.0;
};

}  // namespace

int main(int argc, char** argv) {
  int size = 256, frames = 5, threads = 0;
  std::vector<int> cubes{8, 16};
  std::string only;  // one cell type's name, or all
  std::vector<double> tolerances{1e-3, 0.0};
  bool refinedRows = false, bend = false;
  std::vector<RefinedRow> refinedTable;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const bool more = i + 1 < argc;
    if (a == "--size" && more) size = std::atoi(argv[++i]);
    else if (a == "--frames" && more) frames = std::atoi(argv[++i]);
    else if (a == "--threads" && more) threads = std::atoi(argv[++i]);
    else if (a == "--cells" && more) only = argv[++i];
    else if (a == "--tolerances" && more) tolerances = numbersIn(argv[++i]);
    else if (a == "--refined") refinedRows = true;
    else if (a == "--bent") bend = true;
    else if (a == "--cubes" && more) {
      cubes.clear();
      for (const char* p = argv[++i]; *p;) {
        cubes.push_back(std::atoi(p));
        while (*p && *p != ',') ++p;
        if (*p == ',') ++p;
      }
    } else {
      return bench::usageFor(
          argv[i],
          "volpost_element_field_bench: the CPU ray caster with the tetrahedra's field and with the "
          "cells' own, per cell type: ms per frame, memory, error against the exact reference\n"
          "  --size N        image N x N (default 256)\n"
          "  --frames N      frames along a quarter orbit; the median is printed (default 5)\n"
          "  --cubes N,...   meshes of N^3 cubes on [0,1]^3 (default 8,16)\n"
          "  --threads N     threads (default: all cores)\n"
          "  --cells TYPE    one cell type only (tet4, tet10, hex8, hex20, wedge6, wedge15, pyramid5)\n"
          "  --tolerances E,...  the own field's tolerances per pixel channel (default 1e-3,0; 0: to "
          "rounding)\n"
          "  --refined       also the split refined to each tolerance (what raycast and vicp draw), its "
          "pieces drawn linear\n"
          "  --bent          the meshes bent into a quarter of an annulus (radii 1 to 2), every node on it: "
          "curved quadratic cells\n");
    }
  }
  if (size < 8 || frames < 1 || cubes.empty() || tolerances.empty() ||
      std::any_of(cubes.begin(), cubes.end(), [](int n) { return n < 1 || n > 64; })) {
    std::fprintf(stderr, "--size >= 8, --frames >= 1, --cubes between 1 and 64, --tolerances numbers >= 0\n");
    return 2;
  }
  const TransferFunction tf = sharpPeak();
  std::printf(
      "CPU ray caster, %dx%d, iso camera orbiting a quarter turn (median of %d frames), transfer function "
      "peaked at 0.4 (extinction 40); error: RMSE of premultiplied RGBA against the reference drawing the "
      "cells' own field; %s\n\n",
      size, size, frames,
      bend ? "the cubes bent into a quarter annulus (radii 1 to 2), midside nodes on its arcs" : "straight cubes");
  std::printf(
      "| cells | n | count | tets | split: ms wall / CPU | split: bytes | split: RMSE | tolerance | own field: ms "
      "wall / CPU | own field: bytes | own field: RMSE | own field: largest | drawn by the split "
      "|\n|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (const int n : cubes)
    for (const CellType type : kAllCellTypes) {
      if (!only.empty() && only != cellTypeName(type)) continue;
      const Model model = modelOf(type, n, bend);
      const TetMesh split = tetrahedralize(model.mesh);
      const std::vector<double> tetValues = split.nodeValues(model.mesh, model.values);
      const volume::TetWalkMesh walk(split.mesh, FieldLocation::Node, tetValues);
      auto element = std::make_shared<volume::CpuElementField>();
      element->field = std::make_shared<const optics::ElementField>(model.mesh, model.values, split, walk.origin());
      for (std::size_t t = 0; t < walk.tetCount(); ++t) element->cellOfTet.push_back(split.sourceCell(walk.meshTet(t)));

      Camera camera;
      camera.setView(StandardView::Isometric);
      camera.fit(model.mesh.bounds());
      volume::CpuRaySettings linear;
      linear.terminationTransmittance = 0.0;
      const volume::VisiblePart linearPart = volume::findVisiblePart(walk, tf, {}, threads);
      const volume::VisiblePart ownPart = volume::findVisiblePart(walk, tf, {}, threads, element.get());
      const Timing a = timeFrames(walk, linearPart, tf, camera, size, linear, frames, threads);

      const optics::TetVolume volume(split.mesh, FieldLocation::Node, tetValues);
      const optics::ElementField field(model.mesh, model.values, split, volume.origin());
      optics::RaySettings exact;
      exact.elementField = &field;
      const optics::ReferenceImage reference =
          optics::renderReference(volume, tf, camera, size, size, exact, {}, threads);
      const std::size_t walkBytes = walk.bytes();
      const std::size_t elementBytes = model.values.size() * sizeof(double) + model.mesh.cellCount() +
                                       element->cellOfTet.size() * sizeof(std::uint32_t);
      for (const double tolerance : tolerances) {
        volume::CpuRaySettings own = linear;
        own.element = element;
        own.elementTolerance = tolerance;
        const Timing b = timeFrames(walk, ownPart, tf, camera, size, own, frames, threads);
        std::printf("| %s | %d | %zu | %zu | %.1f / %.1f | %zu | %.2g | %g | %.1f / %.1f | %zu | %.2g | %.2g | %zu |\n",
                    std::string(cellTypeName(type)).c_str(), n, model.mesh.cellCount(), walk.tetCount(), a.wallMs,
                    a.cpuMs, walkBytes, rmse(a.first, reference), tolerance, b.wallMs, b.cpuMs,
                    walkBytes + elementBytes, rmse(b.first, reference), largestError(b.first, reference),
                    field.uninvertibleCells().size());
        std::fflush(stdout);
      }
      if (refinedRows) {
        for (const double tolerance : tolerances) {
          if (tolerance <= 0.0) continue;  // pieces cannot be exact
          std::vector<std::uint32_t> all(split.mesh.cellCount());
          for (std::size_t t = 0; t < all.size(); ++t) all[t] = std::uint32_t(t);
          for (const bool bisected : {false, true}) {
            const auto start = Clock::now();
            VolumeRefinementGoal goal;
            goal.perChannel = tolerance;
            goal.transferFunction = &tf;
            const RefinedTetrahedra refined = bisected
                                                  ? refineVolumeAdaptively(field, all, goal)
                                                  : refineTetrahedra(field, all, limitsForElementTolerance(tolerance));
            const double refineMs = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
            const volume::TetWalkMesh pieces(refined.tets.mesh, FieldLocation::Node, refined.values);
            const volume::VisiblePart part = volume::findVisiblePart(pieces, tf, {}, threads);
            const Timing c = timeFrames(pieces, part, tf, camera, size, linear, frames, threads);
            refinedTable.push_back({std::string(cellTypeName(type)), bisected ? "bisected" : "uniform", n,
                                    model.mesh.cellCount(), walk.tetCount(), tolerance,
                                    bisected ? refined.bisections : refined.level, refined.tets.mesh.cellCount(),
                                    refineMs, c.wallMs, c.cpuMs, pieces.bytes(), rmse(c.first, reference),
                                    largestError(c.first, reference), refined.deviation});
          }
        }
      }
    }
  if (!refinedTable.empty()) {
    std::printf(
        "\nThe cells' own field on the split refined to the tolerance, drawn here by the CPU ray caster as "
        "linear pieces: uniform (each split tetrahedron cut `level` times along each edge, what surfaces use) "
        "and bisected (longest-edge bisection where the transfer function shows the field, up to `level` "
        "halvings: what the renderers of tetrahedra, raycast and vicp, are given)\n\n"
        "| cells | n | count | tets | tolerance | method | level | pieces | refine ms | ms wall / CPU | bytes | RMSE | "
        "largest | estimated deviation |\n|---|---:|---:|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    for (const RefinedRow& r : refinedTable)
      std::printf("| %s | %d | %zu | %zu | %g | %s | %d | %zu | %.0f | %.1f / %.1f | %zu | %.2g | %.2g | %.2g |\n",
                  r.cells.c_str(), r.n, r.count, r.tets, r.tolerance, r.method.c_str(), r.level, r.pieces, r.refineMs,
                  r.wallMs, r.cpuMs, r.bytes, r.rmse, r.largest, r.deviation);
  }
  return 0;
}

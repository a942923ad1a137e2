// SPDX-License-Identifier: MIT
#include "host/optics/ReferenceRenderer.hpp"

#include <volpost/core/optics/ElementStretch.hpp>
#include <volpost/core/optics/Headlight.hpp>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_inverse.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <limits>
#include <mutex>
#include <optional>
#include <thread>

#include <volpost/core/WorkerThreads.hpp>

namespace volpost::optics {
namespace {

// A tet's part of the ray, or (tet == kOwnShape) a curved cell's, found on its own shape.
constexpr std::uint32_t kOwnShape = 0xffffffffu;
struct Interval {
  double t0, t1;
  std::uint32_t tet;
  std::uint32_t cell = 0;  ///< with kOwnShape
  bool operator<(const Interval& o) const { return t0 < o.t0 || (t0 == o.t0 && t1 < o.t1); }
};

// Restricts [t0, t1] to where A + t B > 0 (or == 0 on the inside of the perturbation).
// Returns false when nothing is left.
bool clipHalfSpace(double a, double b, bool tieInside, double& t0, double& t1) {
  if (b == 0.0) return a > 0.0 || (a == 0.0 && tieInside);
  const double t = -a / b;
  if (b > 0.0) t0 = std::max(t0, t);
  else t1 = std::min(t1, t);
  return t0 < t1;
}

// Intervals of the ray inside each tet and the clip half-spaces, sorted front to back.
std::vector<Interval> intervals(const TetVolume& volume, const glm::dvec3& o, const glm::dvec3& d, double tMin,
                                double tMax, const RaySettings& settings) {
  std::vector<Interval> out;
  volume.forEachCandidate(o, d, tMin, tMax, [&](std::uint32_t index) {
    const PreparedTet& tet = volume.tet(index);
    double t0 = tMin, t1 = tMax;
    for (const TetPlane& p : tet.planes)
      if (!clipHalfSpace(glm::dot(p.normal, o) - p.offset, glm::dot(p.normal, d), p.tieInside, t0, t1)) return;
    for (const ClipPlane& c : settings.clipPlanes) {
      const glm::dvec3 point = c.point - volume.origin();
      if (!clipHalfSpace(glm::dot(c.normal, o - point), glm::dot(c.normal, d), true, t0, t1)) return;
    }
    out.push_back({t0, t1, index});
  });
  std::sort(out.begin(), out.end());
  return out;
}

struct LocalRay {
  glm::dvec3 o, d;
  double tMin, tMax;
};

// The ray's parts as the volume draws them, front to back: the split's tets, except that a
// curved cell's tets make way for the stretches inside the cell's own shape (clipped as
// they are); those tets go to `aside`, for a stretch whose field cannot be fitted.
std::vector<Interval> rayIntervals(const TetVolume& volume, const LocalRay& r, const RaySettings& settings,
                                   std::vector<Interval>& aside) {
  std::vector<Interval> list = intervals(volume, r.o, r.d, r.tMin, r.tMax, settings);
  const CurvedCells* curved = settings.elementField ? settings.curvedCells : nullptr;
  if (!curved || curved->empty()) return list;
  const ElementField& field = *settings.elementField;
  const auto ofCurvedCell = [&](const Interval& i) {
    return curved->curved(field.cellOfTet(volume.tet(i.tet).source));
  };
  for (const Interval& i : list)
    if (ofCurvedCell(i)) aside.push_back(i);
  list.erase(std::remove_if(list.begin(), list.end(), ofCurvedCell), list.end());
  std::vector<double> seeds;
  for (const Interval& i : aside) seeds.insert(seeds.end(), {i.t0, 0.5 * (i.t0 + i.t1), i.t1});
  std::vector<CellStretch> stretches;
  curved->stretches(r.o, r.d, r.tMin, r.tMax, seeds, stretches);
  const auto add = [&](std::vector<CellStretch>& found) {
    for (CellStretch& c : found) {
      bool kept = true;
      for (const ClipPlane& p : settings.clipPlanes) {
        const glm::dvec3 point = p.point - volume.origin();
        kept = kept && clipHalfSpace(glm::dot(p.normal, r.o - point), glm::dot(p.normal, r.d), true, c.t0, c.t1);
      }
      if (kept) list.push_back({c.t0, c.t1, kOwnShape, c.cell});
    }
    found.clear();
    std::sort(list.begin(), list.end());
  };
  add(stretches);
  // Cells tile the model: a gap between two parts of the ray may hide a stretch too short
  // for the samples (a ray cutting a cell's corner). Each gap is searched again, sampled
  // finely within it, until none gives more (a gap across a hollow gives nothing).
  for (int pass = 0; pass < 4; ++pass) {
    std::size_t before = list.size();
    for (std::size_t k = 0; k + 1 < before; ++k) {
      const double from = list[k].t1, to = list[k + 1].t0;
      if (to - from > 1e-9 * (std::abs(from) + std::abs(to) + (list[k].t1 - list[k].t0)))
        curved->stretches(r.o, r.d, from, to, {}, stretches);
    }
    if (stretches.empty()) break;
    add(stretches);
  }
  return list;
}

LocalRay localRay(const TetVolume& volume, glm::dvec3 origin, glm::dvec3 direction, double tMin, double tMax) {
  const double len = glm::length(direction);
  return {origin - volume.origin(), direction / len, tMin, tMax};
}

}  // namespace

// A tet's segment with the iso-surfaces it crosses: volume pieces between crossings, each
// surface composited at its crossing. A crossing counts when the value lies in
// (sFront, sBack] along the ray, so a surface on a shared face is met once.
SegmentLight segmentWithSurfaces(const TransferFunction& tf, const RaySettings& settings, double sFront, double sBack,
                                 double length, const glm::dvec3& gradient, const glm::dvec3& direction) {
  if (settings.isoSurfaces.empty() || sFront == sBack) return integrateSegment(tf, sFront, sBack, length);
  std::vector<std::pair<double, const IsoSurface*>> hits;
  for (const IsoSurface& s : settings.isoSurfaces) {
    const bool crossed = sBack > sFront ? (s.value > sFront && s.value <= sBack) : (s.value < sFront && s.value >= sBack);
    if (crossed) hits.push_back({(s.value - sFront) / (sBack - sFront), &s});
  }
  if (hits.empty()) return integrateSegment(tf, sFront, sBack, length);
  std::sort(hits.begin(), hits.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  const double shade = isoShade(gradient, direction);
  SegmentLight total;
  double x0 = 0.0;
  for (const auto& [x, surface] : hits) {
    compositeBehind(total, integrateSegment(tf, sFront + (sBack - sFront) * x0, surface->value, (x - x0) * length));
    compositeBehind(total, {surface->color * shade * surface->opacity, 1.0 - surface->opacity});
    x0 = x;
  }
  compositeBehind(total, integrateSegment(tf, sFront + (sBack - sFront) * x0, sBack, (1.0 - x0) * length));
  return total;
}

namespace {

SegmentLight linearTetSegment(const TetVolume& volume, const TransferFunction& tf, const RaySettings& settings,
                              const LocalRay& r, const Interval& i) {
  const PreparedTet& tet = volume.tet(i.tet);
  const double sFront = tet.valueAtOrigin + glm::dot(tet.gradient, r.o + i.t0 * r.d);
  const double sBack = tet.valueAtOrigin + glm::dot(tet.gradient, r.o + i.t1 * r.d);
  return segmentWithSurfaces(tf, settings, sFront, sBack, i.t1 - i.t0, tet.gradient, r.d);
}

// A curved cell's stretch on its own shape, its field fitted along it; where the map cannot
// be inverted along it, the split's tets of the cell within the stretch, linear.
SegmentLight ownShapeStretch(const TetVolume& volume, const TransferFunction& tf, const RaySettings& settings,
                             const LocalRay& r, const Interval& stretch, const std::vector<Interval>& aside) {
  const ElementField& field = *settings.elementField;
  if (const auto light = integrateElementStretch(field, stretch.cell, tf, settings.isoSurfaces, r.o, r.d, stretch.t0,
                                                 stretch.t1, exactStretches(field)))
    return *light;
  field.countFallback();
  SegmentLight total;
  for (Interval i : aside) {
    if (field.cellOfTet(volume.tet(i.tet).source) != stretch.cell) continue;
    i.t0 = std::max(i.t0, stretch.t0), i.t1 = std::min(i.t1, stretch.t1);
    if (i.t1 > i.t0) compositeBehind(total, linearTetSegment(volume, tf, settings, r, i));
  }
  return total;
}

}  // namespace

SegmentLight integrateRay(const TetVolume& volume, const TransferFunction& tf, glm::dvec3 origin, glm::dvec3 direction,
                          double tMin, double tMax, const RaySettings& settings) {
  const LocalRay r = localRay(volume, origin, direction, tMin, tMax);
  const ElementField* field = settings.elementField;
  SegmentLight total;
  std::vector<Interval> aside;
  const std::vector<Interval> list = rayIntervals(volume, r, settings, aside);
  for (std::size_t i = 0; i < list.size() && total.transmittance >= settings.terminationTransmittance; ++i) {
    if (list[i].tet == kOwnShape) {
      compositeBehind(total, ownShapeStretch(volume, tf, settings, r, list[i], aside));
      continue;
    }
    const std::uint32_t cell = field ? field->cellOfTet(volume.tet(list[i].tet).source) : 0;
    if (!field || field->linearIn(cell)) {
      compositeBehind(total, linearTetSegment(volume, tf, settings, r, list[i]));
      continue;
    }
    // The cell's tets the ray crosses one after another make one stretch of the cell.
    std::size_t last = i;
    double end = list[i].t1;
    while (last + 1 < list.size() && list[last + 1].t0 <= end && list[last + 1].tet != kOwnShape &&
           field->cellOfTet(volume.tet(list[last + 1].tet).source) == cell)
      end = std::max(end, list[++last].t1);
    if (const auto light = integrateElementStretch(*field, cell, tf, settings.isoSurfaces, r.o, r.d, list[i].t0, end,
                                                   exactStretches(*field))) {
      compositeBehind(total, *light);
    } else {  // the map could not be inverted along this ray: the split's field there
      field->countFallback();
      for (std::size_t k = i; k <= last; ++k)
        compositeBehind(total, linearTetSegment(volume, tf, settings, r, list[k]));
    }
    i = last;
  }
  return total;
}

double lengthInside(const TetVolume& volume, glm::dvec3 origin, glm::dvec3 direction, double tMin, double tMax,
                    const RaySettings& settings) {
  const LocalRay r = localRay(volume, origin, direction, tMin, tMax);
  double length = 0.0;
  std::vector<Interval> aside;
  for (const Interval& i : rayIntervals(volume, r, settings, aside)) length += i.t1 - i.t0;
  return length;
}

ReferenceImage renderPixelRays(const Camera& camera, int width, int height, const PixelRay& ray,
                               const Progress& progress, int threads) {
  ReferenceImage image{width, height, std::vector<glm::dvec4>(std::size_t(width) * std::size_t(height)), {}};
  const double aspect = double(width) / double(height);
  const glm::dmat4 toModel = glm::inverse(camera.projectionMatrix(aspect) * camera.viewMatrix());
  const bool ortho = camera.projection() == Camera::Projection::Orthographic;
  const auto unproject = [&](double x, double y, double z) {
    const glm::dvec4 p = toModel * glm::dvec4(x, y, z, 1.0);
    return glm::dvec3(p) / p.w;
  };
  if (threads <= 0) threads = int(usableCores());
  std::atomic<int> nextRow{0}, rowsDone{0};
  std::atomic<bool> stop{false};
  const auto work = [&](unsigned worker) {
    const bool reports = worker == 0;  // progress callbacks come from the calling thread
    try {
      for (int y; !stop && (y = nextRow++) < height;) {
        for (int x = 0; x < width; ++x) {
          const double nx = 2.0 * (x + 0.5) / width - 1.0, ny = 1.0 - 2.0 * (y + 0.5) / height;
          // The ray through the pixel centre, from the near plane to the far plane.
          const glm::dvec3 nearPoint = unproject(nx, ny, -1.0), farPoint = unproject(nx, ny, 1.0);
          const glm::dvec3 start = ortho ? nearPoint : camera.eye();
          const glm::dvec3 dir = farPoint - start;
          const double length = glm::length(dir);
          const double tStart = ortho ? 0.0 : glm::length(nearPoint - start);
          const SegmentLight light = ray(start, dir, tStart, length);
          image.pixels[std::size_t(y) * std::size_t(width) + std::size_t(x)] =
              glm::dvec4(light.color, 1.0 - light.transmittance);
        }
        const int done = ++rowsDone;
        if (reports) progress.report(double(done) / height);
      }
    } catch (...) {
      stop = true;  // the others stop at their next row
      throw;
    }
  };
  runOnThreads(unsigned(threads), work);
  return image;
}

ReferenceImage renderReference(const TetVolume& volume, const TransferFunction& tf, const Camera& camera, int width,
                               int height, const RaySettings& settings, const Progress& progress, int threads) {
  // The curved cells' shapes, found once for the picture.
  std::optional<CurvedCells> curved;
  RaySettings withShapes = settings;
  if (settings.elementField && !settings.curvedCells) {
    curved.emplace(*settings.elementField);
    withShapes.curvedCells = &*curved;
  }
  return renderPixelRays(
      camera, width, height,
      [&](glm::dvec3 origin, glm::dvec3 direction, double tMin, double tMax) {
        return integrateRay(volume, tf, origin, direction, tMin, tMax, withShapes);
      },
      progress, threads);
}

}  // namespace volpost::optics

// SPDX-License-Identifier: MIT
#include "host/Streamlines.hpp"
#include "host/ElementRefinement.hpp"

#include <volpost/core/CellShape.hpp>

#include <volpost/core/TetAdjacency.hpp>
#include <volpost/core/WorkerThreads.hpp>

#include <glm/geometric.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <thread>

namespace volpost {
namespace {

constexpr double kInside = 1e-10;  // barycentric slack: on a face counts as inside

std::string pointText(const glm::dvec3& p) {
  char text[96];
  std::snprintf(text, sizeof text, "(%g, %g, %g)", p.x, p.y, p.z);
  return text;
}

// One Runge-Kutta attempt: the proposed end and the error estimate (model units), or
// `outside` when a stage point left the mesh.
struct Attempt {
  bool outside = false;
  glm::dvec3 end{0.0};
  double error = 0.0;
};

}  // namespace

const char* toString(StreamlineMethod method) {
  switch (method) {
    case StreamlineMethod::RK2: return "rk2";
    case StreamlineMethod::RK4: return "rk4";
    case StreamlineMethod::RK45: return "rk45";
  }
  return "?";
}

const char* toString(StreamlineDirection direction) {
  switch (direction) {
    case StreamlineDirection::Forward: return "forward";
    case StreamlineDirection::Backward: return "backward";
    case StreamlineDirection::Both: return "both";
  }
  return "?";
}

const char* describe(StreamlineStop stop) {
  switch (stop) {
    case StreamlineStop::None: return "not traced";
    case StreamlineStop::LeftMesh: return "left the mesh";
    case StreamlineStop::MaxSteps: return "reached the step limit";
    case StreamlineStop::MaxLength: return "reached the length limit";
    case StreamlineStop::Stagnation: return "stopped at a stagnation point";
    case StreamlineStop::ClosedOrbit: return "closed on itself";
    case StreamlineStop::StepTooSmall: return "needed steps too small to go on";
    case StreamlineStop::PointBudget:
      static_assert(kMaxStreamlinePoints == 2097152, "the words below give the limit");
      return "reached the limit of 2,097,152 points for all lines together (fewer seeds or a shorter --max-length)";
  }
  return "?";
}

StreamlineTracer::StreamlineTracer(const TetMesh& tets, std::vector<glm::dvec3> vectors, const Mesh* cells)
    : tets_(tets), vectors_(std::move(vectors)), neighbors_(faceNeighbors(tets.mesh)), locator_(tets) {
  if (cells && hasNonlinearCells(*cells)) {
    cells_ = cells;
    ownField_.assign(cells->cellCount(), 0);
    std::vector<glm::dvec3> nodes;
    for (std::size_t c = 0; c < cells->cellCount(); ++c) {
      if (cells->cellType(c) == CellType::Tet4) continue;
      nodes.clear();
      for (NodeIndex n : cells->cellNodes(c)) nodes.push_back(cells->nodes[n]);
      ownField_[c] = mapInvertible(cells->cellType(c), nodes);  // else its split's field, as the volume draws it
    }
  }
  if (vectors_.size() != tets.mesh.nodeCount())
    throw std::invalid_argument("streamlines: " + std::to_string(vectors_.size()) + " vectors for " +
                                std::to_string(tets.mesh.nodeCount()) + " nodes");
  const Bounds b = tets.mesh.bounds();
  modelSize_ = b.valid && b.diagonal() > 0.0 ? b.diagonal() : 1.0;
  for (const glm::dvec3& v : vectors_)
    if (std::isfinite(glm::length(v))) maxSpeed_ = std::max(maxSpeed_, glm::length(v));
}

glm::dvec4 StreamlineTracer::barycentric(std::uint32_t tet, const glm::dvec3& p) const {
  const auto n = tets_.mesh.cellNodes(tet);
  const glm::dvec3& a = tets_.mesh.nodes[n[0]];
  const glm::dvec3 ab = tets_.mesh.nodes[n[1]] - a, ac = tets_.mesh.nodes[n[2]] - a, ad = tets_.mesh.nodes[n[3]] - a;
  const glm::dvec3 ap = p - a;
  const double volume = glm::dot(ab, glm::cross(ac, ad));
  if (volume == 0.0) return glm::dvec4(-1.0);  // a flat tet holds nothing
  const double l1 = glm::dot(ap, glm::cross(ac, ad)) / volume;
  const double l2 = glm::dot(ab, glm::cross(ap, ad)) / volume;
  const double l3 = glm::dot(ab, glm::cross(ac, ap)) / volume;
  return {1.0 - l1 - l2 - l3, l1, l2, l3};
}

glm::dvec3 StreamlineTracer::velocityIn(std::uint32_t tet, const glm::dvec3& p) const {
  const glm::dvec4 w = barycentric(tet, p);
  if (cells_ && ownField_[tets_.sourceCell(tet)])
    if (const auto v = ownVelocity(tet, w, p)) return *v;
  const auto n = tets_.mesh.cellNodes(tet);
  glm::dvec3 v(0.0);
  for (int k = 0; k < 4; ++k) v += std::clamp(w[k], -1e-6, 1.0 + 1e-6) * vectors_[n[std::size_t(k)]];
  return v;
}

std::optional<glm::dvec3> StreamlineTracer::ownVelocity(std::uint32_t tet, const glm::dvec4& w,
                                                        const glm::dvec3& p) const {
  const std::uint32_t cell = tets_.sourceCell(tet);
  const CellType type = cells_->cellType(cell);
  const auto ids = cells_->cellNodes(cell);
  std::array<glm::dvec3, kMaxCellNodes> nodes;
  const std::size_t count = std::min<std::size_t>(ids.size(), kMaxCellNodes);
  for (std::size_t i = 0; i < count; ++i) nodes[i] = cells_->nodes[ids[i]];
  // Newton's method starts where the split's tet puts the point: close, so few steps.
  glm::dvec3 start(0.0);
  const auto corners = tets_.mesh.cellNodes(tet);
  for (int k = 0; k < 4; ++k)
    start += std::clamp(w[k], 0.0, 1.0) * naturalCoordinatesOfSplitNode(*cells_, cell, corners[std::size_t(k)]);
  const auto xi = naturalCoordinates(type, std::span<const glm::dvec3>(nodes.data(), count), p, start);
  if (!xi) return std::nullopt;
  const ShapeValues n = shapeFunctions(type, clampToReference(type, *xi));
  glm::dvec3 v(0.0);
  for (std::size_t i = 0; i < count; ++i) v += n[i] * vectors_[ids[i]];
  return v;
}

// |grad v| (Frobenius) in a tet: v is linear there, sum_k v_k grad(lambda_k). 1/|grad v| is
// the field's own time scale: steps longer than it are unstable near stagnation points,
// whatever the error estimate says (it vanishes with |v|).
double StreamlineTracer::gradientNorm(std::uint32_t tet) const {
  const auto n = tets_.mesh.cellNodes(tet);
  const glm::dvec3& a = tets_.mesh.nodes[n[0]];
  const glm::dvec3 e1 = tets_.mesh.nodes[n[1]] - a, e2 = tets_.mesh.nodes[n[2]] - a, e3 = tets_.mesh.nodes[n[3]] - a;
  const double volume = glm::dot(e1, glm::cross(e2, e3));
  if (volume == 0.0) return 0.0;
  const glm::dvec3 g1 = glm::cross(e2, e3) / volume, g2 = glm::cross(e3, e1) / volume, g3 = glm::cross(e1, e2) / volume;
  const glm::dvec3& v0 = vectors_[n[0]];
  // grad v = (v1 - v0) g1^T + (v2 - v0) g2^T + (v3 - v0) g3^T
  double sum = 0.0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const double gij = (vectors_[n[1]][i] - v0[i]) * g1[j] + (vectors_[n[2]][i] - v0[i]) * g2[j] +
                         (vectors_[n[3]][i] - v0[i]) * g3[j];
      sum += gij * gij;
    }
  return std::sqrt(sum);
}

double StreamlineTracer::cellSize(std::uint32_t tet) const {
  const auto n = tets_.mesh.cellNodes(tet);
  double longest = 0.0;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j)
      longest = std::max(longest, glm::length(tets_.mesh.nodes[n[std::size_t(i)]] - tets_.mesh.nodes[n[std::size_t(j)]]));
  return longest > 0.0 ? longest : modelSize_ * 1e-9;
}

// Along p(s) = a + s (b - a) each barycentric coordinate is linear in s: the tet is left
// at the smallest s where a decreasing coordinate reaches 0, through that face.
StreamlineTracer::Walk StreamlineTracer::walk(std::uint32_t from, const glm::dvec3& a, const glm::dvec3& b) const {
  std::uint32_t t = from;
  double s = 0.0;
  for (int hop = 0; hop < 100000; ++hop) {
    const glm::dvec4 la = barycentric(t, a), lb = barycentric(t, b);
    double exit = std::numeric_limits<double>::infinity();
    int face = -1;
    for (int k = 0; k < 4; ++k) {
      if (!(lb[k] < la[k]) || lb[k] >= -kInside) continue;
      const double sk = la[k] / (la[k] - lb[k]);
      if (sk < exit) {
        exit = sk;
        face = k;
      }
    }
    if (face < 0) return {true, t, b};  // b is in t
    exit = std::max(exit, s);  // rounding may put the crossing behind where we entered
    const int next = neighbors_[t][face];
    if (next < 0) return {false, t, a + std::min(exit, 1.0) * (b - a)};  // on the boundary face
    t = std::uint32_t(next);
    s = exit;
  }
  // A walk that goes round in circles (rays along faces of degenerate tets): ask the grid.
  if (const auto at = locator_.locate(b)) return {true, std::uint32_t(at->tet), b};
  return {false, t, a};
}

void StreamlineTracer::traceOneWay(const glm::dvec3& seed, std::uint32_t seedTet, double sign,
                                   const StreamlineSettings& settings, std::vector<glm::dvec3>& points,
                                   std::vector<glm::dvec3>& velocity, StreamlineStop& stop, std::size_t& steps,
                                   std::size_t& rejected, double& totalLength, double& closure,
                                   std::atomic<std::int64_t>* pointsLeft) const {
  // The limit holds for each direction: this direction's own length, added to the line's
  // when it ends.
  double length = 0.0;
  struct AddLength {
    double& total;
    const double& mine;
    ~AddLength() { total += mine; }
  } addLength{totalLength, length};
  const double eps = std::max(settings.tolerance, 1e-14) * modelSize_;
  const double maxLength = settings.maxLength > 0.0 ? settings.maxLength : 20.0 * modelSize_;
  const double slow = settings.stagnation * maxSpeed_;
  // Where the line is: the point, its tet and the (signed) field there.
  struct State {
    glm::dvec3 x;
    std::uint32_t t;
    glm::dvec3 v;
  };
  State at{seed, seedTet, sign * velocityIn(seedTet, seed)};
  const glm::dvec3 seedDirection = glm::length(at.v) > 0.0 ? glm::normalize(at.v) : glm::dvec3(0.0);
  const double orbitRadius = std::max(100.0 * eps, 0.05 * cellSize(seedTet));
  double h = 0.25 * cellSize(at.t) / std::max(glm::length(at.v), 1e-300);
  std::size_t taken = 0;

  // One Runge-Kutta step of length `step` from `from`: its end and error estimate.
  const auto attempt = [&](const State& from, double step) -> Attempt {
    // The field where a stage point lies, found by walking from the step's start.
    const auto field = [&](const glm::dvec3& q) -> std::optional<glm::dvec3> {
      const Walk w = walk(from.t, from.x, q);
      if (!w.inside) return std::nullopt;
      return sign * velocityIn(w.tet, q);
    };
    const glm::dvec3& x = from.x;
    const glm::dvec3& v = from.v;
    Attempt a;
    if (settings.method == StreamlineMethod::RK2) {  // Heun with Euler as the embedded estimate
      const auto k2 = field(x + step * v);
      if (!k2) return {true};
      a.end = x + 0.5 * step * (v + *k2);
      a.error = 0.5 * step * glm::length(*k2 - v);
      return a;
    }
    if (settings.method == StreamlineMethod::RK4) {  // classical, error by step doubling
      const auto rk4 = [&](const glm::dvec3& start, const glm::dvec3& k1, double dt) -> std::optional<glm::dvec3> {
        const auto k2 = field(start + 0.5 * dt * k1);
        if (!k2) return std::nullopt;
        const auto k3 = field(start + 0.5 * dt * *k2);
        if (!k3) return std::nullopt;
        const auto k4 = field(start + dt * *k3);
        if (!k4) return std::nullopt;
        return start + dt / 6.0 * (k1 + 2.0 * *k2 + 2.0 * *k3 + *k4);
      };
      const auto whole = rk4(x, v, step);
      const auto half = rk4(x, v, 0.5 * step);
      if (!whole || !half) return {true};
      const auto kMid = field(*half);
      if (!kMid) return {true};
      const auto twoHalves = rk4(*half, *kMid, 0.5 * step);
      if (!twoHalves) return {true};
      a.error = glm::length(*twoHalves - *whole) / 15.0;
      a.end = *twoHalves + (*twoHalves - *whole) / 15.0;  // Richardson
      return a;
    }
    // Dormand-Prince 5(4).
    static constexpr double c[7][6] = {{0, 0, 0, 0, 0, 0},
                                       {1.0 / 5, 0, 0, 0, 0, 0},
                                       {3.0 / 40, 9.0 / 40, 0, 0, 0, 0},
                                       {44.0 / 45, -56.0 / 15, 32.0 / 9, 0, 0, 0},
                                       {19372.0 / 6561, -25360.0 / 2187, 64448.0 / 6561, -212.0 / 729, 0, 0},
                                       {9017.0 / 3168, -355.0 / 33, 46732.0 / 5247, 49.0 / 176, -5103.0 / 18656, 0},
                                       {35.0 / 384, 0, 500.0 / 1113, 125.0 / 192, -2187.0 / 6784, 11.0 / 84}};
    static constexpr double e[7] = {71.0 / 57600, 0, -71.0 / 16695, 71.0 / 1920, -17253.0 / 339200, 22.0 / 525, -1.0 / 40};
    glm::dvec3 k[7];
    k[0] = v;
    for (int i = 1; i < 7; ++i) {
      glm::dvec3 q = x;
      for (int j = 0; j < i; ++j) q += step * c[i][j] * k[j];
      const auto ki = field(q);
      if (!ki) return {true};
      k[i] = *ki;
    }
    a.end = x;
    glm::dvec3 err(0.0);
    for (int i = 0; i < 6; ++i) a.end += step * c[6][i] * k[i];
    for (int i = 0; i < 7; ++i) err += step * e[i] * k[i];
    a.error = glm::length(err);
    return a;
  };
  // The step from `from` whose end satisfies `reached` first, by bisection on the step
  // length between 0 and `step` (whose end satisfies it): each trial is a whole Runge-Kutta
  // step, so the point found lies on the integrated line, within the tolerance.
  struct Reached {
    glm::dvec3 end;
    double step;
  };
  const auto firstStepReaching = [&](const State& from, double step, const auto& reached) {
    double lo = 0.0, hi = step;
    Attempt best = attempt(from, step);
    for (int i = 0; i < 60 && hi - lo > 1e-14 * step; ++i) {
      const double mid = 0.5 * (lo + hi);
      const Attempt a = attempt(from, mid);
      if (a.outside || !reached(a.end)) {
        lo = mid;
      } else {
        hi = mid;
        best = a;
      }
    }
    return Reached{best.end, hi};
  };
  bool budgetSpent = false;
  const auto record = [&](const glm::dvec3& p, const glm::dvec3& fieldThere) {  // the field, not its signed walk
    points.push_back(p);
    velocity.push_back(fieldThere);
    if (pointsLeft && pointsLeft->fetch_sub(1) <= 1) budgetSpent = true;
  };
  const double shrinkExponent = settings.method == StreamlineMethod::RK2 ? 0.5 : 0.2;
  const double growExponent = settings.method == StreamlineMethod::RK2 ? 1.0 / 3.0 : 0.2;

  while (true) {
    if (budgetSpent || (pointsLeft && pointsLeft->load() <= 0)) {
      stop = StreamlineStop::PointBudget;
      return;
    }
    const double speed = glm::length(at.v);
    if (!(speed > slow) || !std::isfinite(speed)) {
      stop = StreamlineStop::Stagnation;
      return;
    }
    if (taken >= settings.maxSteps) {
      stop = StreamlineStop::MaxSteps;
      return;
    }
    if (length >= maxLength) {
      stop = StreamlineStop::MaxLength;
      return;
    }
    const double size = cellSize(at.t);
    h = std::min(h, 2.0 * size / speed);                 // a step crosses at most a couple of cells
    // Within each method's stability bound on the field's time scale (Heun: |h lambda| < 2,
    // the fourth- and fifth-order methods a little more), with a margin.
    if (const double g = gradientNorm(at.t); g > 0.0)
      h = std::min(h, (settings.method == StreamlineMethod::RK2 ? 1.0 : 2.0) / g);
    h = std::min(h, (maxLength - length) / speed * 1.0001);
    const Attempt a = attempt(at, h);
    if (a.outside) {
      // A stage left the mesh: shorter steps, until the step is tiny; then go straight to
      // the boundary along the field and stop there.
      if (h * speed > 1e-6 * size) {
        h *= 0.5;
        continue;
      }
      const Walk w = walk(at.t, at.x, at.x + (2.0 * size / speed) * at.v);
      if (!w.inside) {
        const double remaining = maxLength - length, straight = glm::length(w.end - at.x);
        if (straight > remaining) {  // the limit comes first on the way to the boundary
          const glm::dvec3 end = at.x + (remaining / straight) * (w.end - at.x);
          length = maxLength;
          record(end, velocityIn(w.tet, end));
          stop = StreamlineStop::MaxLength;
          return;
        }
        length += straight;
        record(w.end, velocityIn(w.tet, w.end));
        stop = StreamlineStop::LeftMesh;
        return;
      }
      h = 0.25 * size / speed;  // the straight step stays inside: go on from the field there
      at = {w.end, w.tet, sign * velocityIn(w.tet, w.end)};
      continue;
    }
    if (a.error > eps) {
      ++rejected;
      h *= std::max(0.1, 0.9 * std::pow(eps / a.error, shrinkExponent));
      if (h * speed < 1e-12 * modelSize_) {
        stop = StreamlineStop::StepTooSmall;
        return;
      }
      continue;
    }
    // Accepted. The step was sized by the speed at its start, so it may run past the length
    // limit: then the line ends where the integrated step reaches the limit.
    glm::dvec3 end = a.end;
    double stepTaken = h;
    const double remaining = maxLength - length;
    const bool lastStep = glm::length(end - at.x) > remaining;
    if (lastStep) {
      const Reached r =
          firstStepReaching(at, h, [&](const glm::dvec3& p) { return glm::length(p - at.x) >= remaining; });
      end = r.end;
      stepTaken = r.step;
    }
    // The end's tet by walking along the step; a step that leaves the mesh ends on the
    // boundary face it crosses.
    const Walk w = walk(at.t, at.x, end);
    double stepLength = std::min(glm::length(w.end - at.x), remaining);
    const State previous = at;
    at = {w.end, w.tet, sign * velocityIn(w.tet, w.end)};
    ++steps;
    ++taken;
    // Back through the plane across the seed, heading the same way and close to it: a
    // closed orbit. The crossing is found on the integrated line (a step from the previous
    // end sized to reach the plane); the closure error is how far from the seed it is.
    const auto side = [&](const glm::dvec3& p) { return glm::dot(p - seed, seedDirection); };
    bool closed = false;
    if (w.inside && !lastStep && settings.stopOnClosedOrbits && length > 8.0 * orbitRadius && side(previous.x) < 0.0 &&
        side(at.x) >= 0.0 && glm::length(at.x - seed) < orbitRadius + 2.0 * stepLength) {
      const Reached crossing = firstStepReaching(previous, h, [&](const glm::dvec3& p) { return side(p) >= 0.0; });
      if (const double gap = glm::length(crossing.end - seed); gap < orbitRadius) {
        closed = true;
        closure = gap;
        stepTaken = crossing.step;
        stepLength = glm::length(crossing.end - previous.x);
        at = {crossing.end, walk(previous.t, previous.x, crossing.end).tet, glm::dvec3(0.0)};
        at.v = sign * velocityIn(at.t, at.x);
      }
    }
    // Where asked, points inside the step, each a Runge-Kutta step of its own from the
    // step's start (as accurate as the step end); else only the step end is written (points
    // on a curve through the ends would not be within the tolerance).
    if (settings.pointSpacing > 0.0 && w.inside && stepLength > settings.pointSpacing) {
      const int pieces = int(std::min(64.0, std::ceil(stepLength / settings.pointSpacing)));
      for (int i = 1; i < pieces; ++i) {
        const Attempt inner = attempt(previous, stepTaken * double(i) / double(pieces));
        if (inner.outside) continue;
        record(inner.end, velocityIn(walk(previous.t, previous.x, inner.end).tet, inner.end));
      }
    }
    record(at.x, sign * at.v);
    length += stepLength;
    if (!w.inside) {
      stop = StreamlineStop::LeftMesh;
      return;
    }
    if (lastStep) {
      length = maxLength;
      stop = StreamlineStop::MaxLength;
      return;
    }
    if (closed) {
      stop = StreamlineStop::ClosedOrbit;
      return;
    }
    h *= std::min(5.0, 0.9 * std::pow(eps / std::max(a.error, 1e-300), growExponent));
  }
}

Streamline StreamlineTracer::trace(const glm::dvec3& seed, const StreamlineSettings& settings,
                                   std::atomic<std::int64_t>* pointsLeft) const {
  const auto at = locator_.locate(seed, 1e-6);
  if (!at) throw std::invalid_argument("the seed " + pointText(seed) + " is outside the mesh");
  const std::uint32_t tet = std::uint32_t(at->tet);
  Streamline line;
  if (settings.direction != StreamlineDirection::Forward) {
    std::vector<glm::dvec3> points, velocity;
    traceOneWay(seed, tet, -1.0, settings, points, velocity, line.backwardStop, line.steps, line.rejected, line.length,
                line.closureError, pointsLeft);
    line.points.assign(points.rbegin(), points.rend());
    line.velocity.assign(velocity.rbegin(), velocity.rend());
  }
  line.seedIndex = line.points.size();
  line.points.push_back(seed);
  line.velocity.push_back(velocityIn(tet, seed));
  if (settings.direction != StreamlineDirection::Backward)
    traceOneWay(seed, tet, 1.0, settings, line.points, line.velocity, line.forwardStop, line.steps, line.rejected,
                line.length, line.closureError, pointsLeft);
  return line;
}

std::vector<Streamline> StreamlineTracer::traceAll(const std::vector<glm::dvec3>& seeds,
                                                   const StreamlineSettings& settings, std::size_t* outside,
                                                   const Progress& progress, std::size_t maxPoints) const {
  std::vector<Streamline> lines(seeds.size());
  // Each line's seed takes a point too; what is left is shared as the lines are traced.
  std::atomic<std::int64_t> pointsLeft{std::int64_t(maxPoints) - std::int64_t(seeds.size())};
  std::vector<char> missed(seeds.size(), 0);
  std::atomic<std::size_t> next{0}, done{0};
  std::atomic<bool> cancelled{false};
  runOnThreads(usableCores(), [&](unsigned worker) {
    for (std::size_t i; !cancelled && (i = next++) < seeds.size();) {
      try {
        lines[i] = trace(seeds[i], settings, &pointsLeft);
      } catch (const std::invalid_argument&) {
        missed[i] = 1;
      }
      const std::size_t finished = ++done;
      if (worker == 0) {
        try {
          progress.report(double(finished) / double(seeds.size()));
        } catch (...) {
          cancelled = true;
          throw;
        }
      }
    }
  });
  std::vector<Streamline> out;
  std::size_t missing = 0;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    if (missed[i]) ++missing;
    else out.push_back(std::move(lines[i]));
  }
  if (outside) *outside = missing;
  return out;
}

std::vector<glm::dvec3> tetNodeVectors(const TetMesh& tets, const Mesh& source, const std::vector<double>& nodal) {
  if (nodal.size() != source.nodeCount() * 3)
    throw std::invalid_argument("streamlines need a vector (3 values) per node");
  std::vector<glm::dvec3> out(tets.mesh.nodeCount());
  for (int k = 0; k < 3; ++k) {
    std::vector<double> component(source.nodeCount());
    for (std::size_t i = 0; i < component.size(); ++i) component[i] = nodal[3 * i + std::size_t(k)];
    const std::vector<double> onTets = tets.nodeValues(source, component);
    for (std::size_t i = 0; i < out.size(); ++i) out[i][k] = onTets[i];
  }
  return out;
}

std::vector<double> averageCellVectorsToNodes(const Mesh& mesh, const std::vector<double>& perCell) {
  std::vector<double> sum(mesh.nodeCount() * 3, 0.0);
  std::vector<int> count(mesh.nodeCount(), 0);
  for (std::size_t c = 0; c < mesh.cellCount(); ++c)
    for (NodeIndex n : mesh.cellNodes(c)) {
      for (int k = 0; k < 3; ++k) sum[3 * n + std::size_t(k)] += perCell[3 * c + std::size_t(k)];
      ++count[n];
    }
  for (std::size_t n = 0; n < count.size(); ++n)
    for (int k = 0; k < 3; ++k) sum[3 * n + std::size_t(k)] = count[n] ? sum[3 * n + std::size_t(k)] / count[n] : 0.0;
  return sum;
}

}  // namespace volpost

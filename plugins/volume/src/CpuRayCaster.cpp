// SPDX-License-Identifier: MIT
// Built with -ffp-contract=off (see CMakeLists.txt): a fused multiply-add would make
// cross(a, b) differ from -cross(b, a) in the last bit, and the two tets sharing a face
// must compute the very same edge products.
#include "CpuRayCaster.hpp"

#include "ExactRaySide.hpp"
#include "PiecewiseIntegrator.hpp"

#include <volpost/core/WorkerThreads.hpp>
#include <volpost/core/optics/ElementStretch.hpp>

#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>
#include <glm/gtc/matrix_inverse.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <mutex>
#include <thread>

namespace volpost::volume {
namespace {

using Clock = std::chrono::steady_clock;
double msSince(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }

struct PixelRay {
  glm::vec3 o, d;  ///< mesh-relative origin (the ray's point nearest the mesh centre), unit direction
  float tStart, tEnd;  ///< the near and far planes (or opaque geometry)
  float tEye;          ///< the camera (the near plane of an orthographic view)
  glm::dvec3 exactO, exactD;  ///< the same in double, for decisions float cannot make
};

// The product of the ray with the directed edge p -> q, and which side it counts as.
struct Side {
  float value;
  bool positive;
  bool nearZero = false;  ///< decided in double or exactly: too small to weigh a crossing with
};

inline float l1(const glm::vec3& v) { return std::abs(v.x) + std::abs(v.y) + std::abs(v.z); }

// Each edge's product is computed from the lower id to the higher (then negated), so every
// tet sharing the edge gets the same bits. A float product within its rounding bound of
// zero is decided exactly instead.
[[gnu::always_inline]] inline Side edgeSide(const TetWalkMesh& mesh, const PixelRay& ray, std::uint32_t p, const glm::vec3& rp, std::uint32_t q,
                     const glm::vec3& rq) {
  const bool ascending = p < q;
  const glm::vec3& lo = ascending ? rp : rq;
  const glm::vec3& hi = ascending ? rq : rp;
  const float c = glm::dot(ray.d, glm::cross(lo, hi));
  Side side{c, c > 0.0f};
  // |rounding| of d . (A x B) with A, B rounded differences: under 8 ulp of |A|_1 |B|_1.
  if (std::abs(c) <= 1e-6f * l1(lo) * l1(hi)) {
    const auto& exact = mesh.exactPositions();
    double value;
    const bool positive = rayEdgeSidePositive(ray.exactO, ray.exactD, exact[ascending ? p : q], exact[ascending ? q : p], value);
    side = {float(value), positive, true};
  }
  return ascending ? side : Side{-side.value, !side.positive, side.nearZero};
}

// Weight of a face corner where the ray crosses it: the product of the edge opposite the
// corner, counted only on the side the ray passes (negative for an entering face).
inline float cornerWeight(const Side& s) { return s.positive ? 0.0f : std::max(0.0f, -s.value); }

// The face a ray is crossing into a tet: its three vertex ids listed counter-clockwise
// seen from outside that tet (so a ray entering gives negative products), their positions
// relative to the ray origin, their values, and the products of the edges AB, BC, CA.
struct EntryFace {
  std::uint32_t id[3];
  glm::vec3 r[3];
  float s[3];
  Side ab, bc, ca;
};

// Barycentric weights of p (in the face's plane) in the triangle abc, clamped to it.
double faceValue(const glm::dvec3& n, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& p,
                 const float* values) {
  double w[3] = {glm::dot(n, glm::cross(c - b, p - b)), glm::dot(n, glm::cross(a - c, p - c)), glm::dot(n, glm::cross(b - a, p - a))};
  double sum = 0.0;
  for (double& x : w) sum += (x = std::max(x, 0.0));
  return sum > 0.0 ? (w[0] * values[0] + w[1] * values[1] + w[2] * values[2]) / sum : values[0];
}

// Where the ray crosses the face, from the face's plane in double: for rays through a
// vertex or an edge of the face (the edge products are rounding noise there), and where the
// ray enters or leaves the mesh (the float point's error would add to the ray's length;
// inside the mesh the errors of consecutive crossings cancel in the sum). A ray
// lying in the plane (within rounding) runs along the face: any point of the stretch it
// shares with the triangle is right (the tets on both sides get the rest), so the noisy
// estimate `guess` is kept within that stretch.
[[gnu::noinline]] void crossingInDouble(const TetWalkMesh& mesh, const PixelRay& ray, const EntryFace& f, float guess, float& t, float& s) {
  const auto& exact = mesh.exactPositions();
  const glm::dvec3 a = exact[f.id[0]], b = exact[f.id[1]], c = exact[f.id[2]];
  const glm::dvec3 n = glm::cross(b - a, c - a);
  const double along = glm::dot(n, ray.exactD);
  if (std::abs(along) > 1e-9 * glm::length(n)) {
    const double tp = glm::dot(n, a - ray.exactO) / along;
    t = float(tp);
    s = float(faceValue(n, a, b, c, ray.exactO + tp * ray.exactD, f.s));
    return;
  }
  double t0 = -INFINITY, t1 = INFINITY;
  const glm::dvec3 corners[3] = {a, b, c};
  for (int i = 0; i < 3; ++i) {  // inside each edge's half-plane: dot(m, o + t d - p) >= 0
    const glm::dvec3 &p = corners[i], &q = corners[(i + 1) % 3];
    const glm::dvec3 m = glm::cross(n, q - p);
    const double at = glm::dot(m, ray.exactO - p), rate = glm::dot(m, ray.exactD);
    if (rate > 0.0) t0 = std::max(t0, -at / rate);
    else if (rate < 0.0) t1 = std::min(t1, -at / rate);
  }
  const double tp = t0 <= t1 ? std::clamp(double(guess), t0, t1) : double(guess);
  t = float(tp);
  s = float(faceValue(n, a, b, c, ray.exactO + tp * ray.exactD, f.s));
}

// Parameter and value where the ray crosses the face (barycentric weights from the edge
// products; in double where those cannot tell, or always with `boundary`); false when no
// point can be told.
[[gnu::always_inline]] inline bool crossing(const TetWalkMesh& mesh, const PixelRay& ray, const EntryFace& f, float& t, float& s,
                     bool boundary = false) {
  const float wa = cornerWeight(f.bc), wb = cornerWeight(f.ca), wc = cornerWeight(f.ab);
  const float sum = wa + wb + wc;
  const bool weighed = sum > 0.0f;
  // Each weight is off by up to its product's rounding bound (edgeSide): where they sum to
  // less than a thousand bounds (a ray grazing the face, or near its edges), the float point
  // and value would be off by more than 1e-3 of the face: take the plane in double.
  const float la = l1(f.r[0]), lb = l1(f.r[1]), lc = l1(f.r[2]);
  boundary = boundary || !(sum > 3e-4f * (la * lb + lb * lc + lc * la));
  if (weighed) {
    const glm::vec3 p = (wa * f.r[0] + wb * f.r[1] + wc * f.r[2]) / sum;
    t = glm::dot(p, ray.d);
    s = (wa * f.s[0] + wb * f.s[1] + wc * f.s[2]) / sum;
  }
  if (boundary || f.ab.nearZero || f.bc.nearZero || f.ca.nearZero) {
    const float guess = weighed ? t : glm::dot((f.r[0] + f.r[1] + f.r[2]) / 3.0f, ray.d);
    crossingInDouble(mesh, ray, f, guess, t, s);
    return true;
  }
  return weighed;
}

struct Entry {
  std::uint32_t pixel;
  float t, s;  ///< where the ray crosses the face, and the value there (found in double)
  std::uint32_t face;
  bool operator<(const Entry& o) const { return pixel < o.pixel || (pixel == o.pixel && t < o.t); }
};

struct Shared {
  const TetWalkMesh& mesh;
  const PiecewiseIntegrator& tf;
  const CpuRaySettings& settings;
  const std::vector<std::uint8_t>& visible;  ///< per tet: can it add anything to a picture?
  std::size_t stepCap;
  float reentryTolerance;
  const TransferFunction& transfer;  ///< what the element field's stretches are lit by
  const CpuElementField* element;    ///< null: the tetrahedra's field
  glm::dvec3 toField;                ///< walk coordinates + this = the element field's
  optics::StretchAccuracy accuracy;  ///< how closely element stretches are lit
};

// Empty-space skipping: a tet whose values all map to zero extinction (and hold no
// iso-surface) adds nothing, so rays are walked only through the others. They leave that
// part of the mesh through its boundary and re-enter through the next boundary face along
// them, found like the mesh's own boundary: typical transfer functions, transparent over
// most of the range, leave most tets out.
std::vector<std::uint8_t> visibleTets(const TetWalkMesh& mesh, const PiecewiseIntegrator& tf,
                                      const std::vector<optics::IsoSurface>& isoSurfaces, unsigned threads,
                                      const CpuElementField* element) {
  std::vector<std::uint8_t> visible(mesh.tetCount());
  const double offset = mesh.valueOffset();
  std::atomic<std::size_t> next{0};
  constexpr std::size_t kChunk = 4096;
  runOnThreads(threads, [&](unsigned) {
    for (std::size_t first; (first = next.fetch_add(kChunk)) < visible.size();)
      for (std::size_t t = first; t < std::min(first + kChunk, visible.size()); ++t) {
        double lo, hi;
        const std::uint32_t cell = element ? element->cellOfTet[t] : 0;
        if (element && !element->field->linearIn(cell)) {
          // The cell's own field reaches past its tets' corner values: its bound, or all of it.
          const auto bound = element->field->valueBound(cell);
          if (!bound) {
            visible[t] = 1;
            continue;
          }
          lo = bound->first - offset, hi = bound->second - offset;
        } else if (mesh.cellValues()) {
          lo = hi = mesh.tetValue(t);
        } else {
          const glm::uvec4 v = mesh.tetNodes(t);
          const auto& n = mesh.nodes();
          lo = std::min({n[v[0]].w, n[v[1]].w, n[v[2]].w, n[v[3]].w});
          hi = std::max({n[v[0]].w, n[v[1]].w, n[v[2]].w, n[v[3]].w});
        }
        lo += offset, hi += offset;
        bool shows = !tf.transparent(lo, hi);
        for (const optics::IsoSurface& s : isoSurfaces) shows = shows || (s.value >= lo && s.value <= hi);
        visible[t] = shows;
      }
  });
  return visible;
}

EntryFace boundaryEntry(const TetWalkMesh& mesh, const BoundaryFace& f, const PixelRay& ray) {
  EntryFace e;
  const auto& nodes = mesh.nodes();
  for (int i = 0; i < 3; ++i) {
    e.id[i] = f.v[i];
    e.r[i] = glm::vec3(nodes[f.v[i]]) - ray.o;
    e.s[i] = nodes[f.v[i]].w;
  }
  e.ab = edgeSide(mesh, ray, e.id[0], e.r[0], e.id[1], e.r[1]);
  e.bc = edgeSide(mesh, ray, e.id[1], e.r[1], e.id[2], e.r[2]);
  e.ca = edgeSide(mesh, ray, e.id[2], e.r[2], e.id[0], e.r[0]);
  return e;
}

// Gradient of the scalar in a tet (for shading iso-surfaces), from its four corners.
glm::dvec3 tetGradient(const TetWalkMesh& mesh, const glm::uvec4& v) {
  const auto& pos = mesh.exactPositions();
  const auto& nodes = mesh.nodes();
  const glm::dvec3 p0 = pos[v[0]];
  const glm::dmat3 edges{pos[v[1]] - p0, pos[v[2]] - p0, pos[v[3]] - p0};
  const double s0 = nodes[v[0]].w;
  const glm::dvec3 ds(nodes[v[1]].w - s0, nodes[v[2]].w - s0, nodes[v[3]].w - s0);
  const double det = glm::determinant(edges);
  return det != 0.0 ? glm::inverse(glm::transpose(edges)) * ds : glm::dvec3(0.0);
}

// A tet's segment (values relative to the mesh's value offset) with the iso-surfaces it
// crosses, as the reference: a surface counts when its value lies in (sFront, sBack].
optics::SegmentLight segmentLight(const Shared& sh, double sFront, double sBack, double length, const glm::uvec4& tet,
                          const glm::vec3& d) {
  const double offset = sh.mesh.valueOffset();
  const double a = sFront + offset, b = sBack + offset;
  if (sh.settings.isoSurfaces.empty() || sFront == sBack) {
    return sh.tf.integrate(a, b, length);  // nothing to do where the range is transparent
  }
  double hits[16];
  const optics::IsoSurface* surfaces[16];
  int n = 0;
  for (const optics::IsoSurface& s : sh.settings.isoSurfaces) {
    const bool crossed = b > a ? (s.value > a && s.value <= b) : (s.value < a && s.value >= b);
    if (crossed && n < 16) hits[n] = (s.value - a) / (b - a), surfaces[n++] = &s;
  }
  if (n == 0) return sh.tf.integrate(a, b, length);
  for (int i = 1; i < n; ++i)  // few surfaces: insertion sort by position
    for (int j = i; j > 0 && hits[j] < hits[j - 1]; --j) std::swap(hits[j], hits[j - 1]), std::swap(surfaces[j], surfaces[j - 1]);
  const glm::dvec3 g = tetGradient(sh.mesh, tet);
  const double gl = glm::length(g);
  const double shade = gl > 0.0 ? 0.3 + 0.7 * std::abs(glm::dot(g / gl, glm::dvec3(d))) : 1.0;
  optics::SegmentLight total;
  double x0 = 0.0;
  for (int i = 0; i < n; ++i) {
    optics::compositeBehind(total, sh.tf.integrate(a + (b - a) * x0, surfaces[i]->value, (hits[i] - x0) * length));
    optics::compositeBehind(total, {surfaces[i]->color * shade * surfaces[i]->opacity, 1.0 - surfaces[i]->opacity});
    x0 = hits[i];
  }
  optics::compositeBehind(total, sh.tf.integrate(a + (b - a) * x0, b, (1.0 - x0) * length));
  return total;
}

// A tet's piece of a ray as the tetrahedra's field gives it: what an element stretch falls
// back to where the cell's map cannot be inverted along it.
struct LinearPiece {
  double sFront, sBack, length;
  glm::uvec4 tet;
};

struct RayTotals {
  std::size_t steps = 0, stopped = 0, ambiguous = 0, capped = 0;
  double maxStop = 0.0;
  std::vector<LinearPiece> stretchPieces;  ///< the open element stretch's tets (kept per thread)
};

// The ray's way through one cell drawn by the cell's own field: its tets' segments, joined,
// lit together once the ray leaves the cell.
struct OpenStretch {
  bool open = false;
  std::uint32_t cell = 0;
  double t0 = 0.0, t1 = 0.0;
};

// The exit face of the tet entered through `in`, whose fourth vertex is k (r, s): each
// of the three faces through k is named by the signs of the edges k->A, k->B, k->C.
// Returns 0, 1 or 2: the face opposite A, B or C.
inline int exitFace(const Side& eA, const Side& eB, const Side& eC, bool& ambiguous) {
  // Leaving through the face opposite A (k, B, C) needs k->B negative and k->C positive.
  const bool nA = !eA.positive, nB = !eB.positive, nC = !eC.positive;
  ambiguous = false;
  if (nB && !nC) return 0;
  if (nC && !nA) return 1;
  if (nA && !nB) return 2;
  // All three alike: float signs name no face. Take the face the ray misses by the least.
  ambiguous = true;
  const float m0 = std::min(-eB.value, eC.value), m1 = std::min(-eC.value, eA.value), m2 = std::min(-eA.value, eB.value);
  return m0 >= m1 && m0 >= m2 ? 0 : (m1 >= m2 ? 1 : 2);
}

// Lights the open element stretch (if any) behind `light`: the cell's own field fitted and
// integrated in double, or its tets' linear pieces where the map cannot be inverted.
// Returns whether the ray is now nearly opaque (and counts it).
bool closeStretch(const Shared& sh, const PixelRay& ray, OpenStretch& stretch, optics::SegmentLight& light,
                  RayTotals& totals) {
  if (!stretch.open) return false;
  stretch.open = false;
  const optics::ElementField& field = *sh.element->field;
  const auto lit =
      optics::integrateElementStretch(field, stretch.cell, sh.transfer, sh.settings.isoSurfaces,
                                      ray.exactO + sh.toField, ray.exactD, stretch.t0, stretch.t1, sh.accuracy);
  if (lit) {
    optics::compositeBehind(light, *lit);
  } else {
    field.countFallback();
    for (const LinearPiece& p : totals.stretchPieces)
      optics::compositeBehind(light, segmentLight(sh, p.sFront, p.sBack, p.length, p.tet, ray.d));
  }
  totals.stretchPieces.clear();
  if (light.transmittance >= sh.settings.terminationTransmittance) return false;
  ++totals.stopped;
  totals.maxStop = std::max(totals.maxStop, light.transmittance);
  return true;
}

// The walk itself (walk below): an element stretch still open when it returns is closed
// by the caller.
float walkTets(const Shared& sh, const PixelRay& ray, EntryFace in, std::uint32_t tet, float tIn, float sIn, float w0,
               float w1, optics::SegmentLight& light, RayTotals& totals, OpenStretch& stretch) {
  const TetWalkMesh& mesh = sh.mesh;
  const auto& nodes = mesh.nodes();
  const bool cellData = mesh.cellValues();
  constexpr float inf = std::numeric_limits<float>::infinity();
  for (std::size_t step = 0;; ++step) {
    if (step >= sh.stepCap) {
      ++totals.capped;
      return inf;
    }
    ++totals.steps;
    const glm::uvec4 v = mesh.tetNodes(tet);
    // The fourth vertex and where A, B, C sit in this tet.
    int local[3] = {-1, -1, -1}, kLocal = -1;
    for (int i = 0; i < 4; ++i) {
      if (v[i] == in.id[0]) local[0] = i;
      else if (v[i] == in.id[1]) local[1] = i;
      else if (v[i] == in.id[2]) local[2] = i;
      else kLocal = i;
    }
    if (kLocal < 0 || local[0] < 0 || local[1] < 0 || local[2] < 0) {  // adjacency disagrees with the ids
      ++totals.capped;
      return inf;
    }
    const std::uint32_t k = v[kLocal];
    const glm::vec4 node = nodes[k];
    const glm::vec3 rk = glm::vec3(node) - ray.o;
    const float sk = node.w;
    const Side eA = edgeSide(mesh, ray, k, rk, in.id[0], in.r[0]);
    const Side eB = edgeSide(mesh, ray, k, rk, in.id[1], in.r[1]);
    const Side eC = edgeSide(mesh, ray, k, rk, in.id[2], in.r[2]);
    bool ambiguous;
    const int exit = exitFace(eA, eB, eC, ambiguous);
    totals.ambiguous += ambiguous;
    // The exit face listed (k, X, Y) continues the entry's orientation; its edge products
    // are k->X, X->Y (an edge of the entry face) and Y->k.
    EntryFace out;
    const int x = (exit + 1) % 3, y = (exit + 2) % 3;
    const Side kx = exit == 0 ? eB : (exit == 1 ? eC : eA);
    const Side ky = exit == 0 ? eC : (exit == 1 ? eA : eB);
    const Side xy = exit == 0 ? in.bc : (exit == 1 ? in.ca : in.ab);
    out.id[0] = k, out.id[1] = in.id[x], out.id[2] = in.id[y];
    out.r[0] = rk, out.r[1] = in.r[x], out.r[2] = in.r[y];
    out.s[0] = sk, out.s[1] = in.s[x], out.s[2] = in.s[y];
    out.ab = kx;
    out.bc = xy;
    out.ca = {-ky.value, !ky.positive, ky.nearZero};
    int next = mesh.tetNeighbors(tet)[local[exit]];
    if (next >= 0 && !sh.visible[std::size_t(next)]) next = -1;  // leaving what shows
    float tOut = tIn, sOut = sIn;
    if (!crossing(mesh, ray, out, tOut, sOut, next < 0)) tOut = tIn, sOut = sIn;
    tOut = std::max(tOut, tIn);
    // The segment [tIn, tOut], cut to the window.
    if (tIn >= w1) return inf;
    if (tOut > w0 && tOut > tIn) {
      float a = tIn, b = tOut, sa = sIn, sb = sOut;
      if (cellData) sa = sb = mesh.tetValue(tet);
      const float span = tOut - tIn;
      if (a < w0) sa = sIn + (sOut - sIn) * ((w0 - tIn) / span), a = w0;
      if (b > w1) sb = sIn + (sOut - sIn) * ((w1 - tIn) / span), b = w1;
      if (cellData) sa = sb = mesh.tetValue(tet);
      const std::uint32_t cell = sh.element ? sh.element->cellOfTet[tet] : 0;
      if (sh.element && !sh.element->field->linearIn(cell)) {
        if (stretch.open && stretch.cell != cell && closeStretch(sh, ray, stretch, light, totals)) return inf;
        if (!stretch.open) stretch = {true, cell, double(a), double(b)};
        stretch.t1 = double(b);
        totals.stretchPieces.push_back({sa, sb, double(b) - double(a), v});
      } else {
        if (closeStretch(sh, ray, stretch, light, totals)) return inf;
        optics::compositeBehind(light, segmentLight(sh, sa, sb, double(b) - double(a), v, ray.d));
        if (light.transmittance < sh.settings.terminationTransmittance) {
          ++totals.stopped;
          totals.maxStop = std::max(totals.maxStop, light.transmittance);
          return inf;
        }
      }
    }
    if (next < 0) return tOut;
    tet = std::uint32_t(next);
    in = out;
    tIn = tOut;
    sIn = sOut;
  }
}

// Walks one ray from a boundary entry until it leaves the mesh, stops, or passes the end of
// its window [w0, w1]. Returns the parameter where it left the mesh (or +inf when done).
float walk(const Shared& sh, const PixelRay& ray, const EntryFace& in, std::uint32_t tet, float tIn, float sIn,
           float w0, float w1, optics::SegmentLight& light, RayTotals& totals) {
  OpenStretch stretch;
  const float left = walkTets(sh, ray, in, tet, tIn, sIn, w0, w1, light, totals, stretch);
  // Leaving the cell through the mesh's boundary, the window's end or a stop ends its stretch.
  if (closeStretch(sh, ray, stretch, light, totals)) return std::numeric_limits<float>::infinity();
  return left;
}

// Asks progress whether to go on (the calling thread's worker does); on cancellation the
// other workers see `stop` at their next item.
void stopIfCancelled(const Progress& progress, std::atomic<bool>& stop) {
  try {
    progress.report(0.0);
  } catch (...) {
    stop = true;
    throw;
  }
}

// The ray through the centre of pixel (x, y), the same rays as every other renderer. Made
// per tile as it is walked: a frame keeps no array of rays (at 1024x768 it was 70 MB,
// fresh pages whose first touches and release cost a fifth of the frame).
class PixelRayMaker {
 public:
  PixelRayMaker(const TetWalkMesh& mesh, const Camera& camera, int width, int height,
                const std::vector<float>& sceneDepth)
      : toModel_(glm::inverse(camera.projectionMatrix(double(width) / height) * camera.viewMatrix())),
        eye_(camera.eye()),
        origin_(mesh.origin()),
        ortho_(camera.projection() == Camera::Projection::Orthographic),
        width_(width),
        height_(height),
        depth_(sceneDepth.size() == std::size_t(width) * std::size_t(height) ? &sceneDepth : nullptr) {}

  PixelRay operator()(int x, int y) const {
    const double nx = 2.0 * (x + 0.5) / width_ - 1.0, ny = 1.0 - 2.0 * (y + 0.5) / height_;
    const glm::dvec3 nearPoint = unproject(nx, ny, -1.0), farPoint = unproject(nx, ny, 1.0);
    const glm::dvec3 start = ortho_ ? nearPoint : eye_;
    const glm::dvec3 dir = farPoint - start;
    const double length = glm::length(dir);
    // Parameters count from the ray's point nearest the mesh centre: the vectors from it to
    // the vertices stay short, so float products and parameters keep their precision.
    const glm::dvec3 unit = dir / length;
    const double shift = -glm::dot(start - origin_, unit);
    PixelRay r;
    r.exactO = start - origin_ + shift * unit;
    r.exactD = unit;
    r.o = glm::vec3(r.exactO);
    r.d = glm::vec3(unit);
    r.tEye = float(-shift);
    r.tStart = float((ortho_ ? 0.0 : glm::length(nearPoint - start)) - shift);
    double end = length;
    if (depth_) {  // stop at the opaque geometry in front
      const double z = (*depth_)[std::size_t(height_ - 1 - y) * std::size_t(width_) + std::size_t(x)];
      if (z < 1.0) end = std::min(end, glm::dot(unproject(nx, ny, 2.0 * z - 1.0) - start, unit));
    }
    r.tEnd = float(end - shift);
    return r;
  }

 private:
  glm::dvec3 unproject(double x, double y, double z) const {
    const glm::dvec4 p = toModel_ * glm::dvec4(x, y, z, 1.0);
    return glm::dvec3(p) / p.w;
  }
  glm::dmat4 toModel_;
  glm::dvec3 eye_, origin_;
  bool ortho_;
  int width_, height_;
  const std::vector<float>* depth_;
};

constexpr int kTile = 16;  ///< pixels are shared out in tiles of kTile x kTile

// The pixels of one tile, [x0, x1) x [y0, y1).
struct Tile {
  int x0, y0, x1, y1;
  int local(int x, int y) const { return (y - y0) * kTile + (x - x0); }
};

// The pixels whose rays may enter the visible part through a face: [x0, x1] x [y0, y1],
// empty (x0 > x1) for a face no ray can enter.
struct Footprint {
  int x0 = 1, y0 = 1, x1 = 0, y1 = 0;
};

// Every boundary face of the visible part, projected once per frame: where on the image
// its rays may enter (back faces and faces off the image enter none), and each tile's list
// of the faces whose footprint it meets.
struct FaceTiles {
  std::vector<Footprint> footprint;  ///< per face
  std::vector<std::uint32_t> first;  ///< tile i's faces: faces[first[i], first[i + 1])
  std::vector<std::uint32_t> faces;  ///< face indices, tile by tile
  bool eyeInside = false;            ///< rays may start inside the mesh (entered behind the eye)
};

Footprint footprintOf(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dmat4& viewProjection,
                      bool ortho, const glm::dvec3& eye, const glm::dvec3& viewDir, bool eyeInside, int width,
                      int height) {
  const glm::dvec3 n = glm::cross(b - a, c - a);
  int front = 0;
  double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
  for (const glm::dvec3& p : {a, b, c}) {
    const glm::dvec4 clip = viewProjection * glm::dvec4(p, 1.0);
    front += clip.w > 0.0;
    // Also right for corners behind the eye: the line through the eye and the pixel.
    const double px = (clip.x / clip.w + 1.0) * 0.5 * width - 0.5, py = (1.0 - clip.y / clip.w) * 0.5 * height - 0.5;
    lo[0] = std::min(lo[0], px), hi[0] = std::max(hi[0], px);
    lo[1] = std::min(lo[1], py), hi[1] = std::max(hi[1], py);
  }
  const bool behind = !ortho && front == 0, straddles = !ortho && front > 0 && front < 3;
  // Faces behind the eye matter only to rays that start inside the mesh (entered behind).
  if (behind && !eyeInside) return {};
  // Back faces cannot be entered: every ray passes through the eye, so a face turns the
  // same side to all of them (the other side when it lies behind the eye).
  const double facing = glm::dot(n, ortho ? viewDir : a - eye);
  if (!straddles && (behind ? facing < 0.0 : facing > 0.0)) return {};
  if (straddles) return {0, 0, width - 1, height - 1};  // its projection is no bounding box: every pixel
  if (!(hi[0] >= -1.0 && lo[0] <= width && hi[1] >= -1.0 && lo[1] <= height)) return {};
  return {std::max(0, int(std::floor(lo[0]))), std::max(0, int(std::floor(lo[1]))),
          std::min(width - 1, int(std::ceil(hi[0]))), std::min(height - 1, int(std::ceil(hi[1])))};
}

FaceTiles faceTiles(const TetWalkMesh& mesh, const std::vector<BoundaryFace>& faces, const Camera& camera, int width,
                    int height, unsigned threads, const Progress& progress) {
  const glm::dmat4 viewProjection = camera.projectionMatrix(double(width) / height) * camera.viewMatrix(mesh.origin());
  const bool ortho = camera.projection() == Camera::Projection::Orthographic;
  const glm::dvec3 eye = camera.eye() - mesh.origin();
  const glm::dvec3 viewDir = camera.viewDirection();
  const auto& pos = mesh.exactPositions();
  FaceTiles out;
  // Is the eye inside the mesh's box? Then rays may start inside the mesh: they are walked
  // from where they entered behind the eye, and integrated from the near plane on.
  glm::dvec3 boxLo(INFINITY), boxHi(-INFINITY);
  for (const glm::dvec3& p : pos) boxLo = glm::min(boxLo, p), boxHi = glm::max(boxHi, p);
  out.eyeInside = !ortho && glm::all(glm::greaterThanEqual(eye, boxLo)) && glm::all(glm::lessThanEqual(eye, boxHi));
  out.footprint.resize(faces.size());
  std::atomic<std::size_t> next{0};
  std::atomic<bool> stop{false};
  constexpr std::size_t kChunk = 1024;
  runOnThreads(threads, [&](unsigned worker) {
    for (std::size_t first; !stop && (first = next.fetch_add(kChunk)) < faces.size();) {
      if (worker == 0) stopIfCancelled(progress, stop);  // a cancelled frame stops here too
      for (std::size_t fi = first; fi < std::min(first + kChunk, faces.size()); ++fi) {
        const BoundaryFace& f = faces[fi];
        out.footprint[fi] = footprintOf(pos[f.v[0]], pos[f.v[1]], pos[f.v[2]], viewProjection, ortho, eye, viewDir,
                                        out.eyeInside, width, height);
      }
    }
  });
  // Each tile's faces by a counting sort, faces in ascending order within a tile.
  const int tilesX = (width + kTile - 1) / kTile, tilesY = (height + kTile - 1) / kTile;
  out.first.assign(std::size_t(tilesX) * std::size_t(tilesY) + 1, 0);
  const auto eachTile = [&](const Footprint& p, auto&& visit) {
    for (int ty = p.y0 / kTile; ty <= p.y1 / kTile; ++ty)
      for (int tx = p.x0 / kTile; tx <= p.x1 / kTile; ++tx)
        visit(std::size_t(ty) * std::size_t(tilesX) + std::size_t(tx));
  };
  for (const Footprint& p : out.footprint)
    if (p.x0 <= p.x1) eachTile(p, [&](std::size_t tile) { ++out.first[tile + 1]; });
  for (std::size_t i = 1; i < out.first.size(); ++i) out.first[i] += out.first[i - 1];
  out.faces.resize(out.first.back());
  std::vector<std::uint32_t> fill(out.first.begin(), out.first.end() - 1);
  for (std::size_t fi = 0; fi < faces.size(); ++fi)
    if (out.footprint[fi].x0 <= out.footprint[fi].x1)
      eachTile(out.footprint[fi], [&](std::size_t tile) { out.faces[fill[tile]++] = std::uint32_t(fi); });
  return out;
}

// Where a tile's rays enter the visible part: each face of the tile's list tested against
// the rays of the pixels its footprint shares with the tile. Listed by pixel (the tile's
// own index), then parameter: pixel p's entries are list[first[p], first[p + 1]).
struct TileEntries {
  std::vector<Entry> list;
  std::uint32_t first[kTile * kTile + 1];
};

void findTileEntries(const TetWalkMesh& mesh, const std::vector<BoundaryFace>& faces, const FaceTiles& bins,
                     std::size_t tileIndex, const Tile& tile, const PixelRay* rays, TileEntries& out) {
  out.list.clear();
  for (std::uint32_t i = bins.first[tileIndex]; i < bins.first[tileIndex + 1]; ++i) {
    const std::uint32_t fi = bins.faces[i];
    const Footprint& p = bins.footprint[fi];
    const BoundaryFace& f = faces[fi];
    for (int y = std::max(p.y0, tile.y0); y <= std::min(p.y1, tile.y1 - 1); ++y)
      for (int x = std::max(p.x0, tile.x0); x <= std::min(p.x1, tile.x1 - 1); ++x) {
        const int pixel = tile.local(x, y);
        const PixelRay& ray = rays[pixel];
        const EntryFace e = boundaryEntry(mesh, f, ray);
        if (e.ab.positive || e.bc.positive || e.ca.positive) continue;  // not entering through this face
        float t, s;
        if (!crossing(mesh, ray, e, t, s, true)) continue;
        if (!bins.eyeInside && t < ray.tEye) continue;  // behind the eye
        out.list.push_back({std::uint32_t(pixel), t, s, fi});
      }
  }
  std::sort(out.list.begin(), out.list.end());
  std::size_t at = 0;
  for (std::uint32_t p = 0; p <= std::uint32_t(kTile * kTile); ++p) {
    out.first[p] = std::uint32_t(at);
    while (at < out.list.size() && out.list[at].pixel == p) ++at;
  }
}

// Where the clip half-spaces leave the ray: [t0, t1] (empty when t0 >= t1).
void clipWindow(const std::vector<ClipPlane>& planes, const glm::dvec3& origin, const PixelRay& ray, float& t0,
                float& t1) {
  for (const ClipPlane& c : planes) {
    const double a = glm::dot(c.normal, glm::dvec3(ray.o) - (c.point - origin)), b = glm::dot(c.normal, glm::dvec3(ray.d));
    if (b == 0.0) {
      if (a < 0.0) t1 = t0;
      continue;
    }
    const float t = float(-a / b);
    if (b > 0.0) t0 = std::max(t0, t);
    else t1 = std::min(t1, t);
  }
}

}  // namespace

namespace {
unsigned threadsFor(int threadCount) { return threadCount > 0 ? unsigned(threadCount) : usableCores(); }
}  // namespace

VisiblePart findVisiblePart(const TetWalkMesh& mesh, const TransferFunction& tf,
                            const std::vector<optics::IsoSurface>& isoSurfaces, int threadCount,
                            const CpuElementField* element) {
  VisiblePart part;
  part.tets = visibleTets(mesh, PiecewiseIntegrator(tf), isoSurfaces, threadsFor(threadCount), element);
  part.faces = mesh.boundaryOf(part.tets);
  return part;
}

CpuImage renderCpu(const TetWalkMesh& mesh, const TransferFunction& tf, const Camera& camera, int width, int height,
                   const CpuRaySettings& settings, const Progress& progress, int threadCount) {
  return renderCpu(mesh, findVisiblePart(mesh, tf, settings.isoSurfaces, threadCount, settings.element.get()), tf,
                   camera, width, height, settings, progress, threadCount);
}

CpuImage renderCpu(const TetWalkMesh& mesh, const VisiblePart& part, const TransferFunction& tf, const Camera& camera,
                   int width, int height, const CpuRaySettings& settings, const Progress& progress, int threadCount) {
  CpuImage image{width, height, std::vector<float>(std::size_t(width) * std::size_t(height) * 4, 0.0f), {}};
  const unsigned threads = threadsFor(threadCount);
  const auto entryStart = Clock::now();
  const PiecewiseIntegrator integrator(tf);
  const std::vector<std::uint8_t>& visible = part.tets;
  const std::vector<BoundaryFace>& faces = part.faces;
  const FaceTiles bins = faceTiles(mesh, faces, camera, width, height, threads, progress);
  progress.report(0.0);  // a cancelled frame stops between its stages too
  const PixelRayMaker makeRay(mesh, camera, width, height, settings.sceneDepth);
  const double binMs = msSince(entryStart);

  const CpuElementField* element = settings.element.get();
  if (element && (element->cellOfTet.size() != mesh.tetCount() || mesh.cellValues()))
    throw std::invalid_argument(
        "the element field does not fit the mesh: " + std::to_string(element->cellOfTet.size()) + " cells named for " +
        std::to_string(mesh.tetCount()) + " tetrahedra");
  const Shared shared{mesh,
                      integrator,
                      settings,
                      visible,
                      mesh.tetCount() + 16,
                      float(1e-6 * mesh.diagonal()),
                      tf,
                      element,
                      element ? mesh.origin() - element->field->origin() : glm::dvec3(0.0),
                      element ? optics::toleratedStretches(*element->field, tf, !settings.isoSurfaces.empty(),
                                                           settings.elementTolerance)
                              : optics::StretchAccuracy{}};
  const int tilesX = (width + kTile - 1) / kTile, tilesY = (height + kTile - 1) / kTile;
  std::atomic<int> nextTile{0}, tilesDone{0};
  std::atomic<bool> stop{false};
  std::mutex totalsMutex;
  RayTotals all;
  std::size_t raysHit = 0;
  double entrySeconds = 0.0;  // all threads together
  const auto walkStart = Clock::now();
  const unsigned ran = runOnThreads(threads, [&](unsigned worker) {
    RayTotals totals;
    std::size_t hit = 0;
    PixelRay rays[kTile * kTile];
    TileEntries entries;
    Clock::duration inEntries{};
    try {
      for (int tileIndex; !stop && (tileIndex = nextTile++) < tilesX * tilesY;) {
        const int tx = tileIndex % tilesX, ty = tileIndex / tilesX;
        const Tile tile{tx * kTile, ty * kTile, std::min(width, (tx + 1) * kTile), std::min(height, (ty + 1) * kTile)};
        const auto tileStart = Clock::now();
        if (bins.first[std::size_t(tileIndex)] != bins.first[std::size_t(tileIndex) + 1])  // else no ray enters
          for (int y = tile.y0; y < tile.y1; ++y)
            for (int x = tile.x0; x < tile.x1; ++x) rays[tile.local(x, y)] = makeRay(x, y);
        findTileEntries(mesh, faces, bins, std::size_t(tileIndex), tile, rays, entries);
        inEntries += Clock::now() - tileStart;
        for (int y = tile.y0; y < tile.y1; ++y)
          for (int x = tile.x0; x < tile.x1; ++x) {
            const int local = tile.local(x, y);
            const std::uint32_t begin = entries.first[local], end = entries.first[local + 1];
            if (begin == end) continue;
            const PixelRay& ray = rays[local];
            float w0 = ray.tStart, w1 = ray.tEnd;
            clipWindow(settings.clipPlanes, mesh.origin(), ray, w0, w1);
            if (!(w0 < w1)) continue;
            ++hit;
            optics::SegmentLight light;
            float leftAt = -std::numeric_limits<float>::infinity();
            for (std::uint32_t i = begin; i < end; ++i) {
              const Entry& e = entries.list[i];
              if (e.t < leftAt - shared.reentryTolerance) continue;  // inside what was walked already
              if (e.t >= w1) break;
              const BoundaryFace& f = faces[e.face];
              // The crossing was found with the entry (in double): only the face's products again.
              leftAt = walk(shared, ray, boundaryEntry(mesh, f, ray), f.tet, e.t, e.s, w0, w1, light, totals);
              if (std::isinf(leftAt)) break;
            }
            float* out = &image.rgba[4 * (std::size_t(y) * std::size_t(width) + std::size_t(x))];
            out[0] = float(light.color.r), out[1] = float(light.color.g), out[2] = float(light.color.b);
            out[3] = float(1.0 - light.transmittance);
          }
        const int done = ++tilesDone;
        if (worker == 0) progress.report(double(done) / (tilesX * tilesY));
      }
    } catch (...) {
      stop = true;
      throw;
    }
    const std::lock_guard lock(totalsMutex);
    entrySeconds += std::chrono::duration<double>(inEntries).count();
    all.steps += totals.steps, all.stopped += totals.stopped, all.ambiguous += totals.ambiguous;
    all.capped += totals.capped, all.maxStop = std::max(all.maxStop, totals.maxStop);
    raysHit += hit;
  });
  // The entries are found tile by tile as the rays are walked: their share of the wall time
  // is their share of the threads' time.
  const double tilesMs = msSince(walkStart), entryShare = std::min(1e3 * entrySeconds / std::max(ran, 1u), tilesMs);
  image.stats.entryMs = binMs + entryShare;
  image.stats.walkMs = tilesMs - entryShare;
  image.stats.rays = raysHit;
  image.stats.visibleTets = std::size_t(std::count(visible.begin(), visible.end(), std::uint8_t(1)));
  image.stats.steps = all.steps;
  image.stats.stoppedRays = all.stopped;
  image.stats.maxStopTransmittance = all.maxStop;
  image.stats.ambiguousExits = all.ambiguous;
  image.stats.cappedRays = all.capped;
  image.stats.threads = ran;
  return image;
}

}  // namespace volpost::volume

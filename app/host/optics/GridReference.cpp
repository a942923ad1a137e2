// SPDX-License-Identifier: MIT
#include "host/optics/GridReference.hpp"

#include <volpost/core/optics/Headlight.hpp>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <stdexcept>

namespace volpost::optics {
namespace {

// A cubic on u in [0, 1]: c0 + c1 u + c2 u^2 + c3 u^3.
struct Cubic {
  double c0 = 0, c1 = 0, c2 = 0, c3 = 0;
  double operator()(double u) const { return c0 + u * (c1 + u * (c2 + u * c3)); }
  // Through the values at u = 0, 1/3, 2/3, 1 (Lagrange to monomial).
  static Cubic through(double p0, double p1, double p2, double p3) {
    Cubic c;
    c.c0 = p0;
    c.c1 = (-11.0 * p0 + 18.0 * p1 - 9.0 * p2 + 2.0 * p3) / 2.0;
    c.c2 = 9.0 * (2.0 * p0 - 5.0 * p1 + 4.0 * p2 - p3) / 2.0;
    c.c3 = 27.0 * (-p0 + 3.0 * p1 - 3.0 * p2 + p3) / 6.0;
    return c;
  }
};

// The trilinear polynomial of one cell, evaluated anywhere (extrapolated outside it, so a
// piece whose ends round just outside the cell still sees one polynomial).
struct Cell {
  std::array<double, 8> v{};  // v[i + 2 j + 4 k]
  glm::dvec3 base{0.0};
  double at(const glm::dvec3& index) const {
    const glm::dvec3 w = index - base;
    const double a = v[0] + w.x * (v[1] - v[0]), b = v[2] + w.x * (v[3] - v[2]);
    const double c = v[4] + w.x * (v[5] - v[4]), d = v[6] + w.x * (v[7] - v[6]);
    const double e = a + w.y * (b - a), f = c + w.y * (d - c);
    return e + w.z * (f - e);
  }
  glm::dvec3 gradient(const glm::dvec3& index) const {  // d/d(index)
    const glm::dvec3 w = index - base;
    const auto lerp = [](double p, double q, double t) { return p + t * (q - p); };
    const double gx = lerp(lerp(v[1] - v[0], v[3] - v[2], w.y), lerp(v[5] - v[4], v[7] - v[6], w.y), w.z);
    const double gy = lerp(lerp(v[2] - v[0], v[3] - v[1], w.x), lerp(v[6] - v[4], v[7] - v[5], w.x), w.z);
    const double gz = lerp(lerp(v[4] - v[0], v[5] - v[1], w.x), lerp(v[6] - v[2], v[7] - v[3], w.x), w.y);
    return {gx, gy, gz};
  }
};

Cell cellAt(const RegularGrid& g, SampleView values, const glm::dvec3& index) {
  Cell c;
  std::size_t b[3];
  for (int a = 0; a < 3; ++a) {
    const double top = double(g.dims[a] - 2);
    const double x = std::clamp(std::floor(index[a]), 0.0, top);
    b[a] = std::size_t(x);
    c.base[a] = x;
  }
  for (int n = 0; n < 8; ++n) {
    const double v = values[g.pointIndex(b[0] + (n & 1), b[1] + ((n >> 1) & 1), b[2] + ((n >> 2) & 1))];
    c.v[std::size_t(n)] = std::isfinite(v) ? v : 0.0;
  }
  return c;
}

// Where p(u) = value for u in (a, b), p monotone there with p(a), p(b) on either side.
double rootBetween(const Cubic& p, double a, double b, double value) {
  const bool rising = p(b) > p(a);
  for (int i = 0; i < 100 && b - a > 1e-16; ++i) {
    const double m = 0.5 * (a + b);
    if ((p(m) < value) == rising) a = m;
    else b = m;
  }
  return 0.5 * (a + b);
}

struct Cut {
  double u;
  const IsoSurface* iso;  // nullptr: a control point
};

// The places in (0, 1) where p crosses a control-point value or an iso-value, sorted.
std::vector<Cut> cutsOf(const Cubic& p, const TransferFunction& tf, const RaySettings& settings) {
  // Monotone pieces: split at the roots of p' = c1 + 2 c2 u + 3 c3 u^2 in (0, 1).
  std::vector<double> knots{0.0};
  const double qa = 3.0 * p.c3, qb = 2.0 * p.c2, qc = p.c1;
  if (qa != 0.0) {
    const double disc = qb * qb - 4.0 * qa * qc;
    if (disc > 0.0) {
      const double s = std::sqrt(disc);
      const double q = -0.5 * (qb + (qb >= 0.0 ? s : -s));
      for (double r : {q / qa, q != 0.0 ? qc / q : -1.0})
        if (r > 0.0 && r < 1.0) knots.push_back(r);
    }
  } else if (qb != 0.0) {
    const double r = -qc / qb;
    if (r > 0.0 && r < 1.0) knots.push_back(r);
  }
  std::sort(knots.begin(), knots.end());
  knots.push_back(1.0);
  std::vector<Cut> cuts;
  const std::vector<ControlPoint>& points = tf.points();
  for (std::size_t k = 0; k + 1 < knots.size(); ++k) {
    const double a = knots[k], b = knots[k + 1];
    const double sa = p(a), sb = p(b);
    const double lo = std::min(sa, sb), hi = std::max(sa, sb);
    if (!(hi > lo)) continue;
    // Control points strictly inside (lo, hi), found by binary search.
    auto first = std::upper_bound(points.begin(), points.end(), lo,
                                  [](double v, const ControlPoint& c) { return v < c.value; });
    for (auto it = first; it != points.end() && it->value < hi; ++it)
      cuts.push_back({rootBetween(p, a, b, it->value), nullptr});
    // An iso-surface counts where the value lies in (front, back] along the ray.
    for (const IsoSurface& s : settings.isoSurfaces)
      if ((sb > sa && s.value > sa && s.value <= sb) || (sb < sa && s.value < sa && s.value >= sb))
        cuts.push_back({s.value == sb ? b : rootBetween(p, a, b, s.value), &s});
  }
  std::sort(cuts.begin(), cuts.end(), [](const Cut& x, const Cut& y) { return x.u < y.u; });
  return cuts;
}

// Color and extinction as linear functions of the scalar on the TF segment holding `s`
// (constant beyond the ends).
struct LinearOptics {
  double s0 = 0, ds = 1;  // the scalar's offset and span of the segment
  glm::dvec3 c0{0.0}, c1{0.0};
  double tau0 = 0, tau1 = 0;
};
LinearOptics opticsAt(const TransferFunction& tf, double s) {
  const std::vector<ControlPoint>& pts = tf.points();
  LinearOptics o;
  if (pts.empty()) return o;
  auto hi = std::upper_bound(pts.begin(), pts.end(), s, [](double v, const ControlPoint& c) { return v < c.value; });
  if (hi == pts.begin() || hi == pts.end()) {
    const ControlPoint& end = hi == pts.begin() ? pts.front() : pts.back();
    o.c0 = o.c1 = end.color;
    o.tau0 = o.tau1 = end.extinction;
    return o;
  }
  const ControlPoint& a = *(hi - 1);
  const ControlPoint& b = *hi;
  o.s0 = a.value;
  o.ds = b.value - a.value;
  o.c0 = a.color;
  o.c1 = b.color;
  o.tau0 = a.extinction;
  o.tau1 = b.extinction;
  return o;
}

// One piece [ua, ub] of a cell's cubic over which the TF is one linear segment: optical
// depth exactly, emission by Gauss-Legendre on panels of bounded optical depth.
// `shade(u)`, if given, is the emission's shading there (multiplier, white added).
using ShadeAt = std::function<glm::dvec2(double u)>;
SegmentLight integrateSmoothPiece(const Cubic& p, double ua, double ub, double length, const TransferFunction& tf,
                                  const ShadeAt& shade) {
  SegmentLight out;
  if (!(ub > ua)) return out;
  const LinearOptics o = opticsAt(tf, p(0.5 * (ua + ub)));
  const auto weight = [&](double u) { return o.ds > 0.0 ? std::clamp((p(u) - o.s0) / o.ds, 0.0, 1.0) : 0.0; };
  // tau(u) = tau0 + (tau1 - tau0) w(u), w cubic: its integral is a quartic.
  const double k = o.ds > 0.0 ? (o.tau1 - o.tau0) / o.ds : 0.0;
  const Cubic tau{o.tau0 + k * (p.c0 - o.s0), k * p.c1, k * p.c2, k * p.c3};
  const auto depth = [&](double u) {  // L * integral_ua^u tau
    const auto prim = [&](double x) {
      return x * (tau.c0 + x * (tau.c1 / 2.0 + x * (tau.c2 / 3.0 + x * tau.c3 / 4.0)));
    };
    return length * (prim(u) - prim(ua));
  };
  const double total = std::max(depth(ub), 0.0);
  out.transmittance = std::exp(-total);
  if (total == 0.0) return out;
  static constexpr double x8[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267, 0.9602898564975363};
  static constexpr double w8[4] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};
  const int panels = int(std::clamp(std::ceil(total / 0.25), 1.0, 4096.0));
  const double h = (ub - ua) / panels;
  for (int n = 0; n < panels; ++n) {
    const double mid = ua + (n + 0.5) * h, half = 0.5 * h;
    if (depth(mid - half) > 40.0) break;  // what is behind counts less than 1e-17
    for (int q = 0; q < 4; ++q)
      for (double u : {mid - half * x8[q], mid + half * x8[q]}) {
        const double w = weight(u);
        glm::dvec3 color = o.c0 + w * (o.c1 - o.c0);
        if (shade) {
          const glm::dvec2 lit = shade(u);
          color = color * lit.x + glm::dvec3(lit.y);
        }
        out.color += (w8[q] * half * length) * color * std::max(tau(u), 0.0) * std::exp(-depth(u));
      }
  }
  return out;
}

// A grid without defects and a value per point, or std::invalid_argument saying which.
void requireGridValues(const RegularGrid& grid, SampleView values) {
  if (const std::string defect = grid.defect(); !defect.empty()) throw std::invalid_argument(defect);
  if (values.size() != grid.pointCount())
    throw std::invalid_argument(std::to_string(values.size()) + " values for a grid of " +
                                std::to_string(grid.pointCount()) + " points");
}

// The ray's part inside the grid's box and the clip planes, cut where it crosses grid
// planes: the parameters of the cells' boundaries along it, in order (empty: it misses).
// o and e: the ray's origin and unit direction in index space.
std::vector<double> cellBoundaries(const RegularGrid& grid, const glm::dvec3& origin, const glm::dvec3& d,
                                   const glm::dvec3& o, const glm::dvec3& e, double tMin, double tMax,
                                   const RaySettings& settings) {
  double t0 = tMin, t1 = tMax;
  for (int a = 0; a < 3; ++a) {  // the grid's box in index space
    const double top = double(grid.dims[a] - 1);
    if (e[a] == 0.0) {
      if (o[a] < 0.0 || o[a] > top) return {};
      continue;
    }
    const double ta = -o[a] / e[a], tb = (top - o[a]) / e[a];
    t0 = std::max(t0, std::min(ta, tb));
    t1 = std::min(t1, std::max(ta, tb));
  }
  for (const ClipPlane& c : settings.clipPlanes) {
    const double a = glm::dot(c.normal, origin - c.point), b = glm::dot(c.normal, d);
    if (b == 0.0) {
      if (a < 0.0) return {};
      continue;
    }
    if (b > 0.0) t0 = std::max(t0, -a / b);
    else t1 = std::min(t1, -a / b);
  }
  if (!(t0 < t1)) return {};
  std::vector<double> ts{t0, t1};
  for (int a = 0; a < 3; ++a) {
    if (e[a] == 0.0) continue;
    const double x0 = o[a] + t0 * e[a], x1 = o[a] + t1 * e[a];
    for (double k = std::ceil(std::min(x0, x1)); k <= std::floor(std::max(x0, x1)); k += 1.0) {
      const double t = (k - o[a]) / e[a];
      if (t > t0 && t < t1) ts.push_back(t);
    }
  }
  std::sort(ts.begin(), ts.end());
  return ts;
}

}  // namespace

SegmentLight integrateGridRay(const RegularGrid& grid, SampleView values, const TransferFunction& tf,
                              glm::dvec3 origin, glm::dvec3 direction, double tMin, double tMax,
                              const RaySettings& settings) {
  SegmentLight total;
  const glm::dvec3 d = direction / glm::length(direction);
  const glm::dmat3 toIndex = glm::inverse(grid.indexToWorld());
  const glm::dvec3 o = toIndex * (origin - grid.origin), e = toIndex * d;
  const std::vector<double> ts = cellBoundaries(grid, origin, d, o, e, tMin, tMax, settings);
  const glm::dmat3 gradientToWorld = glm::transpose(toIndex);
  for (std::size_t n = 0; n + 1 < ts.size(); ++n) {
    const double ta = ts[n], tb = ts[n + 1], length = tb - ta;
    if (!(length > 0.0)) continue;
    const Cell cell = cellAt(grid, values, o + (0.5 * (ta + tb)) * e);
    const auto sAt = [&](double u) { return cell.at(o + (ta + u * length) * e); };
    const Cubic p = Cubic::through(sAt(0.0), sAt(1.0 / 3.0), sAt(2.0 / 3.0), sAt(1.0));
    ShadeAt shade;
    if (settings.shading)
      shade = [&](double u) { return headlight(gradientToWorld * cell.gradient(o + (ta + u * length) * e), d); };
    double ua = 0.0;
    for (const Cut& cut : cutsOf(p, tf, settings)) {
      compositeBehind(total, integrateSmoothPiece(p, ua, cut.u, length, tf, shade));
      if (cut.iso) {
        const double surfaceShade = isoShade(gradientToWorld * cell.gradient(o + (ta + cut.u * length) * e), d);
        compositeBehind(total, {cut.iso->color * surfaceShade * cut.iso->opacity, 1.0 - cut.iso->opacity});
      }
      ua = cut.u;
    }
    compositeBehind(total, integrateSmoothPiece(p, ua, 1.0, length, tf, shade));
    if (total.transmittance < settings.terminationTransmittance) break;
  }
  return total;
}

ReferenceImage renderGridReference(const RegularGrid& grid, SampleView values, const TransferFunction& tf,
                                   const Camera& camera, int width, int height, const RaySettings& settings,
                                   const Progress& progress, int threads) {
  requireGridValues(grid, values);
  return renderPixelRays(
      camera, width, height,
      [&](glm::dvec3 origin, glm::dvec3 direction, double tMin, double tMax) {
        return integrateGridRay(grid, values, tf, origin, direction, tMin, tMax, settings);
      },
      progress, threads);
}

// ---- 2D transfer functions: converged step halving ------------------------------------

namespace {

// The ray by the midpoint rule, each cell's part cut at the iso-surfaces it crosses and
// into parts of at most `step`: each part's color and extinction at its middle, from the
// cell's trilinear value and gradient magnitude there.
SegmentLight integrateGridRay2DAtStep(const RegularGrid& grid, SampleView values,
                                      const TransferFunction2D& tf, const glm::dvec3& origin, const glm::dvec3& d,
                                      double tMin, double tMax, const RaySettings& settings, double step) {
  SegmentLight total;
  const glm::dmat3 toIndex = glm::inverse(grid.indexToWorld());
  const glm::dmat3 gradientToWorld = glm::transpose(toIndex);
  const glm::dvec3 o = toIndex * (origin - grid.origin), e = toIndex * d;
  const std::vector<double> ts = cellBoundaries(grid, origin, d, o, e, tMin, tMax, settings);
  const TransferFunction none;
  for (std::size_t n = 0; n + 1 < ts.size(); ++n) {
    const double ta = ts[n], tb = ts[n + 1], length = tb - ta;
    if (!(length > 0.0)) continue;
    const Cell cell = cellAt(grid, values, o + (0.5 * (ta + tb)) * e);
    const auto sAt = [&](double u) { return cell.at(o + (ta + u * length) * e); };
    const Cubic p = Cubic::through(sAt(0.0), sAt(1.0 / 3.0), sAt(2.0 / 3.0), sAt(1.0));
    const auto midpoints = [&](double ua, double ub) {
      const int parts = std::max(1, int(std::ceil((ub - ua) * length / step)));
      for (int k = 0; k < parts; ++k) {
        const double u = ua + (ub - ua) * (k + 0.5) / parts;
        const glm::dvec3 index = o + (ta + u * length) * e;
        const glm::dvec3 gradient = gradientToWorld * cell.gradient(index);
        glm::dvec4 c = tf.evaluate(cell.at(index), glm::length(gradient));
        if (!(c.a > 0.0)) continue;
        if (settings.shading) {
          const glm::dvec2 k2 = headlight(gradient, d);
          c = glm::dvec4(glm::dvec3(c) * k2.x + k2.y, c.a);
        }
        const double transmittance = std::exp(-c.a * (ub - ua) * length / parts);
        compositeBehind(total, {glm::dvec3(c) * (1.0 - transmittance), transmittance});
      }
    };
    double ua = 0.0;
    for (const Cut& cut : cutsOf(p, none, settings)) {  // iso-surfaces only
      midpoints(ua, cut.u);
      const double surfaceShade = isoShade(gradientToWorld * cell.gradient(o + (ta + cut.u * length) * e), d);
      compositeBehind(total, {cut.iso->color * surfaceShade * cut.iso->opacity, 1.0 - cut.iso->opacity});
      ua = cut.u;
    }
    midpoints(ua, 1.0);
  }
  return total;
}

}  // namespace

SegmentLight integrateGridRay2D(const RegularGrid& grid, SampleView values, const TransferFunction2D& tf,
                                glm::dvec3 origin, glm::dvec3 direction, double tMin, double tMax,
                                const RaySettings& settings, double tolerance) {
  const glm::dvec3 d = direction / glm::length(direction);
  const double spacing =
      std::min({glm::length(grid.axes[0]), glm::length(grid.axes[1]), glm::length(grid.axes[2])});
  double step = 0.25 * spacing;
  SegmentLight last = integrateGridRay2DAtStep(grid, values, tf, origin, d, tMin, tMax, settings, step);
  double previousChange = 1e300;
  for (int halvings = 0; halvings < 10; ++halvings) {
    step *= 0.5;
    const SegmentLight next = integrateGridRay2DAtStep(grid, values, tf, origin, d, tMin, tMax, settings, step);
    const double change = std::max({std::abs(next.color.r - last.color.r), std::abs(next.color.g - last.color.g),
                                    std::abs(next.color.b - last.color.b),
                                    std::abs(next.transmittance - last.transmittance)});
    last = next;
    // Two small changes in a row: one alone can be a coincidence (the error of a step
    // that happens to cancel at a kink of the table).
    if (change <= tolerance && previousChange <= 2.0 * tolerance) break;
    previousChange = change;
  }
  return last;
}

ReferenceImage renderGridReference2D(const RegularGrid& grid, SampleView values,
                                     const TransferFunction2D& tf, const Camera& camera, int width, int height,
                                     const RaySettings& settings, double tolerance, const Progress& progress,
                                     int threads) {
  requireGridValues(grid, values);
  return renderPixelRays(
      camera, width, height,
      [&](glm::dvec3 origin, glm::dvec3 direction, double tMin, double tMax) {
        return integrateGridRay2D(grid, values, tf, origin, direction, tMin, tMax, settings, tolerance);
      },
      progress, threads);
}

}  // namespace volpost::optics

// SPDX-License-Identifier: MIT
#include <volpost/core/CellShape.hpp>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>

namespace volpost {

namespace {

// A number with its derivatives along the three natural coordinates: evaluating the shape
// functions on these gives the Jacobian exactly, from the same code as the values.
struct Dual {
  double v = 0.0;
  glm::dvec3 d{0.0};
};
Dual operator+(Dual a, Dual b) { return {a.v + b.v, a.d + b.d}; }
Dual operator-(Dual a, Dual b) { return {a.v - b.v, a.d - b.d}; }
Dual operator*(Dual a, Dual b) { return {a.v * b.v, a.v * b.d + b.v * a.d}; }
Dual operator*(double k, Dual a) { return {k * a.v, k * a.d}; }
Dual operator+(double k, Dual a) { return {k + a.v, a.d}; }
Dual operator-(double k, Dual a) { return {k - a.v, -a.d}; }
Dual operator+(Dual a, double k) { return {a.v + k, a.d}; }
double valueOf(const Dual& x) { return x.v; }

constexpr glm::dvec3 kHexCorners[8] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                       {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
constexpr glm::dvec3 kTetCorners[4] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
constexpr glm::dvec3 kWedgeCorners[6] = {{0, 0, -1}, {1, 0, -1}, {0, 1, -1}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}};
constexpr glm::dvec3 kPyramidCorners[5] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, 1}};

glm::dvec3 cornerOf(CellType type, int corner) {
  switch (type) {
    case CellType::Tet4:
    case CellType::Tet10: return kTetCorners[corner];
    case CellType::Hex8:
    case CellType::Hex20: return kHexCorners[corner];
    case CellType::Wedge6:
    case CellType::Wedge15: return kWedgeCorners[corner];
    case CellType::Pyramid5: return kPyramidCorners[corner];
  }
  return glm::dvec3(0.0);
}

// The shape functions at xi, written once for plain numbers and for Duals. Midside nodes
// follow topology(type).edges, so their order is the one the rest of volpost uses.
template <class T>
void evaluate(CellType type, const T xi[3], T n[kMaxCellNodes]) {
  const CellTopology& topo = topology(type);
  switch (type) {
    case CellType::Tet4:
    case CellType::Tet10: {
      const T l[4] = {1.0 - xi[0] - xi[1] - xi[2], xi[0], xi[1], xi[2]};
      if (type == CellType::Tet4) {
        for (int i = 0; i < 4; ++i) n[i] = l[i];
        return;
      }
      for (int i = 0; i < 4; ++i) n[i] = l[i] * (2.0 * l[i] + (-1.0));
      for (const CellEdge& e : topo.edges) n[e.mid] = 4.0 * (l[e.a] * l[e.b]);
      return;
    }
    case CellType::Hex8:
    case CellType::Hex20: {
      for (int i = 0; i < 8; ++i) {
        const glm::dvec3 c = kHexCorners[i];
        const T f = (1.0 + c.x * xi[0]) * ((1.0 + c.y * xi[1]) * (1.0 + c.z * xi[2]));
        n[i] = type == CellType::Hex8 ? 0.125 * f : 0.125 * (f * ((c.x * xi[0] + c.y * xi[1]) + c.z * xi[2] + (-2.0)));
      }
      if (type == CellType::Hex8) return;
      for (const CellEdge& e : topo.edges) {
        const glm::dvec3 c = 0.5 * (kHexCorners[e.a] + kHexCorners[e.b]);  // one coordinate is 0
        T f = T(1.0);
        for (int k = 0; k < 3; ++k) f = f * (c[k] == 0.0 ? 1.0 - xi[k] * xi[k] : 1.0 + c[k] * xi[k]);
        n[e.mid] = 0.25 * f;
      }
      return;
    }
    case CellType::Wedge6:
    case CellType::Wedge15: {
      const T l[3] = {1.0 - xi[0] - xi[1], xi[0], xi[1]};
      const T& z = xi[2];
      for (int i = 0; i < 6; ++i) {
        const double zi = i < 3 ? -1.0 : 1.0;
        const T& li = l[i % 3];
        n[i] = type == CellType::Wedge6 ? 0.5 * (li * (1.0 + zi * z))
                                        : 0.5 * (li * ((2.0 * li + (-1.0)) * (1.0 + zi * z))) - 0.5 * (li * (1.0 - z * z));
      }
      if (type == CellType::Wedge6) return;
      for (const CellEdge& e : topo.edges) {
        if (e.b == e.a + 3) {  // a vertical edge: corner column times the bubble in zeta
          n[e.mid] = l[e.a % 3] * (1.0 - z * z);
        } else {
          const double zm = e.a < 3 ? -1.0 : 1.0;
          n[e.mid] = 2.0 * (l[e.a % 3] * l[e.b % 3]) * (1.0 + zm * z);
        }
      }
      return;
    }
    case CellType::Pyramid5: {
      const T &r = xi[0], &s = xi[1], &t = xi[2];
      n[0] = (1.0 - r) * ((1.0 - s) * (1.0 - t));
      n[1] = r * ((1.0 - s) * (1.0 - t));
      n[2] = r * (s * (1.0 - t));
      n[3] = (1.0 - r) * (s * (1.0 - t));
      n[4] = t;
      return;
    }
  }
}

}  // namespace

ShapeValues shapeFunctions(CellType type, const glm::dvec3& xi) {
  const double x[3] = {xi.x, xi.y, xi.z};
  ShapeValues n{};
  evaluate(type, x, n.data());
  return n;
}

glm::dvec3 naturalCoordinatesOfNode(CellType type, int node) {
  const CellTopology& topo = topology(type);
  if (node < topo.cornerCount) return cornerOf(type, node);
  for (const CellEdge& e : topo.edges)
    if (e.mid == node) return 0.5 * (cornerOf(type, e.a) + cornerOf(type, e.b));
  return referenceCentre(type);
}

glm::dvec3 referenceCentre(CellType type) {
  switch (type) {
    case CellType::Tet4:
    case CellType::Tet10: return glm::dvec3(0.25);
    case CellType::Hex8:
    case CellType::Hex20: return glm::dvec3(0.0);
    case CellType::Wedge6:
    case CellType::Wedge15: return glm::dvec3(1.0 / 3.0, 1.0 / 3.0, 0.0);
    case CellType::Pyramid5: return glm::dvec3(0.5, 0.5, 0.2);
  }
  return glm::dvec3(0.0);
}

double outsideReference(CellType type, const glm::dvec3& x) {
  switch (type) {
    case CellType::Tet4:
    case CellType::Tet10: return std::max({0.0, -x.x, -x.y, -x.z, x.x + x.y + x.z - 1.0});
    case CellType::Hex8:
    case CellType::Hex20: return std::max({0.0, std::abs(x.x) - 1.0, std::abs(x.y) - 1.0, std::abs(x.z) - 1.0});
    case CellType::Wedge6:
    case CellType::Wedge15: return std::max({0.0, -x.x, -x.y, x.x + x.y - 1.0, std::abs(x.z) - 1.0});
    case CellType::Pyramid5: return std::max({0.0, -x.x, x.x - 1.0, -x.y, x.y - 1.0, -x.z, x.z - 1.0});
  }
  return 0.0;
}

double signedOutsideReference(CellType type, const glm::dvec3& x) {
  switch (type) {
    case CellType::Tet4:
    case CellType::Tet10:
      return std::max({-x.x, -x.y, -x.z, x.x + x.y + x.z - 1.0});
    case CellType::Hex8:
    case CellType::Hex20:
      return std::max({std::abs(x.x), std::abs(x.y), std::abs(x.z)}) - 1.0;
    case CellType::Wedge6:
    case CellType::Wedge15:
      return std::max({-x.x, -x.y, x.x + x.y - 1.0, std::abs(x.z) - 1.0});
    case CellType::Pyramid5:
      return std::max({-x.x, x.x - 1.0, -x.y, x.y - 1.0, -x.z, x.z - 1.0});
  }
  return 0.0;
}

double faceBend(CellType type, std::span<const glm::dvec3> nodes) {
  const CellTopology& topo = topology(type);
  if (int(nodes.size()) != topo.nodeCount) return 0.0;
  double bend = 0.0;
  for (const CellEdge& e : topo.edges)
    if (e.mid >= 0)
      bend = std::max(
          bend, glm::length(nodes[std::size_t(e.mid)] - 0.5 * (nodes[std::size_t(e.a)] + nodes[std::size_t(e.b)])));
  for (const CellFace& f : topo.faces) {
    if (f.size != 4) continue;
    for (int k = 0; k < 4; ++k) {  // each corner against the plane of the other three
      const glm::dvec3 p = nodes[f.corners[k]], a = nodes[f.corners[(k + 1) % 4]], b = nodes[f.corners[(k + 2) % 4]],
                       c = nodes[f.corners[(k + 3) % 4]];
      const glm::dvec3 n = glm::cross(b - a, c - a);
      const double area = glm::length(n);
      if (area > 0.0) bend = std::max(bend, std::abs(glm::dot(p - a, n)) / area);
    }
  }
  return bend;
}

glm::dvec3 clampToReference(CellType type, const glm::dvec3& xi) {
  glm::dvec3 x = xi;
  const auto ontoSimplex = [](double* c, int n) {  // c >= 0, sum <= 1
    double sum = 0.0;
    for (int k = 0; k < n; ++k) sum += (c[k] = std::max(c[k], 0.0));
    if (sum > 1.0)
      for (int k = 0; k < n; ++k) c[k] /= sum;
  };
  switch (type) {
    case CellType::Tet4:
    case CellType::Tet10: {
      double c[3] = {x.x, x.y, x.z};
      ontoSimplex(c, 3);
      return {c[0], c[1], c[2]};
    }
    case CellType::Hex8:
    case CellType::Hex20: return glm::clamp(x, glm::dvec3(-1.0), glm::dvec3(1.0));
    case CellType::Wedge6:
    case CellType::Wedge15: {
      double c[2] = {x.x, x.y};
      ontoSimplex(c, 2);
      return {c[0], c[1], std::clamp(x.z, -1.0, 1.0)};
    }
    case CellType::Pyramid5: return glm::clamp(x, glm::dvec3(0.0), glm::dvec3(1.0));
  }
  return x;
}

glm::dvec3 positionAt(CellType type, std::span<const glm::dvec3> nodes, const glm::dvec3& xi) {
  const ShapeValues n = shapeFunctions(type, xi);
  const glm::dvec3 origin = nodes.empty() ? glm::dvec3(0.0) : nodes[0];
  glm::dvec3 x(0.0);
  for (std::size_t i = 0; i < nodes.size() && i < n.size(); ++i) x += n[i] * (nodes[i] - origin);
  return origin + x;
}

namespace {

// The shape functions at xi with their derivatives along the natural coordinates.
void evaluateWithDerivatives(CellType type, const glm::dvec3& xi, Dual n[kMaxCellNodes]) {
  Dual d[3];
  for (int k = 0; k < 3; ++k) d[k] = Dual{xi[k], glm::dvec3(0.0)}, d[k].d[k] = 1.0;
  evaluate(type, d, n);
}

}  // namespace

glm::dmat3 jacobianAt(CellType type, std::span<const glm::dvec3> nodes, const glm::dvec3& xi) {
  Dual n[kMaxCellNodes];
  evaluateWithDerivatives(type, xi, n);
  const int count = std::min(int(nodes.size()), topology(type).nodeCount);
  glm::dmat3 jacobian(0.0);
  for (int i = 0; i < count; ++i)
    for (int k = 0; k < 3; ++k) jacobian[k] += n[i].d[k] * (nodes[std::size_t(i)] - nodes[0]);
  return jacobian;
}

glm::dvec3 fieldGradient(CellType type, std::span<const glm::dvec3> nodes, std::span<const double> values,
                         const glm::dvec3& xi) {
  Dual n[kMaxCellNodes];
  evaluateWithDerivatives(type, xi, n);
  const int count = std::min({int(nodes.size()), int(values.size()), topology(type).nodeCount});
  glm::dmat3 jacobian(0.0);
  glm::dvec3 natural(0.0);
  for (int i = 0; i < count; ++i) {
    natural += values[std::size_t(i)] * n[i].d;
    for (int k = 0; k < 3; ++k) jacobian[k] += n[i].d[k] * (nodes[std::size_t(i)] - nodes[0]);
  }
  // dS/dxi = J^T grad S, so grad S = J^-T dS/dxi.
  const double det = glm::determinant(jacobian);
  if (!(std::abs(det) > 0.0) || !std::isfinite(det)) return glm::dvec3(0.0);
  return glm::inverse(glm::transpose(jacobian)) * natural;
}

bool mapInvertible(CellType type, std::span<const glm::dvec3> nodes) {
  const CellTopology& topo = topology(type);
  if (int(nodes.size()) != topo.nodeCount) return false;
  double size = 0.0;
  for (const glm::dvec3& x : nodes) size = std::max(size, glm::length(x - nodes[0]));
  if (!(size > 0.0) || !std::isfinite(size)) return false;
  const double tiny = 1e-12 * size * size * size;
  int sign = 0;
  const auto sameSign = [&](const glm::dvec3& xi) {
    const double det = glm::determinant(jacobianAt(type, nodes, xi));
    const int s = det > tiny ? 1 : det < -tiny ? -1 : 0;
    if (s == 0 || (sign != 0 && s != sign)) return false;
    sign = s;
    return true;
  };
  for (int corner = 0; corner < topo.cornerCount; ++corner) {
    if (type == CellType::Pyramid5 && corner == 4) continue;
    if (!sameSign(cornerOf(type, corner))) return false;
  }
  return sameSign(referenceCentre(type));
}

std::optional<glm::dvec3> naturalCoordinates(CellType type, std::span<const glm::dvec3> nodes, const glm::dvec3& p,
                                             const glm::dvec3& start) {
  const int count = topology(type).nodeCount;
  if (int(nodes.size()) != count) return std::nullopt;
  // Positions relative to the first node, so far-from-origin models keep their digits.
  const glm::dvec3 origin = nodes[0];
  double size = 0.0;
  for (const glm::dvec3& x : nodes) size = std::max(size, glm::length(x - origin));
  if (!(size > 0.0) || !std::isfinite(size)) return std::nullopt;
  const glm::dvec3 target = p - origin;
  glm::dvec3 xi = start;
  for (int iteration = 0; iteration < 40; ++iteration) {
    Dual d[3];
    for (int k = 0; k < 3; ++k) d[k] = Dual{xi[k], glm::dvec3(0.0)}, d[k].d[k] = 1.0;
    Dual n[kMaxCellNodes];
    evaluate(type, d, n);
    glm::dvec3 x(0.0);
    glm::dmat3 jacobian(0.0);  // column k: dx/dxi_k
    for (int i = 0; i < count; ++i) {
      const glm::dvec3 node = nodes[std::size_t(i)] - origin;
      x += valueOf(n[i]) * node;
      for (int k = 0; k < 3; ++k) jacobian[k] += n[i].d[k] * node;
    }
    const glm::dvec3 residual = x - target;
    if (glm::length(residual) <= 1e-13 * size) return xi;
    const double det = glm::determinant(jacobian);
    if (!(std::abs(det) > 1e-14 * size * size * size)) return std::nullopt;  // singular (an apex, a folded cell)
    glm::dvec3 step = glm::inverse(jacobian) * residual;
    // Keep each step within the reference cell's scale: a far guess must not throw the
    // iteration where a quadratic map folds over.
    const double longest = std::max({std::abs(step.x), std::abs(step.y), std::abs(step.z)});
    if (longest > 1.0) step /= longest;
    xi -= step;
    if (longest < 1e-14) return xi;
    if (outsideReference(type, xi) > 10.0) return std::nullopt;  // far outside: not this cell
  }
  return std::nullopt;
}

}  // namespace volpost

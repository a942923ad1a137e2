// SPDX-License-Identifier: MIT
#include <volpost/core/optics/ElementField.hpp>

#include <volpost/core/CellShape.hpp>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace volpost::optics {
namespace {

// The map is affine when its Jacobian is the same at every node and at the centre (to
// rounding): a parallelepiped, or straight edges with midside nodes halfway.
bool affineMap(CellType type, std::span<const glm::dvec3> nodes) {
  if (type == CellType::Pyramid5) return false;  // rational functions: never affine
  const glm::dmat3 centre = jacobianAt(type, nodes, referenceCentre(type));
  double scale = 0.0;
  for (int k = 0; k < 3; ++k) scale = std::max(scale, glm::length(centre[k]));
  for (int i = 0; i < int(nodes.size()); ++i) {
    const glm::dmat3 j = jacobianAt(type, nodes, naturalCoordinatesOfNode(type, i));
    for (int k = 0; k < 3; ++k)
      if (!(glm::length(j[k] - centre[k]) <= 1e-12 * scale)) return false;
  }
  return true;
}

// The shape functions and their gradients at each type's reference centre: there an affine
// cell's Jacobian is sum x_i g_i^T and its centre sum N_i x_i, with no differentiation per cell.
struct CentreShape {
  ShapeValues n{};
  std::array<glm::dvec3, kMaxCellNodes> gradient{};
};

const CentreShape& centreShape(CellType type) {
  static const std::array<CentreShape, kAllCellTypes.size()> all = [] {
    std::array<CentreShape, kAllCellTypes.size()> shapes{};
    for (const CellType t : kAllCellTypes) {
      CentreShape& c = shapes[std::size_t(t)];
      const glm::dvec3 centre = referenceCentre(t);
      c.n = shapeFunctions(t, centre);
      const int count = topology(t).nodeCount;
      std::vector<glm::dvec3> unit(std::size_t(count), glm::dvec3(0.0));
      for (int i = 0; i < count; ++i) {  // node i at x = 1, the rest at 0: row x of the Jacobian is g_i
        unit[std::size_t(i)] = glm::dvec3(1.0, 0.0, 0.0);
        const glm::dmat3 j = jacobianAt(t, unit, centre);
        c.gradient[std::size_t(i)] = glm::dvec3(j[0].x, j[1].x, j[2].x);
        unit[std::size_t(i)] = glm::dvec3(0.0);
      }
    }
    return shapes;
  }();
  return all[std::size_t(type)];
}

// A cell whose faces leave its split's facets by less than this part of its size is drawn
// by them: files that print six digits (a CalculiX .frd) leave straight cells' midside
// nodes about 1e-5 off.
constexpr double kStraightBend = 1e-4;

}  // namespace

ElementField::ElementField(const Mesh& mesh, std::span<const double> values, const TetMesh& tets, glm::dvec3 origin)
    : mesh_(mesh),
      values_(values.begin(), values.end()),
      tets_(tets),
      origin_(origin),
      elementCells_(mesh.cellCount(), 0) {
  if (values.size() != mesh.nodeCount())
    throw std::invalid_argument("the element interpolation needs one value per node: " + std::to_string(values.size()) +
                                " values for " + std::to_string(mesh.nodeCount()) + " nodes");
  double lo = INFINITY, hi = -INFINITY;
  for (double v : values_)
    if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
  scale_ = hi > lo ? hi - lo : (std::isfinite(lo) && lo != 0.0 ? std::abs(lo) : 1.0);
  glm::dvec3 low(INFINITY), high(-INFINITY);
  for (const glm::dvec3& p : mesh.nodes) low = glm::min(low, p), high = glm::max(high, p);
  if (!mesh.nodes.empty()) diagonal_ = glm::length(high - low);
  glm::dvec3 nodes[kMaxCellNodes];
  double cellValues[kMaxCellNodes];
  for (std::size_t c = 0; c < mesh.cellCount(); ++c) {
    const CellType type = mesh.cellType(c);
    if (type == CellType::Tet4) continue;  // linear: its split (itself) is its field
    const int count = gather(std::uint32_t(c), nodes, cellValues);
    bool finite = true;
    for (int i = 0; i < count; ++i) finite = finite && std::isfinite(cellValues[i]);
    if (!finite) continue;  // the split leaves its tets out
    const std::span<const glm::dvec3> at(nodes, std::size_t(count));
    if (mapInvertible(type, at)) elementCells_[c] = affineMap(type, at) ? kAffine : 1;
    else uninvertible_.push_back(std::uint32_t(c));
    if (!elementCells_[c]) continue;
    glm::dvec3 cellLow(INFINITY), cellHigh(-INFINITY);
    for (const glm::dvec3& p : at) cellLow = glm::min(cellLow, p), cellHigh = glm::max(cellHigh, p);
    const double bend = faceBend(type, at);
    if (bend > kStraightBend * glm::length(cellHigh - cellLow)) {
      if (bends_.empty()) bends_.assign(mesh.cellCount(), 0.0f);
      bends_[c] = float(bend);
    }
  }
}

int ElementField::gather(std::uint32_t cell, glm::dvec3* nodes, double* values) const {
  const auto ids = mesh_.cellNodes(cell);
  const int count = std::min(int(ids.size()), kMaxCellNodes);
  for (int i = 0; i < count; ++i) {
    nodes[i] = mesh_.nodes[ids[std::size_t(i)]] - origin_;
    values[i] = values_[ids[std::size_t(i)]];
  }
  return count;
}

std::optional<double> ElementField::value(std::uint32_t cell, const glm::dvec3& p, glm::dvec3& xi) const {
  glm::dvec3 nodes[kMaxCellNodes];
  double values[kMaxCellNodes];
  const int count = gather(cell, nodes, values);
  const CellType type = mesh_.cellType(cell);
  const auto found = naturalCoordinates(type, std::span<const glm::dvec3>(nodes, std::size_t(count)), p, xi);
  if (!found) return std::nullopt;
  xi = *found;
  const ShapeValues n = shapeFunctions(type, xi);
  double v = 0.0;
  for (int i = 0; i < count; ++i) v += n[std::size_t(i)] * values[i];
  return v;
}

bool ElementField::affineCoordinates(std::uint32_t cell, const glm::dvec3* p, glm::dvec3* xi, int count) const {
  const CellType type = mesh_.cellType(cell);
  const CentreShape& shape = centreShape(type);
  const auto ids = mesh_.cellNodes(cell);
  glm::dmat3 j(0.0);
  glm::dvec3 x(0.0);
  for (std::size_t i = 0; i < ids.size() && i < std::size_t(kMaxCellNodes); ++i) {
    const glm::dvec3 node = mesh_.nodes[ids[i]] - origin_;
    const glm::dvec3& g = shape.gradient[i];
    x += shape.n[i] * node;
    j[0] += g.x * node;
    j[1] += g.y * node;
    j[2] += g.z * node;
  }
  if (!(std::abs(glm::determinant(j)) > 0.0)) return false;
  const glm::dmat3 inverse = glm::inverse(j);
  const glm::dvec3 centre = referenceCentre(type);
  for (int i = 0; i < count; ++i) xi[i] = centre + inverse * (p[i] - x);
  return true;
}

int ElementField::degreeAlongLine(std::uint32_t cell) const {
  if (!affine(cell)) return -1;
  switch (mesh_.cellType(cell)) {
    case CellType::Tet10:
    case CellType::Wedge6:
      return 2;
    case CellType::Hex8:
    case CellType::Wedge15:
      return 3;
    case CellType::Hex20:
      return 4;
    default:
      return -1;
  }
}

std::optional<ScalarPolynomial> ElementField::polynomialAlong(std::uint32_t cell, const glm::dvec3& front,
                                                              const glm::dvec3& back) const {
  const int degree = degreeAlongLine(cell);
  if (degree < 0) return std::nullopt;
  const CellType type = mesh_.cellType(cell);
  const auto ids = mesh_.cellNodes(cell);
  const std::size_t count = std::min(ids.size(), std::size_t(kMaxCellNodes));
  double nodeValues[kMaxCellNodes];
  for (std::size_t i = 0; i < count; ++i) nodeValues[i] = values_[ids[i]];
  const glm::dvec3 middle = 0.5 * (front + back), half = 0.5 * (back - front);
  ScalarPolynomial p;
  if (type == CellType::Hex8) {
    // N_i = (1 + x_i xi)(1 + y_i eta)(1 + z_i zeta) / 8, each factor linear in u: a + b u.
    std::array<double, 4> c{};
    for (std::size_t i = 0; i < count; ++i) {
      const glm::dvec3 corner = naturalCoordinatesOfNode(type, int(i));
      const glm::dvec3 a = 1.0 + corner * middle, b = corner * half;
      const double w = 0.125 * nodeValues[i];
      c[0] += w * a.x * a.y * a.z;
      c[1] += w * (b.x * a.y * a.z + a.x * b.y * a.z + a.x * a.y * b.z);
      c[2] += w * (b.x * b.y * a.z + b.x * a.y * b.z + a.x * b.y * b.z);
      c[3] += w * b.x * b.y * b.z;
    }
    // Coefficients at rounding level dropped, as the interpolation does: a ray along an axis
    // sees a linear field, whose zeros are cheap.
    const double size = std::abs(c[0]) + std::abs(c[1]) + std::abs(c[2]) + std::abs(c[3]);
    p.degree = 3;
    while (p.degree > 0 && std::abs(c[std::size_t(p.degree)]) <= 1e-14 * size) --p.degree;
    for (int k = 0; k <= p.degree; ++k) p.c[std::size_t(k)] = c[std::size_t(k)];
  } else {
    const std::span<const double> points = chebyshevPoints(degree + 1);
    double values[ScalarPolynomial::kMaxDegree + 1];
    for (std::size_t k = 0; k < points.size(); ++k) {
      const ShapeValues n = shapeFunctions(type, middle + points[k] * half);
      double v = 0.0;
      for (std::size_t i = 0; i < count; ++i) v += n[i] * nodeValues[i];
      values[k] = v;
    }
    p = interpolateChebyshev(std::span<const double>(values, points.size()));
  }
  for (int k = 0; k <= p.degree; ++k)
    if (!std::isfinite(p.c[std::size_t(k)])) return std::nullopt;
  return p;
}

double ElementField::valueAt(std::uint32_t cell, const glm::dvec3& xi) const {
  const ShapeValues n = shapeFunctions(mesh_.cellType(cell), xi);
  const auto ids = mesh_.cellNodes(cell);
  double v = 0.0;
  for (std::size_t i = 0; i < ids.size() && i < n.size(); ++i) v += n[i] * values_[ids[i]];
  return v;
}

glm::dvec3 ElementField::gradient(std::uint32_t cell, const glm::dvec3& xi) const {
  glm::dvec3 nodes[kMaxCellNodes];
  double values[kMaxCellNodes];
  const int count = gather(cell, nodes, values);
  return fieldGradient(mesh_.cellType(cell), std::span<const glm::dvec3>(nodes, std::size_t(count)),
                       std::span<const double>(values, std::size_t(count)), xi);
}

namespace {

// A quadratic's Bernstein coefficients from its values at the ends and the middle: the
// quadratic lies between the least and the largest of them.
void quadraticBernstein(double& first, double& middle, double& last) { middle = 2.0 * middle - 0.5 * (first + last); }

}  // namespace

std::optional<std::pair<double, double>> ElementField::valueBound(std::uint32_t cell) const {
  const CellType type = mesh_.cellType(cell);
  const auto ids = mesh_.cellNodes(cell);
  double lo = INFINITY, hi = -INFINITY;
  const auto take = [&](double v) { lo = std::min(lo, v), hi = std::max(hi, v); };
  if (type == CellType::Hex20) {
    // The serendipity field is triquadratic: its 27 tensor Bernstein coefficients, from its
    // values on the 3 x 3 x 3 grid of the reference cube, bound it.
    double f[3][3][3];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        for (int k = 0; k < 3; ++k) f[i][j][k] = valueAt(cell, glm::dvec3(i - 1, j - 1, k - 1));
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) {
        quadraticBernstein(f[0][a][b], f[1][a][b], f[2][a][b]);
        quadraticBernstein(f[a][0][b], f[a][1][b], f[a][2][b]);
        quadraticBernstein(f[a][b][0], f[a][b][1], f[a][b][2]);
      }
    for (auto& plane : f)
      for (auto& row : plane)
        for (double v : row) take(v);
    return std::pair{lo, hi};
  }
  if (type == CellType::Wedge15) {
    // Quadratic on the triangle times quadratic along the axis: Bernstein coefficients from
    // the values at the triangle's corners and edge midpoints on three levels.
    const glm::dvec2 at[6] = {{0, 0}, {1, 0}, {0, 1}, {0.5, 0}, {0.5, 0.5}, {0, 0.5}};
    const int edges[3][3] = {{0, 1, 3}, {1, 2, 4}, {2, 0, 5}};  // corner, corner, midpoint
    double f[6][3];
    for (int p = 0; p < 6; ++p) {
      for (int z = 0; z < 3; ++z) f[p][z] = valueAt(cell, glm::dvec3(at[p], z - 1));
      quadraticBernstein(f[p][0], f[p][1], f[p][2]);
    }
    for (int z = 0; z < 3; ++z)
      for (const auto& e : edges) f[e[2]][z] = 2.0 * f[e[2]][z] - 0.5 * (f[e[0]][z] + f[e[1]][z]);
    for (auto& point : f)
      for (double v : point) take(v);
    return std::pair{lo, hi};
  }
  const int corners = topology(type).cornerCount;
  for (int i = 0; i < corners; ++i) take(values_[ids[std::size_t(i)]]);
  if (type == CellType::Tet10)  // edge Bernstein coefficient: 2 v_mid - (v_a + v_b) / 2
    for (const CellEdge& e : topology(type).edges)
      take(2.0 * values_[ids[std::size_t(e.mid)]] -
           0.5 * (values_[ids[std::size_t(e.a)]] + values_[ids[std::size_t(e.b)]]));
  return std::pair{lo, hi};
}

glm::dvec3 ElementField::start(std::uint32_t cell) const { return referenceCentre(mesh_.cellType(cell)); }

}  // namespace volpost::optics

// SPDX-License-Identifier: MIT
// The reference renderer with the cells' own interpolation, on fields the elements
// represent exactly, against independent evaluation: the closed-form field summed along
// each ray by the midpoint rule over the ray's exact path through the cell (slabs for boxes,
// planes for a tet), no volpost geometry or shape function involved. The same rays drawn
// with the field linear on the split differ visibly: these tests cannot pass on the split.
#include "host/optics/ReferenceRenderer.hpp"
#include "support/ReferenceCells.hpp"

#include <volpost/core/Tetrahedralize.hpp>

#include <volpost/core/CellShape.hpp>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <random>

using namespace volpost;
using namespace volpost::optics;

namespace {

using ClosedForm = std::function<double(const glm::dvec3&)>;

TransferFunction peakTf(double lo, double hi) {
  const auto at = [&](double f) { return lo + f * (hi - lo); };
  return TransferFunction({{at(0.0), {0.1, 0.2, 0.9}, 0.3},
                           {at(0.3), {0.9, 0.1, 0.1}, 0.5},
                           {at(0.34), {1.0, 0.9, 0.2}, 12.0},
                           {at(0.38), {0.2, 0.8, 0.3}, 0.5},
                           {at(1.0), {1.0, 1.0, 1.0}, 1.5}});
}

// A box [lo, hi] cut into n^3 cells of `type` (hex8 or hex20), nodes shared, planes spaced
// unevenly; the field sampled at every node.
Mesh boxOfHexes(CellType type, glm::dvec3 lo, glm::dvec3 hi, int n) {
  Mesh mesh;
  std::map<std::array<long, 3>, NodeIndex> index;  // by position on a fine lattice
  const auto plane = [&](int k, double f) { return lo[k] + (hi[k] - lo[k]) * (f + 0.15 * f * (1.0 - f)); };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        std::vector<NodeIndex> ids;
        for (int node = 0; node < topology(type).nodeCount; ++node) {
          const glm::dvec3 xi = naturalCoordinatesOfNode(type, node);  // in [-1, 1]^3
          const glm::dvec3 g = 2.0 * glm::dvec3(i, j, k) + xi + 1.0;   // in half-cell steps
          const std::array<long, 3> key{long(g.x), long(g.y), long(g.z)};
          auto [it, fresh] = index.emplace(key, NodeIndex(mesh.nodes.size()));
          if (fresh) {
            glm::dvec3 x;
            for (int a = 0; a < 3; ++a) {
              // Midside nodes halfway between their corners: straight edges.
              const double c0 = plane(a, std::floor(g[a] / 2.0) / n), c1 = plane(a, std::ceil(g[a] / 2.0) / n);
              x[a] = 0.5 * (c0 + c1);
            }
            mesh.nodes.push_back(x);
          }
          ids.push_back(it->second);
        }
        mesh.addCell(type, ids);
      }
  return mesh;
}

// One straight tet10 (midside nodes at the middle of its edges).
Mesh oneTet10(const std::array<glm::dvec3, 4>& v) {
  Mesh mesh;
  std::vector<NodeIndex> ids;
  for (int node = 0; node < 10; ++node) {
    const glm::dvec3 r = naturalCoordinatesOfNode(CellType::Tet10, node);
    mesh.nodes.push_back(v[0] + r.x * (v[1] - v[0]) + r.y * (v[2] - v[0]) + r.z * (v[3] - v[0]));
    ids.push_back(NodeIndex(node));
  }
  mesh.addCell(CellType::Tet10, ids);
  return mesh;
}

std::vector<double> sampled(const Mesh& mesh, const ClosedForm& f) {
  std::vector<double> v;
  for (const glm::dvec3& x : mesh.nodes) v.push_back(f(x));
  return v;
}

// The ray's light by the midpoint rule along [t0, t1] (unit direction), Richardson-extrapolated.
SegmentLight independent(const TransferFunction& tf, const ClosedForm& f, glm::dvec3 o, glm::dvec3 d, double t0,
                         double t1) {
  const auto sum = [&](int steps) {
    SegmentLight total;
    const double h = (t1 - t0) / steps;
    for (int i = 0; i < steps; ++i) {
      const double v = f(o + (t0 + (i + 0.5) * h) * d);
      compositeBehind(total, constantSegment(tf.color(v), tf.extinction(v), h));
    }
    return total;
  };
  const SegmentLight a = sum(40000), b = sum(80000);
  return {(4.0 * b.color - a.color) / 3.0, (4.0 * b.transmittance - a.transmittance) / 3.0};
}

// Where the ray o + t d (unit d) is inside the box: slabs.
std::pair<double, double> throughBox(glm::dvec3 lo, glm::dvec3 hi, glm::dvec3 o, glm::dvec3 d) {
  double t0 = -1e30, t1 = 1e30;
  for (int k = 0; k < 3; ++k) {
    double a = (lo[k] - o[k]) / d[k], b = (hi[k] - o[k]) / d[k];
    if (a > b) std::swap(a, b);
    t0 = std::max(t0, a);
    t1 = std::min(t1, b);
  }
  return {t0, t1};
}

double difference(const SegmentLight& a, const SegmentLight& b) {
  return std::max({std::abs(a.color.r - b.color.r), std::abs(a.color.g - b.color.g), std::abs(a.color.b - b.color.b),
                   std::abs(a.transmittance - b.transmittance)});
}

struct Drawn {
  SegmentLight element, split;
};

// The mesh's split, drawn both ways along one ray.
class BothFields {
 public:
  BothFields(const Mesh& mesh, std::vector<double> values)
      : mesh_(mesh),
        values_(std::move(values)),
        tets_(tetrahedralize(mesh_)),
        volume_(tets_.mesh, FieldLocation::Node, tets_.nodeValues(mesh_, values_)),
        field_(mesh_, values_, tets_, volume_.origin()) {}
  Drawn ray(const TransferFunction& tf, glm::dvec3 o, glm::dvec3 d, RaySettings settings = {}) const {
    RaySettings element = settings;
    element.elementField = &field_;
    return {integrateRay(volume_, tf, o, d, 0.0, 100.0, element),
            integrateRay(volume_, tf, o, d, 0.0, 100.0, settings)};
  }
  const ElementField& field() const { return field_; }
  /// The cells' own field along the cells' own shapes (curved faces followed).
  SegmentLight shaped(const TransferFunction& tf, glm::dvec3 o, glm::dvec3 d) const {
    RaySettings element;
    element.elementField = &field_;
    element.curvedCells = &curved_;
    return integrateRay(volume_, tf, o, d, 0.0, 100.0, element);
  }
  const CurvedCells& curved() const { return curved_; }

 private:
  Mesh mesh_;
  std::vector<double> values_;
  TetMesh tets_;
  TetVolume volume_;
  ElementField field_;
  CurvedCells curved_{field_};
};

// Random rays from outside through the box [0.2, 1.3] x [-0.4, 0.9] x [0.1, 1.0].
std::vector<std::pair<glm::dvec3, glm::dvec3>> raysThroughBox(int count) {
  std::mt19937 random(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<std::pair<glm::dvec3, glm::dvec3>> rays;
  while (int(rays.size()) < count) {
    const glm::dvec3 target(0.2 + 1.1 * u(random), -0.4 + 1.3 * u(random), 0.1 + 0.9 * u(random));
    const glm::dvec3 d = glm::normalize(glm::dvec3(u(random) - 0.5, u(random) - 0.5, u(random) - 0.5));
    rays.push_back({target - 4.0 * d, d});
  }
  return rays;
}

const glm::dvec3 kLo(0.2, -0.4, 0.1), kHi(1.3, 0.9, 1.0);

void expectElementFieldDrawn(CellType type, const ClosedForm& f, double lo, double hi) {
  BothFields both(boxOfHexes(type, kLo, kHi, 2), sampled(boxOfHexes(type, kLo, kHi, 2), f));
  EXPECT_TRUE(both.field().uninvertibleCells().empty());
  const TransferFunction tf = peakTf(lo, hi);
  double worst = 0.0, splitWorst = 0.0;
  for (const auto& [o, d] : raysThroughBox(24)) {
    const auto [t0, t1] = throughBox(kLo, kHi, o, d);
    const SegmentLight truth = independent(tf, f, o, d, t0, t1);
    const Drawn drawn = both.ray(tf, o, d);
    worst = std::max(worst, difference(drawn.element, truth));
    splitWorst = std::max(splitWorst, difference(drawn.split, truth));
  }
  EXPECT_LT(worst, 1e-7);
  EXPECT_GT(splitWorst, 1e-3);  // the split's field is visibly another one
  EXPECT_EQ(both.field().fallbacks(), 0u);
}

}  // namespace

TEST(ElementReference, AHex8MeshCarryingXyzIsDrawnAsXyz) {
  // xyz is trilinear: the hex8's field is xyz itself, cubic along an oblique ray.
  expectElementFieldDrawn(
      CellType::Hex8, [](const glm::dvec3& x) { return x.x * x.y * x.z; }, -0.5, 1.2);
}

TEST(ElementReference, AHex20MeshCarryingAQuadraticIsDrawnAsIt) {
  expectElementFieldDrawn(
      CellType::Hex20, [](const glm::dvec3& x) { return x.x * x.x - 0.7 * x.y * x.z + 0.4 * x.z * x.z - 0.3 * x.x; },
      -0.7, 1.6);
}

TEST(ElementReference, AStraightTet10CarryingAQuadraticIsDrawnAsIt) {
  const std::array<glm::dvec3, 4> v{glm::dvec3(0.1, 0.0, 0.2), glm::dvec3(1.4, 0.1, 0.0), glm::dvec3(0.3, 1.2, 0.1),
                                    glm::dvec3(0.5, 0.4, 1.3)};
  const ClosedForm f = [](const glm::dvec3& x) { return 1.5 * x.x * x.x - x.y * x.z + 0.8 * x.y * x.y; };
  const Mesh mesh = oneTet10(v);
  BothFields both(mesh, sampled(mesh, f));
  double lo = INFINITY, hi = -INFINITY;
  for (double s : sampled(mesh, f)) lo = std::min(lo, s), hi = std::max(hi, s);
  const TransferFunction tf = peakTf(lo - 0.2, hi + 0.2);
  // The tet's faces as planes n.x <= c, for the path of each ray through it.
  std::vector<std::pair<glm::dvec3, double>> faces;
  const int opposite[4][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};
  for (int k = 0; k < 4; ++k) {
    glm::dvec3 n = glm::cross(v[opposite[k][1]] - v[opposite[k][0]], v[opposite[k][2]] - v[opposite[k][0]]);
    if (glm::dot(n, v[k] - v[opposite[k][0]]) > 0.0) n = -n;
    faces.push_back({n, glm::dot(n, v[opposite[k][0]])});
  }
  std::mt19937 random(8);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  double worst = 0.0, splitWorst = 0.0;
  for (int k = 0; k < 24; ++k) {
    double b[4] = {u(random) + 0.1, u(random) + 0.1, u(random) + 0.1, u(random) + 0.1};
    const double sum = b[0] + b[1] + b[2] + b[3];
    const glm::dvec3 inside = (b[0] * v[0] + b[1] * v[1] + b[2] * v[2] + b[3] * v[3]) / sum;
    const glm::dvec3 d = glm::normalize(glm::dvec3(u(random) - 0.5, u(random) - 0.5, u(random) - 0.5));
    const glm::dvec3 o = inside - 4.0 * d;
    double t0 = -1e30, t1 = 1e30;
    for (const auto& [n, c] : faces) {
      const double t = (c - glm::dot(n, o)) / glm::dot(n, d);
      if (glm::dot(n, d) > 0.0) t1 = std::min(t1, t);
      else t0 = std::max(t0, t);
    }
    const Drawn drawn = both.ray(tf, o, d);
    const SegmentLight truth = independent(tf, f, o, d, t0, t1);
    worst = std::max(worst, difference(drawn.element, truth));
    splitWorst = std::max(splitWorst, difference(drawn.split, truth));
  }
  EXPECT_LT(worst, 1e-7);
  EXPECT_GT(splitWorst, 1e-3);
}

TEST(ElementReference, TheIsoSurfaceOfXyzIsWhereXyzTakesItsValueShadedByItsGradient) {
  const ClosedForm f = [](const glm::dvec3& x) { return x.x * x.y * x.z; };
  const Mesh mesh = boxOfHexes(CellType::Hex8, glm::dvec3(0.1), glm::dvec3(1.0), 3);
  BothFields both(mesh, sampled(mesh, f));
  const TransferFunction clear({{0.0, glm::dvec3(0.0), 0.0}, {1.0, glm::dvec3(0.0), 0.0}});
  const double c = 0.2;
  RaySettings settings;
  settings.isoSurfaces = {{c, glm::dvec3(1.0), 1.0}};
  std::mt19937 random(4);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int tested = 0;
  for (int k = 0; k < 20; ++k) {
    // Rays rising through the box from its low corner's side: xyz grows along them.
    const glm::dvec3 d = glm::normalize(glm::dvec3(0.3 + u(random), 0.3 + u(random), 0.3 + u(random)));
    const glm::dvec3 o = glm::dvec3(0.1 + 0.3 * u(random), 0.1 + 0.3 * u(random), 0.1) - 0.05 * d;
    // Independently: where x y z = c along the ray (bisection on the closed form).
    double a = 0.05, b = 0.05;
    while (f(o + b * d) < c && b < 3.0) b += 0.01;
    if (f(o + b * d) < c) continue;
    for (int i = 0; i < 200; ++i) (f(o + 0.5 * (a + b) * d) < c ? a : b) = 0.5 * (a + b);
    const glm::dvec3 x = o + a * d;
    if (x.x > 1.0 || x.y > 1.0 || x.z > 1.0) continue;
    const glm::dvec3 gradient(x.y * x.z, x.x * x.z, x.x * x.y);
    const double shade = 0.3 + 0.7 * std::abs(glm::dot(glm::normalize(gradient), d));
    const Drawn drawn = both.ray(clear, o, d, settings);
    EXPECT_NEAR(drawn.element.color.r, shade, 1e-9) << k;
    EXPECT_NEAR(drawn.element.transmittance, 0.0, 1e-15) << k;
    ++tested;
  }
  EXPECT_GE(tested, 10);
}

TEST(ElementReference, AnInvertedCellIsListedAndDrawnByItsSplit) {
  Mesh mesh = boxOfHexes(CellType::Hex8, kLo, kHi, 2);
  // Cell 0's first corner (a corner of the box) pulled through its cell: the map folds.
  const NodeIndex corner = mesh.cellNodes(0)[0];
  mesh.nodes[corner] = glm::dvec3(1.0, 0.6, 0.8);
  const BothFields both(mesh, sampled(mesh, [](const glm::dvec3& x) { return x.x + x.y; }));
  EXPECT_TRUE(both.field().affine(1)) << "a box cell's map is affine";
  ASSERT_EQ(both.field().uninvertibleCells().size(), 1u);
  EXPECT_EQ(both.field().uninvertibleCells()[0], 0u);
}

TEST(ElementReference, ATaperedHex8WhoseFieldIsNoPolynomialAlongTheRayIsFittedToTolerance) {
  // A frustum: plane faces, but the map is not affine, so the field along a ray is a
  // rational-like function the reference fits piecewise. The truth evaluates the element's
  // interpolation point by point (its inverse map) along the ray's path between the faces.
  Mesh mesh;
  const double bottom = 1.0, top = 0.45;
  for (double z : {0.0, 1.0}) {
    const double h = z == 0.0 ? bottom : top;
    for (const glm::dvec2 c : {glm::dvec2(-1, -1), glm::dvec2(1, -1), glm::dvec2(1, 1), glm::dvec2(-1, 1)})
      mesh.nodes.push_back(glm::dvec3(h * c.x, h * c.y, z));
  }
  const std::vector<NodeIndex> ids{0, 1, 2, 3, 4, 5, 6, 7};
  mesh.addCell(CellType::Hex8, ids);
  const std::vector<double> values{0.0, 1.0, 0.3, 0.9, 1.4, -0.2, 0.7, 0.1};
  const BothFields both(mesh, values);
  EXPECT_FALSE(both.field().affine(0)) << "a frustum's map is not affine: each point goes through Newton's method";
  const ClosedForm f = [&](const glm::dvec3& x) {
    const auto xi = naturalCoordinates(CellType::Hex8, mesh.nodes, x, glm::dvec3(0.0));
    const ShapeValues n = shapeFunctions(CellType::Hex8, *xi);
    double v = 0.0;
    for (int i = 0; i < 8; ++i) v += n[std::size_t(i)] * values[std::size_t(i)];
    return v;
  };
  // Faces as planes n.x <= c through three of their corners.
  const int quads[6][3] = {{0, 3, 2}, {4, 5, 6}, {0, 1, 5}, {1, 2, 6}, {2, 3, 7}, {3, 0, 4}};
  std::vector<std::pair<glm::dvec3, double>> faces;
  for (const auto& q : quads) {
    glm::dvec3 n = glm::cross(mesh.nodes[q[1]] - mesh.nodes[q[0]], mesh.nodes[q[2]] - mesh.nodes[q[0]]);
    if (glm::dot(n, glm::dvec3(0, 0, 0.5) - mesh.nodes[q[0]]) > 0.0) n = -n;
    faces.push_back({n, glm::dot(n, mesh.nodes[q[0]])});
  }
  const TransferFunction tf = peakTf(-0.2, 1.4);
  std::mt19937 random(9);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  double worst = 0.0, splitWorst = 0.0;
  for (int k = 0; k < 16; ++k) {
    const glm::dvec3 inside(0.6 * (u(random) - 0.5), 0.6 * (u(random) - 0.5), 0.2 + 0.6 * u(random));
    const glm::dvec3 d = glm::normalize(glm::dvec3(u(random) - 0.5, u(random) - 0.5, u(random) - 0.5));
    const glm::dvec3 o = inside - 4.0 * d;
    double t0 = -1e30, t1 = 1e30;
    for (const auto& [n, c] : faces) {
      const double t = (c - glm::dot(n, o)) / glm::dot(n, d);
      if (glm::dot(n, d) > 0.0) t1 = std::min(t1, t);
      else t0 = std::max(t0, t);
    }
    const Drawn drawn = both.ray(tf, o, d);
    const SegmentLight truth = independent(tf, f, o, d, t0, t1);
    worst = std::max(worst, difference(drawn.element, truth));
    splitWorst = std::max(splitWorst, difference(drawn.split, truth));
  }
  EXPECT_LT(worst, 1e-7);
  EXPECT_GT(splitWorst, 1e-3);
  EXPECT_EQ(both.field().fallbacks(), 0u);
}

// The bound that lets empty-space skipping leave a cell out: every value of the cell's own
// field, sampled densely through its reference cell, lies inside it, for node values drawn
// at random (quadratic cells rise and fall beyond their node values); and it is not loose by
// more than the field's own swing.
TEST(ElementReference, EveryCellsFieldStaysInsideItsBound) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  for (const CellType type : kAllCellTypes) {
    const Mesh mesh = volpost::test::referenceCell(type).first;
    const TetMesh split = tetrahedralize(mesh);
    for (int trial = 0; trial < 20; ++trial) {
      std::vector<double> values(mesh.nodes.size());
      for (double& v : values) v = value(rng);
      const optics::ElementField field(mesh, values, split, glm::dvec3(0.0));
      if (field.linearIn(0)) continue;  // tet4: its own split
      const auto bound = field.valueBound(0);
      ASSERT_TRUE(bound) << cellTypeName(type);
      double lo = INFINITY, hi = -INFINITY;
      constexpr int n = 16;
      for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= n; ++j)
          for (int k = 0; k <= n; ++k) {
            const glm::dvec3 u(double(i) / n, double(j) / n, double(k) / n);  // the unit cube, mapped below
            glm::dvec3 xi = u;
            if (type == CellType::Hex8 || type == CellType::Hex20) xi = 2.0 * u - 1.0;
            if (type == CellType::Wedge6 || type == CellType::Wedge15) xi = {u.x * (1.0 - u.y), u.y, 2.0 * u.z - 1.0};
            if (type == CellType::Tet10) xi = {u.x * (1.0 - u.y) * (1.0 - u.z), u.y * (1.0 - u.z), u.z};
            if (type == CellType::Pyramid5) xi = {u.x, u.y, u.z * 0.999};
            if (outsideReference(type, xi) > 0.0) continue;
            const double v = field.valueAt(0, xi);
            lo = std::min(lo, v), hi = std::max(hi, v);
          }
      EXPECT_LE(bound->first, lo + 1e-12) << cellTypeName(type) << " trial " << trial;
      EXPECT_GE(bound->second, hi - 1e-12) << cellTypeName(type) << " trial " << trial;
      EXPECT_LE(bound->second - bound->first, 4.0 * (hi - lo)) << cellTypeName(type) << " trial " << trial;
    }
  }
}

// An affine cell's field along a straight line is the polynomial polynomialAlong gives
// (a hex8's cubic multiplied out, the others interpolated): the same values as the shape
// functions at any point of the line, for random node values and lines.
TEST(ElementReference, AnAffineCellsFieldAlongALineIsItsPolynomial) {
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> value(-1.0, 1.0), unit(0.0, 1.0);
  for (const CellType type : {CellType::Hex8, CellType::Hex20, CellType::Tet10, CellType::Wedge6, CellType::Wedge15}) {
    const Mesh mesh = volpost::test::referenceCell(type).first;
    const TetMesh split = tetrahedralize(mesh);
    std::vector<double> values(mesh.nodes.size());
    for (double& v : values) v = value(rng);
    const optics::ElementField field(mesh, values, split, glm::dvec3(0.0));
    ASSERT_TRUE(field.affine(0)) << cellTypeName(type);
    for (int line = 0; line < 10; ++line) {
      const glm::dvec3 front = clampToReference(type, {unit(rng), unit(rng), 2.0 * unit(rng) - 1.0});
      const glm::dvec3 back = clampToReference(type, {unit(rng), unit(rng), 2.0 * unit(rng) - 1.0});
      const auto p = field.polynomialAlong(0, front, back);
      ASSERT_TRUE(p) << cellTypeName(type);
      EXPECT_LE(p->degree, field.degreeAlongLine(0));
      for (double u = -1.0; u <= 1.0; u += 0.2)
        EXPECT_NEAR(p->at(u), field.valueAt(0, front + 0.5 * (u + 1.0) * (back - front)), 1e-12)
            << cellTypeName(type) << " u " << u;
    }
  }
}

// Two hex20 cells side by side filling [-1, 1]^3 bent by x -> (x, y, z + a (1 - x^2) (1 + z) / 2):
// quadratic, so the cells' nodes placed by it reproduce it exactly, and the top is the curved
// surface z = 1 + a (1 - x^2) where the split's facets are flat at z = 1. The field is the
// height z, which the cells also represent exactly. The truth: each ray's exact path (the
// slabs and the top's quadratic along the ray) summed by the midpoint rule.
TEST(ElementReference, CurvedHex20CellsAreDrawnToTheirOwnCurvedFacesNotTheSplitsFacets) {
  constexpr double a = 0.3;
  const auto bend = [](const glm::dvec3& x) {
    return glm::dvec3(x.x, x.y, x.z + a * (1.0 - x.x * x.x) * (1.0 + x.z) / 2.0);
  };
  Mesh mesh = boxOfHexes(CellType::Hex20, glm::dvec3(-1.0), glm::dvec3(1.0), 2);
  for (glm::dvec3& x : mesh.nodes) x = bend(x);
  const ClosedForm height = [](const glm::dvec3& x) { return x.z; };
  BothFields both(mesh, sampled(mesh, height));
  ASSERT_TRUE(both.field().uninvertibleCells().empty());
  EXPECT_EQ(both.curved().count(), 8u) << "every cell reaches the curved top";
  const TransferFunction tf = peakTf(-1.0, 1.0 + a);
  // Where o + t d is inside: within the side slabs and the bottom, under the top.
  const auto path = [&](glm::dvec3 o, glm::dvec3 d) {
    auto [t0, t1] = throughBox(glm::dvec3(-1.0, -1.0, -1.0), glm::dvec3(1.0, 1.0, 10.0), o, d);
    // g(t) = 1 + a (1 - x(t)^2) - z(t) >= 0: a quadratic in t opening downward (or a line).
    const double qa = -a * d.x * d.x, qb = -2.0 * a * o.x * d.x - d.z, qc = 1.0 + a * (1.0 - o.x * o.x) - o.z;
    if (qa == 0.0) {
      const double root = -qc / qb;
      (qb > 0.0 ? t0 : t1) = qb > 0.0 ? std::max(t0, root) : std::min(t1, root);
    } else {
      const double disc = std::sqrt(qb * qb - 4.0 * qa * qc);
      const double r1 = (-qb + disc) / (2.0 * qa), r2 = (-qb - disc) / (2.0 * qa);
      t0 = std::max(t0, std::min(r1, r2)), t1 = std::min(t1, std::max(r1, r2));
    }
    return std::pair{t0, t1};
  };
  std::vector<std::pair<glm::dvec3, glm::dvec3>> rays;
  for (double x0 : {-0.8, -0.35, 0.0, 0.2, 0.65}) rays.push_back({{x0, 0.3, 4.0}, {0.0, 0.0, -1.0}});  // down
  for (double z0 : {1.05, 1.15, 1.25}) rays.push_back({{-4.0, -0.2, z0}, {1.0, 0.0, 0.0}});            // only the bulge
  std::mt19937 random(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  while (rays.size() < 30) {
    const glm::dvec3 target(0.9 * u(random), 0.9 * u(random), 0.6 + 0.5 * u(random));
    const glm::dvec3 d = glm::normalize(glm::dvec3(u(random), u(random), u(random)));
    rays.push_back({target - 5.0 * d, d});
  }
  double worst = 0.0, splitWorst = 0.0;
  for (const auto& [o, d] : rays) {
    const auto [t0, t1] = path(o, d);
    const SegmentLight truth = t1 > t0 ? independent(tf, height, o, d, t0, t1) : SegmentLight{};
    worst = std::max(worst, difference(both.shaped(tf, o, d), truth));
    splitWorst = std::max(splitWorst, difference(both.ray(tf, o, d).element, truth));
  }
  EXPECT_LT(worst, 1e-7);                                                  // measured 3.4e-9
  EXPECT_GT(splitWorst, 0.05) << "the split's flat top is another shape";  // measured 0.32
  EXPECT_EQ(both.field().fallbacks(), 0u);
}

// A cell whose split draws it as it is (flat faces, midside nodes at the middles) does not
// bend; one whose midside node leaves its edge, or whose quadrilateral face warps, does.
TEST(ElementReference, OnlyCellsTheSplitDoesNotFollowBend) {
  const auto bendOf = [](Mesh mesh) {
    const TetMesh tets = tetrahedralize(mesh);
    const std::vector<double> values(mesh.nodes.size(), 1.0);
    return ElementField(mesh, values, tets, glm::dvec3(0.0)).bend(0);
  };
  Mesh hex20 = boxOfHexes(CellType::Hex20, glm::dvec3(0.0), glm::dvec3(1.0), 1);
  EXPECT_EQ(bendOf(hex20), 0.0);
  hex20.nodes[8].z += 1e-5;  // as six printed digits leave it: still straight
  EXPECT_EQ(bendOf(hex20), 0.0);
  hex20.nodes[8].z += 0.01;                   // a midside node off its edge
  EXPECT_NEAR(bendOf(hex20), 0.01001, 1e-8);  // kept as a float
  Mesh hex8 = boxOfHexes(CellType::Hex8, glm::dvec3(0.0), glm::dvec3(1.0), 1);
  EXPECT_EQ(bendOf(hex8), 0.0);
  hex8.nodes[6].z += 0.05;  // one corner out of its faces' planes: warped faces
  EXPECT_GT(bendOf(hex8), 0.01);
}

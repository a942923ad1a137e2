// SPDX-License-Identifier: MIT
// Marching-tetrahedra iso-surfaces and point location on tetrahedralized grids, where the
// exact answers are planes, spheres and linear fields.
#include "support/TetGrid.hpp"

#include "host/IsoSurfaceExtraction.hpp"
#include "host/PointLocator.hpp"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <random>

using namespace volpost;
using volpost::test::tetGrid;

namespace {

std::vector<double> nodal(const Mesh& m, double (*f)(const glm::dvec3&)) {
  std::vector<double> v;
  for (const auto& p : m.nodes) v.push_back(f(p));
  return v;
}

double area(const ExtractedSurface& s) {
  double a = 0.0;
  for (auto f : s.mesh.faces()) a += double(s.mesh.calc_face_area(f));
  return a;
}

}  // namespace

TEST(IsoSurfaceExtraction, PlaneOfALinearFieldIsExactAndFacesTheGradient) {
  const TetMesh tets = tetrahedralize(tetGrid(6, 4, 3));
  const auto values = nodal(tets.mesh, [](const glm::dvec3& p) { return p.x; });
  const ExtractedSurface s = extractIsoSurface(tets, values, 2.3);
  ASSERT_GT(s.mesh.n_faces(), 0u);
  for (auto v : s.mesh.vertices()) EXPECT_NEAR(double(s.mesh.point(v)[0]) + s.origin.x, 2.3, 1e-5);
  EXPECT_NEAR(area(s), 4.0 * 3.0, 1e-4);
  SurfaceMesh m = s.mesh;
  m.request_face_normals();
  m.update_face_normals();
  for (auto f : m.faces()) EXPECT_GT(m.normal(f)[0], 0.99f) << "normals point toward larger values";
}

TEST(IsoSurfaceExtraction, SphereInsideTheMeshIsClosed) {
  const TetMesh tets = tetrahedralize(tetGrid(12, 12, 12));
  const auto values = nodal(tets.mesh, [](const glm::dvec3& p) { return glm::length(p - glm::dvec3(6.0)); });
  const ExtractedSurface s = extractIsoSurface(tets, values, 4.0);
  std::size_t boundaryEdges = 0;
  for (auto e : s.mesh.edges()) boundaryEdges += s.mesh.is_boundary(e) ? 1 : 0;
  EXPECT_EQ(boundaryEdges, 0u) << "vertices are shared across tets: a closed, watertight surface";
  const double exact = 4.0 * M_PI * 16.0;
  EXPECT_NEAR(area(s), exact, 0.05 * exact) << "piecewise-linear sphere of radius 4 on unit cells";
  for (auto v : s.mesh.vertices()) {
    const auto p = s.mesh.point(v);
    const glm::dvec3 q = glm::dvec3(p[0], p[1], p[2]) + s.origin;
    EXPECT_NEAR(glm::length(q - glm::dvec3(6.0)), 4.0, 0.15);
  }
}

TEST(IsoSurfaceExtraction, IsoValueOnNodesAndNaNsDoNotBreakIt) {
  const TetMesh tets = tetrahedralize(tetGrid(4, 4, 4));
  auto values = nodal(tets.mesh, [](const glm::dvec3& p) { return std::round(p.x); });  // iso hits nodes exactly
  values[7] = std::nan("");
  const ExtractedSurface s = extractIsoSurface(tets, values, 2.0);
  EXPECT_GT(s.mesh.n_faces(), 0u);
  for (auto f : s.mesh.faces()) EXPECT_GT(s.mesh.calc_face_area(f), 0.0f) << "no degenerate triangles";
  EXPECT_EQ(extractIsoSurface(tets, values, 99.0).mesh.n_faces(), 0u);
  EXPECT_THROW(extractIsoSurface(tets, std::vector<double>(3, 0.0), 1.0), std::invalid_argument);
}

// A grid's iso-surface without its cells: on a rotated, left-handed grid a linear field's
// surface is its plane with the plane's area, facing the gradient; a sphere inside is
// closed (neighbouring cells share their vertices); a NaN or a wrong count does no harm.
TEST(IsoSurfaceExtraction, AGridsSurfaceComesFromItsCellsSplitOnTheFly) {
  RegularGrid g;
  g.dims = {13, 13, 13};
  g.origin = {100.0, 50.0, 0.0};
  const double c = std::cos(0.5), s = std::sin(0.5);
  g.axes = {glm::dvec3(c, s, 0.0), glm::dvec3(-s, c, 0.0), glm::dvec3(0.0, 0.0, -1.0)};  // left-handed
  const Mesh points = hexahedraOfGrid(g);
  const glm::dvec3 gradientDirection = glm::normalize(glm::dvec3(c, s, 0.0));
  std::vector<double> linear, sphere;
  const glm::dvec3 centre = g.position(6, 6, 6);
  for (const glm::dvec3& p : points.nodes) {
    linear.push_back(glm::dot(p - g.origin, gradientDirection));  // index i along the first axis
    sphere.push_back(glm::length(p - centre));
  }
  const ExtractedSurface plane = extractIsoSurface(g, linear, 4.3);
  EXPECT_NEAR(area(plane), 12.0 * 12.0, 1e-3);
  SurfaceMesh m = plane.mesh;
  m.request_face_normals();
  m.update_face_normals();
  for (auto f : m.faces()) {
    const auto n = m.normal(f);
    EXPECT_GT(double(n[0]) * gradientDirection.x + double(n[1]) * gradientDirection.y, 0.99);
  }
  const ExtractedSurface ball = extractIsoSurface(g, sphere, 4.0);
  std::size_t boundaryEdges = 0;
  for (auto e : ball.mesh.edges()) boundaryEdges += ball.mesh.is_boundary(e) ? 1 : 0;
  EXPECT_EQ(boundaryEdges, 0u);
  EXPECT_NEAR(area(ball), 4.0 * M_PI * 16.0, 0.05 * 4.0 * M_PI * 16.0);
  // The same as the grid's tetrahedralized hexahedra would give, to rounding of the split.
  const TetMesh tets = tetrahedralize(points);
  EXPECT_NEAR(area(ball), area(extractIsoSurface(tets, tets.nodeValues(points, sphere), 4.0)), 0.01 * area(ball));
  sphere[g.pointIndex(6, 6, 2)] = std::nan("");
  EXPECT_GT(extractIsoSurface(g, sphere, 4.0).mesh.n_faces(), 0u);
  EXPECT_THROW(extractIsoSurface(g, std::vector<double>(3, 0.0), 1.0), std::invalid_argument);
}

// Integer samples put grid points exactly on the iso-value: two balls touching at one such
// point make two sheets through one vertex, which a manifold mesh refuses. No triangle may
// be lost there: the pair gives exactly the two balls' triangles, each ball as alone.
TEST(IsoSurfaceExtraction, SheetsTouchingAtANodeOnTheIsoValueLoseNoTriangle) {
  RegularGrid g;
  g.dims = {11, 9, 9};
  std::vector<double> left(g.pointCount()), right(g.pointCount()), both(g.pointCount());
  for (std::size_t k = 0; k < 9; ++k)
    for (std::size_t j = 0; j < 9; ++j)
      for (std::size_t i = 0; i < 11; ++i) {
        const auto squared = [&](double ci) {  // integer distance squared to (ci, 4, 4)
          const double x = double(i) - ci, y = double(j) - 4.0, z = double(k) - 4.0;
          return x * x + y * y + z * z;
        };
        const std::size_t p = g.pointIndex(i, j, k);
        left[p] = squared(3.0), right[p] = squared(7.0);
        both[p] = std::min(left[p], right[p]);  // the balls of radius 2 touch at (5, 4, 4)
      }
  const std::size_t alone = extractIsoSurface(g, left, 4.0).mesh.n_faces();
  const ExtractedSurface pair = extractIsoSurface(g, both, 4.0);
  EXPECT_GT(alone, 0u);
  EXPECT_EQ(extractIsoSurface(g, right, 4.0).mesh.n_faces(), alone);
  EXPECT_EQ(pair.mesh.n_faces(), 2 * alone);
  EXPECT_GT(pair.separatedFaces, 0u) << "the balls should touch at one vertex";
}

TEST(PointLocator, InterpolatesLinearFieldsExactlyAndRejectsOutsidePoints) {
  const TetMesh tets = tetrahedralize(tetGrid(5, 3, 4, glm::dvec3(1e6, -2.0, 0.5), 0.25));
  const auto f = [](const glm::dvec3& p) { return 3.0 * (p.x - 1e6) - 2.0 * p.y + 0.5 * p.z; };
  std::vector<double> values;
  for (const auto& p : tets.mesh.nodes) values.push_back(f(p));
  const PointLocator locator(tets);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < 500; ++i) {
    const glm::dvec3 p = glm::dvec3(1e6, -2.0, 0.5) + glm::dvec3(u(random) * 1.25, u(random) * 0.75, u(random) * 1.0);
    const auto at = locator.locate(p);
    ASSERT_TRUE(at) << i;
    EXPECT_NEAR(PointLocator::interpolateNodal(*at, values), f(p), 1e-8);
  }
  // Grid nodes, edges and faces are found (they lie on several tets at once).
  for (const auto& p : {glm::dvec3(1e6, -2.0, 0.5), glm::dvec3(1e6 + 0.5, -1.5, 1.0), glm::dvec3(1e6 + 1.25, -1.25, 1.5)})
    EXPECT_TRUE(locator.locate(p)) << p.x << " " << p.y << " " << p.z;
  EXPECT_FALSE(locator.locate(glm::dvec3(1e6 - 0.01, -1.5, 1.0)));
  EXPECT_FALSE(locator.locate(glm::dvec3(1e6 + 0.5, -1.5, 1.6)));
  EXPECT_FALSE(locator.locate(glm::dvec3(NAN, 0.0, 0.0)));
}

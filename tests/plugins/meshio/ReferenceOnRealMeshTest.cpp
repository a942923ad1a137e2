// SPDX-License-Identifier: MIT
// The reference renderer on real gmsh meshes: the bar's image against the per-pixel closed
// form, and ray lengths inside non-convex meshes against an independent count from the
// boundary surface (ray/triangle crossings paired up).
#include "support/TestSupport.hpp"
#include "support/ReaderSupport.hpp"

#include <volpost/core/Tetrahedralize.hpp>

#include "host/BoundarySurface.hpp"
#include "host/optics/ReferenceRenderer.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_inverse.hpp>

#include <array>
#include <map>
#include <random>

using namespace volpost;
using namespace volpost::optics;

namespace {

std::vector<double> xCoordinate(const Mesh& m) {
  std::vector<double> v;
  for (const auto& p : m.nodes) v.push_back(p.x);
  return v;
}

// Length of the ray inside the closed boundary surface, from its crossings (Moller-Trumbore
// in double on the nodes' own coordinates, then entering/leaving pairs): independent of
// the tetrahedra.
double lengthFromBoundary(const BoundarySurface& s, const Mesh& mesh, glm::dvec3 o, glm::dvec3 d) {
  d = glm::normalize(d);
  std::vector<double> hits;
  for (const auto f : s.mesh.faces()) {
    glm::dvec3 p[3];
    int k = 0;
    for (const auto v : f.vertices()) p[k++] = mesh.nodes[s.mesh.property(s.nodeOfVertex, v)];
    const glm::dvec3 e1 = p[1] - p[0], e2 = p[2] - p[0], h = glm::cross(d, e2);
    const double a = glm::dot(e1, h);
    if (std::abs(a) < 1e-14) continue;
    const glm::dvec3 sv = o - p[0];
    const double u = glm::dot(sv, h) / a;
    const glm::dvec3 qv = glm::cross(sv, e1);
    const double v = glm::dot(d, qv) / a;
    if (u < 0 || v < 0 || u + v > 1) continue;
    hits.push_back(glm::dot(e2, qv) / a);
  }
  std::sort(hits.begin(), hits.end());
  double len = 0.0;
  for (std::size_t i = 0; i + 1 < hits.size(); i += 2) len += hits[i + 1] - hits[i];
  return hits.size() % 2 == 0 ? len : -1.0;  // odd: the ray grazed an edge, skip it
}

void compareLengths(const Model& model, int rays, double tolerance) {
  const BoundarySurface surface = extractBoundary(model.mesh());
  const TetVolume volume(model.mesh(), FieldLocation::Node, std::vector<double>(model.mesh().nodeCount(), 0.0));
  const Bounds b = model.mesh().bounds();
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int compared = 0, reentering = 0;
  for (int i = 0; i < rays; ++i) {
    const glm::dvec3 target = b.min + glm::dvec3(u(rng), u(rng), u(rng)) * b.size();
    const glm::dvec3 dir = glm::normalize(glm::dvec3(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5));
    const glm::dvec3 start = target - dir * b.diagonal();
    const double expected = lengthFromBoundary(surface, model.mesh(), start, dir);
    if (expected < 0) continue;
    const double got = lengthInside(volume, start, dir, 0.0, 2.0 * b.diagonal());
    EXPECT_NEAR(got, expected, tolerance * b.diagonal()) << "ray " << i << " start " << start.x << "," << start.y << "," << start.z << " dir " << dir.x << "," << dir.y << "," << dir.z;
    ++compared;
    reentering += expected > 0 && got > 0;
  }
  EXPECT_GT(compared, rays * 9 / 10);
}

}  // namespace

TEST(ReferenceOnRealMesh, BarImageMatchesThePerPixelClosedForm) {
  // s = x; seen along y the bar is 1 thick at constant x: alpha = 1 - exp(-tau(x)).
  const auto model = volpost::test::meshioReaders().load(volpost::test::dataFile("bar/bar_tet4.vtu"));
  const TetVolume volume(model->mesh(), FieldLocation::Node, xCoordinate(model->mesh()));
  EXPECT_EQ(volume.skippedTets(), 0u);
  const TransferFunction tf({{0.0, {0, 0, 1}, 0.1}, {5.0, {0, 1, 0}, 2.5}, {10.0, {1, 0, 0}, 0.7}});
  Camera camera;
  camera.setProjection(Camera::Projection::Orthographic);
  camera.setView(StandardView::MinusY);
  camera.fit(model->mesh().bounds());
  camera.zoom(2.0);
  const int w = 128, h = 64;
  const ReferenceImage image = renderReference(volume, tf, camera, w, h);
  const glm::dmat4 toModel = glm::inverse(camera.projectionMatrix(2.0) * camera.viewMatrix());
  double worst = 0.0;
  int inside = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const glm::dvec4 q = toModel * glm::dvec4(2.0 * (x + 0.5) / w - 1.0, 1.0 - 2.0 * (y + 0.5) / h, 0.0, 1.0);
      const double mx = q.x / q.w, mz = q.z / q.w;
      if (mx < 1e-6 || mx > 10 - 1e-6 || mz < 1e-6 || mz > 1 - 1e-6) continue;
      ++inside;
      const glm::dvec4 p = image.pixels[std::size_t(y * w + x)];
      const double alpha = -std::expm1(-tf.extinction(mx));
      worst = std::max({worst, std::abs(p.a - alpha), std::abs(p.g - tf.color(mx).g * alpha)});
    }
  std::printf("bar reference image, %d pixels inside: worst error against the closed form %.3g\n", inside, worst);
  EXPECT_GT(inside, 400);
  EXPECT_LE(worst, 1e-9);
}

TEST(ReferenceOnRealMesh, RayLengthsAgreeWithTheBoundarySurface) {
  const auto model = volpost::test::meshioReaders().load(volpost::test::dataFile("bar/bar_tet4.vtu"));
  compareLengths(*model, 200, 1e-9);
}

TEST(ReferenceOnRealMesh, NonConvexWheelRaysLeaveAndReenter) {
  VOLPOST_SHARED_OR_SKIP(path, "wheel/tet4/wheel_tet4.vtu");
  const auto model = volpost::test::meshioReaders().load(path);
  compareLengths(*model, 150, 1e-9);
}

TEST(TetrahedralizeRealMesh, TheBundledMixedWheelConforms) {
  // gmsh hexahedra, wedges, pyramids and tetrahedra (resources/examples).
  const auto model = volpost::test::meshioReaders().load(std::string(VOLPOST_SOURCE_DIR) + "/resources/examples/wheel_mixed.vtu");
  const TetMesh t = tetrahedralize(model->mesh());
  std::map<std::array<NodeIndex, 3>, int> faces;
  double volume = 0.0, smallest = 1e300;
  for (std::size_t i = 0; i < t.mesh.cellCount(); ++i) {
    const double v = signedCellVolume(t.mesh, i);
    volume += v;
    smallest = std::min(smallest, v);
    const auto n = t.mesh.cellNodes(i);
    for (const CellFace& f : topology(CellType::Tet4).faces) {
      std::array<NodeIndex, 3> k = {n[f.corners[0]], n[f.corners[1]], n[f.corners[2]]};
      std::sort(k.begin(), k.end());
      ++faces[k];
    }
  }
  double original = 0.0;
  for (std::size_t c = 0; c < model->mesh().cellCount(); ++c) original += signedCellVolume(model->mesh(), c);
  std::size_t boundary = 0, overShared = 0;
  for (const auto& [k, count] : faces) boundary += count == 1, overShared += count > 2;
  std::printf("wheel_mixed: %zu cells -> %zu tets, %zu Steiner points\n", model->mesh().cellCount(), t.mesh.cellCount(),
              t.steinerCell.size());
  EXPECT_NEAR(volume, original, 1e-9 * original);
  EXPECT_GT(smallest, 0.0);
  EXPECT_EQ(overShared, 0u);
  EXPECT_EQ(boundary, extractBoundary(model->mesh()).mesh.n_faces());
}

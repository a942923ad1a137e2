// SPDX-License-Identifier: MIT
#include "host/optics/TetVolume.hpp"

#include <volpost/core/Tetrahedralize.hpp>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace volpost::optics {
namespace {

// Sign of dot(n, delta) for the infinitesimal displacement delta = (e, e^2, e^3): every
// point exactly on a plane is pushed to the same side by every tet that uses the plane.
bool perturbedPositive(const glm::dvec3& n) {
  if (n.x != 0.0) return n.x > 0.0;
  if (n.y != 0.0) return n.y > 0.0;
  return n.z > 0.0;
}

constexpr int kFaces[4][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};  // face i is opposite vertex i

}  // namespace

TetVolume::TetVolume(const Mesh& mesh, FieldLocation location, std::span<const double> values) {
  requireTetrahedraAndValues(mesh, location == FieldLocation::Node, values.size());
  const Bounds b = mesh.bounds();
  origin_ = b.valid ? b.center() : glm::dvec3(0.0);
  std::vector<BoxTree::Box> boxes;
  tets_.reserve(mesh.cellCount());
  for (std::size_t c = 0; c < mesh.cellCount(); ++c) {
    const auto nodes = mesh.cellNodes(c);
    glm::dvec3 p[4];
    double s[4];
    bool finite = true;
    for (int k = 0; k < 4; ++k) {
      p[k] = mesh.nodes[nodes[k]] - origin_;
      s[k] = location == FieldLocation::Node ? values[nodes[k]] : values[c];
      finite = finite && std::isfinite(s[k]) && std::isfinite(p[k].x) && std::isfinite(p[k].y) && std::isfinite(p[k].z);
    }
    const glm::dmat3 edges(p[1] - p[0], p[2] - p[0], p[3] - p[0]);
    const double det = glm::determinant(edges);
    if (!finite || det == 0.0) {
      ++skipped_;
      continue;
    }
    PreparedTet tet;
    for (int f = 0; f < 4; ++f) {
      // The plane through the face's vertices taken in ascending global id order: the
      // neighbour across this face computes bit-identical numbers.
      std::array<int, 3> v = {kFaces[f][0], kFaces[f][1], kFaces[f][2]};
      std::sort(v.begin(), v.end(), [&](int a, int bb) { return nodes[a] < nodes[bb]; });
      const glm::dvec3 n = glm::cross(p[v[1]] - p[v[0]], p[v[2]] - p[v[0]]);
      const double offset = glm::dot(n, p[v[0]]);
      const double side = glm::dot(n, p[f]) - offset;  // the opposite vertex is inside
      const double sign = side > 0.0 ? 1.0 : -1.0;
      tet.planes[f] = {n * sign, offset * sign, perturbedPositive(n * sign)};
    }
    // Gradient from the edge differences: edges^T g = (s1 - s0, s2 - s0, s3 - s0).
    const glm::dvec3 ds(s[1] - s[0], s[2] - s[0], s[3] - s[0]);
    tet.gradient = glm::inverse(glm::transpose(edges)) * ds;
    if (location == FieldLocation::Cell) tet.gradient = glm::dvec3(0.0);
    tet.valueAtOrigin = s[0] - glm::dot(tet.gradient, p[0]);
    tet.source = std::uint32_t(c);
    tets_.push_back(tet);
    glm::dvec3 lo = glm::min(glm::min(p[0], p[1]), glm::min(p[2], p[3]));
    glm::dvec3 hi = glm::max(glm::max(p[0], p[1]), glm::max(p[2], p[3]));
    const glm::dvec3 pad = (hi - lo) * 1e-9 + 1e-300;  // boxes only select candidates: be generous
    boxes.push_back({lo - pad, hi + pad});
  }
  boxes_ = BoxTree(boxes);
}

}  // namespace volpost::optics

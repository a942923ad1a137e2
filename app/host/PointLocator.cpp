// SPDX-License-Identifier: MIT
#include "host/PointLocator.hpp"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace volpost {

// A uniform grid with about 2 tets per grid cell: each tet is listed in every grid cell
// its bounding box touches (two passes: count, then fill).
PointLocator::PointLocator(const TetMesh& tets) : tets_(tets) {
  const Mesh& m = tets.mesh;
  const Bounds b = m.bounds();
  if (!b.valid || m.cellCount() == 0) return;
  const glm::dvec3 size = glm::max(b.size(), glm::dvec3(b.diagonal() * 1e-6 + 1e-300));
  const double perAxis = std::cbrt(double(m.cellCount()) / 2.0 / (size.x * size.y * size.z));
  resolution_ = glm::clamp(glm::ivec3(glm::ceil(size * perAxis)), glm::ivec3(1), glm::ivec3(256));
  min_ = b.min;
  cellSize_ = size / glm::dvec3(resolution_);
  const auto boxOf = [&](std::size_t t, glm::ivec3& lo, glm::ivec3& hi) {
    glm::dvec3 mn(INFINITY), mx(-INFINITY);
    for (NodeIndex n : m.cellNodes(t)) {
      mn = glm::min(mn, m.nodes[n]);
      mx = glm::max(mx, m.nodes[n]);
    }
    lo = gridCell(mn);
    hi = gridCell(mx);
  };
  start_.assign(std::size_t(resolution_.x) * std::size_t(resolution_.y) * std::size_t(resolution_.z) + 1, 0);
  for (int pass = 0; pass < 2; ++pass) {
    std::vector<std::uint32_t> fill;
    if (pass == 1) {
      for (std::size_t i = 1; i < start_.size(); ++i) start_[i] += start_[i - 1];
      items_.resize(start_.back());
      fill.assign(start_.begin(), start_.end() - 1);
    }
    for (std::size_t t = 0; t < m.cellCount(); ++t) {
      glm::ivec3 lo, hi;
      boxOf(t, lo, hi);
      for (int z = lo.z; z <= hi.z; ++z)
        for (int y = lo.y; y <= hi.y; ++y)
          for (int x = lo.x; x <= hi.x; ++x) {
            const std::size_t g = gridIndex({x, y, z});
            if (pass == 0) ++start_[g + 1];
            else items_[fill[g]++] = std::uint32_t(t);
          }
    }
  }
}

glm::ivec3 PointLocator::gridCell(const glm::dvec3& p) const {
  const glm::dvec3 c = glm::floor((p - min_) / cellSize_);
  return glm::clamp(glm::ivec3(glm::clamp(c, glm::dvec3(-1.0), glm::dvec3(resolution_))), glm::ivec3(0), resolution_ - 1);
}

std::size_t PointLocator::gridIndex(const glm::ivec3& c) const {
  return (std::size_t(c.z) * std::size_t(resolution_.y) + std::size_t(c.y)) * std::size_t(resolution_.x) + std::size_t(c.x);
}

std::optional<PointLocation> PointLocator::locate(const glm::dvec3& p, double tolerance) const {
  if (start_.empty() || !std::isfinite(p.x + p.y + p.z)) return std::nullopt;
  const glm::dvec3 rel = (p - min_) / cellSize_;
  if (glm::any(glm::lessThan(rel, glm::dvec3(-1e-6))) || glm::any(glm::greaterThan(rel, glm::dvec3(resolution_) + 1e-6)))
    return std::nullopt;
  const Mesh& m = tets_.mesh;
  const std::size_t g = gridIndex(gridCell(p));
  std::optional<PointLocation> best;
  double bestMin = -INFINITY;
  for (std::uint32_t k = start_[g]; k < start_[g + 1]; ++k) {
    const std::size_t t = items_[k];
    const auto n = m.cellNodes(t);
    const glm::dvec3 a = m.nodes[n[0]], e1 = m.nodes[n[1]] - a, e2 = m.nodes[n[2]] - a, e3 = m.nodes[n[3]] - a;
    const double det = glm::dot(e1, glm::cross(e2, e3));
    if (det == 0.0) continue;
    const glm::dvec3 r = p - a;
    const double w1 = glm::dot(r, glm::cross(e2, e3)) / det, w2 = glm::dot(e1, glm::cross(r, e3)) / det,
                 w3 = glm::dot(e1, glm::cross(e2, r)) / det, w0 = 1.0 - w1 - w2 - w3;
    const double smallest = std::min({w0, w1, w2, w3});
    if (smallest > bestMin) {  // keep the tet the point is deepest inside
      bestMin = smallest;
      best = PointLocation{t, tets_.cellOfTet[t], {n[0], n[1], n[2], n[3]}, {w0, w1, w2, w3}};
    }
    if (smallest >= 0.0) break;
  }
  if (!best || bestMin < -tolerance) return std::nullopt;
  return best;
}

double PointLocator::interpolateNodal(const PointLocation& at, const std::vector<double>& values) {
  double v = 0.0;
  for (int k = 0; k < 4; ++k) v += at.weights[std::size_t(k)] * values[at.nodes[std::size_t(k)]];
  return v;
}

}  // namespace volpost

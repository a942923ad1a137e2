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
  modelSize_ = b.diagonal() > 0.0 ? b.diagonal() : 1.0;
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

double PointLocator::distanceOutside(std::size_t t, const glm::dvec3& p, std::array<double, 4>& w) const {
  const Mesh& m = tets_.mesh;
  const auto n = m.cellNodes(t);
  const glm::dvec3 a = m.nodes[n[0]], e1 = m.nodes[n[1]] - a, e2 = m.nodes[n[2]] - a, e3 = m.nodes[n[3]] - a;
  const double det = glm::dot(e1, glm::cross(e2, e3));
  if (det == 0.0 || !std::isfinite(det)) return INFINITY;
  const glm::dvec3 r = p - a;
  w[1] = glm::dot(r, glm::cross(e2, e3)) / det;
  w[2] = glm::dot(e1, glm::cross(r, e3)) / det;
  w[3] = glm::dot(e1, glm::cross(e2, r)) / det;
  w[0] = 1.0 - w[1] - w[2] - w[3];
  if (std::min({w[0], w[1], w[2], w[3]}) >= 0.0) return 0.0;
  // A negative weight times the height of its vertex over the opposite face is the
  // distance beyond that face; the largest of them bounds the distance to the tet.
  const glm::dvec3 v[4] = {a, m.nodes[n[1]], m.nodes[n[2]], m.nodes[n[3]]};
  double outside = 0.0;
  for (int i = 0; i < 4; ++i) {
    if (w[std::size_t(i)] >= 0.0) continue;
    const glm::dvec3 f0 = v[(i + 1) % 4], f1 = v[(i + 2) % 4], f2 = v[(i + 3) % 4];
    const double faceArea2 = glm::length(glm::cross(f1 - f0, f2 - f0));
    const double height = faceArea2 > 0.0 ? std::abs(det) / faceArea2 : INFINITY;
    outside = std::max(outside, -w[std::size_t(i)] * height);
  }
  return outside;
}

std::vector<std::uint32_t> PointLocator::tetsNear(const glm::dvec3& p, double radius) const {
  std::vector<std::uint32_t> found;
  if (start_.empty() || !std::isfinite(p.x + p.y + p.z)) return found;
  const glm::ivec3 lo = gridCell(p - glm::dvec3(radius)), hi = gridCell(p + glm::dvec3(radius));
  for (int z = lo.z; z <= hi.z; ++z)
    for (int y = lo.y; y <= hi.y; ++y)
      for (int x = lo.x; x <= hi.x; ++x) {
        const std::size_t g = gridIndex({x, y, z});
        found.insert(found.end(), items_.begin() + start_[g], items_.begin() + start_[g + 1]);
      }
  if (lo != hi) {
    std::sort(found.begin(), found.end());
    found.erase(std::unique(found.begin(), found.end()), found.end());
  }
  return found;
}

std::optional<PointLocation> PointLocator::locate(const glm::dvec3& p, double tolerance) const {
  if (start_.empty() || !std::isfinite(p.x + p.y + p.z)) return std::nullopt;
  const double allowed = tolerance * modelSize_;
  const glm::dvec3 rel = (p - min_) / cellSize_, slack = glm::dvec3(allowed) / cellSize_;
  if (glm::any(glm::lessThan(rel, -slack - 1e-9)) || glm::any(glm::greaterThan(rel, glm::dvec3(resolution_) + slack + 1e-9)))
    return std::nullopt;
  const Mesh& m = tets_.mesh;
  const auto locationIn = [&](std::size_t t, const std::array<double, 4>& w) {
    const auto n = m.cellNodes(t);
    return PointLocation{t, tets_.sourceCell(t), {n[0], n[1], n[2], n[3]}, w};
  };
  // Inside a tet of p's grid cell: done. Otherwise the nearest tet within the tolerance,
  // also among the neighbouring grid cells (a point just outside a tet's bounding box can
  // fall in a grid cell that does not list it).
  std::optional<PointLocation> best;
  double bestOutside = INFINITY;
  const std::size_t g = gridIndex(gridCell(p));
  std::array<double, 4> w{};
  for (std::uint32_t k = start_[g]; k < start_[g + 1]; ++k) {
    const double outside = distanceOutside(items_[k], p, w);
    if (outside == 0.0) return locationIn(items_[k], w);
    if (outside < bestOutside) bestOutside = outside, best = locationIn(items_[k], w);
  }
  if (allowed > 0.0)
    for (std::uint32_t t : tetsNear(p, allowed)) {
      const double outside = distanceOutside(t, p, w);
      if (outside < bestOutside) bestOutside = outside, best = locationIn(t, w);
    }
  if (!best || bestOutside > allowed) return std::nullopt;
  return best;
}

double PointLocator::interpolateNodal(const PointLocation& at, const std::vector<double>& values) {
  double v = 0.0;
  for (int k = 0; k < 4; ++k) v += at.weights[std::size_t(k)] * values[at.nodes[std::size_t(k)]];
  return v;
}

}  // namespace volpost

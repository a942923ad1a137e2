// SPDX-License-Identifier: MIT
#include "host/optics/CurvedCells.hpp"

#include <volpost/core/CellShape.hpp>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace volpost::optics {
namespace {

// A point counts as inside the cell this close to the reference cell (natural units): the
// ends of a stretch are where this changes, found to rounding by bisection.
constexpr double kInside = 1e-12;
// Samples nearer than this to the reference cell (natural units) without entering it are
// searched between for a point inside.
constexpr double kGrazing = 0.15;

// A box holding the whole cell: the map sampled over the reference cell (corners, edges,
// faces and inside, 9 points along each natural axis), widened by a twentieth of its size on
// every side (a quadratic surface strays from the samples by far less), since a box that
// misses part of the cell would lose that part.
BoxTree::Box boxOf(CellType type, std::span<const glm::dvec3> nodes) {
  glm::dvec3 lo(INFINITY), hi(-INFINITY);
  for (const glm::dvec3& x : nodes) lo = glm::min(lo, x), hi = glm::max(hi, x);
  constexpr int n = 8;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j)
      for (int k = 0; k <= n; ++k) {
        const glm::dvec3 u(double(i) / n, double(j) / n, double(k) / n);
        glm::dvec3 xi = u;
        if (type == CellType::Hex8 || type == CellType::Hex20) xi = 2.0 * u - 1.0;
        else if (type == CellType::Wedge6 || type == CellType::Wedge15) xi.z = 2.0 * u.z - 1.0;
        xi = clampToReference(type, xi);
        const glm::dvec3 x = positionAt(type, nodes, xi);
        lo = glm::min(lo, x), hi = glm::max(hi, x);
      }
  const glm::dvec3 pad = 0.05 * (hi - lo) + glm::dvec3(1e-12 * glm::length(hi - lo) + 1e-300);
  return {lo - pad, hi + pad};
}

}  // namespace

CurvedCells::CurvedCells(const ElementField& field) : field_(field) {
  const Mesh& mesh = field.mesh();
  std::vector<glm::dvec3> at;
  for (std::size_t c = 0; c < mesh.cellCount(); ++c) {
    if (!curved(std::uint32_t(c))) continue;  // bend() is 0 for cells drawn by their split
    const CellType type = mesh.cellType(c);
    at.clear();
    for (NodeIndex n : mesh.cellNodes(c)) at.push_back(mesh.nodes[n] - field.origin());
    cells_.push_back({std::uint32_t(c), type, std::uint32_t(nodes_.size()), int(at.size())});
    nodes_.insert(nodes_.end(), at.begin(), at.end());
    cellBoxes_.push_back(boxOf(type, at));
  }
  boxes_ = BoxTree(cellBoxes_);
}

void CurvedCells::stretches(const glm::dvec3& o, const glm::dvec3& d, double tMin, double tMax,
                            std::span<const double> seeds, std::vector<CellStretch>& out) const {
  std::vector<double> samples;
  boxes_.forEachCandidate(o, d, tMin, tMax, [&](std::uint32_t index) {
    double t0 = tMin, t1 = tMax;  // the candidate's own box: the tree only says it may be met
    if (!BoxTree::clipToBox(cellBoxes_[index], o, d, t0, t1)) return;
    samples.clear();
    for (int k = 0; k <= kSamples; ++k) samples.push_back(t0 + (t1 - t0) * double(k) / kSamples);
    for (double t : seeds)
      if (t > t0 && t < t1) samples.push_back(t);
    std::sort(samples.begin(), samples.end());
    stretchesIn(cells_[index], o, d, samples, out);
  });
}

void CurvedCells::stretchesIn(const Cell& cell, const glm::dvec3& o, const glm::dvec3& d,
                              const std::vector<double>& samples, std::vector<CellStretch>& out) const {
  const std::span<const glm::dvec3> nodes(nodes_.data() + cell.firstNode, std::size_t(cell.nodeCount));
  const glm::dvec3 centre = referenceCentre(cell.type);
  glm::dvec3 guess = centre;  // natural coordinates of the last point found inside
  // How far outside the reference cell the point at t lies (negative inside; +inf where no
  // natural coordinates are found): Newton's method from the last point inside, and where
  // that says outside (it may have run to another preimage of the map's extension beyond
  // the cell), from the centre too.
  const auto outside = [&](double t) {
    const glm::dvec3 p = o + t * d;
    double best = std::numeric_limits<double>::infinity();
    for (const glm::dvec3& start : {guess, centre}) {
      const std::optional<glm::dvec3> xi = naturalCoordinates(cell.type, nodes, p, start);
      if (xi) best = std::min(best, signedOutsideReference(cell.type, *xi));
      if (best <= kInside) {
        guess = *xi;
        break;
      }
      if (start == centre) break;
    }
    return best;
  };
  std::vector<double> ts = samples, h(ts.size());
  for (std::size_t k = 0; k < ts.size(); ++k) h[k] = outside(ts[k]);
  // A ray grazing the cell (its corner, or a bulge beyond the split) may be inside only
  // between two samples: where the samples come nearest without entering, the nearest point
  // between the neighbours is searched (golden section), and a point found inside is added.
  const std::size_t n = ts.size();
  for (std::size_t k = 0; k < n; ++k) {
    const bool nearest =
        h[k] > kInside && h[k] < kGrazing && (k == 0 || h[k - 1] >= h[k]) && (k + 1 == n || h[k + 1] >= h[k]);
    if (!nearest) continue;
    double a = ts[k == 0 ? 0 : k - 1], b = ts[k + 1 == n ? k : k + 1];
    constexpr double g = 0.6180339887498949;
    double c = b - g * (b - a), e = a + g * (b - a), hc = outside(c), he = outside(e);
    for (int i = 0; i < 40 && std::min(hc, he) > kInside; ++i) {
      if (hc < he) b = e, e = c, he = hc, c = b - g * (b - a), hc = outside(c);
      else a = c, c = e, hc = he, e = a + g * (b - a), he = outside(e);
    }
    if (std::min(hc, he) <= kInside) ts.push_back(hc <= kInside ? c : e), h.push_back(kInside);
  }
  if (ts.size() > n) {  // back in order along the ray
    std::vector<std::size_t> order(ts.size());
    for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
    std::sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) { return ts[x] < ts[y]; });
    std::vector<double> sortedT, sortedH;
    for (std::size_t k : order) sortedT.push_back(ts[k]), sortedH.push_back(h[k]);
    ts.swap(sortedT), h.swap(sortedH);
  }
  // Between two samples that disagree, the end by bisection to rounding.
  bool wasInside = h[0] <= kInside;
  double open = ts[0];
  for (std::size_t k = 1; k < ts.size(); ++k) {
    const bool isInside = h[k] <= kInside;
    if (isInside != wasInside) {
      double lo = ts[k - 1], hi = ts[k];  // lo on the earlier sample's side
      for (int i = 0; i < 80; ++i) {
        const double mid = 0.5 * (lo + hi);
        if (mid <= lo || mid >= hi) break;  // to rounding
        ((outside(mid) <= kInside) == wasInside ? lo : hi) = mid;
      }
      const double crossing = 0.5 * (lo + hi);
      if (isInside) open = crossing;
      else if (crossing > open) out.push_back({open, crossing, cell.id});
    }
    wasInside = isInside;
  }
  if (wasInside && ts.back() > open) out.push_back({open, ts.back(), cell.id});
}

}  // namespace volpost::optics

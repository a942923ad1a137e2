// SPDX-License-Identifier: MIT
#include "host/optics/BoxTree.hpp"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace volpost::optics {

BoxTree::BoxTree(const std::vector<Box>& boxes) {
  order_.resize(boxes.size());
  std::iota(order_.begin(), order_.end(), 0u);
  if (boxes.empty()) return;
  nodes_.reserve(2 * boxes.size() / 4 + 2);
  struct Task {
    std::uint32_t node, first, count;
  };
  std::vector<Task> tasks;
  nodes_.push_back({});
  tasks.push_back({0, 0, std::uint32_t(boxes.size())});
  while (!tasks.empty()) {
    const Task t = tasks.back();
    tasks.pop_back();
    glm::dvec3 lo(INFINITY), hi(-INFINITY), clo(INFINITY), chi(-INFINITY);
    for (std::uint32_t i = t.first; i < t.first + t.count; ++i) {
      const Box& box = boxes[order_[i]];
      lo = glm::min(lo, box[0]);
      hi = glm::max(hi, box[1]);
      const glm::dvec3 c = 0.5 * (box[0] + box[1]);
      clo = glm::min(clo, c);
      chi = glm::max(chi, c);
    }
    nodes_[t.node].box = {lo, hi};
    const glm::dvec3 extent = chi - clo;
    if (t.count <= 4 || (extent.x == 0.0 && extent.y == 0.0 && extent.z == 0.0)) {
      nodes_[t.node].first = t.first;
      nodes_[t.node].count = t.count;
      continue;
    }
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
    const auto begin = order_.begin() + t.first, mid = begin + t.count / 2, end = begin + t.count;
    std::nth_element(begin, mid, end, [&](std::uint32_t a, std::uint32_t b) {
      return boxes[a][0][axis] + boxes[a][1][axis] < boxes[b][0][axis] + boxes[b][1][axis];
    });
    const std::uint32_t children = std::uint32_t(nodes_.size());
    nodes_.push_back({});
    nodes_.push_back({});
    nodes_[t.node].first = children;
    nodes_[t.node].count = 0;
    tasks.push_back({children, t.first, t.count / 2});
    tasks.push_back({children + 1, t.first + t.count / 2, t.count - t.count / 2});
  }
}

bool BoxTree::clipToBox(const Box& box, const glm::dvec3& o, const glm::dvec3& d, double& tMin, double& tMax) {
  for (int k = 0; k < 3; ++k) {
    if (d[k] == 0.0) {
      if (o[k] < box[0][k] || o[k] > box[1][k]) return false;
      continue;
    }
    double t0 = (box[0][k] - o[k]) / d[k], t1 = (box[1][k] - o[k]) / d[k];
    if (t0 > t1) std::swap(t0, t1);
    tMin = std::max(tMin, t0);
    tMax = std::min(tMax, t1);
    if (tMin > tMax) return false;
  }
  return true;
}

}  // namespace volpost::optics

// SPDX-License-Identifier: MIT
// A bounding-volume hierarchy over axis-aligned boxes: which boxes a ray segment may meet.
// Split at the median of the boxes' centres along the widest axis, four boxes a leaf.
#pragma once

#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace volpost::optics {

class BoxTree {
 public:
  using Box = std::array<glm::dvec3, 2>;  ///< low and high corners

  BoxTree() = default;
  explicit BoxTree(const std::vector<Box>& boxes);

  /// Calls visit(index) for every box (its index in the list given) that the ray o + t d
  /// meets with t in [tMin, tMax].
  template <typename Visit>
  void forEachCandidate(const glm::dvec3& o, const glm::dvec3& d, double tMin, double tMax, Visit&& visit) const;

  /// Narrows [tMin, tMax] to the stretch of the ray o + t d inside the box; false when none.
  static bool clipToBox(const Box& box, const glm::dvec3& o, const glm::dvec3& d, double& tMin, double& tMax);

 private:
  struct Node {
    Box box;
    std::uint32_t first, count;  ///< leaf: boxes [first, first+count); inner: count == 0, children first, first+1
  };
  std::vector<std::uint32_t> order_;  ///< box indices in leaf order
  std::vector<Node> nodes_;
};

template <typename Visit>
void BoxTree::forEachCandidate(const glm::dvec3& o, const glm::dvec3& d, double tMin, double tMax,
                               Visit&& visit) const {
  if (nodes_.empty()) return;
  std::uint32_t stack[128];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& n = nodes_[stack[--top]];
    double t0 = tMin, t1 = tMax;
    if (!clipToBox(n.box, o, d, t0, t1)) continue;
    if (n.count > 0) {
      for (std::uint32_t i = n.first; i < n.first + n.count; ++i) visit(order_[i]);
    } else if (top + 2 <= 128) {
      stack[top++] = n.first;
      stack[top++] = n.first + 1;
    }
  }
}

}  // namespace volpost::optics

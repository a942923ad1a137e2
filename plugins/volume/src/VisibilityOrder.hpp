// SPDX-License-Identifier: MIT
// Back-to-front visibility orders of tetrahedra for cell projection, computed on the CPU:
//  - MPVO (Williams 1992): each interior face orders its two tets by the side the eye is
//    on; a topological sort of that graph is exact for convex meshes.
//  - MPVONC: the same, with the tets that start the sort (no tet behind them across a
//    face) taken farthest first. A heuristic: on non-convex meshes it can be wrong where
//    one part is seen through a gap behind another.
//  - Image-space (after Cook et al. 2004): MPVO's relations plus, for every pixel ray of
//    the image, "farther before nearer" between consecutive tets along the ray that do not
//    share a face (the ray left the mesh and came back). Exact for every ray the image
//    samples, on any mesh.
// A cycle in the relations (possible with badly shaped or intersecting cells) is broken by
// placing the farthest remaining tet next; the count is reported.
#pragma once

#include <volpost/core/Camera.hpp>
#include <volpost/core/Mesh.hpp>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstdint>
#include <vector>

namespace volpost::volume {

enum class OrderMethod { Mpvo, Mpvonc, ImageSpace };

struct VisibilityOrder {
  std::vector<std::uint32_t> backToFront;  ///< tet indices, farthest first
  std::size_t cycleBreaks = 0;             ///< tets placed by breaking a cycle
  std::size_t imageRelations = 0;          ///< relations added by the image-space method
  double milliseconds = 0.0;
};

/// A directed graph "a before b" over n items, sorted topologically; among the items that
/// are free at any time, the largest `priority` goes first (a cycle breaks there too).
std::vector<std::uint32_t> priorityTopologicalOrder(std::size_t n, const std::vector<std::pair<std::uint32_t, std::uint32_t>>& edges,
                                                    const std::vector<double>& priority, std::size_t* cycleBreaks);

class VisibilitySorter {
 public:
  /// `tets`: tet4 cells only (the conforming tetrahedra). Face adjacency is built once.
  explicit VisibilitySorter(const Mesh& tets);
  /// With the face adjacency already at hand (faceNeighbors' convention).
  VisibilitySorter(const Mesh& tets, std::vector<glm::ivec4> neighbors);

  /// The order for a camera; the image-space method samples a width x height pixel grid.
  VisibilityOrder order(const Camera& camera, OrderMethod method, int width = 0, int height = 0) const;

  /// The tets a ray crosses, nearest first (for the image-space relations and for tests).
  std::vector<std::uint32_t> tetsAlongRay(const glm::dvec3& origin, const glm::dvec3& direction) const;

 private:
  void imageSpaceRelations(const Camera& camera, int width, int height,
                           std::vector<std::pair<std::uint32_t, std::uint32_t>>& edges, VisibilityOrder& result) const;

  const Mesh& mesh_;
  std::vector<glm::ivec4> neighbors_;  ///< across the face opposite vertex k, -1: boundary
  std::vector<glm::dvec3> centroids_;
};

}  // namespace volpost::volume

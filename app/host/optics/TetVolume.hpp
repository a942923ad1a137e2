// SPDX-License-Identifier: MIT
// A tetrahedral mesh prepared for ray integration: each tet's four face planes (computed
// once per face from its sorted global vertex ids, so two tets sharing a face use the
// very same plane), its scalar as a linear function, and a BVH over the tets. All in
// double precision, relative to the mesh center.
#pragma once

#include "host/optics/BoxTree.hpp"

#include <volpost/core/Field.hpp>
#include <volpost/core/Mesh.hpp>

#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

namespace volpost::optics {

struct TetPlane {
  glm::dvec3 normal;  ///< canonical normal (from sorted vertex ids) times the tet's side
  double offset;      ///< inside: dot(normal, x) - offset > 0
  bool tieInside;     ///< for points exactly on the plane (symbolic perturbation)
};

struct PreparedTet {
  std::array<TetPlane, 4> planes;
  glm::dvec3 gradient;  ///< of the scalar, per length unit
  double valueAtOrigin; ///< scalar at the mesh-relative origin: s(x) = valueAtOrigin + gradient . x
  std::uint32_t source;  ///< its index in the mesh it was built from
};

class TetVolume {
 public:
  /// Tets of the mesh (tet4, or tet10 through its corners) with one scalar per node
  /// (linear in each tet) or per cell (constant). Throws std::invalid_argument for other
  /// cell types (they must be tetrahedralized first) or a wrong number of values. Tets of
  /// zero volume and tets touching a non-finite value are left out and counted.
  TetVolume(const Mesh& mesh, FieldLocation location, std::span<const double> values);

  const glm::dvec3& origin() const { return origin_; }
  std::size_t tetCount() const { return tets_.size(); }
  std::size_t skippedTets() const { return skipped_; }
  const PreparedTet& tet(std::size_t i) const { return tets_[i]; }

  /// Calls visit(tetIndex) for every tet whose box the ray o + t d (mesh-relative o)
  /// meets with t in [tMin, tMax].
  template <typename Visit>
  void forEachCandidate(const glm::dvec3& o, const glm::dvec3& d, double tMin, double tMax, Visit&& visit) const;

 private:
  glm::dvec3 origin_{0.0};
  std::vector<PreparedTet> tets_;
  BoxTree boxes_;  ///< one box per tet, in the order of tets_
  std::size_t skipped_ = 0;
};

template <typename Visit>
void TetVolume::forEachCandidate(const glm::dvec3& o, const glm::dvec3& d, double tMin, double tMax, Visit&& visit) const {
  boxes_.forEachCandidate(o, d, tMin, tMax, std::forward<Visit>(visit));
}

}  // namespace volpost::optics

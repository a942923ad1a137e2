// SPDX-License-Identifier: MIT
// Checks shared by the tests of the two refinements of the cells' own field (uniform and
// bisected): the pieces of one cell fill it and carry its field.
#pragma once

#include "host/BoundarySurface.hpp"
#include "host/ElementRefinement.hpp"

#include <volpost/core/CellShape.hpp>
#include <volpost/core/optics/ElementField.hpp>

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace volpost::test {

/// Every tetrahedron of `split`, by index.
inline std::vector<std::uint32_t> everyTet(const TetMesh& split) {
  std::vector<std::uint32_t> all(split.mesh.cellCount());
  for (std::uint32_t t = 0; t < all.size(); ++t) all[t] = t;
  return all;
}

/// The pieces `r` of cell 0 of `field`'s mesh, whose volume is `volume`: positive, with no
/// gaps or overlaps, closed over the cell's faces, and carrying the cell's own field at
/// every point.
inline void expectTheCellTiledWithItsOwnField(const RefinedTetrahedra& r, const optics::ElementField& field,
                                              double volume) {
  double sum = 0.0;
  for (std::size_t t = 0; t < r.tets.mesh.cellCount(); ++t) sum += signedCellVolume(r.tets.mesh, t);
  EXPECT_NEAR(sum, volume, 1e-12) << "positive pieces, no gaps, no overlaps";
  const BoundarySurface outside = extractBoundary(r.tets.mesh);
  EXPECT_EQ(outside.nonManifoldFaceCount, 0u);
  for (const auto e : outside.mesh.edges()) EXPECT_FALSE(outside.mesh.is_boundary(e)) << "closed";
  for (std::size_t n = 0; n < r.tets.mesh.nodeCount(); ++n) {
    glm::dvec3 xi = field.start(0);
    const auto own = field.value(0, r.tets.mesh.nodes[n], xi);
    ASSERT_TRUE(own.has_value());
    EXPECT_NEAR(r.values[n], *own, 1e-9);
  }
}

}  // namespace volpost::test

// SPDX-License-Identifier: MIT
// Roettger's iso-surface table, kept as the yardstick the exact iso-surfaces are compared with.
#include "host/optics/IsoSurfaceTable.hpp"

#include <gtest/gtest.h>

using namespace volpost;
using namespace volpost::optics;

TEST(IsoSurfaceTable, ColorOfTheFirstSurfaceCrossed) {
  const IsoSurfaceTable t({{0.7, {0, 0, 1}, 0.5}, {0.3, {1, 0, 0}, 1.0}}, 0.0, 1.0, 11);
  EXPECT_EQ(t.at(0.0, 1.0), glm::dvec4(1, 0, 0, 1));
  EXPECT_EQ(t.at(1.0, 0.0), glm::dvec4(0, 0, 0.5, 0.5));
  EXPECT_EQ(t.at(0.4, 0.6), glm::dvec4(0.0));
}

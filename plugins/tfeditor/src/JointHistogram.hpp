// SPDX-License-Identifier: MIT
// The joint distribution of a regular grid's values and their gradient magnitudes, behind
// the 2D transfer-function editor (Kniss et al. 2002): materials are the bright blobs at low
// gradient, the boundaries between two of them the arches joining the blobs. Gradients by
// central differences at the grid's points (one-sided on its faces), in model units, as the
// renderers see them.
#pragma once

#include <volpost/core/RegularGrid.hpp>
#include <volpost/core/SampleView.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace volpost::tfeditor {

struct JointHistogram {
  double valueLow = 0.0, valueHigh = 1.0;
  double gradientHigh = 1.0;  ///< the 99.5th percentile: a few spikes would flatten the rest
  int valueBins = 0, gradientBins = 0;
  std::vector<std::uint32_t> counts;  ///< counts[g * valueBins + v], gradient bin 0 the lowest
  std::uint32_t count(int v, int g) const { return counts[std::size_t(g) * std::size_t(valueBins) + std::size_t(v)]; }
  std::uint32_t largest() const;

  /// Of the grid's finite point values; points beyond 8 million are sampled on a stride.
  static JointHistogram ofGrid(const RegularGrid& grid, SampleView values, int valueBins = 256,
                               int gradientBins = 128);
};

}  // namespace volpost::tfeditor

// SPDX-License-Identifier: MIT
// The range of values mapped onto the color map, and the one a result gets by itself.
#pragma once

namespace volpost::app {

struct ScalarView;

/// The range mapped onto the color map.
struct DisplayRange {
  double min = 0.0, max = 1.0;
  bool operator==(const DisplayRange&) const = default;
};

/// The range a view maps onto the color map: its own, or 0..1 when it has no values.
DisplayRange autoRange(const ScalarView& view);

}  // namespace volpost::app

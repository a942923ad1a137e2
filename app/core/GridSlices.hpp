// SPDX-License-Identifier: MIT
// A regular grid's slices (inline, crossline, time for a survey) as a user names them: the
// axis by its name, letter or number, a slice by its label, checked against the grid, and
// the planes the slices lie in.
#pragma once

#include <volpost/core/ClipPlane.hpp>
#include <volpost/core/RegularGrid.hpp>

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace volpost::app {

/// A label per axis (inline, crossline, time numbers for a survey); nullopt: no slice.
using GridSliceLabels = std::array<std::optional<double>, 3>;

/// The axis of `grid` a user names: the first word of its name ("inline", "crossline",
/// "time" for a survey), its letter (i, j, k) or its number (1, 2, 3), any case; -1 for none.
int gridAxisNamed(const RegularGrid& grid, const std::string& name);

/// Throws std::invalid_argument unless each set label lies on its axis of the grid (within
/// half a step), naming the slice and the axis' range; a mesh (no grid) takes none.
void checkGridSlices(const std::optional<RegularGrid>& grid, const GridSliceLabels& labels);

/// The planes of the set slices, in model coordinates.
std::vector<ClipPlane> gridSlicePlanesAt(const RegularGrid& grid, const GridSliceLabels& labels);

}  // namespace volpost::app

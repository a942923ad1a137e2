// SPDX-License-Identifier: MIT
// What a volume looks like before the user says otherwise, and its legend's colors.
#pragma once

#include "ModelSession.hpp"
#include "SceneState.hpp"

#include <volpost/core/ColorMap.hpp>
#include <volpost/core/TransferFunction.hpp>

#include <optional>
#include <string>

namespace volpost::app {

/// A first transfer function for a result: the color map over its range (or the fixed
/// range); extinction rises linearly from 10% to 100% of 24 / (model diagonal) (1 /
/// length unit), so the part shows as a light fog and the highest values as dense color.
/// For a signed range (min < 0 < max) it rises with |value| instead: both ends dense, clear
/// at zero.
TransferFunction defaultTransferFunction(const ScalarView& view, double modelDiagonal,
                                         const std::string& colorMap = "cool-warm",
                                         std::optional<DisplayRange> range = std::nullopt);

/// A warning when the function's values cover less than half of the result's range at
/// this step (e.g. one loaded from another field), else nothing.
std::optional<std::string> transferFunctionRangeNote(const TransferFunction& tf, const ScalarView& view);

/// The transfer function's colors as a color map over its range (for the legend).
ColorMap colorMapOf(const TransferFunction& tf);

}  // namespace volpost::app

// SPDX-License-Identifier: MIT
// What a volume looks like before the user says otherwise, and its legend's colors.
#pragma once

#include "ModelSession.hpp"
#include "SceneState.hpp"

#include <volpost/core/ColorMap.hpp>
#include <volpost/core/TransferFunction.hpp>

namespace volpost::app {

/// A first transfer function for a result: the color map over its range (or the fixed
/// range); extinction rises linearly from 10% to 100% of 24 / (model diagonal) (1 /
/// length unit), so the part shows as a light fog and the highest values as dense color.
TransferFunction defaultTransferFunction(const ScalarView& view, double modelDiagonal,
                                         const std::string& colorMap = "cool-warm",
                                         std::optional<DisplayRange> range = std::nullopt);

/// The transfer function's colors as a color map over its range (for the legend).
ColorMap colorMapOf(const TransferFunction& tf);

}  // namespace volpost::app

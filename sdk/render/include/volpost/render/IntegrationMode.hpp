// SPDX-License-Identifier: MIT
// How a volume renderer integrates the transfer function along a ray segment, with one
// written form per mode for the command line, state files, benches and settings.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace volpost {

/// How a renderer integrates the transfer function along a ray segment.
enum class IntegrationMode {
  LinearSegments,          ///< cut exactly at every control point crossed, psi table
  PreIntegrated,           ///< 3D (s_front, s_back, length) table
  Sampling,                ///< fixed step, the baseline users know from other tools
  LinearSegmentsIsoTable,  ///< cut points looked up in a 2D (s_front, s_back) table (Espinha 2005, 4.2)
};
/// The one written form of each mode, used by the command line, state files, benches
/// and settings: "linear", "pre-integrated", "sampling", "iso-table".
std::string_view toString(IntegrationMode mode);
/// The mode written `name` (exactly as toString writes it), or nullopt.
std::optional<IntegrationMode> integrationModeFromString(std::string_view name);
/// Every mode, in menu order.
std::vector<IntegrationMode> allIntegrationModes();
/// "linear, iso-table, pre-integrated, sampling": for messages listing the choices.
std::string integrationModeChoices();
/// Words for a menu or a report: "Linear segments, exact cuts", ...
std::string_view describe(IntegrationMode mode);

}  // namespace volpost

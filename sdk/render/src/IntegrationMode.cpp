// SPDX-License-Identifier: MIT
#include <volpost/render/IntegrationMode.hpp>

namespace volpost {

std::string_view toString(IntegrationMode mode) {
  switch (mode) {
    case IntegrationMode::LinearSegments: return "linear";
    case IntegrationMode::PreIntegrated: return "pre-integrated";
    case IntegrationMode::Sampling: return "sampling";
    case IntegrationMode::LinearSegmentsIsoTable: return "iso-table";
  }
  return "?";
}

std::vector<IntegrationMode> allIntegrationModes() {
  return {IntegrationMode::LinearSegments, IntegrationMode::LinearSegmentsIsoTable, IntegrationMode::PreIntegrated,
          IntegrationMode::Sampling};
}

std::optional<IntegrationMode> integrationModeFromString(std::string_view name) {
  for (IntegrationMode mode : allIntegrationModes())
    if (toString(mode) == name) return mode;
  return std::nullopt;
}

std::string integrationModeChoices() {
  std::string out;
  for (IntegrationMode mode : allIntegrationModes()) out += (out.empty() ? "" : ", ") + std::string(toString(mode));
  return out;
}

std::string_view describe(IntegrationMode mode) {
  switch (mode) {
    case IntegrationMode::LinearSegments: return "Linear segments, exact cuts";
    case IntegrationMode::PreIntegrated: return "Pre-integrated (exact opacity, color from a table)";
    case IntegrationMode::Sampling: return "Sampling (fixed step)";
    case IntegrationMode::LinearSegmentsIsoTable: return "Linear segments, a 2D table finds the pieces without cuts";
  }
  return "?";
}

}  // namespace volpost

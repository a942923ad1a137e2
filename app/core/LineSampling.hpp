// SPDX-License-Identifier: MIT
// Plot over line: quantities sampled at evenly spaced points from A to B, each probed as
// the elements interpolate (see Probe.hpp); points outside the mesh give NaN (gaps).
#pragma once

#include "Probe.hpp"

#include <string>
#include <vector>

namespace volpost::app {

struct LineSamples {
  glm::dvec3 from{0.0}, to{0.0};
  std::vector<std::string> keys;             ///< the quantities, written forms
  std::vector<std::string> names;            ///< and their display names
  std::vector<ProbeResult> points;           ///< one per sample, in order from A to B
  std::vector<double> arcLength;             ///< distance from A of each sample
  double value(std::size_t sample, std::size_t key) const;  ///< NaN outside the mesh
};

inline constexpr std::size_t kMaxLineSamples = 100000;

/// `samples` points (2..kMaxLineSamples) from `from` to `to` inclusive. Throws
/// std::invalid_argument for a bad count, equal ends or an unknown quantity.
LineSamples sampleLine(const ModelSession& session, const glm::dvec3& from, const glm::dvec3& to, std::size_t samples,
                       const std::vector<std::string>& keys, std::size_t step, const Progress& progress = {});

/// Comma-separated: arc_length, x, y, z, element, then the quantities, full precision.
std::string lineTable(const LineSamples& samples);

}  // namespace volpost::app

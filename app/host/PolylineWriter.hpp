// SPDX-License-Identifier: MIT
// Polylines (streamlines) out, for ParaView and spreadsheets: VTK XML PolyData (.vtp,
// appended raw binary) with per-point vectors and values and per-line lengths and stop
// reasons, or CSV with one row per point.
#pragma once

#include <glm/vec3.hpp>

#include <string>
#include <vector>

namespace volpost {

struct PolylineSet {
  std::vector<std::vector<glm::dvec3>> points;
  std::vector<std::vector<glm::dvec3>> vectors;  ///< per point (may be empty)
  std::string vectorName = "velocity";
  std::vector<std::vector<double>> values;       ///< per point (may be empty)
  std::string valueName = "value";
  std::vector<double> lengths;                    ///< per line
  std::vector<int> stops;                         ///< per line: a code (StreamlineStop of the forward end)
};

/// Throws std::invalid_argument unless the path names a format writePolylines writes, so a
/// command can refuse it before any work.
void checkPolylineFormat(const std::string& path);

/// By the extension: .vtp or .csv. Throws WriteError naming the file; written through
/// AtomicFile (the previous file stays on failure).
void writePolylines(const PolylineSet& lines, const std::string& path);

}  // namespace volpost

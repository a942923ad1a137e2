// SPDX-License-Identifier: MIT
// Probed points as a table: one row per point, the point, its element and node, and the
// chosen quantities at full precision (shortest text that reads back to the same double).
// `volpost probe --csv`, the window's Probe panel (Copy, Export CSV) and plot-over-line
// write the same columns.
#pragma once

#include "Probe.hpp"

#include <string>
#include <vector>

namespace volpost::app {

/// The written forms ("S.mises", "U.x") of every quantity the probed fields offer, in field order.
std::vector<std::string> allQuantityKeys(const ModelSession& session);

/// A double as the shortest text that reads back to it; "nan", "inf", "-inf" as such.
std::string exactNumber(double value);
/// A double as the screen shows it: displayDigits() significant digits (6 unless set; the
/// window's setting), "nan", "inf", "-inf" as such.
std::string displayNumber(double value);
int displayDigits();
void setDisplayDigits(int digits);  ///< 2 .. 17

/// Comma-separated (or another separator, e.g. a tab for the clipboard), a header line
/// first: x, y, z, element, element_type, node (when the point is one), then `keys`.
/// A point outside the mesh has empty element columns and "nan" values.
std::string probeTable(const std::vector<ProbeResult>& rows, const std::vector<std::string>& keys, char separator = ',');
/// The same table in parts, for tables written as they are probed: its header line, and
/// the lines of some rows.
std::string probeTableHeader(const std::vector<std::string>& keys, char separator = ',');
std::string probeTableRows(const std::vector<ProbeResult>& rows, const std::vector<std::string>& keys,
                           char separator = ',');

}  // namespace volpost::app

// SPDX-License-Identifier: MIT
// Writes a regular grid of samples as a SEG-Y rev 1 post-stack file (EBCDIC text header,
// standard byte positions, CDP coordinates from the grid's plan): for the synthetic-data
// generator, the benches and the reader's round-trip tests.
#pragma once

#include "SegyLayout.hpp"

#include <volpost/core/RegularGrid.hpp>

#include <span>
#include <string>

namespace volpost::seismic {

struct SegyWriteOptions {
  SampleFormat format = SampleFormat::IeeeFloat32;
  ByteOrder order = ByteOrder::Big;
  int coordinateScalar = -100;  ///< CDP x/y stored times 100 (scalar -100)
  int valueUnitCode = 0;        ///< trace bytes 203-204: 0 unknown, 1 Pa, 2 V, ... (SegyLayout.hpp)
  std::string title = "volpost synthetic seismic";
};

/// `values` are the grid's point values (i fastest, k = time slowest); grid.firstLabel and
/// labelStep give the inline/crossline numbers and the first time and sample interval (ms);
/// the plan comes from origin.xy and axes[0..1].xy. Integer formats round and clamp.
/// Throws WriteError naming the file.
void writeSegy(const std::string& path, const RegularGrid& grid, std::span<const double> values,
               const SegyWriteOptions& options = {});

}  // namespace volpost::seismic

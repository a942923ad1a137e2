// SPDX-License-Identifier: MIT
// SEG-Y post-stack volumes in as regular grids: inline (i), crossline (j) and time (k),
// from the trace headers (any trace order; missing traces filled with zero and flagged),
// placed in the world by a least-squares fit of the CDP coordinates (rotated surveys stay
// rotated), time downward with 1 ms (or 1 m of depth) = 1 model unit. Written here rather
// than on Debian's segyio, which aborts the process on some headers: every size and count
// is checked against the file before it is used.
#pragma once

#include "SegyLayout.hpp"

#include <volpost/core/MeshReader.hpp>

#include <optional>

namespace volpost::seismic {

struct SegyOptions {
  TraceFieldPositions positions;
  /// Pre-stack files (several offsets per trace position): the offset to load. Without
  /// one such a file is refused, naming its offsets.
  std::optional<std::int64_t> offset;
};

/// Throws std::invalid_argument when a header field's position lies outside the 240-byte
/// trace header.
void checkPositions(const TraceFieldPositions& positions);

/// Reads the file into a model: a regular grid, its hexahedra and the point field
/// "amplitude". Throws ReadError naming the file and byte, or Cancelled;
/// std::invalid_argument for positions outside the trace header.
std::unique_ptr<Model> readSegy(const std::string& path, const SegyOptions& options, const Progress& progress = {});

class SegyReader : public MeshReader {
 public:
  std::string formatName() const override { return "SEG-Y seismic volume"; }
  std::vector<std::string> extensions() const override { return {"sgy", "segy"}; }
  int sniff(std::string_view head) const override;
  std::unique_ptr<Model> read(const std::string& path, const Progress& progress) const override {
    return readSegy(path, {}, progress);
  }
  /// inline-byte, crossline-byte, cdp-x-byte, cdp-y-byte, scalar-byte, offset-byte (header
  /// positions) and offset (the pre-stack offset to load).
  std::vector<ReaderOption> options() const override;
  std::unique_ptr<Model> readWith(const std::string& path, const ReaderOptions& options,
                                  const Progress& progress) const override;
};

}  // namespace volpost::seismic

// SPDX-License-Identifier: MIT
// Decoding one <DataArray> of a VTK XML file, in any of its encodings.
#pragma once

#include "DiskFile.hpp"
#include "NumericType.hpp"

#include <cstdint>
#include <memory>
#include <string>
#include <functional>
#include <vector>

namespace volpost::meshio {

struct VtuEncoding {
  bool bigEndian = false;
  bool compressed = false;     ///< vtkZLibDataCompressor
  NumericType headerType = NumericType::UInt32;
};

/// Where an array's bytes are and how they are stored; cheap to copy into lazy loaders.
struct VtuArraySource {
  std::string name;
  NumericType type = NumericType::Float64;
  int components = 1;
  enum class Format { Ascii, Binary, Appended } format = Format::Ascii;
  std::shared_ptr<const std::string> file;  ///< the bytes in memory (a small file, or the element's text)
  /// Or, for appended data, the file read where it lies (a large file): `file` is null and
  /// begin / end are offsets in it.
  std::shared_ptr<const DiskFile> disk;
  /// Byte range in `file` (or `disk`): the element's text (ascii, binary), or this array's
  /// own run of the appended block (from the block's start; the array starts at appendedOffset).
  std::size_t begin = 0, end = 0;
  std::size_t appendedOffset = 0;           ///< offset attribute (appended)
  bool appendedBase64 = false;
  std::size_t textLine = 0;                 ///< line of the DataArray element, for messages
};

/// Thrown with a message only; the reader adds the file name and line.
struct VtuArrayError {
  std::string message;
};

/// Number of values (tuples x components) the array holds, read from its header without
/// decompressing (ascii arrays are parsed to count). The values themselves are decoded a
/// chunk (or a zlib block) at a time into the result: no copy of the array's raw bytes.
std::size_t vtuValueCount(const VtuArraySource& src, const VtuEncoding& enc);
std::vector<double> vtuDoubles(const VtuArraySource& src, const VtuEncoding& enc);
/// The same values handed to consume(first, values, count) a run at a time, in order, so
/// that a caller placing them elsewhere (an image's samples in their own type) holds no
/// array of them all as doubles (text arrays are parsed whole first).
void vtuDoubleRuns(const VtuArraySource& src, const VtuEncoding& enc,
                   const std::function<void(std::size_t first, const double* values, std::size_t count)>& consume);
std::vector<std::int64_t> vtuIntegers(const VtuArraySource& src, const VtuEncoding& enc);
/// Thrown by vtuIndices for a value outside [0, limit): its position and the value.
struct VtuIndexError {
  std::size_t position = 0;
  std::int64_t value = 0;
};
/// An integer array of indices in [0, limit), each plus `base`, as 32-bit node indices,
/// decoded without a 64-bit copy (at 100M tets that copy alone is 3.2 GB).
std::vector<std::uint32_t> vtuIndices(const VtuArraySource& src, const VtuEncoding& enc, std::uint64_t limit,
                                      std::uint32_t base);

}  // namespace volpost::meshio

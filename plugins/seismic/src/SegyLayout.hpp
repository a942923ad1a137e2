// SPDX-License-Identifier: MIT
// The fixed parts of a SEG-Y file (SEG-Y rev 0, 1 and 2): the 3200-byte text header, the
// 400-byte binary header, optional extended text headers, then traces of a 240-byte header
// (plus rev 2's extra headers) and their samples. Byte positions below are the standard's
// 1-based ones, as the field's users quote them ("inline at byte 189").
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace volpost::seismic {

enum class ByteOrder { Big, Little };

/// Data sample format codes of the binary header (bytes 3225-3226).
enum class SampleFormat : int {
  IbmFloat32 = 1,
  Int32 = 2,
  Int16 = 3,
  IeeeFloat32 = 5,
  IeeeFloat64 = 6,
  Int8 = 8,
  UInt32 = 10,
  UInt16 = 11,
  UInt8 = 16,
};
/// The format for a code volpost reads, or nullopt.
std::optional<SampleFormat> sampleFormatOf(int code);
std::size_t sampleBytes(SampleFormat format);
/// "IBM float", "16-bit integer", ... for `info`.
std::string describe(SampleFormat format);

/// Reads an integer of `bytes` (1, 2, 4) at a 1-based byte position of a header.
std::int64_t headerInt(const unsigned char* header, int position, int bytes, ByteOrder order, bool isSigned = true);
/// One sample to double.
double decodeSample(const unsigned char* p, SampleFormat format, ByteOrder order);
/// IBM System/360 single precision (base 16 exponent) to double, exactly.
double ibmToDouble(std::uint32_t bits);

/// The text header as text: EBCDIC (the standard's choice) or ASCII, as the bytes say.
std::string textHeaderText(std::string_view bytes);

struct BinaryHeader {
  ByteOrder order = ByteOrder::Big;
  SampleFormat format = SampleFormat::IbmFloat32;
  int formatCode = 0;
  std::size_t samplesPerTrace = 0;
  double sampleIntervalMicroseconds = 0.0;
  int revisionMajor = 0;
  int extendedTextHeaders = 0;     ///< -1: a variable count ended by ((SEG: EndText))
  int extraTraceHeaders = 0;       ///< rev 2: additional 240-byte headers per trace
};

/// Parses the binary header (the 400 bytes after the text header): the byte order from
/// rev 2's constant 16909060 at bytes 3297-3300, else from the format code that makes
/// sense. Returns the reason it is not SEG-Y in `error` otherwise.
std::optional<BinaryHeader> parseBinaryHeader(const unsigned char* header400, std::string& error);

/// Trace value measurement unit (rev 1 and later, trace header bytes 203-204): the unit's
/// symbol for the codes the standard lists (1 Pa, 2 V, 3 mV, 4 A, 5 m, 6 m/s, 7 m/s^2,
/// 8 N, 9 W), empty for 0 (unknown), -1 (other) and any code it does not list.
constexpr int kTraceValueUnitPosition = 203;
std::string traceValueUnits(std::int64_t code);

/// Byte positions (1-based, in the trace header) of the fields the geometry needs. The
/// defaults are the standard's (rev 1): inline 189, crossline 193, CDP x 181, CDP y 185,
/// coordinate scalar 71, offset 37, delay 109.
struct TraceFieldPositions {
  int inlineNumber = 189;
  int crosslineNumber = 193;
  int cdpX = 181;
  int cdpY = 185;
  int coordinateScalar = 71;
  int offset = 37;
  int delayMs = 109;
  int samples = 115;
};

}  // namespace volpost::seismic

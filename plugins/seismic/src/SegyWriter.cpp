// SPDX-License-Identifier: MIT
#include "SegyWriter.hpp"

#include <volpost/core/Error.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <fstream>
#include <vector>

namespace volpost::seismic {
namespace {

void putUnsigned(unsigned char* p, std::uint64_t v, int bytes, ByteOrder order) {
  for (int b = 0; b < bytes; ++b) {
    const int index = order == ByteOrder::Big ? bytes - 1 - b : b;
    p[index] = static_cast<unsigned char>(v >> (8 * b));
  }
}
// At a 1-based byte position, as the standard numbers them.
void put(unsigned char* header, int position, std::int64_t v, int bytes, ByteOrder order) {
  putUnsigned(header + position - 1, std::uint64_t(v), bytes, order);
}

std::uint32_t doubleToIbm(double v) {
  if (v == 0.0 || !std::isfinite(v)) return 0;
  const std::uint32_t sign = v < 0.0 ? 0x80000000u : 0u;
  double m = std::abs(v);
  int exponent = 64;
  while (m >= 1.0 && exponent < 127) { m /= 16.0; ++exponent; }
  while (m < 1.0 / 16.0 && exponent > 0) { m *= 16.0; --exponent; }
  auto fraction = std::uint32_t(std::llround(m * 16777216.0));
  if (fraction >= 0x1000000u) { fraction >>= 4; ++exponent; }
  return sign | (std::uint32_t(exponent) << 24) | fraction;
}

void encodeSample(unsigned char* p, double v, SampleFormat format, ByteOrder order) {
  const auto integer = [v](double lo, double hi) { return std::int64_t(std::clamp(std::round(v), lo, hi)); };
  switch (format) {
    case SampleFormat::IbmFloat32: putUnsigned(p, doubleToIbm(v), 4, order); break;
    case SampleFormat::Int32: putUnsigned(p, std::uint64_t(integer(-2147483648.0, 2147483647.0)), 4, order); break;
    case SampleFormat::Int16: putUnsigned(p, std::uint64_t(integer(-32768.0, 32767.0)), 2, order); break;
    case SampleFormat::Int8: putUnsigned(p, std::uint64_t(integer(-128.0, 127.0)), 1, order); break;
    case SampleFormat::UInt32: putUnsigned(p, std::uint64_t(integer(0.0, 4294967295.0)), 4, order); break;
    case SampleFormat::UInt16: putUnsigned(p, std::uint64_t(integer(0.0, 65535.0)), 2, order); break;
    case SampleFormat::UInt8: putUnsigned(p, std::uint64_t(integer(0.0, 255.0)), 1, order); break;
    case SampleFormat::IeeeFloat32: putUnsigned(p, std::bit_cast<std::uint32_t>(float(v)), 4, order); break;
    case SampleFormat::IeeeFloat64: putUnsigned(p, std::bit_cast<std::uint64_t>(v), 8, order); break;
  }
}

// ASCII to EBCDIC (code page 037) for the characters a text header uses.
unsigned char toEbcdic(char c) {
  if (c >= 'a' && c <= 'i') return static_cast<unsigned char>(0x81 + (c - 'a'));
  if (c >= 'j' && c <= 'r') return static_cast<unsigned char>(0x91 + (c - 'j'));
  if (c >= 's' && c <= 'z') return static_cast<unsigned char>(0xA2 + (c - 's'));
  if (c >= 'A' && c <= 'I') return static_cast<unsigned char>(0xC1 + (c - 'A'));
  if (c >= 'J' && c <= 'R') return static_cast<unsigned char>(0xD1 + (c - 'J'));
  if (c >= 'S' && c <= 'Z') return static_cast<unsigned char>(0xE2 + (c - 'S'));
  if (c >= '0' && c <= '9') return static_cast<unsigned char>(0xF0 + (c - '0'));
  switch (c) {
    case '.': return 0x4B; case '(': return 0x4D; case '+': return 0x4E; case '*': return 0x5C;
    case ')': return 0x5D; case '-': return 0x60; case '/': return 0x61; case ',': return 0x6B;
    case '_': return 0x6D; case ':': return 0x7A; case '=': return 0x7E;
    default: return 0x40;
  }
}

}  // namespace

void writeSegy(const std::string& path, const RegularGrid& grid, std::span<const double> values,
               const SegyWriteOptions& options) {
  if (values.size() != grid.pointCount())
    throw WriteError(path, std::to_string(values.size()) + " values for a grid of " +
                               std::to_string(grid.pointCount()) + " points");
  if (grid.dims[2] > 65535) throw WriteError(path, "more than 65535 samples per trace do not fit SEG-Y rev 1");
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) throw WriteError(path, "cannot create the file");
  const ByteOrder order = options.order;

  std::vector<unsigned char> text(3200, 0x40);
  for (int line = 0; line < 40; ++line) {
    std::string words = "C" + std::to_string(line + 1) + (line < 9 ? "  " : " ");
    if (line == 0) words += options.title;
    if (line == 1)
      words += "INLINES " + std::to_string(grid.dims[0]) + " CROSSLINES " + std::to_string(grid.dims[1]) +
               " SAMPLES " + std::to_string(grid.dims[2]);
    if (line == 39) words += "END TEXTUAL HEADER";
    for (std::size_t c = 0; c < std::min<std::size_t>(words.size(), 80); ++c) text[std::size_t(line) * 80 + c] = toEbcdic(words[c]);
  }
  out.write(reinterpret_cast<const char*>(text.data()), std::streamsize(text.size()));

  std::vector<unsigned char> binary(400, 0);
  unsigned char* b = binary.data() - 3200;  // so positions are the standard's file positions
  const auto dtMicro = std::int64_t(std::llround(grid.labelStep[2] * 1000.0));
  put(b, 3213, 1, 2, order);
  put(b, 3217, dtMicro, 2, order);
  put(b, 3221, std::int64_t(grid.dims[2]), 2, order);
  put(b, 3225, int(options.format), 2, order);
  put(b, 3255, 1, 2, order);  // measurement system: meters
  put(b, 3501, 1, 1, order);  // revision 1.0
  put(b, 3503, 1, 2, order);  // fixed-length traces
  out.write(reinterpret_cast<const char*>(binary.data()), std::streamsize(binary.size()));

  const std::size_t bytesPer = sampleBytes(options.format);
  std::vector<unsigned char> trace(240 + grid.dims[2] * bytesPer);
  const double scale = options.coordinateScalar < 0 ? -double(options.coordinateScalar)
                                                    : 1.0 / std::max(1, options.coordinateScalar);
  std::int64_t sequence = 0;
  for (std::size_t i = 0; i < grid.dims[0]; ++i)
    for (std::size_t j = 0; j < grid.dims[1]; ++j) {
      std::fill(trace.begin(), trace.end(), 0);
      unsigned char* h = trace.data();
      const glm::dvec3 at = grid.position(double(i), double(j), 0.0);
      put(h, 1, ++sequence, 4, order);
      put(h, 9, sequence, 4, order);
      put(h, 21, sequence, 4, order);
      put(h, 71, options.coordinateScalar, 2, order);
      put(h, 109, std::llround(grid.firstLabel[2]), 2, order);
      put(h, 115, std::int64_t(grid.dims[2]), 2, order);
      put(h, 117, dtMicro, 2, order);
      put(h, 181, std::llround(at.x * scale), 4, order);
      put(h, 185, std::llround(at.y * scale), 4, order);
      put(h, 189, std::llround(grid.label(0, double(i))), 4, order);
      put(h, 193, std::llround(grid.label(1, double(j))), 4, order);
      put(h, kTraceValueUnitPosition, options.valueUnitCode, 2, order);
      for (std::size_t k = 0; k < grid.dims[2]; ++k)
        encodeSample(trace.data() + 240 + k * bytesPer, values[grid.pointIndex(i, j, k)], options.format, order);
      out.write(reinterpret_cast<const char*>(trace.data()), std::streamsize(trace.size()));
    }
  out.flush();
  if (!out) throw WriteError(path, "writing failed (disk full?)");
}

}  // namespace volpost::seismic

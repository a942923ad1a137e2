// SPDX-License-Identifier: MIT
#include "SegyLayout.hpp"

#include <array>
#include <bit>
#include <cmath>
#include <cstdio>
#include <cstring>

namespace volpost::seismic {

std::optional<SampleFormat> sampleFormatOf(int code) {
  switch (code) {
    case 1: case 2: case 3: case 5: case 6: case 8: case 10: case 11: case 16: return SampleFormat(code);
    default: return std::nullopt;
  }
}

std::size_t sampleBytes(SampleFormat format) {
  switch (format) {
    case SampleFormat::Int8: case SampleFormat::UInt8: return 1;
    case SampleFormat::Int16: case SampleFormat::UInt16: return 2;
    case SampleFormat::IeeeFloat64: return 8;
    default: return 4;
  }
}

std::string describe(SampleFormat format) {
  switch (format) {
    case SampleFormat::IbmFloat32: return "IBM float (format 1)";
    case SampleFormat::Int32: return "32-bit integer (format 2)";
    case SampleFormat::Int16: return "16-bit integer (format 3)";
    case SampleFormat::IeeeFloat32: return "IEEE float (format 5)";
    case SampleFormat::IeeeFloat64: return "IEEE double (format 6)";
    case SampleFormat::Int8: return "8-bit integer (format 8)";
    case SampleFormat::UInt32: return "unsigned 32-bit integer (format 10)";
    case SampleFormat::UInt16: return "unsigned 16-bit integer (format 11)";
    case SampleFormat::UInt8: return "unsigned 8-bit integer (format 16)";
  }
  return "unknown";
}

namespace {

std::uint64_t unsignedAt(const unsigned char* p, int bytes, ByteOrder order) {
  std::uint64_t v = 0;
  for (int b = 0; b < bytes; ++b) {
    const int index = order == ByteOrder::Big ? b : bytes - 1 - b;
    v = (v << 8) | p[index];
  }
  return v;
}

std::int64_t signExtend(std::uint64_t v, int bytes) {
  const int bits = 8 * bytes;
  if (bits >= 64) return std::int64_t(v);
  const std::uint64_t sign = std::uint64_t(1) << (bits - 1);
  return std::int64_t((v ^ sign) - sign);
}

}  // namespace

std::int64_t headerInt(const unsigned char* header, int position, int bytes, ByteOrder order, bool isSigned) {
  const std::uint64_t v = unsignedAt(header + position - 1, bytes, order);
  return isSigned ? signExtend(v, bytes) : std::int64_t(v);
}

double ibmToDouble(std::uint32_t bits) {
  const std::uint32_t fraction = bits & 0x00ffffffu;
  if (fraction == 0) return 0.0;
  const int exponent = int((bits >> 24) & 0x7f) - 64;
  const double magnitude = std::ldexp(double(fraction), 4 * exponent - 24);
  return (bits & 0x80000000u) ? -magnitude : magnitude;
}

double decodeSample(const unsigned char* p, SampleFormat format, ByteOrder order) {
  switch (format) {
    case SampleFormat::IbmFloat32: return ibmToDouble(std::uint32_t(unsignedAt(p, 4, order)));
    case SampleFormat::Int32: return double(signExtend(unsignedAt(p, 4, order), 4));
    case SampleFormat::Int16: return double(signExtend(unsignedAt(p, 2, order), 2));
    case SampleFormat::Int8: return double(signExtend(p[0], 1));
    case SampleFormat::UInt32: return double(unsignedAt(p, 4, order));
    case SampleFormat::UInt16: return double(unsignedAt(p, 2, order));
    case SampleFormat::UInt8: return double(p[0]);
    case SampleFormat::IeeeFloat32: return double(std::bit_cast<float>(std::uint32_t(unsignedAt(p, 4, order))));
    case SampleFormat::IeeeFloat64: return std::bit_cast<double>(unsignedAt(p, 8, order));
  }
  return 0.0;
}

namespace {

// EBCDIC (code page 037) to ASCII for the characters text headers use; others become '.'.
char ebcdicToAscii(unsigned char c) {
  static const std::array<char, 256> table = [] {
    std::array<char, 256> t{};
    t.fill('.');
    const auto run = [&t](int from, const char* chars) {
      for (int i = 0; chars[i]; ++i) t[std::size_t(from + i)] = chars[i];
    };
    run(0x40, " ");
    run(0x4A, "[.<(+|&");
    run(0x5A, "!$*);^-/");
    run(0x6A, "|,%_>?");
    run(0x79, "`:#@'=\"");
    run(0x81, "abcdefghi");
    run(0x91, "jklmnopqr");
    run(0xA1, "~stuvwxyz");
    run(0xC0, "{ABCDEFGHI");
    run(0xD0, "}JKLMNOPQR");
    run(0xE0, "\\");
    run(0xE2, "STUVWXYZ");
    run(0xF0, "0123456789");
    t[0x25] = '\n';
    return t;
  }();
  return table[c];
}

}  // namespace

std::string textHeaderText(std::string_view bytes) {
  std::size_t printableAscii = 0;
  for (unsigned char c : bytes) printableAscii += (c >= 0x20 && c < 0x7f) || c == '\n' || c == '\r';
  const bool ascii = printableAscii * 10 >= bytes.size() * 9;
  std::string text;
  text.reserve(bytes.size());
  for (unsigned char c : bytes) {
    const char a = ascii ? char(c) : ebcdicToAscii(c);
    text.push_back((a >= 0x20 && a < 0x7f) || a == '\n' ? a : ' ');
  }
  return text;
}

std::optional<BinaryHeader> parseBinaryHeader(const unsigned char* h, std::string& error) {
  // Positions relative to the binary header: file byte 3201 is its byte 1.
  const auto at = [h](int filePosition, int bytes, ByteOrder order, bool isSigned = true) {
    return headerInt(h, filePosition - 3200, bytes, order, isSigned);
  };
  BinaryHeader b;
  const auto formatBig = at(3225, 2, ByteOrder::Big), formatLittle = at(3225, 2, ByteOrder::Little);
  if (at(3297, 4, ByteOrder::Big) == 16909060) b.order = ByteOrder::Big;
  else if (at(3297, 4, ByteOrder::Little) == 16909060) b.order = ByteOrder::Little;
  else if (sampleFormatOf(int(formatBig))) b.order = ByteOrder::Big;
  else if (sampleFormatOf(int(formatLittle))) b.order = ByteOrder::Little;
  else {
    error = "binary header: data sample format code " + std::to_string(formatBig) +
            " (bytes 3225-3226) is not one volpost reads (1 IBM float, 2/3/8 32/16/8-bit integer, 5/6 IEEE "
            "float/double, 10/11/16 unsigned integers)";
    return std::nullopt;
  }
  b.formatCode = int(at(3225, 2, b.order));
  const auto format = sampleFormatOf(b.formatCode);
  if (!format) {
    error = "binary header: data sample format code " + std::to_string(b.formatCode) +
            " (bytes 3225-3226) is not one volpost reads";
    return std::nullopt;
  }
  b.format = *format;
  b.revisionMajor = int(at(3501, 1, b.order, false));
  // The count is unsigned: 60000 samples is a valid count, not -5536.
  b.samplesPerTrace = std::size_t(at(3221, 2, b.order, false));
  if (b.samplesPerTrace == 0 && b.revisionMajor >= 2) b.samplesPerTrace = std::size_t(at(3269, 4, b.order, false));
  b.sampleIntervalMicroseconds = double(at(3217, 2, b.order, false));
  if (b.sampleIntervalMicroseconds == 0.0 && b.revisionMajor >= 2) {
    const double extended = std::bit_cast<double>(std::uint64_t(at(3273, 8, b.order, false)));
    if (std::isfinite(extended) && extended > 0.0) b.sampleIntervalMicroseconds = extended;
  }
  b.extendedTextHeaders = int(at(3505, 2, b.order));
  b.extraTraceHeaders = b.revisionMajor >= 2 ? int(at(3507, 2, b.order, false)) : 0;
  return b;
}

std::string traceValueUnits(std::int64_t code) {
  static constexpr const char* kSymbols[] = {"Pa", "V", "mV", "A", "m", "m/s", "m/s^2", "N", "W"};
  return code >= 1 && code <= 9 ? kSymbols[code - 1] : "";
}

}  // namespace volpost::seismic

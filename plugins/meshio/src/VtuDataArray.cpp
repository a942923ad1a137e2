// SPDX-License-Identifier: MIT
#include "VtuDataArray.hpp"

#include "Base64.hpp"

#include <volpost/core/ResourceLimits.hpp>

#include <zlib.h>

#include <algorithm>
#include <charconv>
#include <cctype>
#include <cmath>
#include <string_view>

namespace volpost::meshio {
namespace {

[[noreturn]] void fail(const VtuArraySource& src, const std::string& message) {
  throw VtuArrayError{"DataArray \"" + src.name + "\": " + message};
}

std::uint64_t headerValue(const std::uint8_t* p, const VtuEncoding& enc) {
  return std::uint64_t(toIntegers(p, 1, enc.headerType, enc.bigEndian)[0]);
}

// The bytes the array's binary data starts with: its header, then (compressed) blocks.
struct BinaryView {
  std::vector<std::uint8_t> decoded;  // owned bytes when base64 was decoded
  const std::uint8_t* data = nullptr;
  std::size_t size = 0;
};

BinaryView binaryBytes(const VtuArraySource& src) {
  BinaryView view;
  const std::string& f = *src.file;
  if (src.format == VtuArraySource::Format::Appended) {
    if (src.appendedOffset >= src.end - src.begin)
      fail(src, "offset " + std::to_string(src.appendedOffset) + " is beyond the appended data (" +
                    std::to_string(src.end - src.begin) + " bytes; the file is truncated?)");
    const std::size_t at = src.begin + src.appendedOffset;
    if (!src.appendedBase64) {
      view.data = reinterpret_cast<const std::uint8_t*>(f.data() + at);
      view.size = src.end - at;
      return view;
    }
    auto d = decodeBase64(std::string_view(f.data() + at, src.end - at));
    if (!d) fail(src, "invalid base64 in the appended data");
    view.decoded = std::move(*d);
  } else {
    std::size_t err = 0;
    auto d = decodeBase64(std::string_view(f.data() + src.begin, src.end - src.begin), &err);
    if (!d) fail(src, "invalid base64 data (character " + std::to_string(err) + ")");
    view.decoded = std::move(*d);
  }
  view.data = view.decoded.data();
  view.size = view.decoded.size();
  return view;
}

struct BlockLayout {
  std::uint64_t blocks = 0, blockSize = 0, lastSize = 0;
  std::size_t headerBytes = 0;
  std::uint64_t rawBytes = 0;
};

BlockLayout blockLayout(const VtuArraySource& src, const VtuEncoding& enc, const BinaryView& v) {
  const std::size_t h = sizeOf(enc.headerType);
  BlockLayout b;
  if (!enc.compressed) {
    if (v.size < h) fail(src, "data ends inside its header (truncated)");
    b.headerBytes = h;
    b.rawBytes = headerValue(v.data, enc);
    return b;
  }
  if (v.size < 3 * h) fail(src, "data ends inside its compression header (truncated)");
  b.blocks = headerValue(v.data, enc);
  b.blockSize = headerValue(v.data + h, enc);
  b.lastSize = headerValue(v.data + 2 * h, enc);
  if (b.blocks > (v.size / h)) fail(src, "compression header claims " + std::to_string(b.blocks) + " blocks (corrupt or truncated)");
  b.headerBytes = (3 + b.blocks) * h;
  if (v.size < b.headerBytes) fail(src, "data ends inside its compression header (truncated)");
  // (blocks - 1) * blockSize + last, in arithmetic that cannot wrap: a hostile header
  // could otherwise claim 2^63-byte blocks whose total wraps to a few bytes.
  std::uint64_t full = 0, total = 0;
  if (b.blocks > 0 && (__builtin_mul_overflow(b.blocks - 1, b.blockSize, &full) ||
                       __builtin_add_overflow(full, b.lastSize ? b.lastSize : b.blockSize, &total)))
    fail(src, "compression header claims " + std::to_string(b.blocks) + " blocks of " + std::to_string(b.blockSize) +
                  " bytes, more than 64 bits can count (corrupt)");
  b.rawBytes = total;
  return b;
}

std::vector<std::uint8_t> rawBytes(const VtuArraySource& src, const VtuEncoding& enc) {
  const BinaryView v = binaryBytes(src);
  const BlockLayout b = blockLayout(src, enc, v);
  if (!enc.compressed) {
    if (v.size - b.headerBytes < b.rawBytes)
      fail(src, "data is cut short: header says " + std::to_string(b.rawBytes) + " bytes, " +
                    std::to_string(v.size - b.headerBytes) + " are there (truncated)");
    return {v.data + b.headerBytes, v.data + b.headerBytes + b.rawBytes};
  }
  // Check the header against the data before allocating what it claims: every block must
  // lie in the data, and zlib cannot expand more than about 1032:1.
  const std::size_t h = sizeOf(enc.headerType);
  std::uint64_t compressedTotal = 0;
  for (std::uint64_t k = 0; k < b.blocks; ++k) {
    const std::uint64_t csize = headerValue(v.data + (3 + k) * h, enc);
    if (csize > v.size - b.headerBytes - compressedTotal)
      fail(src, "compressed block " + std::to_string(k) + " runs past the end of the data (truncated)");
    compressedTotal += csize;
  }
  if (b.lastSize > b.blockSize || b.rawBytes > 1032 * compressedTotal + 64)
    fail(src, "compression header claims " + std::to_string(b.rawBytes) + " bytes from " + std::to_string(compressedTotal) +
                  " compressed bytes (corrupt)");
  if (double(b.rawBytes) > double(memoryBudget()))
    fail(src, "decompresses to " + byteSizeText(double(b.rawBytes)) + ", more than the memory budget of " +
                  byteSizeText(double(memoryBudget())) + " (--memory-budget or VOLPOST_MEMORY_BUDGET)");
  std::vector<std::uint8_t> out(b.rawBytes);
  std::size_t in = b.headerBytes, done = 0;
  for (std::uint64_t k = 0; k < b.blocks; ++k) {
    const std::uint64_t csize = headerValue(v.data + (3 + k) * h, enc);
    const std::uint64_t usize = (k + 1 == b.blocks && b.lastSize) ? b.lastSize : b.blockSize;
    if (csize > v.size - in) fail(src, "compressed block " + std::to_string(k) + " runs past the end of the data (truncated)");
    if (usize > out.size() - done) fail(src, "zlib block " + std::to_string(k) + " is larger than the header's total (corrupt)");
    uLongf destLen = uLongf(usize);
    const int rc = uncompress(out.data() + done, &destLen, v.data + in, uLong(csize));
    if (rc != Z_OK || destLen != usize)
      fail(src, "zlib block " + std::to_string(k) + " does not decompress (" + (rc == Z_OK ? "wrong size" : zError(rc)) + ")");
    in += csize;
    done += usize;
  }
  return out;
}

std::vector<double> asciiValues(const VtuArraySource& src) {
  const std::string& f = *src.file;
  std::vector<double> out;
  std::size_t i = src.begin;
  while (i < src.end) {
    while (i < src.end && std::isspace(static_cast<unsigned char>(f[i]))) ++i;
    if (i >= src.end) break;
    std::size_t j = i;
    while (j < src.end && !std::isspace(static_cast<unsigned char>(f[j]))) ++j;
    double v = 0.0;
    const auto r = std::from_chars(f.data() + i, f.data() + j, v);
    if (r.ec == std::errc::result_out_of_range) v = f[i] == '-' ? -HUGE_VAL : HUGE_VAL;
    else if (r.ec != std::errc() || r.ptr != f.data() + j)
      fail(src, "value " + std::to_string(out.size() + 1) + " is '" + f.substr(i, std::min<std::size_t>(j - i, 40)) + "', not a number");
    out.push_back(v);
    i = j;
  }
  return out;
}

}  // namespace

std::size_t vtuValueCount(const VtuArraySource& src, const VtuEncoding& enc) {
  if (src.format == VtuArraySource::Format::Ascii) return asciiValues(src).size();
  const BinaryView v = binaryBytes(src);
  const BlockLayout b = blockLayout(src, enc, v);
  if (b.rawBytes % sizeOf(src.type)) fail(src, "byte count " + std::to_string(b.rawBytes) + " is not a whole number of values");
  return std::size_t(b.rawBytes / sizeOf(src.type));
}

namespace {

// Raw appended data that is not compressed is decoded where it lies in the file: no copy
// of its bytes (at 100M tets, 3.2 GB of Int64 connectivity).
template <typename Decode>
auto decodeBinary(const VtuArraySource& src, const VtuEncoding& enc, Decode decode) {
  if (!enc.compressed && src.format == VtuArraySource::Format::Appended && !src.appendedBase64) {
    const BinaryView v = binaryBytes(src);
    const BlockLayout b = blockLayout(src, enc, v);
    if (v.size - b.headerBytes < b.rawBytes)
      fail(src, "data is cut short: header says " + std::to_string(b.rawBytes) + " bytes, " +
                    std::to_string(v.size - b.headerBytes) + " are there (truncated)");
    return decode(v.data + b.headerBytes, std::size_t(b.rawBytes / sizeOf(src.type)));
  }
  const auto raw = rawBytes(src, enc);
  return decode(raw.data(), raw.size() / sizeOf(src.type));
}

}  // namespace

std::vector<std::uint32_t> vtuIndices(const VtuArraySource& src, const VtuEncoding& enc, std::uint64_t limit,
                                      std::uint32_t base) {
  const auto convert = [&](const std::int64_t* values, std::size_t count, std::size_t at, std::uint32_t* out) {
    for (std::size_t k = 0; k < count; ++k) {
      if (values[k] < 0 || std::uint64_t(values[k]) >= limit) throw VtuIndexError{at + k, values[k]};
      out[k] = std::uint32_t(std::uint64_t(values[k]) + base);
    }
  };
  if (src.format == VtuArraySource::Format::Ascii) {
    const std::vector<std::int64_t> values = vtuIntegers(src, enc);
    std::vector<std::uint32_t> out(values.size());
    convert(values.data(), values.size(), 0, out.data());
    return out;
  }
  if (isFloating(src.type)) fail(src, "must hold integers, its type is floating point");
  return decodeBinary(src, enc, [&](const std::uint8_t* data, std::size_t count) {
    std::vector<std::uint32_t> out(count);
    constexpr std::size_t kChunk = 1 << 16;  // 64-bit values a chunk at a time
    for (std::size_t at = 0; at < count; at += kChunk) {
      const std::size_t n = std::min(kChunk, count - at);
      const std::vector<std::int64_t> chunk = toIntegers(data + at * sizeOf(src.type), n, src.type, enc.bigEndian);
      convert(chunk.data(), n, at, out.data() + at);
    }
    return out;
  });
}

VtuArraySource vtuDetached(const VtuArraySource& src, const VtuEncoding& enc) {
  VtuArraySource out = src;
  std::size_t begin = src.begin, length = src.end - src.begin;
  if (src.format == VtuArraySource::Format::Appended && !src.appendedBase64) {
    const BinaryView v = binaryBytes(src);
    const BlockLayout b = blockLayout(src, enc, v);
    std::uint64_t payload = b.rawBytes;
    if (enc.compressed) {
      payload = 0;
      for (std::uint64_t k = 0; k < b.blocks; ++k) payload += headerValue(v.data + (3 + k) * sizeOf(enc.headerType), enc);
    }
    begin = src.begin + src.appendedOffset;
    length = std::size_t(std::min<std::uint64_t>(b.headerBytes + payload, v.size));
    out.appendedOffset = 0;
  } else if (src.format == VtuArraySource::Format::Appended) {  // base64: its own run already
    begin = src.begin + src.appendedOffset;
    length = src.end - begin;
    out.appendedOffset = 0;
  }
  out.file = std::make_shared<const std::string>(*src.file, begin, length);
  out.begin = 0;
  out.end = length;
  return out;
}

std::vector<double> vtuDoubles(const VtuArraySource& src, const VtuEncoding& enc) {
  if (src.format == VtuArraySource::Format::Ascii) return asciiValues(src);
  return decodeBinary(src, enc, [&](const std::uint8_t* data, std::size_t count) {
    return toDoubles(data, count, src.type, enc.bigEndian);
  });
}

std::vector<std::int64_t> vtuIntegers(const VtuArraySource& src, const VtuEncoding& enc) {
  if (isFloating(src.type)) fail(src, "must hold integers, its type is floating point");
  if (src.format == VtuArraySource::Format::Ascii) {
    const auto d = asciiValues(src);
    std::vector<std::int64_t> out(d.size());
    for (std::size_t i = 0; i < d.size(); ++i) {
      if (d[i] != std::floor(d[i]) || !std::isfinite(d[i])) fail(src, "value " + std::to_string(i + 1) + " is not an integer");
      if (std::abs(d[i]) > 9.0e18) fail(src, "value " + std::to_string(i + 1) + " is too large for an index or count");
      out[i] = std::int64_t(d[i]);
    }
    return out;
  }
  return decodeBinary(src, enc, [&](const std::uint8_t* data, std::size_t count) {
    return toIntegers(data, count, src.type, enc.bigEndian);
  });
}

}  // namespace volpost::meshio

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

// The binary bytes of one array (its header, then its values or compressed blocks) where
// they lie: in memory (decoded first when they are base64) or in the file, read a piece at
// a time, so that decoding never holds more than a chunk of them besides the result.
class BinaryRun {
 public:
  explicit BinaryRun(const VtuArraySource& src) {
    if (src.format == VtuArraySource::Format::Appended) {
      if (src.appendedOffset >= src.end - src.begin)
        fail(src, "offset " + std::to_string(src.appendedOffset) + " is beyond the appended data (" +
                      std::to_string(src.end - src.begin) + " bytes; the file is truncated?)");
      const std::size_t at = src.begin + src.appendedOffset;
      size_ = src.end - at;
      if (!src.appendedBase64) {
        if (src.disk) {
          disk_ = src.disk.get();
          fileAt_ = at;
        } else {
          memory_ = reinterpret_cast<const std::uint8_t*>(src.file->data() + at);
        }
        return;
      }
      if (src.disk && 1.75 * double(size_) > double(memoryBudget()))  // the text and its decoded bytes
        fail(src, "its " + byteSizeText(double(size_)) + " of base64 text need more than the memory budget of " +
                      byteSizeText(double(memoryBudget())) + " to decode (--memory-budget or VOLPOST_MEMORY_BUDGET)");
      const std::string text = src.disk ? src.disk->readString(at, size_) : std::string(src.file->data() + at, size_);
      auto d = decodeBase64(text);
      if (!d) fail(src, "invalid base64 in the appended data");
      owned_ = std::move(*d);
    } else {
      std::size_t err = 0;
      auto d = decodeBase64(std::string_view(src.file->data() + src.begin, src.end - src.begin), &err);
      if (!d) fail(src, "invalid base64 data (character " + std::to_string(err) + ")");
      owned_ = std::move(*d);
    }
    memory_ = owned_.data();
    size_ = owned_.size();
  }
  BinaryRun(const BinaryRun&) = delete;
  BinaryRun& operator=(const BinaryRun&) = delete;

  std::size_t size() const { return size_; }
  /// `n` bytes from `at` (at + n <= size()): where they are in memory, or read into `scratch`.
  const std::uint8_t* bytes(std::size_t at, std::size_t n, std::vector<std::uint8_t>& scratch) const {
    if (memory_) return memory_ + at;
    scratch.resize(n);
    disk_->read(fileAt_ + at, n, scratch.data());
    return scratch.data();
  }
  /// The `index`-th value of the array's header.
  std::uint64_t header(std::size_t index, const VtuEncoding& enc) const {
    std::vector<std::uint8_t> scratch;
    return headerValue(bytes(index * sizeOf(enc.headerType), sizeOf(enc.headerType), scratch), enc);
  }

 private:
  std::vector<std::uint8_t> owned_;  // base64, decoded
  const std::uint8_t* memory_ = nullptr;
  const DiskFile* disk_ = nullptr;
  std::uint64_t fileAt_ = 0;
  std::size_t size_ = 0;
};

struct BlockLayout {
  std::uint64_t blocks = 0, blockSize = 0, lastSize = 0;
  std::size_t headerBytes = 0;
  std::uint64_t rawBytes = 0;
};

BlockLayout blockLayout(const VtuArraySource& src, const VtuEncoding& enc, const BinaryRun& run) {
  const std::size_t h = sizeOf(enc.headerType);
  BlockLayout b;
  if (!enc.compressed) {
    if (run.size() < h) fail(src, "data ends inside its header (truncated)");
    b.headerBytes = h;
    b.rawBytes = run.header(0, enc);
    return b;
  }
  if (run.size() < 3 * h) fail(src, "data ends inside its compression header (truncated)");
  b.blocks = run.header(0, enc);
  b.blockSize = run.header(1, enc);
  b.lastSize = run.header(2, enc);
  if (b.blocks > (run.size() / h)) fail(src, "compression header claims " + std::to_string(b.blocks) + " blocks (corrupt or truncated)");
  b.headerBytes = (3 + b.blocks) * h;
  if (run.size() < b.headerBytes) fail(src, "data ends inside its compression header (truncated)");
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

// The compressed size of every block, checked against the data before anything is
// allocated for what the header claims: every block must lie in the data, and zlib cannot
// expand more than about 1032:1.
std::vector<std::uint64_t> compressedSizes(const VtuArraySource& src, const VtuEncoding& enc, const BinaryRun& run,
                                           const BlockLayout& b) {
  const std::size_t h = sizeOf(enc.headerType);
  if (double(b.blocks) * double(h + 8) > double(memoryBudget()))  // its table, read from the file, and the sizes
    fail(src, "compression header claims " + std::to_string(b.blocks) + " blocks, more than the memory budget of " +
                  byteSizeText(double(memoryBudget())) + " can list (corrupt)");
  std::vector<std::uint8_t> scratch;
  const std::uint8_t* table = run.bytes(3 * h, std::size_t(b.blocks) * h, scratch);
  std::vector<std::uint64_t> sizes(std::size_t(b.blocks));
  std::uint64_t compressedTotal = 0;
  for (std::size_t k = 0; k < sizes.size(); ++k) {
    sizes[k] = headerValue(table + k * h, enc);
    if (sizes[k] > run.size() - b.headerBytes - compressedTotal)
      fail(src, "compressed block " + std::to_string(k) + " runs past the end of the data (truncated)");
    compressedTotal += sizes[k];
  }
  if (b.lastSize > b.blockSize || b.rawBytes > 1032 * compressedTotal + 64)
    fail(src, "compression header claims " + std::to_string(b.rawBytes) + " bytes from " + std::to_string(compressedTotal) +
                  " compressed bytes (corrupt)");
  if (double(b.rawBytes) > double(memoryBudget()))
    fail(src, "decompresses to " + byteSizeText(double(b.rawBytes)) + ", more than the memory budget of " +
                  byteSizeText(double(memoryBudget())) + " (--memory-budget or VOLPOST_MEMORY_BUDGET)");
  return sizes;
}

// Hands the array's values to consume(bytes, count, first) a run of whole values at a
// time, in order: chunks of the raw data, or each zlib block as it is decompressed (a
// value split between two blocks is carried over).
template <typename Consume>
void forEachValueRun(const VtuArraySource& src, const VtuEncoding& enc, const BinaryRun& run, const BlockLayout& b,
                     Consume consume) {
  const std::size_t valueSize = sizeOf(src.type);
  std::vector<std::uint8_t> scratch;
  if (!enc.compressed) {  // decodeBinary checked that the header's bytes are there
    const std::size_t count = std::size_t(b.rawBytes / valueSize);
    const std::size_t perChunk = std::size_t(1) << 19;  // values: a few MB of raw bytes and of their conversion
    for (std::size_t first = 0; first < count; first += perChunk) {
      const std::size_t n = std::min(perChunk, count - first);
      consume(run.bytes(b.headerBytes + first * valueSize, n * valueSize, scratch), n, first);
    }
    return;
  }
  const std::vector<std::uint64_t> sizes = compressedSizes(src, enc, run, b);
  std::vector<std::uint8_t> pending;  // decompressed bytes not yet handed over (less than a value)
  std::size_t in = b.headerBytes, first = 0;
  std::uint64_t done = 0;
  for (std::size_t k = 0; k < sizes.size(); ++k) {
    const std::uint64_t usize = (k + 1 == sizes.size() && b.lastSize) ? b.lastSize : b.blockSize;
    if (usize > b.rawBytes - done) fail(src, "zlib block " + std::to_string(k) + " is larger than the header's total (corrupt)");
    const std::uint8_t* compressed = run.bytes(in, std::size_t(sizes[k]), scratch);
    const std::size_t carried = pending.size();
    pending.resize(carried + std::size_t(usize));
    uLongf destLen = uLongf(usize);
    const int rc = uncompress(pending.data() + carried, &destLen, compressed, uLong(sizes[k]));
    if (rc != Z_OK || destLen != usize)
      fail(src, "zlib block " + std::to_string(k) + " does not decompress (" + (rc == Z_OK ? "wrong size" : zError(rc)) + ")");
    in += std::size_t(sizes[k]);
    done += usize;
    const std::size_t whole = pending.size() / valueSize;
    if (whole > 0) consume(pending.data(), whole, first);
    first += whole;
    pending.erase(pending.begin(), pending.begin() + std::ptrdiff_t(whole * valueSize));
  }
}

// A binary array's values a run at a time: sized(total) with the header's count first, then
// consume(bytes, count, first) for each run, never past that count. Data cut short fails.
template <typename Sized, typename Consume>
void forEachCheckedRun(const VtuArraySource& src, const VtuEncoding& enc, Sized sized, Consume consume) {
  const BinaryRun run(src);
  const BlockLayout b = blockLayout(src, enc, run);
  if (!enc.compressed && run.size() - b.headerBytes < b.rawBytes)
    fail(src, "data is cut short: header says " + std::to_string(b.rawBytes) + " bytes, " +
                  std::to_string(run.size() - b.headerBytes) + " are there (truncated)");
  const std::size_t total = std::size_t(b.rawBytes / sizeOf(src.type));
  sized(total);
  forEachValueRun(src, enc, run, b, [&](const std::uint8_t* bytes, std::size_t count, std::size_t first) {
    const std::size_t n = std::min(count, total - std::min(first, total));
    if (n > 0) consume(bytes, n, first);
  });
}

// The array's values converted by convert(bytes, count, first, out) into a vector of its count.
template <typename Out, typename Convert>
std::vector<Out> decodeBinary(const VtuArraySource& src, const VtuEncoding& enc, Convert convert) {
  std::vector<Out> out;
  forEachCheckedRun(
      src, enc, [&out](std::size_t total) { out.resize(total); },
      [&](const std::uint8_t* bytes, std::size_t count, std::size_t first) { convert(bytes, count, first, out.data() + first); });
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
  const BinaryRun run(src);
  const BlockLayout b = blockLayout(src, enc, run);
  if (b.rawBytes % sizeOf(src.type)) fail(src, "byte count " + std::to_string(b.rawBytes) + " is not a whole number of values");
  return std::size_t(b.rawBytes / sizeOf(src.type));
}

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
  return decodeBinary<std::uint32_t>(src, enc, [&](const std::uint8_t* bytes, std::size_t count, std::size_t first,
                                                   std::uint32_t* out) {
    convert(toIntegers(bytes, count, src.type, enc.bigEndian).data(), count, first, out);
  });
}

std::vector<double> vtuDoubles(const VtuArraySource& src, const VtuEncoding& enc) {
  if (src.format == VtuArraySource::Format::Ascii) return asciiValues(src);
  return decodeBinary<double>(src, enc, [&](const std::uint8_t* bytes, std::size_t count, std::size_t, double* out) {
    const std::vector<double> values = toDoubles(bytes, count, src.type, enc.bigEndian);
    std::copy(values.begin(), values.end(), out);
  });
}

void vtuDoubleRuns(const VtuArraySource& src, const VtuEncoding& enc,
                   const std::function<void(std::size_t first, const double* values, std::size_t count)>& consume) {
  if (src.format == VtuArraySource::Format::Ascii) {
    const std::vector<double> values = asciiValues(src);
    consume(0, values.data(), values.size());
    return;
  }
  forEachCheckedRun(
      src, enc, [](std::size_t) {},
      [&](const std::uint8_t* bytes, std::size_t count, std::size_t first) {
        const std::vector<double> values = toDoubles(bytes, count, src.type, enc.bigEndian);
        consume(first, values.data(), count);
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
  return decodeBinary<std::int64_t>(src, enc, [&](const std::uint8_t* bytes, std::size_t count, std::size_t,
                                                  std::int64_t* out) {
    const std::vector<std::int64_t> values = toIntegers(bytes, count, src.type, enc.bigEndian);
    std::copy(values.begin(), values.end(), out);
  });
}

}  // namespace volpost::meshio

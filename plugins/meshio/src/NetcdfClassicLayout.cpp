// SPDX-License-Identifier: MIT
#include "NetcdfClassicLayout.hpp"

#include <volpost/core/Error.hpp>

#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>
#include <vector>

namespace volpost::meshio {
namespace {

constexpr std::uint32_t kDimension = 0x0A, kVariable = 0x0B, kAttribute = 0x0C;

// Big-endian fields of the header, each read with a bounds check.
class HeaderCursor {
 public:
  HeaderCursor(const std::string& bytes, const std::string& path, int version)
      : b_(bytes), path_(path), version_(version) {}

  [[noreturn]] void fail(const std::string& what) const {
    throw ReadError(path_, "cannot read as netCDF/Exodus: its header is damaged or truncated (" + what + " at byte " +
                               std::to_string(pos_) + ")");
  }
  std::uint64_t unsignedOf(int bytes) {
    if (b_.size() - pos_ < std::size_t(bytes)) fail("ends early");
    std::uint64_t v = 0;
    for (int i = 0; i < bytes; ++i) v = (v << 8) | static_cast<unsigned char>(b_[pos_ + std::size_t(i)]);
    pos_ += std::size_t(bytes);
    return v;
  }
  std::uint32_t u32() { return std::uint32_t(unsignedOf(4)); }
  /// NON_NEG: 8 bytes in CDF-5, else 4.
  std::uint64_t count() { return unsignedOf(version_ == 5 ? 8 : 4); }
  /// OFFSET: 4 bytes in CDF-1, else 8.
  std::uint64_t offset() { return unsignedOf(version_ == 1 ? 4 : 8); }
  void skip(std::uint64_t n) {
    if (n > b_.size() - pos_) fail("an entry runs past the end of the file");
    pos_ += std::size_t(n);
  }
  std::string name() {
    const std::uint64_t n = count();
    if (n > 65536) fail("a name of " + std::to_string(n) + " bytes");
    if (n > b_.size() - pos_) fail("a name runs past the end of the file");
    std::string s(b_.data() + pos_, std::size_t(n));
    skip((n + 3) / 4 * 4);
    return s;
  }
  /// An attribute list: skipped (values padded to 4 bytes).
  void attributes() {
    const std::uint32_t tag = u32();
    const std::uint64_t n = count();
    if (tag == 0 && n == 0) return;
    if (tag != kAttribute) fail("expected an attribute list");
    for (std::uint64_t i = 0; i < n; ++i) {
      name();
      const std::uint32_t type = u32();
      const std::uint64_t values = count();
      const std::uint64_t size = typeSize(type);
      if (values > (b_.size() - pos_) / size) fail("attribute values run past the end of the file");
      skip((values * size + 3) / 4 * 4);
    }
  }
  std::uint64_t typeSize(std::uint32_t type) const {
    switch (type) {
      case 1: case 2: case 7: return 1;    // byte, char, ubyte
      case 3: case 8: return 2;            // short, ushort
      case 4: case 5: case 9: return 4;    // int, float, uint
      case 6: case 10: case 11: return 8;  // double, int64, uint64
      default: break;
    }
    const_cast<HeaderCursor*>(this)->fail("unknown data type " + std::to_string(type));
  }

 private:
  const std::string& b_;
  const std::string& path_;
  std::size_t pos_ = 4;
  int version_;
};

std::uint64_t product(std::uint64_t a, std::uint64_t b, HeaderCursor& c, const std::string& variable) {
  std::uint64_t r = 0;
  if (__builtin_mul_overflow(a, b, &r)) c.fail("variable " + variable + " is larger than 64 bits can count");
  return r;
}

}  // namespace

void checkClassicNetcdfExtent(const std::string& path) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) return;  // nc_open reports it
  const std::uint64_t fileSize = std::uint64_t(in.tellg());
  // The header is at most a few MB for any real file; read up to 64 MB of it.
  const std::size_t headerBytes = std::size_t(std::min<std::uint64_t>(fileSize, 64u << 20));
  std::string head(headerBytes, '\0');
  in.seekg(0);
  in.read(head.data(), std::streamsize(headerBytes));
  if (head.size() < 4 || head.compare(0, 3, "CDF") != 0) return;  // netCDF-4/HDF5: checked by HDF5
  const int version = head[3];
  if (version != 1 && version != 2 && version != 5) return;
  HeaderCursor c(head, path, version);
  const std::uint64_t numrecs = c.count();
  const bool streaming = version == 5 ? numrecs == std::numeric_limits<std::uint64_t>::max() : numrecs == 0xFFFFFFFFull;

  std::vector<std::uint64_t> dims;
  std::size_t recordDim = std::size_t(-1);
  {
    const std::uint32_t tag = c.u32();
    const std::uint64_t n = c.count();
    if (!(tag == 0 && n == 0)) {
      if (tag != kDimension) c.fail("expected the dimension list");
      if (n > head.size() / 8) c.fail(std::to_string(n) + " dimensions");
      for (std::uint64_t i = 0; i < n; ++i) {
        c.name();
        dims.push_back(c.count());
        if (dims.back() == 0) recordDim = dims.size() - 1;
      }
    }
  }
  c.attributes();

  struct Variable {
    std::string name;
    bool record;
    std::uint64_t size;  // bytes per record (record variables) or in all
    std::uint64_t begin;
  };
  std::vector<Variable> variables;
  const std::uint32_t tag = c.u32();
  const std::uint64_t n = c.count();
  if (!(tag == 0 && n == 0)) {
    if (tag != kVariable) c.fail("expected the variable list");
    if (n > head.size() / 8) c.fail(std::to_string(n) + " variables");
    for (std::uint64_t i = 0; i < n; ++i) {
      Variable v;
      v.name = c.name();
      const std::uint64_t rank = c.count();
      if (rank > 1024) c.fail("variable " + v.name + " has " + std::to_string(rank) + " dimensions");
      std::uint64_t elements = 1;
      v.record = false;
      for (std::uint64_t k = 0; k < rank; ++k) {
        const std::uint64_t id = c.count();
        if (id >= dims.size()) c.fail("variable " + v.name + " uses dimension " + std::to_string(id) + ", which is not defined");
        if (k == 0 && id == recordDim) {
          v.record = true;
          continue;
        }
        elements = product(elements, dims[id], c, v.name);
      }
      c.attributes();
      const std::uint32_t type = c.u32();
      c.count();  // vsize as written: capped for large variables, so computed below instead
      v.begin = c.offset();
      const std::uint64_t bytes = product(elements, c.typeSize(type), c, v.name);
      v.size = bytes > std::numeric_limits<std::uint64_t>::max() - 3 ? bytes : (bytes + 3) / 4 * 4;
      variables.push_back(v);
    }
  }
  std::uint64_t recordSize = 0;
  for (const Variable& v : variables)
    if (v.record) recordSize += v.size;
  for (const Variable& v : variables) {
    std::uint64_t end = 0;
    if (!v.record) {
      if (__builtin_add_overflow(v.begin, v.size, &end)) end = std::numeric_limits<std::uint64_t>::max();
    } else {
      if (streaming || numrecs == 0) continue;
      std::uint64_t before = 0;
      if (__builtin_mul_overflow(numrecs - 1, recordSize, &before) || __builtin_add_overflow(before, v.begin, &end) ||
          __builtin_add_overflow(end, v.size, &end))
        end = std::numeric_limits<std::uint64_t>::max();
    }
    // The last variable's padding may be missing at the very end of a file.
    if (end > fileSize + 3)
      throw ReadError(path, "variable " + v.name + (v.record ? " (" + std::to_string(numrecs) + " records)" : std::string()) +
                                " needs the file to be at least " + std::to_string(end) + " bytes, but it has " +
                                std::to_string(fileSize) + ": the file is truncated or its header is damaged");
  }
}

}  // namespace volpost::meshio

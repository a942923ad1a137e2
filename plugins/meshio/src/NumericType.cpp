// SPDX-License-Identifier: MIT
#include "NumericType.hpp"

#include <algorithm>
#include <bit>
#include <cstring>

namespace volpost::meshio {
namespace {

template <typename T>
T load(const std::uint8_t* p, bool bigEndian) {
  std::uint8_t b[sizeof(T)];
  std::memcpy(b, p, sizeof(T));
  if (bigEndian != (std::endian::native == std::endian::big)) std::reverse(b, b + sizeof(T));
  T v;
  std::memcpy(&v, b, sizeof(T));
  return v;
}

template <typename Out>
std::vector<Out> convert(const std::uint8_t* bytes, std::size_t count, NumericType type, bool be) {
  std::vector<Out> out(count);
  const std::size_t s = sizeOf(type);
  for (std::size_t i = 0; i < count; ++i) {
    const std::uint8_t* p = bytes + i * s;
    switch (type) {
      case NumericType::Int8: out[i] = Out(load<std::int8_t>(p, be)); break;
      case NumericType::UInt8: out[i] = Out(load<std::uint8_t>(p, be)); break;
      case NumericType::Int16: out[i] = Out(load<std::int16_t>(p, be)); break;
      case NumericType::UInt16: out[i] = Out(load<std::uint16_t>(p, be)); break;
      case NumericType::Int32: out[i] = Out(load<std::int32_t>(p, be)); break;
      case NumericType::UInt32: out[i] = Out(load<std::uint32_t>(p, be)); break;
      case NumericType::Int64: out[i] = Out(load<std::int64_t>(p, be)); break;
      case NumericType::UInt64: out[i] = Out(load<std::uint64_t>(p, be)); break;
      case NumericType::Float32: out[i] = Out(load<float>(p, be)); break;
      case NumericType::Float64: out[i] = Out(load<double>(p, be)); break;
    }
  }
  return out;
}

// Stored as T in the file, kept as Kept (64-bit integers as doubles, as every reader takes them).
template <typename T, typename Kept = T>
SampleArray loadAll(const std::uint8_t* bytes, std::size_t count, NumericType stored, bool be, SampleType kept) {
  SampleArray out(kept, count);
  auto values = out.as<Kept>();
  const std::size_t s = sizeOf(stored);
  for (std::size_t i = 0; i < count; ++i) values[i] = Kept(load<T>(bytes + i * s, be));
  return out;
}

}  // namespace

SampleType sampleTypeFor(NumericType type) {
  switch (type) {
    case NumericType::Int8: return SampleType::Int8;
    case NumericType::UInt8: return SampleType::UInt8;
    case NumericType::Int16: return SampleType::Int16;
    case NumericType::UInt16: return SampleType::UInt16;
    case NumericType::Int32: return SampleType::Int32;
    case NumericType::UInt32: return SampleType::UInt32;
    case NumericType::Float32: return SampleType::Float32;
    default: return SampleType::Float64;
  }
}

SampleArray toSamples(const std::uint8_t* bytes, std::size_t count, NumericType type, bool be) {
  const SampleType kept = sampleTypeFor(type);
  switch (type) {
    case NumericType::Int8: return loadAll<std::int8_t>(bytes, count, type, be, kept);
    case NumericType::UInt8: return loadAll<std::uint8_t>(bytes, count, type, be, kept);
    case NumericType::Int16: return loadAll<std::int16_t>(bytes, count, type, be, kept);
    case NumericType::UInt16: return loadAll<std::uint16_t>(bytes, count, type, be, kept);
    case NumericType::Int32: return loadAll<std::int32_t>(bytes, count, type, be, kept);
    case NumericType::UInt32: return loadAll<std::uint32_t>(bytes, count, type, be, kept);
    case NumericType::Float32: return loadAll<float>(bytes, count, type, be, kept);
    case NumericType::Float64: return loadAll<double>(bytes, count, type, be, kept);
    case NumericType::Int64: return loadAll<std::int64_t, double>(bytes, count, type, be, kept);
    case NumericType::UInt64: return loadAll<std::uint64_t, double>(bytes, count, type, be, kept);
  }
  return {};  // every type is handled above
}

SampleArray toSamples(const std::vector<double>& values, NumericType type) {
  SampleArray out(sampleTypeFor(type), values.size());
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (!out.fitsExactly(values[i]) && out.type() != SampleType::Float64) out = out.widenedTo(SampleType::Float64);
    out.set(i, values[i]);
  }
  return out;
}

std::size_t sizeOf(NumericType type) {
  switch (type) {
    case NumericType::Int8: case NumericType::UInt8: return 1;
    case NumericType::Int16: case NumericType::UInt16: return 2;
    case NumericType::Int32: case NumericType::UInt32: case NumericType::Float32: return 4;
    case NumericType::Int64: case NumericType::UInt64: case NumericType::Float64: return 8;
  }
  return 1;
}

bool isFloating(NumericType type) { return type == NumericType::Float32 || type == NumericType::Float64; }

std::optional<NumericType> numericTypeFromXml(std::string_view n) {
  if (n == "Int8" || n == "Char") return NumericType::Int8;
  if (n == "UInt8") return NumericType::UInt8;
  if (n == "Int16") return NumericType::Int16;
  if (n == "UInt16") return NumericType::UInt16;
  if (n == "Int32") return NumericType::Int32;
  if (n == "UInt32") return NumericType::UInt32;
  if (n == "Int64") return NumericType::Int64;
  if (n == "UInt64") return NumericType::UInt64;
  if (n == "Float32") return NumericType::Float32;
  if (n == "Float64") return NumericType::Float64;
  return std::nullopt;
}

std::optional<NumericType> numericTypeFromLegacy(std::string_view n) {
  if (n == "char") return NumericType::Int8;
  if (n == "unsigned_char" || n == "bit") return NumericType::UInt8;
  if (n == "short") return NumericType::Int16;
  if (n == "unsigned_short") return NumericType::UInt16;
  if (n == "int") return NumericType::Int32;
  if (n == "unsigned_int") return NumericType::UInt32;
  // VTK writes 64-bit ids as vtktypeint64; "long" is 8 bytes in the files VTK writes on
  // 64-bit Linux, the only place such files come from in practice.
  if (n == "long" || n == "vtktypeint64" || n == "vtkIdType") return NumericType::Int64;
  if (n == "unsigned_long" || n == "vtktypeuint64") return NumericType::UInt64;
  if (n == "float") return NumericType::Float32;
  if (n == "double") return NumericType::Float64;
  return std::nullopt;
}

std::vector<double> toDoubles(const std::uint8_t* bytes, std::size_t count, NumericType type, bool bigEndian) {
  return convert<double>(bytes, count, type, bigEndian);
}

std::vector<std::int64_t> toIntegers(const std::uint8_t* bytes, std::size_t count, NumericType type, bool bigEndian) {
  return convert<std::int64_t>(bytes, count, type, bigEndian);
}

}  // namespace volpost::meshio

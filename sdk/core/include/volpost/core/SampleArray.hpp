// SPDX-License-Identifier: MIT
// Values kept in the type their file stored them in (8/16/32-bit integers, 32/64-bit
// floats): a 16-bit seismic cube holds 2 bytes per sample, not the 8 of a double.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <variant>
#include <vector>

namespace volpost {

enum class SampleType : std::uint8_t { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

/// "16-bit integer", "32-bit float", ...: the words `info` and the Model panel use.
const char* toString(SampleType type);
std::size_t bytesPerSample(SampleType type);

class SampleArray {
 public:
  SampleArray() = default;
  /// `count` zeros of `type`.
  SampleArray(SampleType type, std::size_t count);

  SampleType type() const { return SampleType(values_.index()); }
  std::size_t size() const;
  std::size_t bytes() const { return size() * bytesPerSample(type()); }

  /// The i-th value as a double (every stored type converts exactly).
  double operator[](std::size_t i) const;
  /// Stores v converted to the array's type; the caller keeps v within what it holds
  /// (fitsExactly) or accepts the conversion (a float's rounding, an integer's truncation).
  void set(std::size_t i, double v);
  /// Whether v is stored without change.
  bool fitsExactly(double v) const;
  /// The same values in a wider type (e.g. 32-bit floats to 64-bit when one does not fit).
  SampleArray widenedTo(SampleType type) const;

  /// All values as doubles, converted on all cores.
  std::vector<double> toDoubles() const;
  void copyTo(std::span<double> out) const;

  /// The stored values of type T (std::get: throws std::bad_variant_access for another type).
  template <typename T>
  std::span<const T> as() const { return std::get<std::vector<T>>(values_); }
  template <typename T>
  std::span<T> as() { return std::get<std::vector<T>>(values_); }

 private:
  // In SampleType's order, so that index() is the type.
  std::variant<std::vector<std::int8_t>, std::vector<std::uint8_t>, std::vector<std::int16_t>,
               std::vector<std::uint16_t>, std::vector<std::int32_t>, std::vector<std::uint32_t>,
               std::vector<float>, std::vector<double>>
      values_;
};

}  // namespace volpost

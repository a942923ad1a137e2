// SPDX-License-Identifier: MIT
// A read-only view of values in whatever type holds them: the samples of a field as its
// file stored them (a 16-bit seismic cube, 2 bytes a point) or doubles computed from a
// result. What draws, cuts or counts a whole grid takes this view, so showing a 2 GB cube
// of 16-bit samples does not first make an 8 GB array of doubles of it. A view owns
// nothing: what it views must outlive it (a temporary vector only for the call it is
// passed to).
#pragma once

#include <volpost/core/SampleArray.hpp>

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace volpost {

class SampleView {
 public:
  SampleView() = default;
  SampleView(std::span<const double> values) : data_(values.data()), size_(values.size()) {}
  SampleView(const std::vector<double>& values) : SampleView(std::span<const double>(values)) {}
  SampleView(const SampleArray& samples);

  SampleType type() const { return type_; }
  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  std::size_t bytes() const { return size_ * bytesPerSample(type_); }
  /// Where the values lie: with size() and type(), which values are viewed (a panel that
  /// keeps a histogram of them knows when they are others).
  const void* data() const { return data_; }

  /// The i-th value as a double (every type converts exactly).
  double operator[](std::size_t i) const {
    switch (type_) {
      case SampleType::Int8: return static_cast<const std::int8_t*>(data_)[i];
      case SampleType::UInt8: return static_cast<const std::uint8_t*>(data_)[i];
      case SampleType::Int16: return static_cast<const std::int16_t*>(data_)[i];
      case SampleType::UInt16: return static_cast<const std::uint16_t*>(data_)[i];
      case SampleType::Int32: return static_cast<const std::int32_t*>(data_)[i];
      case SampleType::UInt32: return static_cast<const std::uint32_t*>(data_)[i];
      case SampleType::Float32: return static_cast<const float*>(data_)[i];
      case SampleType::Float64: return static_cast<const double*>(data_)[i];
    }
    return 0.0;
  }

  /// Calls f(std::span<const T>) with the values in their own type: the loops that cross
  /// every value are compiled once per type instead of converting one value at a time.
  template <typename F>
  decltype(auto) visit(F&& f) const {
    switch (type_) {
      case SampleType::Int8: return f(typed<std::int8_t>());
      case SampleType::UInt8: return f(typed<std::uint8_t>());
      case SampleType::Int16: return f(typed<std::int16_t>());
      case SampleType::UInt16: return f(typed<std::uint16_t>());
      case SampleType::Int32: return f(typed<std::int32_t>());
      case SampleType::UInt32: return f(typed<std::uint32_t>());
      case SampleType::Float32: return f(typed<float>());
      case SampleType::Float64: break;
    }
    return f(typed<double>());
  }

  /// The values as doubles: the view's own when they are doubles, else converted into
  /// `scratch` (for what needs doubles and is not worth a loop per type).
  std::span<const double> doubles(std::vector<double>& scratch) const;
  /// All values as doubles into `out` (its size is size()), converted on all cores.
  void copyTo(std::span<double> out) const;

 private:
  template <typename T>
  std::span<const T> typed() const { return {static_cast<const T*>(data_), size_}; }

  const void* data_ = nullptr;
  std::size_t size_ = 0;
  SampleType type_ = SampleType::Float64;
};

}  // namespace volpost

// SPDX-License-Identifier: MIT
#include <volpost/core/SampleArray.hpp>

#include <volpost/core/SampleView.hpp>

#include <algorithm>
#include <cmath>
#include <type_traits>
#include <limits>
#include <stdexcept>

namespace volpost {
namespace {

template <typename T>
bool holds(double v) {
  if constexpr (std::is_floating_point_v<T>) {
    return std::isnan(v) || double(T(v)) == v;  // NaN is stored as NaN
  } else {
    return v >= double(std::numeric_limits<T>::min()) && v <= double(std::numeric_limits<T>::max()) && v == std::trunc(v);
  }
}

template <typename T>
T converted(double v) {
  if constexpr (std::is_floating_point_v<T>) {
    return T(v);
  } else {  // clamped, NaN as 0: a cast of an out-of-range double is undefined
    if (!(v == v)) return T(0);
    return T(std::clamp(v, double(std::numeric_limits<T>::min()), double(std::numeric_limits<T>::max())));
  }
}

}  // namespace

const char* toString(SampleType type) {
  switch (type) {
    case SampleType::Int8: return "8-bit integer";
    case SampleType::UInt8: return "8-bit unsigned integer";
    case SampleType::Int16: return "16-bit integer";
    case SampleType::UInt16: return "16-bit unsigned integer";
    case SampleType::Int32: return "32-bit integer";
    case SampleType::UInt32: return "32-bit unsigned integer";
    case SampleType::Float32: return "32-bit float";
    case SampleType::Float64: return "64-bit float";
  }
  return "?";
}

std::size_t bytesPerSample(SampleType type) {
  switch (type) {
    case SampleType::Int8: case SampleType::UInt8: return 1;
    case SampleType::Int16: case SampleType::UInt16: return 2;
    case SampleType::Int32: case SampleType::UInt32: case SampleType::Float32: return 4;
    case SampleType::Float64: return 8;
  }
  return 8;
}

SampleArray::SampleArray(SampleType type, std::size_t count) {
  switch (type) {
    case SampleType::Int8: values_ = std::vector<std::int8_t>(count); break;
    case SampleType::UInt8: values_ = std::vector<std::uint8_t>(count); break;
    case SampleType::Int16: values_ = std::vector<std::int16_t>(count); break;
    case SampleType::UInt16: values_ = std::vector<std::uint16_t>(count); break;
    case SampleType::Int32: values_ = std::vector<std::int32_t>(count); break;
    case SampleType::UInt32: values_ = std::vector<std::uint32_t>(count); break;
    case SampleType::Float32: values_ = std::vector<float>(count); break;
    case SampleType::Float64: values_ = std::vector<double>(count); break;
  }
}

std::size_t SampleArray::size() const {
  return std::visit([](const auto& v) { return v.size(); }, values_);
}

double SampleArray::operator[](std::size_t i) const {
  return std::visit([i](const auto& v) { return double(v[i]); }, values_);
}

void SampleArray::set(std::size_t i, double value) {
  std::visit([i, value](auto& v) { v[i] = converted<typename std::decay_t<decltype(v)>::value_type>(value); }, values_);
}

bool SampleArray::fitsExactly(double value) const {
  return std::visit([value](const auto& v) { return holds<typename std::decay_t<decltype(v)>::value_type>(value); },
                    values_);
}

SampleArray SampleArray::widenedTo(SampleType wider) const {
  SampleArray out(wider, size());
  for (std::size_t i = 0; i < size(); ++i) {
    const double v = (*this)[i];
    if (!out.fitsExactly(v)) throw std::invalid_argument(std::string("a value does not fit ") + toString(wider));
    out.set(i, v);
  }
  return out;
}

void SampleArray::copyTo(std::span<double> out) const { SampleView(*this).copyTo(out); }

std::vector<double> SampleArray::toDoubles() const {
  std::vector<double> out(size());
  copyTo(out);
  return out;
}

}  // namespace volpost

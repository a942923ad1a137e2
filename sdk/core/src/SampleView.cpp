// SPDX-License-Identifier: MIT
#include <volpost/core/SampleView.hpp>

#include <volpost/core/WorkerThreads.hpp>

#include <stdexcept>

namespace volpost {

SampleView::SampleView(const SampleArray& samples) : size_(samples.size()), type_(samples.type()) {
  switch (type_) {
    case SampleType::Int8: data_ = samples.as<std::int8_t>().data(); break;
    case SampleType::UInt8: data_ = samples.as<std::uint8_t>().data(); break;
    case SampleType::Int16: data_ = samples.as<std::int16_t>().data(); break;
    case SampleType::UInt16: data_ = samples.as<std::uint16_t>().data(); break;
    case SampleType::Int32: data_ = samples.as<std::int32_t>().data(); break;
    case SampleType::UInt32: data_ = samples.as<std::uint32_t>().data(); break;
    case SampleType::Float32: data_ = samples.as<float>().data(); break;
    case SampleType::Float64: data_ = samples.as<double>().data(); break;
  }
}

std::span<const double> SampleView::doubles(std::vector<double>& scratch) const {
  if (type_ == SampleType::Float64) return typed<double>();
  scratch.resize(size_);
  copyTo(scratch);
  return scratch;
}

void SampleView::copyTo(std::span<double> out) const {
  if (out.size() != size_) throw std::invalid_argument("copyTo: the target's size differs");
  visit([&out](auto values) {
    forEachChunk(values.size(), 1 << 16, [&](std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i) out[i] = double(values[i]);
    });
  });
}

}  // namespace volpost

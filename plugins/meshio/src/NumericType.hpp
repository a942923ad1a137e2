// SPDX-License-Identifier: MIT
// Numeric element types of VTK files and their conversion from raw bytes.
#pragma once

#include <cstddef>
#include <cstdint>

#include <volpost/core/SampleArray.hpp>

#include <optional>
#include <string_view>
#include <vector>

namespace volpost::meshio {

enum class NumericType { Int8, UInt8, Int16, UInt16, Int32, UInt32, Int64, UInt64, Float32, Float64 };

std::size_t sizeOf(NumericType type);
bool isFloating(NumericType type);
/// XML names: "Int32", "Float64", ...
std::optional<NumericType> numericTypeFromXml(std::string_view name);
/// Legacy names: "int", "double", "vtktypeint64", "unsigned_char", ...
std::optional<NumericType> numericTypeFromLegacy(std::string_view name);

/// Converts `count` values stored at `bytes` (little or big endian) to doubles.
std::vector<double> toDoubles(const std::uint8_t* bytes, std::size_t count, NumericType type, bool bigEndian);
/// The type a grid keeps such values in: the same, 64-bit integers as 64-bit floats.
SampleType sampleTypeFor(NumericType type);
/// `count` values stored at `bytes` in the type sampleTypeFor gives (no copy as doubles).
SampleArray toSamples(const std::uint8_t* bytes, std::size_t count, NumericType type, bool bigEndian);
/// Values read as text into that type, widened to 64-bit floats when one does not fit
/// (text "300" in an unsigned_char array is kept as written).
SampleArray toSamples(const std::vector<double>& values, NumericType type);

/// Converts `count` integer values; floating values are rejected by the caller.
std::vector<std::int64_t> toIntegers(const std::uint8_t* bytes, std::size_t count, NumericType type, bool bigEndian);

}  // namespace volpost::meshio

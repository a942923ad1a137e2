// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

namespace volpost::meshio {

/// Decodes base64, skipping whitespace. Padding may end any 4-character group, not only
/// the last: VTK encodes an array's header and its data as two separate base64 runs.
/// Returns nullopt on a character outside the alphabet (its index in `error`).
std::optional<std::vector<std::uint8_t>> decodeBase64(std::string_view text, std::size_t* error = nullptr);

}  // namespace volpost::meshio

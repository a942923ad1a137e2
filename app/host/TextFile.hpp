// SPDX-License-Identifier: MIT
// Small text inputs (state files, transfer functions): read whole, regular files only (a
// FIFO would block, a device would never end), with a size limit.
#pragma once

#include <cstddef>
#include <string>

namespace volpost {

/// The file's bytes. Throws ReadError naming the file when it is missing, not a regular
/// file, larger than `maxBytes`, or unreadable.
std::string readTextFile(const std::string& path, std::size_t maxBytes = std::size_t(64) << 20);

}  // namespace volpost

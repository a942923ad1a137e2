// SPDX-License-Identifier: MIT
#pragma once

#include <volpost/core/Progress.hpp>

#include <memory>
#include <string>

namespace volpost::meshio {

/// The whole file in memory, shared by the lazy field loaders. Throws ReadError.
std::shared_ptr<const std::string> readFileBytes(const std::string& path, const Progress& progress);

/// Blanks a UTF-8 byte-order mark at the start (some Windows editors write one; no format
/// has it), keeping every offset.
void blankByteOrderMark(std::string& text);

/// 1-based line number of byte `offset` (for error messages).
std::int64_t lineAt(const std::string& bytes, std::size_t offset);

}  // namespace volpost::meshio

// SPDX-License-Identifier: MIT
#pragma once

#include <volpost/core/Progress.hpp>

#include <memory>
#include <string>

namespace volpost::meshio {

/// The whole file in memory, shared by the lazy field loaders. Throws ReadError.
std::shared_ptr<const std::string> readFileBytes(const std::string& path, const Progress& progress);

/// 1-based line number of byte `offset` (for error messages).
std::int64_t lineAt(const std::string& bytes, std::size_t offset);

}  // namespace volpost::meshio

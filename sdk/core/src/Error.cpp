// SPDX-License-Identifier: MIT
#include <volpost/core/Error.hpp>

namespace volpost {

ReadError::ReadError(const std::string& file, const std::string& message)
    : ReadError(file, -1, -1, message) {}

ReadError::ReadError(const std::string& file, std::int64_t line, std::int64_t offset,
                     const std::string& message)
    : std::runtime_error(file +
                         (line >= 0     ? ":" + std::to_string(line)
                          : offset >= 0 ? ": byte " + std::to_string(offset)
                                        : std::string()) +
                         ": " + message),
      file_(file),
      detail_(message),
      line_(line),
      offset_(offset) {}

ReadError ReadError::atLine(const std::string& file, std::int64_t line, const std::string& message) {
  return ReadError(file, line, -1, message);
}

ReadError ReadError::atOffset(const std::string& file, std::uint64_t offset,
                              const std::string& message) {
  return ReadError(file, -1, static_cast<std::int64_t>(offset), message);
}

}  // namespace volpost

// SPDX-License-Identifier: MIT
// Errors that carry where in a file they happened.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

namespace volpost {

/// A file could not be read. what() is the full message: "FILE:LINE: text" or
/// "FILE: byte OFFSET: text", ready for a message box or stderr.
class ReadError : public std::runtime_error {
 public:
  ReadError(const std::string& file, const std::string& message);
  static ReadError atLine(const std::string& file, std::int64_t line, const std::string& message);
  static ReadError atOffset(const std::string& file, std::uint64_t offset, const std::string& message);
  const std::string& file() const { return file_; }
  std::int64_t line() const { return line_; }
  std::int64_t offset() const { return offset_; }
  const std::string& detail() const { return detail_; }

 private:
  ReadError(const std::string& file, std::int64_t line, std::int64_t offset, const std::string& message);
  std::string file_;
  std::string detail_;
  std::int64_t line_ = -1;
  std::int64_t offset_ = -1;
};

/// A file could not be written. what() is "FILE: text".
class WriteError : public std::runtime_error {
 public:
  WriteError(const std::string& file, const std::string& message) : std::runtime_error(file + ": " + message) {}
};

/// Long work was cancelled by the user.
class Cancelled : public std::runtime_error {
 public:
  Cancelled() : std::runtime_error("cancelled") {}
};

}  // namespace volpost

// SPDX-License-Identifier: MIT
// Line-by-line reading of a text file held in memory, with errors that name the line.
// Shared by the Gmsh, Abaqus, CalculiX and Tecgraf readers.
#pragma once

#include <volpost/core/Error.hpp>
#include <volpost/core/Progress.hpp>

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace volpost::meshio {

class TextScanner {
 public:
  TextScanner(std::shared_ptr<const std::string> bytes, std::string path);

  bool atEnd() const { return pos_ >= b_.size(); }
  /// The next line without its end-of-line characters; advances. Empty at the end.
  std::string_view nextLine();
  /// The next whitespace-separated token, possibly on a later line; empty at the end.
  std::string_view nextToken();
  /// The next line without advancing.
  std::string_view peekLine() const;
  /// 1-based number of the line where the last line or token started (counted on demand:
  /// it is only needed for messages).
  std::int64_t lineNumber() const;
  std::size_t offset() const { return pos_; }
  /// Moves to a byte offset (binary sections).
  void seek(std::size_t offset);
  const std::string& bytes() const { return b_; }
  const std::string& path() const { return path_; }

  /// Throws ReadError naming the file and the current line.
  [[noreturn]] void fail(const std::string& message) const;
  /// Throws ReadError naming the file and a byte offset (binary data).
  [[noreturn]] void failAtOffset(std::size_t offset, const std::string& message) const;
  /// Reports progress as the fraction of bytes read, mapped to [from, to].
  void report(const Progress& progress, double from, double to) const;
  /// Refuses a declared count of items that each take at least `minBytes` in the file
  /// when the rest of the file cannot hold them: checked before anything is allocated, so
  /// a few hostile bytes cannot ask for gigabytes.
  void requirePlausibleCount(std::int64_t count, std::size_t minBytes, const std::string& what) const;
  /// volpost::requireMemory, with the refusal naming the current line.
  void requireMemory(double bytes, const std::string& what) const;

 private:
  std::shared_ptr<const std::string> bytesPtr_;
  const std::string& b_;
  std::string path_;
  std::size_t pos_ = 0;
  std::size_t last_ = 0;
};

/// Whitespace- (and optionally comma-) separated fields of a line.
std::vector<std::string_view> splitFields(std::string_view line, bool commas = false);
std::string_view trim(std::string_view s);
std::string toUpper(std::string_view s);

/// Parsing of one field; nullopt-free: they throw through `scanner.fail` with `what`.
std::int64_t parseInteger(const TextScanner& scanner, std::string_view field, const char* what);
double parseReal(const TextScanner& scanner, std::string_view field, const char* what);
/// Like parseReal, but also reads Fortran's "1.0D+03" and spellings like NaN, Inf.
double parseFortranReal(const TextScanner& scanner, std::string_view field, const char* what);

}  // namespace volpost::meshio

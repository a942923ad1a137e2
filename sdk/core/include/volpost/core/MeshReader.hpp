// SPDX-License-Identifier: MIT
// A reader of one mesh file format. Plugins provide readers through ReaderPlugin.
#pragma once

#include <volpost/core/Model.hpp>
#include <volpost/core/Progress.hpp>

#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace volpost {

/// A setting a reader takes besides the file, such as where a SEG-Y file keeps its inline
/// numbers: shown by `volpost info --help`, the window's File > Reader Options, and kept in
/// state files.
struct ReaderOption {
  std::string name;         ///< lower case with dashes: "inline-byte"
  std::string valueName;    ///< what the value is, in a word: "BYTE"
  std::string description;  ///< one sentence, with the default
};

/// Option name -> value as the user typed it; the reader parses and checks it.
using ReaderOptions = std::map<std::string, std::string>;

/// A reader option the reader does not take, or a value it cannot use: the user's mistake
/// (a usage error on the command line), said before anything is read.
struct ReaderOptionError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

class MeshReader {
 public:
  virtual ~MeshReader() = default;
  virtual std::string formatName() const = 0;
  /// Lower-case extensions without the dot, e.g. {"vtu"}.
  virtual std::vector<std::string> extensions() const = 0;
  /// How sure the reader is that it reads this file, 0 (no) to 100, from its first bytes
  /// (up to 4 KiB) alone. A file is never read by a reader that scores 0.
  virtual int sniff(std::string_view head) const = 0;
  /// Reads the file. Throws ReadError (naming the file and line or byte) or Cancelled.
  virtual std::unique_ptr<Model> read(const std::string& path, const Progress& progress) const = 0;

  /// The options this reader takes (none unless it says).
  virtual std::vector<ReaderOption> options() const { return {}; }
  /// Reads the file with options. Throws ReaderOptionError naming an option the reader
  /// does not take or a value it cannot use, before reading; otherwise as read(). The
  /// default takes no options: empty ones read as read() does.
  virtual std::unique_ptr<Model> readWith(const std::string& path, const ReaderOptions& options,
                                          const Progress& progress) const;
};

/// Throws ReaderOptionError for the first of `given` that `reader` does not list,
/// naming it and what the reader takes.
void refuseUnknownOptions(const MeshReader& reader, const ReaderOptions& given);

}  // namespace volpost

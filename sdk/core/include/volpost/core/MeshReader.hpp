// SPDX-License-Identifier: MIT
// A reader of one mesh file format. Plugins provide readers through ReaderPlugin.
#pragma once

#include <volpost/core/Model.hpp>
#include <volpost/core/Progress.hpp>

#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace volpost {

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
};

}  // namespace volpost

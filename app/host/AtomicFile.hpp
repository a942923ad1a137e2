// SPDX-License-Identifier: MIT
// Output files that are either complete or not there: written to a unique temporary file
// in the target's folder (mkstemp: no predictable name another user could plant a link
// at), flushed to disk, then renamed over the target. A failed write (disk full, a
// missing folder, a target that is a directory) throws WriteError naming the file and
// leaves what was there before intact. A replaced file keeps its permissions; a symbolic
// link is written through (the link stays, the file it points to is replaced); a process
// ended by SIGINT, SIGTERM or SIGHUP removes its temporaries first.
#pragma once

#include <volpost/core/Error.hpp>

#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace volpost {

class AtomicFile {
 public:
  /// Creates the temporary file. Throws WriteError if the target cannot be written.
  explicit AtomicFile(std::string path);
  /// Removes the temporary file unless commit() succeeded.
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  /// Appends bytes; throws WriteError on a short write.
  void write(std::string_view bytes);
  /// Flushes to disk and renames the temporary file over the target; throws WriteError.
  void commit();

  /// For libraries that write by file name (OpenMesh): write there, then commit().
  const std::string& temporaryPath() const { return temporary_; }
  const std::string& path() const { return path_; }

 private:
  std::string path_, target_, temporary_;  // target_: path_, or the file its link points to
  int fd_ = -1;
  int slot_ = -1;  // where the interrupt handler finds the temporary's name
  bool committed_ = false;
};

/// The whole file at once, through AtomicFile.
void writeFileAtomically(const std::string& path, std::string_view bytes);

/// Several files of one result (a picture, its float image, its state): every temporary is
/// written first, then all are renamed, so a failed write leaves every target as it was.
void writeFilesTogether(const std::vector<std::pair<std::string, std::string>>& pathsAndBytes);

/// Throws WriteError now if `path` could not be written later (missing folder, a folder
/// as target, no permission): long work checks its outputs before it starts.
void checkWritable(const std::string& path);

}  // namespace volpost

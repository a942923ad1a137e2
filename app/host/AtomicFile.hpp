// SPDX-License-Identifier: MIT
// Output files that are either complete or not there: written to a unique temporary file
// in the target's folder (mkstemp: no predictable name another user could plant a link
// at), flushed to disk, then renamed over the target. A failed write (disk full, a
// missing folder, a target that is a directory) throws WriteError naming the file and
// leaves what was there before intact.
#pragma once

#include <volpost/core/Error.hpp>

#include <string>
#include <string_view>

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
  std::string path_, temporary_;
  int fd_ = -1;
  bool committed_ = false;
};

/// The whole file at once, through AtomicFile.
void writeFileAtomically(const std::string& path, std::string_view bytes);

/// Throws WriteError now if `path` could not be written later (missing folder, a folder
/// as target, no permission): long work checks its outputs before it starts.
void checkWritable(const std::string& path);

}  // namespace volpost

// SPDX-License-Identifier: MIT
// A file read a piece at a time where it lies, instead of all of it into memory: what a
// large VTK XML file's appended arrays are decoded from (at 100M tets the file is 4.4 GB,
// and holding it while decoding was half of the reader's peak memory).
#pragma once

#include <cstdint>
#include <string>

namespace volpost::meshio {

class DiskFile {
 public:
  /// Opens `path` for reading. Throws ReadError naming the file.
  explicit DiskFile(const std::string& path);
  ~DiskFile();
  DiskFile(const DiskFile&) = delete;
  DiskFile& operator=(const DiskFile&) = delete;

  const std::string& path() const { return path_; }
  std::uint64_t size() const { return size_; }

  /// Copies `length` bytes at `offset` into `out`; safe from several threads at once.
  /// Throws ReadError when the range is past the end, the read fails, or the file was
  /// changed since it was opened (its size or modification time): a lazy field read later
  /// must not take another run's values for this one's.
  void read(std::uint64_t offset, std::size_t length, void* out) const;
  std::string readString(std::uint64_t offset, std::size_t length) const;

 private:
  void requireUnchanged() const;

  std::string path_;
  int fd_ = -1;
  std::uint64_t size_ = 0;
  std::int64_t modifiedSeconds_ = 0, modifiedNanoseconds_ = 0;
};

}  // namespace volpost::meshio

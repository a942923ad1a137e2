// SPDX-License-Identifier: MIT
// A std::istream over a DiskFile: text-like parts of a file (headers, text or compressed
// data) read as a stream through the descriptor that was checked when the file was opened,
// never by opening its name again (a name can point elsewhere by then: another file, or a
// pipe that would block the reader for ever).
#pragma once

#include "DiskFile.hpp"

#include <istream>
#include <memory>
#include <streambuf>
#include <vector>

namespace volpost::meshio {

class DiskFileBuffer : public std::streambuf {
 public:
  DiskFileBuffer(std::shared_ptr<const DiskFile> file, std::uint64_t offset);

 protected:
  int_type underflow() override;
  pos_type seekoff(off_type offset, std::ios_base::seekdir way, std::ios_base::openmode) override;
  pos_type seekpos(pos_type position, std::ios_base::openmode) override;

 private:
  std::shared_ptr<const DiskFile> file_;
  std::vector<char> chunk_;
  std::uint64_t chunkStart_ = 0;  ///< file offset of chunk_[0]
};

class DiskFileStream : public std::istream {
 public:
  /// Reads `file` from `offset` on (seekg and tellg work in file offsets).
  explicit DiskFileStream(std::shared_ptr<const DiskFile> file, std::uint64_t offset = 0);

 private:
  DiskFileBuffer buffer_;
};

}  // namespace volpost::meshio

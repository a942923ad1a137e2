// SPDX-License-Identifier: MIT
#include "DiskFileStream.hpp"

#include <algorithm>

namespace volpost::meshio {
namespace {
constexpr std::size_t kChunkBytes = 1 << 16;
}  // namespace

DiskFileBuffer::DiskFileBuffer(std::shared_ptr<const DiskFile> file, std::uint64_t offset)
    : file_(std::move(file)), chunk_(kChunkBytes), chunkStart_(std::min(offset, file_->size())) {
  setg(chunk_.data(), chunk_.data(), chunk_.data());  // empty: the first read fills it
}

DiskFileBuffer::int_type DiskFileBuffer::underflow() {
  if (gptr() < egptr()) return traits_type::to_int_type(*gptr());
  const std::uint64_t next = chunkStart_ + std::uint64_t(egptr() - eback());
  if (next >= file_->size()) return traits_type::eof();
  const std::size_t length = std::size_t(std::min<std::uint64_t>(kChunkBytes, file_->size() - next));
  file_->read(next, length, chunk_.data());  // ReadError when the file changed or fails
  chunkStart_ = next;
  setg(chunk_.data(), chunk_.data(), chunk_.data() + length);
  return traits_type::to_int_type(*gptr());
}

DiskFileBuffer::pos_type DiskFileBuffer::seekoff(off_type offset, std::ios_base::seekdir way, std::ios_base::openmode) {
  const std::int64_t here = std::int64_t(chunkStart_) + (gptr() - eback());
  const std::int64_t base = way == std::ios_base::beg   ? 0
                            : way == std::ios_base::cur ? here
                                                        : std::int64_t(file_->size());
  return seekpos(pos_type(off_type(base + offset)), std::ios_base::in);
}

DiskFileBuffer::pos_type DiskFileBuffer::seekpos(pos_type position, std::ios_base::openmode) {
  const std::int64_t to = std::int64_t(off_type(position));
  if (to < 0 || std::uint64_t(to) > file_->size()) return pos_type(off_type(-1));
  if (std::uint64_t(to) >= chunkStart_ && std::uint64_t(to) <= chunkStart_ + std::uint64_t(egptr() - eback())) {
    setg(eback(), eback() + (std::uint64_t(to) - chunkStart_), egptr());  // within what is held
  } else {
    chunkStart_ = std::uint64_t(to);
    setg(chunk_.data(), chunk_.data(), chunk_.data());
  }
  return position;
}

DiskFileStream::DiskFileStream(std::shared_ptr<const DiskFile> file, std::uint64_t offset)
    : std::istream(nullptr), buffer_(std::move(file), offset) {
  rdbuf(&buffer_);
  exceptions(std::ios::badbit);  // a ReadError from the file (changed, failing) reaches the reader as itself
}

}  // namespace volpost::meshio

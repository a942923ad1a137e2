// SPDX-License-Identifier: MIT
#include "DiskFile.hpp"

#include <volpost/core/Error.hpp>
#include <volpost/core/ResourceLimits.hpp>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace volpost::meshio {

DiskFile::DiskFile(const std::string& path) : path_(path) {
  requireRegularFile(path);
  // Without blocking: the name may have been swapped for a pipe since it was checked, and
  // opening a pipe waits for a writer. What was opened is checked again by its descriptor.
  fd_ = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  if (fd_ < 0) throw ReadError(path, std::string("cannot open: ") + std::strerror(errno));
  struct stat st {};
  if (::fstat(fd_, &st) != 0 || !S_ISREG(st.st_mode)) {
    const int error = errno;
    const bool regular = S_ISREG(st.st_mode);
    ::close(fd_);
    if (!regular) throw ReadError(path, "is no longer a regular file (it was replaced while being opened)");
    throw ReadError(path, std::string("cannot read its size: ") + std::strerror(error));
  }
  size_ = std::uint64_t(st.st_size);
  modifiedSeconds_ = std::int64_t(st.st_mtim.tv_sec);
  modifiedNanoseconds_ = std::int64_t(st.st_mtim.tv_nsec);
}

DiskFile::~DiskFile() {
  if (fd_ >= 0) ::close(fd_);
}

void DiskFile::requireUnchanged() const {
  struct stat st {};
  if (::fstat(fd_, &st) != 0) throw ReadError(path_, std::string("cannot check the file: ") + std::strerror(errno));
  if (std::uint64_t(st.st_size) != size_ || std::int64_t(st.st_mtim.tv_sec) != modifiedSeconds_ ||
      std::int64_t(st.st_mtim.tv_nsec) != modifiedNanoseconds_)
    throw ReadError(path_, "the file was changed after it was opened (" + std::to_string(size_) + " bytes then, " +
                               std::to_string(std::uint64_t(st.st_size)) + " now): open it again to see its new contents");
}

void DiskFile::read(std::uint64_t offset, std::size_t length, void* out) const {
  if (offset > size_ || length > size_ - offset)
    throw ReadError::atOffset(path_, offset, "needs " + std::to_string(length) + " bytes here, past the end of the file (" +
                                                 std::to_string(size_) + " bytes)");
  requireUnchanged();
  auto* to = static_cast<char*>(out);
  for (std::size_t done = 0; done < length;) {
    const ssize_t n = ::pread(fd_, to + done, length - done, off_t(offset + done));
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw ReadError::atOffset(path_, offset + done, std::string("read error: ") + std::strerror(errno));
    if (n == 0) throw ReadError::atOffset(path_, offset + done, "the file ended early (was it cut short after it was opened?)");
    done += std::size_t(n);
  }
}

std::string DiskFile::readString(std::uint64_t offset, std::size_t length) const {
  std::string out(length, '\0');
  read(offset, length, out.data());
  return out;
}

}  // namespace volpost::meshio

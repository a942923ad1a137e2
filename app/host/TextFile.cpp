// SPDX-License-Identifier: MIT
#include "host/TextFile.hpp"

#include <volpost/core/Error.hpp>

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace volpost {

std::string readTextFile(const std::string& path, std::size_t maxBytes) {
  // O_NONBLOCK: opening a FIFO must not wait for a writer; it is refused just below.
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) throw ReadError(path, std::string("cannot open: ") + std::strerror(errno));
  struct Closer {
    int fd;
    ~Closer() { ::close(fd); }
  } closer{fd};
  struct stat st {};
  if (::fstat(fd, &st) != 0) throw ReadError(path, std::string("cannot open: ") + std::strerror(errno));
  if (S_ISDIR(st.st_mode)) throw ReadError(path, "is a folder, not a file");
  if (!S_ISREG(st.st_mode)) throw ReadError(path, "is not a regular file (a pipe or a device?)");
  if (std::size_t(st.st_size) > maxBytes)
    throw ReadError(path, "is " + std::to_string(st.st_size) + " bytes, more than the " + std::to_string(maxBytes) +
                              " this kind of file may have");
  std::string text(std::size_t(st.st_size), '\0');
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::read(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw ReadError(path, std::string("read failed: ") + std::strerror(errno));
    if (n == 0) break;  // shrank while reading
    done += std::size_t(n);
  }
  text.resize(done);
  return text;
}

}  // namespace volpost

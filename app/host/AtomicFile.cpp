// SPDX-License-Identifier: MIT
#include "host/AtomicFile.hpp"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

namespace volpost {
namespace {

std::string reason(int error) { return std::strerror(error); }

}  // namespace

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)) {
  namespace fs = std::filesystem;
  if (path_.empty()) throw WriteError("(no name)", "no output file name given");
  struct stat st {};
  if (::lstat(path_.c_str(), &st) == 0) {
    // Renaming over a device or a pipe would replace it (as root, /dev/full itself).
    if (S_ISDIR(st.st_mode)) throw WriteError(path_, "is a folder, not a file");
    if (S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode)) throw WriteError(path_, "is a device, not a file");
    if (S_ISFIFO(st.st_mode) || S_ISSOCK(st.st_mode)) throw WriteError(path_, "is a pipe or socket, not a file");
  }
  const fs::path parent = fs::path(path_).parent_path();
  const fs::path folder = parent.empty() ? fs::path(".") : parent;
  if (::stat(folder.c_str(), &st) != 0) throw WriteError(path_, "the folder " + folder.string() + " does not exist");
  if (!S_ISDIR(st.st_mode)) throw WriteError(path_, folder.string() + " is not a folder");
  std::string pattern = (folder / ("." + fs::path(path_).filename().string() + ".XXXXXX")).string();
  std::vector<char> name(pattern.begin(), pattern.end());
  name.push_back('\0');
  fd_ = ::mkstemp(name.data());
  if (fd_ < 0) throw WriteError(path_, "cannot write in " + folder.string() + ": " + reason(errno));
  temporary_ = name.data();
  // Keep the permissions a new file would get (mkstemp makes it 0600).
  const mode_t mask = ::umask(0);
  ::umask(mask);
  ::fchmod(fd_, 0666 & ~mask);
}

AtomicFile::~AtomicFile() {
  if (fd_ >= 0) ::close(fd_);
  if (!committed_ && !temporary_.empty()) ::unlink(temporary_.c_str());
}

void AtomicFile::write(std::string_view bytes) {
  while (!bytes.empty()) {
    const ssize_t n = ::write(fd_, bytes.data(), bytes.size());
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw WriteError(path_, "write failed: " + reason(n < 0 ? errno : ENOSPC));
    bytes.remove_prefix(std::size_t(n));
  }
}

void AtomicFile::commit() {
  if (committed_) return;
  // A library may have written the temporary file by name: sync what is there now.
  if (fd_ >= 0) ::close(fd_);
  fd_ = ::open(temporary_.c_str(), O_RDONLY);
  if (fd_ < 0) throw WriteError(path_, "the temporary file disappeared: " + reason(errno));
  if (::fsync(fd_) != 0) throw WriteError(path_, "write failed: " + reason(errno));
  ::close(fd_);
  fd_ = -1;
  if (::rename(temporary_.c_str(), path_.c_str()) != 0)
    throw WriteError(path_, "cannot replace the file: " + reason(errno));
  committed_ = true;
}

void writeFileAtomically(const std::string& path, std::string_view bytes) {
  AtomicFile file(path);
  file.write(bytes);
  file.commit();
}

void checkWritable(const std::string& path) { AtomicFile probe(path); }

}  // namespace volpost

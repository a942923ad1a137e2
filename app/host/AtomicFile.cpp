// SPDX-License-Identifier: MIT
#include "host/AtomicFile.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <array>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <memory>
#include <mutex>
#include <vector>

namespace volpost {
namespace {

std::string reason(int error) { return std::strerror(error); }

// Temporaries not yet committed, removed when the process is interrupted (SIGINT, SIGTERM,
// SIGHUP): a killed export must not leave a hidden ".name.XXXXXX" beside the target. The
// handler only reads fixed slots and calls unlink, both safe in a signal handler.
constexpr std::size_t kSlots = 64, kNameBytes = 4096;
enum SlotState : int { kFree, kFilling, kHeld };
struct Slot {
  std::atomic<int> state{kFree};
  char name[kNameBytes];
};
std::array<Slot, kSlots> g_slots;

extern "C" void removeTemporariesAndDie(int signal) {
  for (Slot& slot : g_slots)
    if (slot.state.load() == kHeld) ::unlink(slot.name);
  std::signal(signal, SIG_DFL);
  std::raise(signal);
}

// Installed once, only where the signal would end the process anyway (its default): a
// program with its own handlers keeps them.
void installSignalHandlers() {
  static std::once_flag once;
  std::call_once(once, [] {
    for (int signal : {SIGINT, SIGTERM, SIGHUP}) {
      struct sigaction current {};
      if (::sigaction(signal, nullptr, &current) != 0 || current.sa_handler != SIG_DFL) continue;
      struct sigaction action {};
      action.sa_handler = removeTemporariesAndDie;
      sigemptyset(&action.sa_mask);
      ::sigaction(signal, &action, nullptr);
    }
  });
}

// Claimed, filled, then published: the handler reads a name only when it is whole.
int registerTemporary(const std::string& name) {
  if (name.size() >= kNameBytes) return -1;
  installSignalHandlers();
  for (std::size_t i = 0; i < kSlots; ++i) {
    int expected = kFree;
    if (!g_slots[i].state.compare_exchange_strong(expected, kFilling)) continue;
    std::memcpy(g_slots[i].name, name.c_str(), name.size() + 1);
    g_slots[i].state.store(kHeld);
    return int(i);
  }
  return -1;  // more than 64 at once: this one is only removed by its destructor
}

void unregisterTemporary(int slot) {
  if (slot >= 0) g_slots[std::size_t(slot)].state.store(kFree);
}

// Where the file's bytes go: a symbolic link is written through, so that the link stays and
// the file it points to is replaced (as editors do), in that file's own folder.
std::string resolvedTarget(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code error;
  if (!fs::is_symlink(path, error)) return path;
  const fs::path target = fs::weakly_canonical(fs::path(path), error);
  return error ? path : target.string();
}

}  // namespace

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)) {
  namespace fs = std::filesystem;
  if (path_.empty()) throw WriteError("(no name)", "no output file name given");
  target_ = resolvedTarget(path_);
  struct stat st {};
  mode_t keptMode = 0;
  bool replacing = false;
  if (::lstat(target_.c_str(), &st) == 0) {
    // Renaming over a device or a pipe would replace it (as root, /dev/full itself).
    if (S_ISDIR(st.st_mode)) throw WriteError(path_, "is a folder, not a file");
    if (S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode)) throw WriteError(path_, "is a device, not a file");
    if (S_ISFIFO(st.st_mode) || S_ISSOCK(st.st_mode)) throw WriteError(path_, "is a pipe or socket, not a file");
    if (S_ISREG(st.st_mode)) replacing = true, keptMode = st.st_mode & 07777;
  }
  const fs::path parent = fs::path(target_).parent_path();
  const fs::path folder = parent.empty() ? fs::path(".") : parent;
  if (::stat(folder.c_str(), &st) != 0) throw WriteError(path_, "the folder " + folder.string() + " does not exist");
  if (!S_ISDIR(st.st_mode)) throw WriteError(path_, folder.string() + " is not a folder");
  std::string pattern = (folder / ("." + fs::path(target_).filename().string() + ".XXXXXX")).string();
  std::vector<char> name(pattern.begin(), pattern.end());
  name.push_back('\0');
  fd_ = ::mkstemp(name.data());
  if (fd_ < 0) throw WriteError(path_, "cannot write in " + folder.string() + ": " + reason(errno));
  temporary_ = name.data();
  slot_ = registerTemporary(temporary_);
  // A replaced file keeps its permissions (a private 0600 picture stays private); a new one
  // gets those a new file would (mkstemp makes it 0600).
  if (replacing) {
    ::fchmod(fd_, keptMode);
  } else {
    const mode_t mask = ::umask(0);
    ::umask(mask);
    ::fchmod(fd_, 0666 & ~mask);
  }
}

AtomicFile::~AtomicFile() {
  if (fd_ >= 0) ::close(fd_);
  if (!committed_ && !temporary_.empty()) ::unlink(temporary_.c_str());
  unregisterTemporary(slot_);
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
  if (::rename(temporary_.c_str(), target_.c_str()) != 0)
    throw WriteError(path_, "cannot replace the file: " + reason(errno));
  committed_ = true;
  unregisterTemporary(slot_);
  slot_ = -1;
}

void writeFileAtomically(const std::string& path, std::string_view bytes) {
  AtomicFile file(path);
  file.write(bytes);
  file.commit();
}

void writeFilesTogether(const std::vector<std::pair<std::string, std::string>>& pathsAndBytes) {
  std::vector<std::unique_ptr<AtomicFile>> files;
  for (const auto& [path, bytes] : pathsAndBytes) {
    files.push_back(std::make_unique<AtomicFile>(path));
    files.back()->write(bytes);
  }
  for (const auto& file : files) file->commit();
}

void checkWritable(const std::string& path) { AtomicFile probe(path); }

}  // namespace volpost

// SPDX-License-Identifier: MIT
#include <volpost/core/ResourceLimits.hpp>

#include <volpost/core/Error.hpp>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

namespace volpost {
namespace {

std::atomic<std::size_t> g_budget{0};  // 0: not set, use the default
std::atomic<std::size_t> g_gpuBudget{0};  // 0: not set, use the default

std::size_t defaultBudget() {
  if (const char* env = std::getenv("VOLPOST_MEMORY_BUDGET"))
    if (const std::size_t b = parseByteSize(env)) return b;
  const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGESIZE);
  double budget = pages > 0 && page > 0 ? double(pages) * double(page) * 0.75 : double(std::size_t(8) << 30);
  // Under a limit on the address space or data (ulimit -v / -d), stay well inside it:
  // the process also needs room for code, libraries and the GPU driver.
  for (int resource : {RLIMIT_AS, RLIMIT_DATA}) {
    struct rlimit limit {};
    if (getrlimit(resource, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY)
      budget = std::min(budget, double(limit.rlim_cur) * 0.5);
  }
  return std::size_t(budget);
}

}  // namespace

std::size_t parseByteSize(const std::string& text) {
  if (text.empty()) return 0;
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(text.c_str(), &end);
  if (errno || end == text.c_str() || !(v > 0.0) || !std::isfinite(v)) return 0;
  double scale = 1.0;
  std::string unit(end);
  if (!unit.empty() && (unit.back() == 'B' || unit.back() == 'b')) unit.pop_back();
  if (unit == "" ) scale = 1.0;
  else if (unit == "K" || unit == "k") scale = 1024.0;
  else if (unit == "M" || unit == "m") scale = 1024.0 * 1024.0;
  else if (unit == "G" || unit == "g") scale = 1024.0 * 1024.0 * 1024.0;
  else if (unit == "T" || unit == "t") scale = 1024.0 * 1024.0 * 1024.0 * 1024.0;
  else return 0;
  const double bytes = v * scale;
  if (bytes >= double(std::numeric_limits<std::size_t>::max())) return std::numeric_limits<std::size_t>::max();
  return std::size_t(bytes);
}

std::string byteSizeText(double bytes) {
  const char* units[] = {"bytes", "KB", "MB", "GB", "TB", "PB", "EB"};
  int u = 0;
  while (bytes >= 1024.0 && u < 6) {
    bytes /= 1024.0;
    ++u;
  }
  char text[64];
  std::snprintf(text, sizeof text, u == 0 ? "%.0f %s" : "%.3g %s", bytes, units[u]);
  return text;
}

std::size_t processResidentBytes() {
  std::FILE* f = std::fopen("/proc/self/statm", "r");
  if (!f) return 0;
  unsigned long long size = 0, resident = 0;
  const int read = std::fscanf(f, "%llu %llu", &size, &resident);
  std::fclose(f);
  const long page = sysconf(_SC_PAGESIZE);
  return read == 2 && page > 0 ? std::size_t(resident) * std::size_t(page) : 0;
}

std::size_t memoryBudget() {
  const std::size_t set = g_budget.load();
  if (set) return set;
  static const std::size_t fallback = defaultBudget();
  return fallback;
}

void setMemoryBudget(std::size_t bytes) { g_budget.store(bytes); }

std::size_t gpuMemoryBudget() {
  if (const std::size_t set = g_gpuBudget.load()) return set;
  if (const char* env = std::getenv("VOLPOST_GPU_MEMORY_BUDGET")) return parseByteSize(env);
  return 0;
}

void setGpuMemoryBudget(std::size_t bytes) { g_gpuBudget.store(bytes); }

void requireMemory(double bytes, const std::string& file, const std::string& what) {
  const std::size_t budget = memoryBudget();
  if (!(bytes <= double(budget)))
    throw ReadError(file, "needs " + byteSizeText(bytes) + " for " + what + ", more than the memory budget of " +
                              byteSizeText(double(budget)) +
                              " (set a larger one with VOLPOST_MEMORY_BUDGET or --memory-budget, e.g. 16G)");
}

std::size_t checkedProduct(std::uint64_t a, std::uint64_t b, const std::string& file, const std::string& what) {
  std::uint64_t r = 0;
  if (__builtin_mul_overflow(a, b, &r) || r > std::numeric_limits<std::size_t>::max())
    throw ReadError(file, what + " is too large: " + std::to_string(a) + " x " + std::to_string(b) +
                              " does not fit in 64 bits (a corrupt or hostile count)");
  return std::size_t(r);
}

std::size_t checkedSum(std::uint64_t a, std::uint64_t b, const std::string& file, const std::string& what) {
  std::uint64_t r = 0;
  if (__builtin_add_overflow(a, b, &r) || r > std::numeric_limits<std::size_t>::max())
    throw ReadError(file, what + " is too large: " + std::to_string(a) + " + " + std::to_string(b) +
                              " does not fit in 64 bits (a corrupt or hostile count)");
  return std::size_t(r);
}

void requireRegularFile(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) throw ReadError(path, std::string("cannot open: ") + std::strerror(errno));
  if (S_ISDIR(st.st_mode)) throw ReadError(path, "is a folder, not a file");
  if (S_ISFIFO(st.st_mode)) throw ReadError(path, "is a pipe (FIFO), not a file: save the data to a file first");
  if (S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode)) throw ReadError(path, "is a device, not a file");
  if (S_ISSOCK(st.st_mode)) throw ReadError(path, "is a socket, not a file");
  if (!S_ISREG(st.st_mode)) throw ReadError(path, "is not a regular file");
}

}  // namespace volpost

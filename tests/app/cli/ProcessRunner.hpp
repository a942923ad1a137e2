// SPDX-License-Identifier: MIT
// Runs the volpost executable as a user would and captures what it prints.
#pragma once

#include <array>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <sys/wait.h>

namespace volpost::test {

struct RunResult {
  int exitCode = -1;
  std::string output;  ///< stdout and stderr together
};

inline RunResult runVolpost(const std::string& args) {
  const std::string command = std::string(VOLPOST_EXECUTABLE) + " " + args + " 2>&1";
  RunResult r;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return r;
  std::array<char, 4096> buffer;
  while (std::fgets(buffer.data(), int(buffer.size()), pipe)) r.output += buffer.data();
  const int status = pclose(pipe);
  r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

/// runVolpost under a limit on memory (ulimit -v, kilobytes) and time (seconds): what a
/// hostile file must not exceed. A time-out shows as exit code 124.
inline RunResult runVolpostLimited(const std::string& args, long memoryKB, int seconds,
                                   const std::string& environment = {}) {
  // AddressSanitizer reserves terabytes of address space for its shadow: under it
  // (scripts/sanitize.sh sets VOLPOST_TESTS_UNDER_ASAN) only the time limit applies.
  const bool asan = std::getenv("VOLPOST_TESTS_UNDER_ASAN") != nullptr;
  const std::string cap = asan ? std::string("true") : "ulimit -v " + std::to_string(memoryKB);
  const std::string command = "bash -c '" + cap + "; exec " + environment + " timeout " +
                              std::to_string(seconds) + " " + std::string(VOLPOST_EXECUTABLE) + " " + args + " 2>&1'";
  RunResult r;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return r;
  std::array<char, 4096> buffer;
  while (std::fgets(buffer.data(), int(buffer.size()), pipe)) r.output += buffer.data();
  const int status = pclose(pipe);
  r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

}  // namespace volpost::test

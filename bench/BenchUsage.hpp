// SPDX-License-Identifier: MIT
// What a bench says to an argument it does not take: --help / -h print its usage and exit
// 0 (nothing runs), anything else is named on stderr with the usage, exit 2.
#pragma once

#include <cstdio>
#include <cstring>

namespace volpost::bench {

/// `usage`: the bench's name and what it measures on the first line, then its options.
inline int usageFor(const char* argument, const char* usage) {
  const bool help = !std::strcmp(argument, "--help") || !std::strcmp(argument, "-h");
  if (help) {
    std::fputs(usage, stdout);
    return 0;
  }
  std::fprintf(stderr, "unknown argument '%s' (or a missing value)\n%s", argument, usage);
  return 2;
}

}  // namespace volpost::bench

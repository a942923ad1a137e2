// SPDX-License-Identifier: MIT
// Paths to test data and helpers shared by the tests.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace volpost::test {

/// Small files committed with the repository (tests/data).
inline std::string dataFile(const std::string& relative) {
  return (std::filesystem::path(VOLPOST_TEST_DATA) / relative).string();
}

/// Larger cases in ../shared/data; empty when that folder is not there (a user's clone).
inline std::string sharedFile(const std::string& relative) {
  const auto p = std::filesystem::path(VOLPOST_SHARED_DATA) / relative;
  return std::filesystem::exists(p) ? p.string() : std::string();
}

}  // namespace volpost::test

/// Declares `path` for a ../shared/data file, or reports the test as not run.
#define VOLPOST_SHARED_OR_SKIP(path, relative)                                               \
  const std::string path = ::volpost::test::sharedFile(relative);                           \
  if (path.empty()) GTEST_SKIP() << "not run: ../shared/data/" << relative << " is absent"

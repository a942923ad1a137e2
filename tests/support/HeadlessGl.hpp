// SPDX-License-Identifier: MIT
// Tests that draw need a headless OpenGL 4.5 context: where the machine has none they report
// themselves as not run, saying why, rather than pass or fail.
#pragma once

#include <volpost/render/HeadlessContext.hpp>

#include <string>

namespace volpost::test {

/// Why no headless OpenGL 4.5 context can be made here; empty when one can.
inline std::string headlessGlMissing() {
  try {
    HeadlessContext probe;
  } catch (const std::exception& e) {
    return e.what();
  }
  return {};
}

}  // namespace volpost::test

/// In a test body: skip it (not run, with the reason) where no context can be made.
#define VOLPOST_SKIP_WITHOUT_GL()                                                          \
  if (const std::string why = volpost::test::headlessGlMissing(); !why.empty())            \
  GTEST_SKIP() << "not run: no headless OpenGL 4.5 context: " << why

// SPDX-License-Identifier: MIT
// The small tet4 bar of tests/data (10 x 1 x 1, fixed at x = 0, pulled at x = 10), read
// once per test program and shared by the scene tests.
#pragma once

#include "support/ReaderSupport.hpp"
#include "support/TestSupport.hpp"

#include "core/ModelSession.hpp"

#include <memory>

namespace volpost::test {

inline std::shared_ptr<const app::ModelSession> barSession() {
  static const auto session = app::ModelSession::load(meshioReaders(), dataFile("bar/bar_tet4.vtu"));
  return session;
}

}  // namespace volpost::test

// SPDX-License-Identifier: MIT
#include "DisplayRange.hpp"

#include "ModelSession.hpp"

namespace volpost::app {

DisplayRange autoRange(const ScalarView& view) {
  if (!view.range.valid()) return {0.0, 1.0};
  return {view.range.min, view.range.max};
}

}  // namespace volpost::app

// SPDX-License-Identifier: MIT
// A model of some of another's cells: every node kept (their indices, so nodal fields are
// shared as they are), the element results cut to the kept cells, each cell keeping the
// file's number. The threshold and the shown sets draw such a part, so the surface, the
// sections, iso-surfaces, the volume, probing and the extremes all follow it.
#pragma once

#include "ModelSession.hpp"

#include <memory>
#include <vector>

namespace volpost::app {

/// The part of `session`'s model made of the cells where kept[c] is nonzero. May keep no
/// cell at all.
std::shared_ptr<ModelSession> cellSubsetSession(const ModelSession& session, const std::vector<char>& kept);

}  // namespace volpost::app

// SPDX-License-Identifier: MIT
// Which of the model's sets hold an element or a node: what an analyst asks of a probed
// point along with its numbers ("element 15600: E_HEXAHEDRON, EALL").
#pragma once

#include <volpost/core/EntitySet.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace volpost::app {

/// The names of the sets of `kind` among `sets` (modelSets() of the model, made once by the
/// caller) holding the element or node `index`, in their order.
std::vector<std::string> setsHolding(const std::vector<EntitySet>& sets, SetKind kind, std::size_t index);
/// "E_HEXAHEDRON, EALL" (names with spaces quoted), or empty.
std::string setNameList(const std::vector<std::string>& names);

}  // namespace volpost::app

// SPDX-License-Identifier: MIT
// CalculiX writes its results (.frd) without the deck's sets; the deck (.inp of the same
// name) is usually beside it. Its ELSET and NSET are read from there and matched to the
// results' mesh by the element and node ids the two files share.
#pragma once

#include <volpost/core/Model.hpp>

#include <string>

namespace volpost::meshio {

/// Adds the sets of the deck beside `resultsPath` (same name, .inp) to `model`, with an
/// info saying where they came from. A deck that cannot be read, or whose ids the results
/// lack, is said in a diagnostic; the results are loaded all the same.
void addSetsFromDeckBeside(const std::string& resultsPath, Model& model);

}  // namespace volpost::meshio

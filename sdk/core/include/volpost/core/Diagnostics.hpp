// SPDX-License-Identifier: MIT
// Defects found in a loaded model: the model loads, the defect is flagged and shown.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace volpost {

enum class Severity { Info, Warning };

struct Diagnostic {
  Severity severity = Severity::Warning;
  std::string code;                 ///< stable key: "inverted-cells", "nan-values", ...
  std::string message;              ///< one line for people
  std::vector<std::size_t> items;   ///< the cells or nodes concerned (0-based), possibly capped
};

}  // namespace volpost

// SPDX-License-Identifier: MIT
// The ".tetra" format of this example: a header line "TETRA 1", then
//   nodes N        followed by N lines "x y z"
//   tets M         followed by M lines of 4 node indices (0-based)
//   field NAME node|cell   followed by one value per node or per tet (optional, repeatable)
// Lines starting with '#' are comments.
#pragma once

#include <volpost/core/MeshReader.hpp>

class TetraReader : public volpost::MeshReader {
 public:
  std::string formatName() const override { return "Example tetra text"; }
  std::vector<std::string> extensions() const override { return {"tetra"}; }
  int sniff(std::string_view head) const override { return head.rfind("TETRA 1", 0) == 0 ? 100 : 0; }
  std::unique_ptr<volpost::Model> read(const std::string& path, const volpost::Progress& progress) const override;
};

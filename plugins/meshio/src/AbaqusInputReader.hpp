// SPDX-License-Identifier: MIT
// Abaqus / CalculiX input decks (.inp): *NODE, *ELEMENT (solid types), element sets,
// *INCLUDE. Decks hold no results (those are in CalculiX's .frd).
#pragma once

#include <volpost/core/MeshReader.hpp>

namespace volpost::meshio {

class AbaqusInputReader : public MeshReader {
 public:
  std::string formatName() const override { return "Abaqus/CalculiX input deck"; }
  std::vector<std::string> extensions() const override { return {"inp"}; }
  int sniff(std::string_view head) const override;
  std::unique_ptr<Model> read(const std::string& path, const Progress& progress) const override;
};

}  // namespace volpost::meshio

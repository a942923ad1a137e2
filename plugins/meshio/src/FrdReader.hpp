// SPDX-License-Identifier: MIT
// CalculiX results (.frd, ASCII): the mesh (node block 2C, element block 3C) and every
// nodal result block (100C) of every step: displacements, stresses, strains, temperatures,
// heat flux, error estimates...
#pragma once

#include <volpost/core/MeshReader.hpp>

namespace volpost::meshio {

class FrdReader : public MeshReader {
 public:
  std::string formatName() const override { return "CalculiX results"; }
  std::vector<std::string> extensions() const override { return {"frd"}; }
  int sniff(std::string_view head) const override;
  std::unique_ptr<Model> read(const std::string& path, const Progress& progress) const override;
};

}  // namespace volpost::meshio

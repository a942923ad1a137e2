// SPDX-License-Identifier: MIT
// Gmsh meshes (.msh): versions 2.2 and 4.1, ASCII and binary, with $NodeData,
// $ElementData and $ElementNodeData result views (one block per time step).
#pragma once

#include <volpost/core/MeshReader.hpp>

namespace volpost::meshio {

class GmshReader : public MeshReader {
 public:
  std::string formatName() const override { return "Gmsh mesh"; }
  std::vector<std::string> extensions() const override { return {"msh"}; }
  int sniff(std::string_view head) const override;
  std::unique_ptr<Model> read(const std::string& path, const Progress& progress) const override;
};

}  // namespace volpost::meshio

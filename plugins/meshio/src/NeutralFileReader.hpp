// SPDX-License-Identifier: MIT
// The Tecgraf/PUC-Rio neutral file (.nf, .pos) of the Pos3D family (MTool, MView, FAST):
// %NODE.COORD, %ELEMENT.<type> (TETR4/TET4, TET10, BRICK8, BRICK20; T3/T6/Q4/Q8 surfaces
// skipped), and %RESULT.CASE.STEP blocks: nodal displacement, scalars and vectors,
// Gauss-point and element-nodal scalars. What is accepted: docs/user/formats.md.
#pragma once

#include <volpost/core/MeshReader.hpp>

namespace volpost::meshio {

class NeutralFileReader : public MeshReader {
 public:
  std::string formatName() const override { return "Tecgraf neutral file"; }
  std::vector<std::string> extensions() const override { return {"nf", "pos", "neu"}; }
  int sniff(std::string_view head) const override;
  std::unique_ptr<Model> read(const std::string& path, const Progress& progress) const override;
};

}  // namespace volpost::meshio

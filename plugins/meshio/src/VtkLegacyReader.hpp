// SPDX-License-Identifier: MIT
// Legacy VTK files (.vtk): UNSTRUCTURED_GRID, ASCII or BINARY (big-endian), versions up to
// 5.1 (OFFSETS/CONNECTIVITY cells), POINT_DATA/CELL_DATA with SCALARS, VECTORS, NORMALS,
// TENSORS, TENSORS6 and FIELD arrays.
#pragma once

#include <volpost/core/MeshReader.hpp>

namespace volpost::meshio {

class VtkLegacyReader : public MeshReader {
 public:
  std::string formatName() const override { return "VTK legacy"; }
  std::vector<std::string> extensions() const override { return {"vtk"}; }
  int sniff(std::string_view head) const override;
  std::unique_ptr<Model> read(const std::string& path, const Progress& progress) const override;
};

}  // namespace volpost::meshio

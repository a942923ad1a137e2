// SPDX-License-Identifier: MIT
// Exodus II (.exo, .e): netCDF classic, 64-bit offset or netCDF-4/HDF5 files through the
// netCDF C library. Element blocks of solid types, the node and element number maps, and
// nodal and element variables of every time step.
#pragma once

#include <volpost/core/MeshReader.hpp>

namespace volpost::meshio {

class ExodusReader : public MeshReader {
 public:
  std::string formatName() const override { return "Exodus II"; }
  std::vector<std::string> extensions() const override { return {"exo", "e", "ex2", "exii"}; }
  int sniff(std::string_view head) const override;
  std::unique_ptr<Model> read(const std::string& path, const Progress& progress) const override;
};

}  // namespace volpost::meshio

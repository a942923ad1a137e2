// SPDX-License-Identifier: MIT
// VTK XML image data (.vti), read by the same machinery as .vtu (VtkXmlReading.hpp): every
// encoding, compression and header size, pieces placed at their extents.
#pragma once

#include "VtuReader.hpp"  // kReadVtkXmlInPlaceFrom

#include <volpost/core/MeshReader.hpp>

#include <cstdint>

namespace volpost::meshio {

/// VTK XML image data (.vti): a regular grid (WholeExtent, Origin, Spacing and VTK 9's
/// Direction), its pieces' point and cell arrays placed at their extents; read by the same
/// XML machinery as .vtu (every encoding). The model carries the grid and its hexahedra.
class VtiReader : public MeshReader {
 public:
  explicit VtiReader(std::uint64_t readInPlaceFrom = kReadVtkXmlInPlaceFrom) : readInPlaceFrom_(readInPlaceFrom) {}
  std::string formatName() const override { return "VTK XML image data"; }
  std::vector<std::string> extensions() const override { return {"vti"}; }
  int sniff(std::string_view head) const override;
  std::unique_ptr<Model> read(const std::string& path, const Progress& progress) const override;

 private:
  std::uint64_t readInPlaceFrom_;
};

}  // namespace volpost::meshio

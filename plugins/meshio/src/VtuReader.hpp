// SPDX-License-Identifier: MIT
// VTK XML unstructured grids (.vtu): ascii, inline base64 and appended (raw or base64)
// data, zlib compression, UInt32 or UInt64 headers, either byte order, several pieces.
#pragma once

#include <volpost/core/MeshReader.hpp>

namespace volpost::meshio {

class VtuReader : public MeshReader {
 public:
  std::string formatName() const override { return "VTK XML unstructured grid"; }
  std::vector<std::string> extensions() const override { return {"vtu"}; }
  int sniff(std::string_view head) const override;
  std::unique_ptr<Model> read(const std::string& path, const Progress& progress) const override;
};

}  // namespace volpost::meshio

// SPDX-License-Identifier: MIT
// VTK XML unstructured grids (.vtu): ascii, inline base64 and appended (raw or base64) data,
// zlib compression, UInt32 or UInt64 headers, either byte order, several pieces. The image
// data reader (.vti, VtiReader.hpp) shares the machinery (VtkXmlReading.hpp).
#pragma once

#include <volpost/core/MeshReader.hpp>

#include <cstdint>

namespace volpost::meshio {

/// Files from this size on are not read whole into memory: their appended arrays are
/// decoded from the file where they lie, and their lazy fields read from it when first
/// shown (a field read after the file was changed is refused, naming it).
inline constexpr std::uint64_t kReadVtkXmlInPlaceFrom = std::uint64_t(64) << 20;

class VtuReader : public MeshReader {
 public:
  explicit VtuReader(std::uint64_t readInPlaceFrom = kReadVtkXmlInPlaceFrom) : readInPlaceFrom_(readInPlaceFrom) {}
  std::string formatName() const override { return "VTK XML unstructured grid"; }
  std::vector<std::string> extensions() const override { return {"vtu"}; }
  int sniff(std::string_view head) const override;
  std::unique_ptr<Model> read(const std::string& path, const Progress& progress) const override;

 private:
  std::uint64_t readInPlaceFrom_;
};

}  // namespace volpost::meshio

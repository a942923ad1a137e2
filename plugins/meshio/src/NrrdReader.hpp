// SPDX-License-Identifier: MIT
// NRRD ("nearly raw raster data", Teem's format: a short text header over raw, text, hex
// or gzip samples; .nrrd with the data attached, .nhdr with it in a file of its own), read
// as a regular grid. Three axes of samples make a scalar field; four, of which the first
// is not spatial (2 to 9 components: a vector, a tensor, a color), a field of that many
// components per point. Placement from "space directions" and "space origin" (rotated and
// sheared grids stay so), or "spacings"; raw data is read when first shown, after its size
// was checked against the file.
#pragma once

#include <volpost/core/MeshReader.hpp>

namespace volpost::meshio {

class NrrdReader : public MeshReader {
 public:
  std::string formatName() const override { return "NRRD raw volume"; }
  std::vector<std::string> extensions() const override { return {"nrrd", "nhdr"}; }
  int sniff(std::string_view head) const override;
  std::unique_ptr<Model> read(const std::string& path, const Progress& progress) const override;
};

}  // namespace volpost::meshio

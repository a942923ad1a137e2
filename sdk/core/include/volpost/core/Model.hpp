// SPDX-License-Identifier: MIT
// A loaded FE model (or a regular grid such as a seismic cube): the mesh, its result fields and what was found wrong with it.
#pragma once

#include <volpost/core/Diagnostics.hpp>
#include <volpost/core/Field.hpp>
#include <volpost/core/Mesh.hpp>
#include <volpost/core/RegularGrid.hpp>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace volpost {

struct Model {
  std::string sourcePath;
  std::string formatName;   ///< e.g. "VTK XML unstructured grid"
  std::string title;        ///< header/title line of the file, if any
  Mesh mesh;
  /// Set when the mesh is this regular grid's hexahedra (hexahedraOfGrid): grid renderers
  /// then sample its point fields as a 3D texture.
  std::optional<RegularGrid> grid;
  std::vector<std::shared_ptr<Field>> fields;
  std::vector<Diagnostic> diagnostics;

  const Field* findField(const std::string& name) const;
};

}  // namespace volpost

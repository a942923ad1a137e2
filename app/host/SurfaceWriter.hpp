// SPDX-License-Identifier: MIT
// Surface meshes (boundary, iso-surfaces) to files other tools read.
#pragma once

#include <volpost/core/BoundarySurface.hpp>

#include <string>

namespace volpost {

/// Writes a surface as .obj, .ply, .stl or .off (by the extension) through OpenMesh, in
/// model coordinates (origin added back). Throws WriteError naming the file.
void writeSurface(const SurfaceMesh& mesh, const glm::dvec3& origin, const std::string& path);

}  // namespace volpost

// SPDX-License-Identifier: MIT
// Surface meshes (boundary, iso-surfaces) to files other tools read.
#pragma once

#include "host/BoundarySurface.hpp"

#include <string>

namespace volpost {

struct SurfaceWriteResult {
  bool binary = false;  ///< STL/PLY: binary (float32) or, when float would move vertices, text
};

/// Writes a surface as .obj, .ply, .stl or .off (by the extension) through OpenMesh, in
/// model coordinates (origin added back in double, 17 digits in text). Binary STL/PLY
/// only where float32 keeps every vertex within 1e-6 of the model's size. Throws
/// WriteError naming the file; a failed write leaves the previous file intact.
SurfaceWriteResult writeSurface(const SurfaceMesh& mesh, const glm::dvec3& origin, const std::string& path);

}  // namespace volpost

// SPDX-License-Identifier: MIT
#include "host/SurfaceWriter.hpp"

#include <OpenMesh/Core/IO/MeshIO.hh>

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace volpost {

void writeSurface(const SurfaceMesh& mesh, const glm::dvec3& origin, const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  if (ext != ".obj" && ext != ".ply" && ext != ".stl" && ext != ".off")
    throw WriteError(path, "surface files are written as .obj, .ply, .stl or .off, not '" + ext + "'");
  SurfaceMesh shifted = mesh;
  const SurfaceMesh::Point o(float(origin.x), float(origin.y), float(origin.z));
  for (auto v : shifted.vertices()) shifted.set_point(v, shifted.point(v) + o);
  OpenMesh::IO::Options options;
  if (ext == ".stl" || ext == ".ply") options += OpenMesh::IO::Options::Binary;
  if (!OpenMesh::IO::write_mesh(shifted, path, options)) throw WriteError(path, "OpenMesh could not write the surface");
}

}  // namespace volpost

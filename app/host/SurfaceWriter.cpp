// SPDX-License-Identifier: MIT
#include "host/SurfaceWriter.hpp"

#include "host/AtomicFile.hpp"

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/System/omstream.hh>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <array>
#include <filesystem>
#include <sstream>

namespace volpost {
namespace {

// Written in double: a model placed at UTM coordinates (5e6) with 0.1-unit cells needs
// more digits than float's 7 (in float, its neighbouring nodes merged).
struct DoubleTraits : public OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};
using ExportMesh = OpenMesh::TriMesh_ArrayKernelT<DoubleTraits>;

ExportMesh inModelCoordinates(const SurfaceMesh& mesh, const glm::dvec3& origin) {
  ExportMesh out;
  out.reserve(mesh.n_vertices(), mesh.n_edges(), mesh.n_faces());
  for (auto v : mesh.vertices()) {
    const auto p = mesh.point(v);
    out.add_vertex(ExportMesh::Point(double(p[0]) + origin.x, double(p[1]) + origin.y, double(p[2]) + origin.z));
  }
  for (auto f : mesh.faces()) {
    std::vector<ExportMesh::VertexHandle> corners;
    for (auto v : mesh.fv_range(f)) corners.push_back(ExportMesh::VertexHandle(v.idx()));
    out.add_face(corners);
  }
  return out;
}

// Binary STL and PLY store float32. They are used when float keeps every vertex within a
// millionth of the model's size of where it is; else the text form, with 17 digits.
bool floatIsEnough(const ExportMesh& mesh);

// The text formats, written here in double with 17 significant digits (OpenMesh's writers
// go through float).
std::string textSurface(const ExportMesh& mesh, const std::string& ext) {
  std::ostringstream out;
  out.precision(17);
  const auto corners = [&](ExportMesh::FaceHandle f) {
    std::array<int, 3> v{};
    int k = 0;
    for (auto vh : mesh.fv_range(f)) v[std::size_t(k++)] = vh.idx();
    return v;
  };
  if (ext == ".obj") {
    out << "# volpost surface: " << mesh.n_vertices() << " vertices, " << mesh.n_faces() << " triangles\n";
    for (auto v : mesh.vertices()) {
      const auto& p = mesh.point(v);
      out << "v " << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
    }
    for (auto f : mesh.faces()) {
      const auto c = corners(f);
      out << "f " << c[0] + 1 << ' ' << c[1] + 1 << ' ' << c[2] + 1 << '\n';
    }
  } else if (ext == ".off") {
    out << "OFF\n" << mesh.n_vertices() << ' ' << mesh.n_faces() << " 0\n";
    for (auto v : mesh.vertices()) {
      const auto& p = mesh.point(v);
      out << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
    }
    for (auto f : mesh.faces()) {
      const auto c = corners(f);
      out << "3 " << c[0] << ' ' << c[1] << ' ' << c[2] << '\n';
    }
  } else if (ext == ".ply") {
    out << "ply\nformat ascii 1.0\ncomment volpost surface\nelement vertex " << mesh.n_vertices()
        << "\nproperty double x\nproperty double y\nproperty double z\nelement face " << mesh.n_faces()
        << "\nproperty list uchar int vertex_indices\nend_header\n";
    for (auto v : mesh.vertices()) {
      const auto& p = mesh.point(v);
      out << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
    }
    for (auto f : mesh.faces()) {
      const auto c = corners(f);
      out << "3 " << c[0] << ' ' << c[1] << ' ' << c[2] << '\n';
    }
  } else {  // .stl
    out << "solid volpost\n";
    for (auto f : mesh.faces()) {
      const auto c = corners(f);
      const auto& a = mesh.point(ExportMesh::VertexHandle(c[0]));
      const auto& b = mesh.point(ExportMesh::VertexHandle(c[1]));
      const auto& d = mesh.point(ExportMesh::VertexHandle(c[2]));
      OpenMesh::Vec3d n = OpenMesh::cross(b - a, d - a);
      const double length = n.norm();
      if (length > 0.0) n /= length;
      out << " facet normal " << n[0] << ' ' << n[1] << ' ' << n[2] << "\n  outer loop\n";
      for (const auto* p : {&a, &b, &d}) out << "   vertex " << (*p)[0] << ' ' << (*p)[1] << ' ' << (*p)[2] << '\n';
      out << "  endloop\n endfacet\n";
    }
    out << "endsolid volpost\n";
  }
  return out.str();
}

bool floatIsEnough(const ExportMesh& mesh) {
  double size = 0.0, worst = 0.0;
  OpenMesh::Vec3d lo(1e300), hi(-1e300);
  for (auto v : mesh.vertices()) {
    const auto& p = mesh.point(v);
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], p[k]);
      hi[k] = std::max(hi[k], p[k]);
      worst = std::max(worst, std::abs(double(float(p[k])) - p[k]));
    }
  }
  for (int k = 0; k < 3; ++k) size = std::max(size, hi[k] - lo[k]);
  return worst <= 1e-6 * size;
}

}  // namespace

SurfaceWriteResult writeSurface(const SurfaceMesh& mesh, const glm::dvec3& origin, const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  if (ext != ".obj" && ext != ".ply" && ext != ".stl" && ext != ".off")
    throw WriteError(path, "surface files are written as .obj, .ply, .stl or .off, not '" + ext + "'");
  AtomicFile file(path);  // checks the folder now; a failed write leaves the old file intact
  const ExportMesh out = inModelCoordinates(mesh, origin);
  SurfaceWriteResult result;
  result.binary = (ext == ".stl" || ext == ".ply") && floatIsEnough(out);
  if (!result.binary) {
    file.write(textSurface(out, ext));
    file.commit();
    return result;
  }
  OpenMesh::IO::Options options;
  options += OpenMesh::IO::Options::Binary;
  omlog().disable();  // "[STLWriter] : write binary file" is not for the user
  // OpenMesh picks the format from the name's extension: the temporary file has the
  // target's extension at its end (".name.ext.XXXXXX" would not), so write beside it.
  const std::string named = file.temporaryPath() + ext;
  if (!OpenMesh::IO::write_mesh(out, named, options, 17)) {
    std::filesystem::remove(named);
    throw WriteError(path, "OpenMesh could not write the surface");
  }
  std::error_code ec;
  std::filesystem::rename(named, file.temporaryPath(), ec);
  if (ec) {
    std::filesystem::remove(named);
    throw WriteError(path, "cannot write: " + ec.message());
  }
  file.commit();
  return result;
}

}  // namespace volpost

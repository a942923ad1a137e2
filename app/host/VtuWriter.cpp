// SPDX-License-Identifier: MIT
#include "host/VtuWriter.hpp"

#include <bit>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace volpost {
namespace {

static_assert(std::endian::native == std::endian::little, "the writer declares LittleEndian");

struct Block {
  std::string xmlHead;  // <DataArray ... offset="N"/>
  std::vector<char> bytes;
};

template <typename T>
std::vector<char> bytesOf(const std::vector<T>& v) {
  std::vector<char> out(sizeof(std::uint64_t) + v.size() * sizeof(T));
  const std::uint64_t size = v.size() * sizeof(T);
  std::memcpy(out.data(), &size, sizeof size);
  if (!v.empty()) std::memcpy(out.data() + sizeof size, v.data(), size);
  return out;
}

std::string escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '&') out += "&amp;";
    else if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '"') out += "&quot;";
    else out += c;
  }
  return out;
}

class Appended {
 public:
  template <typename T>
  std::string add(const char* type, const std::string& name, int components, const std::vector<T>& values) {
    std::ostringstream head;
    head << "<DataArray type=\"" << type << "\" Name=\"" << escape(name) << "\"";
    if (components > 1) head << " NumberOfComponents=\"" << components << "\"";
    head << " format=\"appended\" offset=\"" << offset_ << "\"/>";
    auto b = bytesOf(values);
    offset_ += b.size();
    data_.insert(data_.end(), b.begin(), b.end());
    return head.str();
  }
  const std::vector<char>& data() const { return data_; }

 private:
  std::vector<char> data_;
  std::size_t offset_ = 0;
};

}  // namespace

void writeVtu(const Model& model, const std::string& path, const Progress& progress) {
  const Mesh& mesh = model.mesh;
  Appended appended;
  std::ostringstream xml;
  xml << "<?xml version=\"1.0\"?>\n<!-- written by volpost from " << escape(model.sourcePath) << " -->\n"
      << "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
      << "<UnstructuredGrid>\n<Piece NumberOfPoints=\"" << mesh.nodeCount() << "\" NumberOfCells=\"" << mesh.cellCount() << "\">\n";

  std::vector<double> points(mesh.nodeCount() * 3);
  for (std::size_t i = 0; i < mesh.nodeCount(); ++i)
    for (int k = 0; k < 3; ++k) points[i * 3 + std::size_t(k)] = mesh.nodes[i][k];
  xml << "<Points>\n" << appended.add("Float64", "Points", 3, points) << "\n</Points>\n";
  progress.report(0.2);

  std::vector<std::int64_t> connectivity(mesh.connectivity().begin(), mesh.connectivity().end());
  std::vector<std::int64_t> offsets(mesh.cellCount());
  std::vector<std::uint8_t> types(mesh.cellCount());
  std::size_t end = 0;
  for (std::size_t c = 0; c < mesh.cellCount(); ++c) {
    end += mesh.cellNodes(c).size();
    offsets[c] = std::int64_t(end);
    types[c] = std::uint8_t(vtkCellType(mesh.cellType(c)));
  }
  xml << "<Cells>\n" << appended.add("Int64", "connectivity", 1, connectivity) << "\n"
      << appended.add("Int64", "offsets", 1, offsets) << "\n" << appended.add("UInt8", "types", 1, types) << "\n</Cells>\n";
  progress.report(0.4);

  for (const FieldLocation location : {FieldLocation::Node, FieldLocation::Cell}) {
    xml << (location == FieldLocation::Node ? "<PointData>\n" : "<CellData>\n");
    const auto& ids = location == FieldLocation::Node ? mesh.nodeIds : mesh.cellIds;
    if (!ids.empty()) xml << appended.add("Int64", location == FieldLocation::Node ? "node_id" : "element_id", 1, ids) << "\n";
    for (const auto& f : model.fields) {
      if (f->location() != location) continue;
      for (std::size_t s = 0; s < f->stepCount(); ++s) {
        const std::string name = f->stepCount() == 1 ? f->name() : f->name() + " step " + std::to_string(s + 1);
        xml << appended.add("Float64", name, f->components(), f->values(s)) << "\n";
      }
    }
    xml << (location == FieldLocation::Node ? "</PointData>\n" : "</CellData>\n");
  }
  progress.report(0.8);
  xml << "</Piece>\n</UnstructuredGrid>\n<AppendedData encoding=\"raw\">\n_";

  const std::string temporary = path + ".part";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) throw WriteError(path, std::string("cannot write: ") + std::strerror(errno));
    const std::string head = xml.str();
    out.write(head.data(), std::streamsize(head.size()));
    out.write(appended.data().data(), std::streamsize(appended.data().size()));
    out << "\n</AppendedData>\n</VTKFile>\n";
    out.flush();
    if (!out) {
      std::filesystem::remove(temporary);
      throw WriteError(path, "write failed (disk full?)");
    }
  }
  std::error_code ec;
  std::filesystem::rename(temporary, path, ec);
  if (ec) {
    std::filesystem::remove(temporary);
    throw WriteError(path, "cannot replace the file: " + ec.message());
  }
  progress.report(1.0);
}

}  // namespace volpost

// SPDX-License-Identifier: MIT
#include "host/PolylineWriter.hpp"

#include "host/AtomicFile.hpp"

#include <algorithm>
#include <bit>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <stdexcept>

namespace volpost {
namespace {

static_assert(std::endian::native == std::endian::little, "the writer declares LittleEndian");

std::string extensionOf(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

// Appended raw arrays: an 8-byte length, then the values.
class Appended {
 public:
  template <typename T>
  std::string add(const char* type, const std::string& name, int components, const std::vector<T>& v) {
    std::ostringstream head;
    head << "<DataArray type=\"" << type << "\" Name=\"" << name << "\"";
    if (components > 1) head << " NumberOfComponents=\"" << components << "\"";
    head << " format=\"appended\" offset=\"" << data_.size() << "\"/>\n";
    const std::uint64_t bytes = v.size() * sizeof(T);
    data_.append(reinterpret_cast<const char*>(&bytes), sizeof bytes);
    if (bytes) data_.append(reinterpret_cast<const char*>(v.data()), bytes);
    return head.str();
  }
  const std::string& data() const { return data_; }

 private:
  std::string data_;
};

std::string safeName(const std::string& s) {  // an attribute value any XML parser takes
  std::string out;
  for (char c : s) {
    if (c == '&') out += "&amp;";
    else if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '"') out += "&quot;";
    else out += static_cast<unsigned char>(c) < 0x20 ? '?' : c;
  }
  return out;
}

std::string vtp(const PolylineSet& s) {
  std::size_t count = 0;
  for (const auto& l : s.points) count += l.size();
  std::vector<double> xyz, vectors, values;
  std::vector<std::int64_t> connectivity, offsets;
  xyz.reserve(count * 3);
  for (std::size_t l = 0; l < s.points.size(); ++l) {
    for (std::size_t i = 0; i < s.points[l].size(); ++i) {
      connectivity.push_back(std::int64_t(xyz.size() / 3));
      for (int k = 0; k < 3; ++k) xyz.push_back(s.points[l][i][k]);
      if (!s.vectors.empty())
        for (int k = 0; k < 3; ++k) vectors.push_back(s.vectors[l][i][k]);
      if (!s.values.empty()) values.push_back(s.values[l][i]);
    }
    offsets.push_back(std::int64_t(connectivity.size()));
  }
  std::vector<double> lengths = s.lengths;
  std::vector<std::int32_t> stops(s.stops.begin(), s.stops.end());
  Appended a;
  std::ostringstream x;
  x << "<?xml version=\"1.0\"?>\n<!-- streamlines written by volpost -->\n"
    << "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n<PolyData>\n"
    << "<Piece NumberOfPoints=\"" << count << "\" NumberOfVerts=\"0\" NumberOfLines=\"" << s.points.size()
    << "\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n<Points>\n" << a.add("Float64", "Points", 3, xyz) << "</Points>\n"
    << "<PointData>\n";
  if (!s.vectors.empty()) x << a.add("Float64", safeName(s.vectorName), 3, vectors);
  if (!s.values.empty()) x << a.add("Float64", safeName(s.valueName), 1, values);
  x << "</PointData>\n<CellData>\n";
  if (!lengths.empty()) x << a.add("Float64", "length", 1, lengths);
  if (!stops.empty()) x << a.add("Int32", "stop", 1, stops);
  x << "</CellData>\n<Lines>\n" << a.add("Int64", "connectivity", 1, connectivity)
    << a.add("Int64", "offsets", 1, offsets) << "</Lines>\n</Piece>\n</PolyData>\n<AppendedData encoding=\"raw\">\n_";
  return x.str() + a.data() + "\n</AppendedData>\n</VTKFile>\n";
}

std::string csv(const PolylineSet& s) {
  std::ostringstream out;
  out.precision(17);
  out << "line,point,x,y,z";
  if (!s.vectors.empty()) out << "," << s.vectorName << "_x," << s.vectorName << "_y," << s.vectorName << "_z";
  if (!s.values.empty()) out << "," << s.valueName;
  out << "\n";
  for (std::size_t l = 0; l < s.points.size(); ++l)
    for (std::size_t i = 0; i < s.points[l].size(); ++i) {
      const glm::dvec3& p = s.points[l][i];
      out << l << ',' << i << ',' << p.x << ',' << p.y << ',' << p.z;
      if (!s.vectors.empty()) out << ',' << s.vectors[l][i].x << ',' << s.vectors[l][i].y << ',' << s.vectors[l][i].z;
      if (!s.values.empty()) out << ',' << s.values[l][i];
      out << '\n';
    }
  return out.str();
}

}  // namespace

namespace {

bool isPolylineFormat(const std::string& ext) { return ext == ".vtp" || ext == ".csv"; }

std::string formatHint(const std::string& ext) {
  return "streamlines are written as .vtp (VTK PolyData, for ParaView) or .csv, not '" + ext + "'";
}

}  // namespace

void checkPolylineFormat(const std::string& path) {
  if (!isPolylineFormat(extensionOf(path))) throw std::invalid_argument(path + ": " + formatHint(extensionOf(path)));
}

void writePolylines(const PolylineSet& lines, const std::string& path) {
  const std::string ext = extensionOf(path);
  if (!isPolylineFormat(ext)) throw WriteError(path, formatHint(ext));
  writeFileAtomically(path, ext == ".vtp" ? vtp(lines) : csv(lines));
}

}  // namespace volpost

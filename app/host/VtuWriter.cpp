// SPDX-License-Identifier: MIT
#include "host/VtuWriter.hpp"

#include "host/AtomicFile.hpp"

#include <bit>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <set>
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

// A name as an XML attribute value that every parser accepts: markup characters escaped,
// and what XML 1.0 cannot hold at all (control characters, bytes that are not UTF-8)
// replaced by '?'.
std::string escape(const std::string& s) {
  std::string out;
  for (std::size_t i = 0; i < s.size();) {
    const auto c = static_cast<unsigned char>(s[i]);
    if (c == '&') out += "&amp;";
    else if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '"') out += "&quot;";
    else if (c < 0x20 || c == 0x7f) out += '?';
    if (c < 0x80) {
      if (c >= 0x20 && c != 0x7f && c != '&' && c != '<' && c != '>' && c != '"') out += char(c);
      ++i;
      continue;
    }
    // A UTF-8 sequence: its lead byte says how long; keep it only when it is whole.
    const std::size_t length = (c & 0xE0) == 0xC0 ? 2 : (c & 0xF0) == 0xE0 ? 3 : (c & 0xF8) == 0xF0 ? 4 : 0;
    bool valid = length > 0 && i + length <= s.size();
    for (std::size_t k = 1; valid && k < length; ++k) valid = (static_cast<unsigned char>(s[i + k]) & 0xC0) == 0x80;
    if (valid) out.append(s, i, length);
    else out += '?';
    i += valid ? length : 1;
  }
  return out;
}

// Names are unique in a VTU's PointData or CellData: a second "T step 1" (a field of that
// name next to field T's first step) would make readers drop or merge both.
class UniqueNames {
 public:
  std::string take(const std::string& wanted) {
    std::string name = wanted.empty() ? "unnamed" : wanted;
    for (int k = 2; !used_.insert(name).second; ++k) name = wanted + " (" + std::to_string(k) + ")";
    return name;
  }

 private:
  std::set<std::string> used_;
};

/// The data of every array: after the XML in one raw block (appended), or inside each
/// DataArray element as base64 (inline).
class ArrayData {
 public:
  explicit ArrayData(VtuLayout layout) : layout_(layout) {}

  /// `extra`: more attributes, already escaped (" VolpostField=...").
  template <typename T>
  std::string add(const char* type, const std::string& name, int components, const std::vector<T>& values,
                  const std::string& extra = {}) {
    std::ostringstream head;
    head << "<DataArray type=\"" << type << "\" Name=\"" << escape(name) << "\"";
    if (components > 1) head << " NumberOfComponents=\"" << components << "\"";
    auto b = bytesOf(values);
    if (layout_ == VtuLayout::Inline) {
      // As VTK writes it: the byte count and the data as two base64 runs.
      head << extra << " format=\"binary\">" << base64(b.data(), sizeof(std::uint64_t))
           << base64(b.data() + sizeof(std::uint64_t), b.size() - sizeof(std::uint64_t)) << "</DataArray>";
      return head.str();
    }
    head << extra << " format=\"appended\" offset=\"" << offset_ << "\"/>";
    offset_ += b.size();
    data_.insert(data_.end(), b.begin(), b.end());
    return head.str();
  }
  const std::vector<char>& appended() const { return data_; }

 private:
  static std::string base64(const char* bytes, std::size_t count) {
    static constexpr char digits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((count + 2) / 3 * 4);
    for (std::size_t i = 0; i < count; i += 3) {
      const auto byte = [&](std::size_t k) {
        return k < count ? std::uint32_t(static_cast<unsigned char>(bytes[k])) : 0u;
      };
      const std::uint32_t group = byte(i) << 16 | byte(i + 1) << 8 | byte(i + 2);
      out += digits[group >> 18 & 63];
      out += digits[group >> 12 & 63];
      out += i + 1 < count ? digits[group >> 6 & 63] : '=';
      out += i + 2 < count ? digits[group & 63] : '=';
    }
    return out;
  }

  VtuLayout layout_;
  std::vector<char> data_;
  std::size_t offset_ = 0;
};

}  // namespace

void writeVtu(const Model& model, const std::string& path, const Progress& progress, VtuLayout layout) {
  const Mesh& mesh = model.mesh();
  ArrayData arrays(layout);
  std::ostringstream xml;
  // No file name in a comment: "--" in a name would end it early and break the XML.
  xml << "<?xml version=\"1.0\"?>\n<!-- written by volpost -->\n"
      << "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
      << "<UnstructuredGrid" << (model.title.empty() ? "" : " VolpostTitle=\"" + escape(model.title) + "\"")
      << ">\n<Piece NumberOfPoints=\"" << mesh.nodeCount() << "\" NumberOfCells=\"" << mesh.cellCount() << "\">\n";

  std::vector<double> points(mesh.nodeCount() * 3);
  for (std::size_t i = 0; i < mesh.nodeCount(); ++i)
    for (int k = 0; k < 3; ++k) points[i * 3 + std::size_t(k)] = mesh.nodes[i][k];
  xml << "<Points>\n" << arrays.add("Float64", "Points", 3, points) << "\n</Points>\n";
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
  xml << "<Cells>\n"
      << arrays.add("Int64", "connectivity", 1, connectivity) << "\n"
      << arrays.add("Int64", "offsets", 1, offsets) << "\n"
      << arrays.add("UInt8", "types", 1, types) << "\n</Cells>\n";
  progress.report(0.4);

  // Steps: one array each ("T step 2"), with attributes (VolpostField, VolpostStep,
  // VolpostTime, VolpostStepLabel) that volpost reads back as the steps of one field; other
  // tools see one array per step and ignore the attributes.
  for (const FieldLocation location : {FieldLocation::Node, FieldLocation::Cell}) {
    xml << (location == FieldLocation::Node ? "<PointData>\n" : "<CellData>\n");
    UniqueNames names;
    const auto& ids = location == FieldLocation::Node ? mesh.nodeIds : mesh.cellIds;
    const char* idName = location == FieldLocation::Node ? "node_id" : "element_id";
    if (!ids.empty()) xml << arrays.add("Int64", names.take(idName), 1, ids) << "\n";
    for (const auto& f : model.fields) {
      if (f->location() != location) continue;
      for (std::size_t s = 0; s < f->stepCount(); ++s) {
        const Step& step = f->steps()[s];
        const std::string name = names.take(f->stepCount() == 1 ? f->name() : f->name() + " step " + std::to_string(s + 1));
        std::ostringstream extra;
        extra.precision(17);
        extra << " VolpostField=\"" << escape(f->name()) << "\" VolpostStep=\"" << s + 1 << "\" VolpostTime=\""
              << step.time << "\"";
        if (!step.label.empty()) extra << " VolpostStepLabel=\"" << escape(step.label) << "\"";
        xml << arrays.add("Float64", name, f->components(), f->values(s), extra.str()) << "\n";
      }
    }
    xml << (location == FieldLocation::Node ? "</PointData>\n" : "</CellData>\n");
  }
  progress.report(0.8);
  xml << "</Piece>\n</UnstructuredGrid>\n";

  AtomicFile file(path);  // a failed write leaves the previous file as it was
  if (layout == VtuLayout::Inline) {
    xml << "</VTKFile>\n";
    file.write(xml.str());
  } else {
    xml << "<AppendedData encoding=\"raw\">\n_";
    file.write(xml.str());
    file.write(std::string_view(arrays.appended().data(), arrays.appended().size()));
    file.write("\n</AppendedData>\n</VTKFile>\n");
  }
  file.commit();
  progress.report(1.0);
}

}  // namespace volpost

// SPDX-License-Identifier: MIT
#include "VtkLegacyReader.hpp"

#include "FileBytes.hpp"
#include "NumericType.hpp"
#include "VtkCells.hpp"

#include <volpost/core/ResourceLimits.hpp>

#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>
#include <map>

namespace volpost::meshio {
namespace {

std::string decodeName(std::string_view raw) {  // VTK writes spaces in names as %20
  std::string out;
  for (std::size_t i = 0; i < raw.size(); ++i) {
    if (raw[i] == '%' && i + 2 < raw.size()) {
      int v = 0;
      if (std::from_chars(raw.data() + i + 1, raw.data() + i + 3, v, 16).ec == std::errc()) {
        out += char(v);
        i += 2;
        continue;
      }
    }
    out += raw[i];
  }
  return out;
}

class LegacyParser {
 public:
  LegacyParser(std::shared_ptr<const std::string> bytes, std::string path)
      : bytesPtr_(std::move(bytes)), b_(*bytesPtr_), path_(std::move(path)) {}

  bool binary = false;

  [[noreturn]] void fail(const std::string& message) const {
    throw ReadError::atLine(path_, lineAt(b_, tokenStart_), message);
  }
  std::size_t product(std::size_t a, std::size_t b, const std::string& what) const {
    return checkedProduct(a, b, path_, what);
  }
  std::int64_t currentLine() const { return lineAt(b_, tokenStart_); }

  std::string_view line() {
    tokenStart_ = pos_;
    const std::size_t end = std::min(b_.find('\n', pos_), b_.size());
    std::string_view l(b_.data() + pos_, end - pos_);
    pos_ = std::min(end + 1, b_.size());
    if (!l.empty() && l.back() == '\r') l.remove_suffix(1);
    return l;
  }

  std::string_view token() {
    while (pos_ < b_.size() && std::isspace(static_cast<unsigned char>(b_[pos_]))) ++pos_;
    tokenStart_ = pos_;
    while (pos_ < b_.size() && !std::isspace(static_cast<unsigned char>(b_[pos_]))) ++pos_;
    return std::string_view(b_.data() + tokenStart_, pos_ - tokenStart_);
  }

  std::string_view peekToken() {
    const std::size_t save = pos_, saveStart = tokenStart_;
    const auto t = token();
    pos_ = save;
    tokenStart_ = saveStart;
    return t;
  }

  std::int64_t integer(const char* what) {
    const auto t = token();
    std::int64_t v = 0;
    const auto r = std::from_chars(t.data(), t.data() + t.size(), v);
    if (t.empty()) fail(std::string("file ends where ") + what + " was expected (truncated)");
    if (r.ec != std::errc() || r.ptr != t.data() + t.size())
      fail(std::string("expected ") + what + ", found '" + std::string(t.substr(0, 40)) + "'");
    return v;
  }

  std::size_t count(const char* what) {
    const std::int64_t v = integer(what);
    if (v < 0 || v > std::int64_t(1) << 40) fail(std::string(what) + " " + std::to_string(v) + " is out of range");
    return std::size_t(v);
  }

  NumericType type() {
    const auto t = token();
    const auto type = numericTypeFromLegacy(t);
    if (!type) fail("unknown data type '" + std::string(t) + "'");
    return *type;
  }

  /// Binary data starts after the newline that ends its header line.
  void toDataStart() {
    if (!binary) return;
    const std::size_t nl = b_.find('\n', pos_);
    pos_ = nl == std::string::npos ? b_.size() : nl + 1;
  }

  /// Binary: byte offset of `count` values and skips them. ASCII: nothing (use values()).
  std::size_t skipBinary(std::size_t count, NumericType t, const std::string& what) {
    toDataStart();
    const std::size_t need = checkedProduct(count, sizeOf(t), path_, what + " size");
    if (b_.size() - pos_ < need)
      throw ReadError::atOffset(path_, pos_, "file ends inside the " + what + " data (truncated): " +
                                                 std::to_string(need) + " bytes needed, " +
                                                 std::to_string(b_.size() - pos_) + " left");
    const std::size_t at = pos_;
    pos_ += need;
    return at;
  }

  // An ASCII value takes at least two bytes ("0 "): a count the rest of the file cannot
  // hold is refused before anything is allocated for it.
  void checkAsciiCount(std::size_t count, const std::string& what) {
    const std::size_t left = b_.size() - std::min(pos_, b_.size());
    if (count > left / 2 + 1)
      fail(what + " declares " + std::to_string(count) + " values, but the " + std::to_string(left) +
           " bytes left in the file can hold at most " + std::to_string(left / 2 + 1) + " (corrupt or truncated)");
  }

  std::vector<double> values(std::size_t count, NumericType t, const std::string& what) {
    if (binary) {
      const std::size_t at = skipBinary(count, t, what);
      return toDoubles(reinterpret_cast<const std::uint8_t*>(b_.data() + at), count, t, true);
    }
    checkAsciiCount(count, what);
    std::vector<double> out(count);
    for (std::size_t i = 0; i < count; ++i) {
      const auto tok = token();
      if (tok.empty())
        fail("file ends inside the " + what + " data (truncated): " + std::to_string(i) + " of " +
             std::to_string(count) + " values read");
      const auto r = std::from_chars(tok.data(), tok.data() + tok.size(), out[i]);
      if (r.ec == std::errc::result_out_of_range) out[i] = tok[0] == '-' ? -HUGE_VAL : HUGE_VAL;
      else if (r.ec != std::errc() || r.ptr != tok.data() + tok.size())
        fail("in the " + what + " data: expected value " + std::to_string(i + 1) + " of " +
             std::to_string(count) + ", found '" + std::string(tok.substr(0, 40)) + "'");
    }
    return out;
  }

  std::vector<std::int64_t> integers(std::size_t count, NumericType t, const std::string& what) {
    std::vector<std::int64_t> out;
    out.reserve(count);
    eachInteger(count, t, what, [&out](std::int64_t v) { out.push_back(v); });
    return out;
  }

  /// Hands `count` integers to use(value) one by one, decoded a chunk at a time (binary)
  /// or token by token (ASCII): no list of all of them in 64 bits.
  template <typename Use>
  void eachInteger(std::size_t count, NumericType t, const std::string& what, Use use) {
    if (isFloating(t)) fail(what + " must be integers, the file says " + std::string(t == NumericType::Float32 ? "float" : "double"));
    if (binary) {
      const std::size_t at = skipBinary(count, t, what);
      constexpr std::size_t kChunk = std::size_t(1) << 16;
      for (std::size_t i = 0; i < count; i += kChunk) {
        const std::size_t n = std::min(kChunk, count - i);
        for (const std::int64_t v : toIntegers(reinterpret_cast<const std::uint8_t*>(b_.data() + at + i * sizeOf(t)), n, t, true))
          use(v);
      }
      return;
    }
    checkAsciiCount(count, what);
    for (std::size_t i = 0; i < count; ++i) {
      const auto tok = token();
      if (tok.empty())
        fail("file ends inside the " + what + " data (truncated): " + std::to_string(i) + " of " +
             std::to_string(count) + " integers read");
      std::int64_t v = 0;
      const auto r = std::from_chars(tok.data(), tok.data() + tok.size(), v);
      if (r.ec != std::errc() || r.ptr != tok.data() + tok.size())
        fail("in the " + what + " data: expected integer " + std::to_string(i + 1) + " of " +
             std::to_string(count) + ", found '" + std::string(tok.substr(0, 40)) + "'");
      use(v);
    }
  }

  /// A field array: values now (ASCII) or a lazy loader over the shared bytes (binary).
  StepLoader array(std::size_t count, NumericType t, const std::string& what) {
    if (!binary) {
      auto v = std::make_shared<std::vector<double>>(values(count, t, what));
      return [v](std::size_t) { return *v; };
    }
    const std::size_t at = skipBinary(count, t, what);
    auto bytes = bytesPtr_;
    return [bytes, at, count, t](std::size_t) {
      return toDoubles(reinterpret_cast<const std::uint8_t*>(bytes->data() + at), count, t, true);
    };
  }

  /// The same array kept in the file's type (a grid's samples): values now (ASCII) or a
  /// lazy decode of the shared bytes (binary, big-endian as legacy VTK writes it).
  SampleLoader samples(std::size_t count, NumericType t, const std::string& what) {
    if (!binary) {
      auto kept = std::make_shared<SampleArray>(toSamples(values(count, t, what), t));
      return [kept](std::size_t) { return *kept; };
    }
    const std::size_t at = skipBinary(count, t, what);
    auto bytes = bytesPtr_;
    return [bytes, at, count, t](std::size_t) {
      return toSamples(reinterpret_cast<const std::uint8_t*>(bytes->data() + at), count, t, true);
    };
  }

  bool atEnd() {
    while (pos_ < b_.size() && std::isspace(static_cast<unsigned char>(b_[pos_]))) ++pos_;
    return pos_ >= b_.size();
  }
  std::size_t position() const { return pos_; }
  std::size_t size() const { return b_.size(); }

 private:
  std::shared_ptr<const std::string> bytesPtr_;
  const std::string& b_;
  std::string path_;
  std::size_t pos_ = 0;
  std::size_t tokenStart_ = 0;
};

struct PendingArray {
  std::string name;
  FieldLocation location;
  int components;
  std::size_t tuples;
  StepLoader loader;     ///< as doubles (meshes, tensors)
  SampleLoader samples;  ///< or in the file's type (a grid's arrays)
};

// Full 3x3 tensors are stored as their symmetric part, in volpost's xx yy zz xy yz zx order.
StepLoader symmetricPart(StepLoader full) {
  return [full](std::size_t step) {
    const auto v = full(step);
    std::vector<double> out(v.size() / 9 * 6);
    for (std::size_t i = 0; i < v.size() / 9; ++i) {
      const double* t = v.data() + 9 * i;
      double* s = out.data() + 6 * i;
      s[0] = t[0]; s[1] = t[4]; s[2] = t[8];
      s[3] = 0.5 * (t[1] + t[3]); s[4] = 0.5 * (t[5] + t[7]); s[5] = 0.5 * (t[2] + t[6]);
    }
    return out;
  };
}

// Largest |t_ij - t_ji| relative to the largest |t| over all tensors; 0 when symmetric to
// float precision (values written as float32 agree to about 1e-7).
double largestAsymmetry(const std::vector<double>& v) {
  double worst = 0.0, scale = 0.0;
  for (std::size_t i = 0; i + 9 <= v.size(); i += 9) {
    const double* t = v.data() + i;
    for (int k = 0; k < 9; ++k) scale = std::max(scale, std::abs(t[k]));
    worst = std::max({worst, std::abs(t[1] - t[3]), std::abs(t[2] - t[6]), std::abs(t[5] - t[7])});
  }
  if (!(scale > 0.0)) return 0.0;
  const double relative = worst / scale;
  return relative <= 1e-6 ? 0.0 : relative;
}

class LegacyReading {
 public:
  LegacyReading(std::shared_ptr<const std::string> bytes, const std::string& path, const Progress& progress)
      : p_(bytes, path), path_(path), progress_(progress) {}

  std::unique_ptr<Model> run() {
    auto model = std::make_unique<Model>();
    header(*model);
    std::size_t pointCount = 0;
    bool haveCells = false;
    RegularGrid grid;  // STRUCTURED_POINTS: filled by DIMENSIONS, ORIGIN, SPACING
    bool haveDimensions = false;
    VtkCellMapping mapping;
    FieldLocation location = FieldLocation::Node;
    std::size_t sectionCount = 0;
    bool inSection = false;
    std::map<std::string, std::int64_t> seen;  // section -> line: POINTS, CELLS, CELL_TYPES come once
    while (!p_.atEnd()) {
      const std::string key(p_.token());
      if (key == "POINTS" || key == "CELLS" || key == "CELL_TYPES" || key == "POINT_DATA" || key == "CELL_DATA") {
        const auto [it, first] = seen.emplace(key, p_.currentLine());
        if (!first) p_.fail("a second " + key + " section (the first is at line " + std::to_string(it->second) + "): a file has one");
      }
      if (structured_ && (key == "DIMENSIONS" || key == "ORIGIN" || key == "SPACING" || key == "ASPECT_RATIO")) {
        if (haveCells) p_.fail(key + " after the point or cell data: it describes the grid and comes first");
        if (key == "DIMENSIONS") {
          for (std::size_t& n : grid.dims) n = p_.count("a DIMENSIONS entry");
          haveDimensions = true;
        } else {
          glm::dvec3 v;
          for (int a = 0; a < 3; ++a) v[a] = number(key);  // in order: not three arguments of one call
          if (key == "ORIGIN") grid.origin = v;
          else grid.axes = {glm::dvec3(v.x, 0, 0), glm::dvec3(0, v.y, 0), glm::dvec3(0, 0, v.z)};
        }
        continue;
      }
      if (structured_ && (key == "POINTS" || key == "CELLS" || key == "CELL_TYPES"))
        p_.fail(key + " in a STRUCTURED_POINTS file (its points are DIMENSIONS, ORIGIN and SPACING)");
      if (structured_ && !haveCells && (key == "POINT_DATA" || key == "CELL_DATA")) {
        if (!haveDimensions) p_.fail(key + " before DIMENSIONS");
        buildGrid(*model, grid, mapping);
        pointCount = grid.pointCount();
        haveCells = true;
      }
      if (key == "POINTS") {
        if (seen.count("CELLS")) p_.fail("POINTS after CELLS: the cells would refer to points not read yet");
        pointCount = p_.count("the number of points");
        const NumericType t = p_.type();
        const auto xyz = p_.values(p_.product(pointCount, 3, "POINTS"), t, "POINTS");
        model->mesh().nodes.resize(pointCount);
        for (std::size_t i = 0; i < pointCount; ++i)
          model->mesh().nodes[i] = {xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]};
        progress_.report(0.4);
      } else if (key == "CELLS") {
        cells_ = readCells(pointCount);
      } else if (key == "CELL_TYPES") {
        const std::size_t n = p_.count("the number of cell types");
        if (n + 1 != cells_.offsets.size())
          p_.fail("CELL_TYPES lists " + std::to_string(n) + " cells, CELLS has " +
                  std::to_string(cells_.offsets.empty() ? 0 : cells_.offsets.size() - 1));
        cells_.types = p_.integers(n, NumericType::Int32, "CELL_TYPES");
        mapping = addVtkCells(cells_, pointCount, model->mesh(), [this](const std::string& m) { p_.fail(m); });
        haveCells = true;
        if (mapping.skipped)
          model->diagnostics.push_back({Severity::Info, "skipped-cells",
                                        std::to_string(mapping.skipped) + " lower-dimensional cells (points, lines, faces) skipped", {}});
        progress_.report(0.7);
      } else if (key == "POINT_DATA" || key == "CELL_DATA") {
        location = key == "POINT_DATA" ? FieldLocation::Node : FieldLocation::Cell;
        sectionCount = p_.count("the number of values");
        const std::size_t expected = location == FieldLocation::Node ? pointCount : mapping.fileCells;
        if (sectionCount != expected)
          p_.fail(key + " " + std::to_string(sectionCount) + " does not match the " + std::to_string(expected) +
                  (location == FieldLocation::Node ? " points" : " cells"));
        inSection = true;
      } else if (key == "SCALARS" || key == "VECTORS" || key == "NORMALS" || key == "TENSORS" ||
                 key == "TENSORS6" || key == "FIELD" || key == "COLOR_SCALARS" ||
                 key == "TEXTURE_COORDINATES" || key == "LOOKUP_TABLE") {
        if (!inSection && key != "FIELD" && key != "LOOKUP_TABLE")
          p_.fail(key + " before POINT_DATA or CELL_DATA");
        attribute(key, location, sectionCount, inSection);
      } else if (key == "METADATA") {
        skipMetadata();
      } else {
        p_.fail("unexpected keyword '" + key.substr(0, 40) + "'");
      }
    }
    if (structured_ && !haveCells) {
      if (!haveDimensions) p_.fail("a STRUCTURED_POINTS file without DIMENSIONS");
      buildGrid(*model, grid, mapping);
      haveCells = true;
    }
    if (!haveCells) p_.fail(cells_.offsets.empty() ? "no CELLS section" : "CELLS without CELL_TYPES");
    for (auto& a : arrays_) addField(*model, a, mapping);
    model->diagnostics.insert(model->diagnostics.end(), diagnostics_.begin(), diagnostics_.end());
    return model;
  }

 private:
  void header(Model& model) {
    const auto first = p_.line();
    if (first.rfind("# vtk DataFile Version", 0) != 0) p_.fail("not a legacy VTK file (no '# vtk DataFile Version' line)");
    model.title = std::string(p_.line());
    const auto format = p_.token();
    if (format == "BINARY") p_.binary = true;
    else if (format != "ASCII") p_.fail("third line must be ASCII or BINARY, found '" + std::string(format.substr(0, 40)) + "'");
    if (p_.token() != "DATASET") p_.fail("expected DATASET");
    const auto dataset = p_.token();
    structured_ = dataset == "STRUCTURED_POINTS";
    if (dataset != "UNSTRUCTURED_GRID" && !structured_)
      p_.fail("DATASET " + std::string(dataset.substr(0, 40)) +
              " is not a mesh of cells or a regular grid; volpost reads UNSTRUCTURED_GRID and STRUCTURED_POINTS");
  }

  // A number written as text (DIMENSIONS, ORIGIN, SPACING are text in binary files too).
  double number(const std::string& what) {
    const std::string text(p_.token());
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0' || !std::isfinite(v)) p_.fail(what + ": '" + text.substr(0, 40) + "' is not a number");
    return v;
  }

  // The regular grid of a STRUCTURED_POINTS file, with cells numbered as the file's cell
  // data numbers them (x fastest, as VTK and hexahedraOfGrid both do).
  void buildGrid(Model& model, RegularGrid& grid, VtkCellMapping& mapping) {
    if (const std::string defect = grid.defect(); !defect.empty())
      p_.fail(defect + " (DIMENSIONS, SPACING): volpost reads volumes, not 2D images");
    const std::size_t points = p_.product(p_.product(grid.dims[0], grid.dims[1], "DIMENSIONS"), grid.dims[2], "DIMENSIONS");
    // One field's values (up to 8 bytes as stored, 8 more while decoded) and a renderer's
    // copy; the grid holds no cells until something needs them (Model::mesh checks those).
    requireMemory(double(points) * (16.0 + kGridDrawingBytesPerPoint), path_, "a grid of " + std::to_string(points) + " points");
    model.grid = grid;  // its hexahedra are built when something asks for the mesh
    mapping.modelCell.clear();
    mapping.fileCells = grid.cellCount();
    mapping.skipped = 0;
  }

  VtkCellArrays readCells(std::size_t pointCount) {
    VtkCellArrays cells;
    const std::size_t a = p_.count("the number of cells"), b = p_.count("the CELLS size");
    // Offsets (8 bytes a cell) and 32-bit node indices (4 bytes a value) before a value is
    // read: a damaged count must not ask for tens of gigabytes.
    requireMemory(double(a) * 8.0 + double(b) * 4.0, path_,
                  std::to_string(a) + " cells of " + std::to_string(b) + " values");
    if (p_.peekToken() == "OFFSETS") {  // format 5.x: OFFSETS and CONNECTIVITY arrays
      p_.token();
      cells.offsets = p_.integers(a, p_.type(), "OFFSETS");
      if (p_.token() != "CONNECTIVITY") p_.fail("expected CONNECTIVITY after OFFSETS");
      if (cells.offsets.empty() || cells.offsets.front() != 0) p_.fail("OFFSETS must start at 0");
      for (std::size_t i = 1; i < cells.offsets.size(); ++i)
        if (cells.offsets[i] < cells.offsets[i - 1] || std::uint64_t(cells.offsets[i]) > b)
          p_.fail("OFFSETS entry " + std::to_string(i) + " is out of order or beyond CONNECTIVITY");
      // Straight into 32-bit node indices, checked as they come: no 64-bit copy.
      const NumericType type = p_.type();
      cells.connectivity.reserve(b);
      p_.eachInteger(b, type, "CONNECTIVITY", [&](std::int64_t v) {
        if (v < 0 || std::uint64_t(v) >= pointCount) {
          const std::int64_t at = std::int64_t(cells.connectivity.size());
          const auto cell = std::upper_bound(cells.offsets.begin(), cells.offsets.end(), at) - cells.offsets.begin() - 1;
          p_.fail(pointOutsideMessage(std::size_t(std::max<std::ptrdiff_t>(cell, 0)), v, pointCount));
        }
        cells.connectivity.push_back(NodeIndex(v));
      });
      return cells;
    }
    // The packed list (a cell's point count, then its points), straight into 32-bit node
    // indices and offsets: no 64-bit copy of it (at 100M tets that was 40 bytes per tet).
    cells.offsets.reserve(a + 1);
    cells.offsets.push_back(0);
    cells.connectivity.reserve(b - std::min(a, b));
    std::size_t done = 0, used = 0, left = 0;  // cells complete, values read, points of this cell to come
    const auto cellDone = [&] {
      cells.offsets.push_back(std::int64_t(cells.connectivity.size()));
      ++done;
    };
    p_.eachInteger(b, NumericType::Int32, "CELLS", [&](std::int64_t v) {
      ++used;
      if (left == 0) {  // a cell's point count
        if (done == a)
          p_.fail("CELLS size is " + std::to_string(b) + " but its " + std::to_string(a) + " cells use " +
                  std::to_string(used - 1) + " values");
        if (v < 0 || std::uint64_t(v) > b - used)
          p_.fail("CELLS: cell " + std::to_string(done) + " claims " + std::to_string(v) +
                  " points, more than the CELLS size " + std::to_string(b) + " leaves");
        left = std::size_t(v);
        if (left == 0) cellDone();
        return;
      }
      if (v < 0 || std::uint64_t(v) >= pointCount) p_.fail(pointOutsideMessage(done, v, pointCount));
      cells.connectivity.push_back(NodeIndex(v));
      if (--left == 0) cellDone();
    });
    if (done != a)
      p_.fail("CELLS says " + std::to_string(a) + " cells, but its " + std::to_string(b) + " values hold only " +
              std::to_string(done));
    return cells;
  }

  void attribute(const std::string& key, FieldLocation location, std::size_t n, bool inSection) {
    if (key == "FIELD") {
      p_.token();  // field-data name
      const std::size_t arrays = p_.count("the number of FIELD arrays");
      for (std::size_t k = 0; k < arrays; ++k) {
        const std::string name = decodeName(p_.token());
        const int comps = int(p_.count("the number of components"));
        const std::size_t tuples = p_.count("the number of tuples");
        const NumericType t = p_.type();
        if (comps < 1) p_.fail("FIELD array " + name + " has no components");
        const std::size_t count = p_.product(tuples, std::size_t(comps), "FIELD array " + name);
        PendingArray a{name, location, comps, tuples, {}, {}};
        if (structured_) a.samples = p_.samples(count, t, "FIELD array " + name);
        else a.loader = p_.array(count, t, "FIELD array " + name);
        if (p_.peekToken() == "METADATA") { p_.token(); skipMetadata(); }
        if (inSection) arrays_.push_back(std::move(a));
      }
      return;
    }
    if (key == "LOOKUP_TABLE") {  // a color table of its own: read past it
      p_.token();
      const std::size_t size = p_.count("the lookup-table size");
      if (p_.binary) p_.skipBinary(p_.product(size, 4, "LOOKUP_TABLE"), NumericType::UInt8, "LOOKUP_TABLE");
      else p_.values(p_.product(size, 4, "LOOKUP_TABLE"), NumericType::Float32, "LOOKUP_TABLE");
      return;
    }
    const std::string name = decodeName(p_.token());
    if (key == "COLOR_SCALARS") {
      const std::size_t comps = p_.count("the number of color components");
      if (p_.binary) p_.skipBinary(p_.product(n, comps, "COLOR_SCALARS"), NumericType::UInt8, "COLOR_SCALARS");
      else p_.values(p_.product(n, comps, "COLOR_SCALARS"), NumericType::Float32, "COLOR_SCALARS");
      return;
    }
    if (key == "TEXTURE_COORDINATES") {
      const std::size_t dim = p_.count("the texture dimension");
      p_.array(p_.product(n, dim, key), p_.type(), key);
      return;
    }
    const NumericType t = p_.type();
    int comps = key == "SCALARS" ? 1 : key == "TENSORS" ? 9 : key == "TENSORS6" ? 6 : 3;
    if (key == "SCALARS") {
      const auto next = p_.peekToken();
      if (!next.empty() && std::isdigit(static_cast<unsigned char>(next[0]))) comps = int(p_.count("the number of components"));
      if (p_.peekToken() == "LOOKUP_TABLE") { p_.token(); p_.token(); }
    }
    if (comps < 1 || comps > 4096) p_.fail("SCALARS " + name + ": bad number of components");
    const std::size_t count = p_.product(n, std::size_t(comps), key + " " + name);
    if (structured_ && comps != 9) {  // a grid keeps its samples in the file's type (16-bit: 2 bytes, not 8)
      arrays_.push_back({name, location, comps, n, {}, p_.samples(count, t, key + " " + name)});
      return;
    }
    auto loader = p_.array(count, t, key + " " + name);
    if (comps == 9) {
      // A symmetric 3x3 tensor (stress, strain) becomes volpost's six components; one that
      // is not symmetric keeps its nine, and the user is told why it has no von Mises.
      const double asymmetry = largestAsymmetry(loader(0));
      if (asymmetry <= 0.0) {
        loader = symmetricPart(std::move(loader));
        comps = 6;
      } else {
        diagnostics_.push_back({Severity::Warning, "non-symmetric-tensor",
                                "TENSORS " + name + " is not symmetric (entries differ from their transpose by up to " +
                                    std::to_string(asymmetry) +
                                    " relative): kept as 9 components; von Mises and principal values need a "
                                    "symmetric tensor",
                                {}});
      }
    }
    arrays_.push_back({name, location, comps, n, std::move(loader), {}});
  }

  void skipMetadata() {  // METADATA blocks end at an empty line
    while (!p_.atEnd()) {
      const auto l = p_.line();
      if (l.find_first_not_of(" \t\r") == std::string_view::npos) break;
    }
  }

  void addField(Model& model, PendingArray& a, const VtkCellMapping& mapping) {
    const std::size_t expected = a.location == FieldLocation::Node ? model.nodeCount() : mapping.fileCells;
    if (a.tuples != expected) {
      model.diagnostics.push_back({Severity::Warning, "field-dropped",
                                   "field " + a.name + " dropped: " + std::to_string(a.tuples) + " values for " +
                                       std::to_string(expected) + (a.location == FieldLocation::Node ? " points" : " cells"),
                                   {}});
      return;
    }
    if (a.samples) {  // a grid: no cells are ever skipped
      model.fields.push_back(Field::fromSamples(a.name, a.location, a.components, a.tuples, std::vector<Step>{{"", 0.0}},
                                                std::move(a.samples)));
      return;
    }
    StepLoader loader = a.loader;
    std::size_t entities = a.tuples;
    if (a.location == FieldLocation::Cell && mapping.skipped) {
      const int comps = a.components;
      loader = [inner = a.loader, comps, mapping](std::size_t s) { return selectModelCells(inner(s), comps, mapping); };
      entities = model.cellCount();
    }
    model.fields.push_back(std::make_shared<Field>(a.name, a.location, a.components, entities,
                                                   std::vector<Step>{{"", 0.0}}, std::move(loader)));
  }

  LegacyParser p_;
  bool structured_ = false;
  std::string path_;
  const Progress& progress_;
  VtkCellArrays cells_;
  std::vector<PendingArray> arrays_;
  std::vector<Diagnostic> diagnostics_;
};

}  // namespace

int VtkLegacyReader::sniff(std::string_view head) const {
  return head.rfind("# vtk DataFile Version", 0) == 0 ? 100 : 0;
}

std::unique_ptr<Model> VtkLegacyReader::read(const std::string& path, const Progress& progress) const {
  auto bytes = readFileBytes(path, progress);
  auto model = LegacyReading(bytes, path, progress).run();
  model->formatName = formatName();
  progress.report(1.0);
  return model;
}

}  // namespace volpost::meshio

// SPDX-License-Identifier: MIT
#include "VtuReader.hpp"

#include "DiskFile.hpp"
#include "FileBytes.hpp"
#include "VtkCells.hpp"
#include "VtuDataArray.hpp"

#include <volpost/core/ResourceLimits.hpp>

#include <pugixml.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <array>

namespace volpost::meshio {
namespace {

struct AppendedBlock {
  bool present = false;
  bool base64 = false;
  std::size_t begin = 0, end = 0;  // data bytes in the file
};

class VtuReading {
 public:
  VtuReading(std::string path, const Progress& progress, std::uint64_t readInPlaceFrom)
      : path_(std::move(path)), progress_(progress), readInPlaceFrom_(readInPlaceFrom) {}

  std::unique_ptr<Model> run() {
    openFile();
    pugi::xml_document doc;
    const auto parsed = doc.load_buffer(xml_.data(), xml_.size());
    if (!parsed)
      throw ReadError::atLine(path_, lineAt(xml_, std::size_t(parsed.offset)),
                              std::string("malformed XML: ") + parsed.description());
    const pugi::xml_node root = doc.child("VTKFile");
    if (!root) throw ReadError(path_, "no <VTKFile> element: not a VTK XML file");
    readEncoding(root);
    checkAppendedOffsets(root);
    if (const pugi::xml_node image = root.child("ImageData")) return readImage(image);
    const pugi::xml_node grid = root.child("UnstructuredGrid");
    if (!grid) throw ReadError(path_, "this VTK XML file holds a " + std::string(root.attribute("type").as_string("?")) +
                                          "; volpost reads UnstructuredGrid (.vtu) and ImageData (.vti)");
    auto model = std::make_unique<Model>();
    model->title = grid.attribute("VolpostTitle").as_string("");
    std::size_t pieces = 0;
    for (pugi::xml_node piece : grid.children("Piece")) {
      readPiece(piece, *model);
      ++pieces;
    }
    if (pieces == 0) throw ReadError(path_, "<UnstructuredGrid> has no <Piece>");
    finishFields(*model);
    return model;
  }

 private:
  [[noreturn]] void failAt(const pugi::xml_node& node, const std::string& message) const {
    throw ReadError::atLine(path_, lineAt(xml_, std::size_t(node.offset_debug())), message);
  }

  // A file under readInPlaceFrom_ bytes is read whole into memory (its lazy fields keep
  // it). A larger one is read up to its appended data, whose arrays are then decoded from
  // the file where they lie, a chunk at a time (a 12.6M-tet mesh's file is 550 MB, and
  // holding it while decoding was half of the read's peak memory); its lazy fields read
  // from the file when they are first shown.
  void openFile() {
    auto disk = std::make_shared<const DiskFile>(path_);
    if (disk->size() == 0) throw ReadError(path_, "file is empty (0 bytes)");
    if (disk->size() < readInPlaceFrom_) {
      bytes_ = readFileBytes(path_, progress_);
      splitAppended();
      return;
    }
    std::string head;
    std::size_t tag = std::string::npos, tagEnd = std::string::npos, underscore = std::string::npos;
    constexpr std::size_t kChunk = std::size_t(16) << 20;
    while (head.size() < disk->size() && underscore == std::string::npos) {
      const std::size_t searchFrom = head.size() > 16 ? head.size() - 16 : 0;  // a tag cut by the chunk's end
      // A file without appended data is all XML and read whole, as a small one is (growing
      // the text copies it once more).
      const std::size_t n = std::size_t(std::min<std::uint64_t>(kChunk, disk->size() - head.size()));
      requireMemory(double(head.size() + n) * (head.empty() ? 1.0 : 2.0), path_, "the file's XML text");
      head += disk->readString(head.size(), n);
      progress_.report(0.2 * double(head.size()) / double(disk->size()));
      if (tag == std::string::npos) tag = head.find("<AppendedData", searchFrom);
      if (tag != std::string::npos && tagEnd == std::string::npos) tagEnd = head.find('>', tag);
      if (tagEnd != std::string::npos) underscore = head.find('_', tagEnd);
    }
    if (underscore == std::string::npos) {  // all of it read: no appended data to leave in the file
      blankByteOrderMark(head);
      bytes_ = std::make_shared<const std::string>(std::move(head));
      splitAppended();
      return;
    }
    const std::uint64_t close = closingTagOffset(*disk, underscore + 1);
    appended_.present = true;
    appended_.base64 = head.substr(tag, tagEnd - tag).find("\"base64\"") != std::string::npos;
    appended_.begin = underscore + 1;
    appended_.end = std::size_t(close);
    head.resize(tagEnd + 1);
    blankByteOrderMark(head);
    xml_ = std::move(head) + disk->readString(close, std::size_t(disk->size() - close));
    disk_ = std::move(disk);
  }

  // Where the last </AppendedData> starts, searched backwards from the file's end in chunks.
  std::uint64_t closingTagOffset(const DiskFile& disk, std::uint64_t dataBegin) const {
    static constexpr std::string_view kClose = "</AppendedData>";
    constexpr std::uint64_t kChunk = std::uint64_t(1) << 20;
    for (std::uint64_t end = disk.size(); end > dataBegin;) {
      const std::uint64_t from = end - std::min(kChunk, end - dataBegin);
      const std::uint64_t to = std::min<std::uint64_t>(disk.size(), end + kClose.size() - 1);  // a tag cut at `end`
      const std::string part = disk.readString(from, std::size_t(to - from));
      if (const std::size_t at = part.rfind(kClose); at != std::string::npos) return from + at;
      end = from;
    }
    throw ReadError::atOffset(path_, disk.size(), "file ends inside the appended data: no </AppendedData> (truncated)");
  }

  // Raw appended data is not XML: cut it out before parsing and remember where it is.
  void splitAppended() {
    const std::string& b = *bytes_;
    const std::size_t tag = b.find("<AppendedData");
    if (tag == std::string::npos) {
      xml_ = b;
      return;
    }
    const std::size_t tagEnd = b.find('>', tag);
    if (tagEnd == std::string::npos) throw ReadError::atOffset(path_, tag, "<AppendedData> tag is not closed (truncated)");
    const std::string tagText = b.substr(tag, tagEnd - tag);
    appended_.present = true;
    appended_.base64 = tagText.find("\"base64\"") != std::string::npos;
    const std::size_t underscore = b.find('_', tagEnd);
    if (underscore == std::string::npos) throw ReadError::atOffset(path_, tagEnd, "appended data has no '_' marker (truncated)");
    const std::size_t close = b.rfind("</AppendedData>");
    if (close == std::string::npos || close < underscore)
      throw ReadError::atOffset(path_, b.size(), "file ends inside the appended data: no </AppendedData> (truncated)");
    appended_.begin = underscore + 1;
    appended_.end = close;
    xml_ = b.substr(0, tagEnd + 1) + b.substr(close);
  }

  void readEncoding(const pugi::xml_node& root) {
    const std::string order = root.attribute("byte_order").as_string("LittleEndian");
    if (order != "LittleEndian" && order != "BigEndian") failAt(root, "byte_order \"" + order + "\" is neither LittleEndian nor BigEndian");
    enc_.bigEndian = order == "BigEndian";
    const std::string header = root.attribute("header_type").as_string("UInt32");
    if (header == "UInt64") enc_.headerType = NumericType::UInt64;
    else if (header != "UInt32") failAt(root, "header_type \"" + header + "\" is not UInt32 or UInt64");
    const std::string compressor = root.attribute("compressor").as_string("");
    if (compressor == "vtkZLibDataCompressor") enc_.compressed = true;
    else if (!compressor.empty())
      failAt(root, "compressor " + compressor + " is not supported (volpost reads zlib-compressed and uncompressed files)");
  }

  // Appended arrays each own a run of the appended data, from their offset to the next
  // array's: two arrays at one offset (or a run past the data) is a corrupt or hostile
  // file, and decoding every array from the same place to the end would take quadratic time.
  void checkAppendedOffsets(const pugi::xml_node& root) {
    std::map<std::size_t, pugi::xml_node> byOffset;
    for (const pugi::xpath_node& x : root.select_nodes("//DataArray[@format='appended']")) {
      const pugi::xml_node a = x.node();
      const std::size_t offset = std::size_t(a.attribute("offset").as_ullong(0));
      const auto [it, inserted] = byOffset.emplace(offset, a);
      if (!inserted)
        failAt(a, "DataArray \"" + std::string(a.attribute("Name").as_string()) + "\" starts at offset " +
                      std::to_string(offset) + " of the appended data, as DataArray \"" +
                      it->second.attribute("Name").as_string() + "\" does (overlapping arrays: corrupt file)");
    }
    for (const auto& [offset, node] : byOffset) appendedOffsets_.push_back(offset);
  }

  // The end of the run of the appended array starting at `offset`: the next array's offset.
  std::size_t appendedRunEnd(std::size_t offset) const {
    const auto next = std::upper_bound(appendedOffsets_.begin(), appendedOffsets_.end(), offset);
    const std::size_t size = appended_.end - appended_.begin;
    return next == appendedOffsets_.end() ? size : std::min<std::size_t>(*next, size);
  }

  VtuArraySource source(const pugi::xml_node& array) {
    VtuArraySource s;
    s.name = array.attribute("Name").as_string("");
    const std::string typeName = array.attribute("type").as_string("");
    const auto type = numericTypeFromXml(typeName);
    if (!type) failAt(array, "DataArray \"" + s.name + "\" has unknown type \"" + typeName + "\"");
    s.type = *type;
    s.components = array.attribute("NumberOfComponents").as_int(1);
    if (s.components < 1 || s.components > 4096) failAt(array, "DataArray \"" + s.name + "\" has a bad NumberOfComponents");
    const std::string format = array.attribute("format").as_string("ascii");
    if (format == "appended") {
      if (!appended_.present) failAt(array, "DataArray \"" + s.name + "\" is appended but the file has no <AppendedData>");
      s.format = VtuArraySource::Format::Appended;
      s.file = bytes_;
      s.disk = disk_;
      s.begin = appended_.begin;
      s.end = appended_.end;
      s.appendedOffset = std::size_t(array.attribute("offset").as_ullong(0));
      s.appendedBase64 = appended_.base64;
      s.end = s.begin + appendedRunEnd(s.appendedOffset);
    } else if (format == "binary" || format == "ascii") {
      s.format = format == "ascii" ? VtuArraySource::Format::Ascii : VtuArraySource::Format::Binary;
      s.file = std::make_shared<const std::string>(array.child_value());
      s.begin = 0;
      s.end = s.file->size();
    } else {
      failAt(array, "DataArray \"" + s.name + "\" has unknown format \"" + format + "\"");
    }
    return s;
  }

  template <typename F>
  auto guarded(const pugi::xml_node& node, F&& f) -> decltype(f()) {
    try {
      return f();
    } catch (const VtuArrayError& e) {
      failAt(node, e.message);
    }
  }

  pugi::xml_node arrayNamed(const pugi::xml_node& parent, const char* name) {
    for (pugi::xml_node a : parent.children("DataArray"))
      if (std::strcmp(a.attribute("Name").as_string(), name) == 0) return a;
    failAt(parent, std::string("<") + parent.name() + "> has no DataArray \"" + name + "\"");
  }

  std::vector<std::int64_t> integers(const pugi::xml_node& node) {
    const VtuArraySource s = source(node);
    return guarded(node, [&] { return vtuIntegers(s, enc_); });
  }

  void readPiece(const pugi::xml_node& piece, Model& model) {
    const long long points = piece.attribute("NumberOfPoints").as_llong(-1);
    const long long cellCount = piece.attribute("NumberOfCells").as_llong(-1);
    if (points < 0 || cellCount < 0) failAt(piece, "<Piece> needs NumberOfPoints and NumberOfCells");
    const std::size_t nodeBase = model.nodeCount();

    if (points > 0) {
      const pugi::xml_node pts = piece.child("Points").child("DataArray");
      if (!pts) failAt(piece, "<Piece> has no <Points> DataArray");
      const VtuArraySource s = source(pts);
      if (s.components != 3) failAt(pts, "Points must have 3 components, not " + std::to_string(s.components));
      if (std::uint64_t(points) > std::numeric_limits<std::size_t>::max() / 24)
        failAt(piece, "NumberOfPoints " + std::to_string(points) + " is more than any file or memory can hold (corrupt)");
      const std::size_t expected = std::size_t(points) * 3;
      const auto xyz = guarded(pts, [&] { return vtuDoubles(s, enc_); });
      if (xyz.size() != expected)
        failAt(pts, "Points holds " + std::to_string(xyz.size() / 3) + " points, NumberOfPoints says " + std::to_string(points));
      model.mesh().nodes.reserve(nodeBase + std::size_t(points));
      for (std::size_t i = 0; i < std::size_t(points); ++i)
        model.mesh().nodes.push_back({xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]});
    }
    progress_.report(0.4);

    VtkCellArrays cells;
    if (cellCount > 0) {
      const pugi::xml_node cellsNode = piece.child("Cells");
      if (!cellsNode) failAt(piece, "<Piece> has cells but no <Cells>");
      const pugi::xml_node offsetsNode = arrayNamed(cellsNode, "offsets");
      const pugi::xml_node typesNode = arrayNamed(cellsNode, "types");
      const pugi::xml_node connectivityNode = arrayNamed(cellsNode, "connectivity");
      const VtuArraySource connectivitySource = source(connectivityNode);
      const std::size_t entries = guarded(connectivityNode, [&] { return vtuValueCount(connectivitySource, enc_); });
      cells.types = integers(typesNode);
      const std::size_t n = std::size_t(cellCount);
      if (cells.types.size() != n)
        failAt(typesNode, "types holds " + std::to_string(cells.types.size()) + " cells, NumberOfCells says " + std::to_string(n));
      cells.offsets = integers(offsetsNode);
      std::vector<std::int64_t>& offsets = cells.offsets;
      if (offsets.size() == n + 1 && offsets.front() == 0) offsets.erase(offsets.begin());
      if (offsets.size() != n)
        failAt(offsetsNode, "offsets holds " + std::to_string(offsets.size()) + " cells, NumberOfCells says " + std::to_string(n));
      for (std::size_t i = 0; i < n; ++i)
        if (offsets[i] < (i ? offsets[i - 1] : 0) || std::uint64_t(offsets[i]) > entries)
          failAt(offsetsNode, "offset of cell " + std::to_string(i) + " (" + std::to_string(offsets[i]) +
                                  ") is out of order or beyond the " + std::to_string(entries) + " connectivity entries");
      offsets.insert(offsets.begin(), 0);
      // Each piece numbers its own points from 0: an index outside them (negative, or past
      // this piece's points) must not silently land on another piece's nodes.
      if (std::uint64_t(nodeBase) + std::uint64_t(points) > std::numeric_limits<NodeIndex>::max())
        failAt(piece, "the pieces hold " + std::to_string(nodeBase + std::size_t(points)) +
                          " points, more than volpost's 32-bit node numbers can count (4,294,967,295)");
      try {
        cells.connectivity = vtuIndices(connectivitySource, enc_, std::uint64_t(points), NodeIndex(nodeBase));
      } catch (const VtuArrayError& e) {
        failAt(connectivityNode, e.message);
      } catch (const VtuIndexError& e) {
        const auto cell = std::upper_bound(offsets.begin(), offsets.end(), std::int64_t(e.position)) - offsets.begin() - 1;
        failAt(connectivityNode, "cell " + std::to_string(cell) + " uses point " + std::to_string(e.value) +
                                     ", outside this piece's " + std::to_string(points) + " points (0.." +
                                     std::to_string(points - 1) + ")");
      }
      if (cells.connectivity.size() != entries)
        failAt(connectivityNode, "holds " + std::to_string(cells.connectivity.size()) + " values, its header says " +
                                     std::to_string(entries));
    }
    const std::size_t pointTotal = nodeBase + std::size_t(points);
    const pugi::xml_node cellsNode = piece.child("Cells");
    VtkCellMapping mapping = addVtkCells(cells, pointTotal, model.mesh(), [&](const std::string& m) {
      failAt(cellsNode ? cellsNode : piece, m);
    });
    if (mapping.skipped)
      model.diagnostics.push_back({Severity::Info, "skipped-cells",
                                   std::to_string(mapping.skipped) + " lower-dimensional cells (points, lines, faces) skipped", {}});
    progress_.report(0.7);
    collectArrays(piece.child("PointData"), FieldLocation::Node, std::size_t(points), nullptr, model);
    collectArrays(piece.child("CellData"), FieldLocation::Cell, std::size_t(cellCount), &mapping, model);
    ++pieceCount_;
  }

  // ---- ImageData (.vti): a regular grid ----------------------------------------------

  // `count` numbers from an attribute ("0 10 0 10 0 5"), or the defaults when it is absent.
  std::vector<double> numbers(const pugi::xml_node& node, const char* attribute, std::vector<double> defaults) {
    const pugi::xml_attribute a = node.attribute(attribute);
    if (!a) return defaults;
    std::vector<double> out;
    std::istringstream in(a.as_string());
    for (double v; in >> v;) out.push_back(v);
    if (out.size() != defaults.size() || !std::all_of(out.begin(), out.end(), [](double v) { return std::isfinite(v); }))
      failAt(node, std::string(attribute) + "=\"" + a.as_string() + "\" needs " + std::to_string(defaults.size()) +
                       " finite numbers");
    return out;
  }

  struct Extent {
    std::array<long long, 6> e{};
    std::array<std::size_t, 3> points() const {
      return {std::size_t(e[1] - e[0] + 1), std::size_t(e[3] - e[2] + 1), std::size_t(e[5] - e[4] + 1)};
    }
  };
  Extent extentOf(const pugi::xml_node& node, const char* attribute) {
    const std::vector<double> v = numbers(node, attribute, std::vector<double>(6, NAN));
    Extent x;
    for (int a = 0; a < 6; ++a) {
      if (!(std::abs(v[std::size_t(a)]) < 1e15) || v[std::size_t(a)] != std::floor(v[std::size_t(a)]))
        failAt(node, std::string(attribute) + " needs 6 integers");
      x.e[std::size_t(a)] = (long long)v[std::size_t(a)];
    }
    for (int a = 0; a < 3; ++a)
      if (x.e[std::size_t(2 * a + 1)] < x.e[std::size_t(2 * a)])
        failAt(node, std::string(attribute) + " runs backwards along axis " + std::to_string(a));
    return x;
  }

  std::unique_ptr<Model> readImage(const pugi::xml_node& image) {
    const Extent whole = extentOf(image, "WholeExtent");
    const std::vector<double> origin = numbers(image, "Origin", {0, 0, 0});
    const std::vector<double> spacing = numbers(image, "Spacing", {1, 1, 1});
    const std::vector<double> d = numbers(image, "Direction", {1, 0, 0, 0, 1, 0, 0, 0, 1});
    RegularGrid grid;
    grid.dims = whole.points();
    for (int a = 0; a < 3; ++a)  // VTK's Direction is row-major, its columns the index axes
      grid.axes[std::size_t(a)] = spacing[std::size_t(a)] * glm::dvec3(d[std::size_t(a)], d[std::size_t(3 + a)], d[std::size_t(6 + a)]);
    grid.origin = glm::dvec3(origin[0], origin[1], origin[2]) + double(whole.e[0]) * grid.axes[0] +
                  double(whole.e[2]) * grid.axes[1] + double(whole.e[4]) * grid.axes[2];
    grid.axisNames = {"i", "j", "k"};
    grid.firstLabel = {double(whole.e[0]), double(whole.e[2]), double(whole.e[4])};
    if (const std::string defect = grid.defect(); !defect.empty())
      failAt(image, defect + " (WholeExtent, Spacing, Direction): volpost reads volumes, not 2D images");
    const std::size_t pointCount = checkedProduct(checkedProduct(grid.dims[0], grid.dims[1], path_, "the image"),
                                                  grid.dims[2], path_, "the image");
    // One field's values (up to 8 bytes as stored, 8 more while decoded) and a renderer's
    // copy; the image holds no cells until something needs them (Model::mesh checks those).
    requireMemory(double(pointCount) * (16.0 + kGridDrawingBytesPerPoint), path_, "an image of " + std::to_string(pointCount) + " points");

    auto model = std::make_unique<Model>();
    model->title = image.attribute("VolpostTitle").as_string("");
    struct ImageArray {
      Extent extent;  // the piece's points
      VtuArraySource source;
    };
    std::map<std::string, std::vector<ImageArray>> arrays;
    std::map<std::string, int> components;
    std::vector<std::string> order;
    for (pugi::xml_node piece : image.children("Piece")) {
      const Extent e = extentOf(piece, "Extent");
      for (int a = 0; a < 3; ++a)
        if (e.e[std::size_t(2 * a)] < whole.e[std::size_t(2 * a)] || e.e[std::size_t(2 * a + 1)] > whole.e[std::size_t(2 * a + 1)])
          failAt(piece, "the piece's Extent reaches outside the WholeExtent");
      const std::array<std::size_t, 3> pp = e.points();
      for (const auto& [section, location] : {std::pair{"PointData", FieldLocation::Node}, std::pair{"CellData", FieldLocation::Cell}})
        for (pugi::xml_node array : piece.child(section).children("DataArray")) {
          VtuArraySource s = source(array);
          if (s.name.empty()) failAt(array, "DataArray without a Name");
          const std::size_t entities = location == FieldLocation::Node
                                           ? pp[0] * pp[1] * pp[2]
                                           : std::max<std::size_t>(pp[0] - 1, 1) * std::max<std::size_t>(pp[1] - 1, 1) *
                                                 std::max<std::size_t>(pp[2] - 1, 1);
          const std::size_t values = guarded(array, [&] { return vtuValueCount(s, enc_); });
          if (values != entities * std::size_t(s.components))
            failAt(array, "DataArray \"" + s.name + "\" holds " + std::to_string(values) + " values; the piece's " +
                              std::to_string(entities) + (location == FieldLocation::Node ? " points" : " cells") +
                              " x " + std::to_string(s.components) + " components need " +
                              std::to_string(entities * std::size_t(s.components)));
          const std::string key = std::string(location == FieldLocation::Node ? "n:" : "c:") + s.name;
          const auto [it, inserted] = components.try_emplace(key, s.components);
          if (it->second != s.components) failAt(array, "DataArray \"" + s.name + "\" changes its components between pieces");
          if (inserted) order.push_back(key);
          Extent cellsOrPoints = e;
          if (location == FieldLocation::Cell)  // the piece's cells: one fewer than its points along each axis
            for (int a = 0; a < 3; ++a) cellsOrPoints.e[std::size_t(2 * a + 1)] -= 1;
          arrays[key].push_back({cellsOrPoints, std::move(s)});
        }
    }
    model->grid = grid;
    const std::array<long long, 3> low = {whole.e[0], whole.e[2], whole.e[4]};
    // The type an image array is kept in: the pieces' own when they all share it and
    // together cover the image (VTK's pieces do not overlap); else floats wide enough for
    // it, so that a gap can be NaN (32-bit for small integers, 64-bit for the rest).
    // How many of the image's points (or cells) no piece gives a value: pieces may share
    // their boundary planes, so this is counted point by point, not from their sizes.
    const auto uncovered = [&](const std::vector<ImageArray>& parts, const std::array<std::size_t, 3>& size) {
      std::vector<bool> covered(size[0] * size[1] * size[2], false);
      for (const ImageArray& part : parts) {
        const auto n = part.extent.points();
        for (std::size_t k = 0; k < n[2]; ++k)
          for (std::size_t j = 0; j < n[1]; ++j)
            for (std::size_t i = 0; i < n[0]; ++i)
              covered[std::size_t(part.extent.e[0] - low[0]) + i +
                      size[0] * (std::size_t(part.extent.e[2] - low[1]) + j +
                                 size[1] * (std::size_t(part.extent.e[4] - low[2]) + k))] = true;
      }
      return std::size_t(std::count(covered.begin(), covered.end(), false));
    };
    const auto imageSampleType = [](const std::vector<ImageArray>& parts, std::size_t missing) {
      bool same = !parts.empty();
      for (const ImageArray& part : parts) same = same && part.source.type == parts.front().source.type;
      const NumericType type = same ? parts.front().source.type : NumericType::Float64;
      const bool covers = same && missing == 0;
      switch (type) {
        case NumericType::Int8:
          return covers ? SampleType::Int8 : SampleType::Float32;
        case NumericType::UInt8:
          return covers ? SampleType::UInt8 : SampleType::Float32;
        case NumericType::Int16:
          return covers ? SampleType::Int16 : SampleType::Float32;
        case NumericType::UInt16:
          return covers ? SampleType::UInt16 : SampleType::Float32;
        case NumericType::Int32:
          return covers ? SampleType::Int32 : SampleType::Float64;
        case NumericType::UInt32:
          return covers ? SampleType::UInt32 : SampleType::Float64;
        case NumericType::Float32:
          return SampleType::Float32;
        default:
          return SampleType::Float64;  // 64-bit integers as doubles, as they are read
      }
    };
    for (const std::string& key : order) {
      const FieldLocation location = key[0] == 'n' ? FieldLocation::Node : FieldLocation::Cell;
      const int comps = components[key];
      std::array<std::size_t, 3> size = grid.dims;
      if (location == FieldLocation::Cell)
        for (std::size_t& n : size) n -= 1;
      const std::size_t entities = size[0] * size[1] * size[2];
      auto parts = std::make_shared<std::vector<ImageArray>>(std::move(arrays[key]));
      // Kept in the file's type when every piece has it and the pieces cover the image;
      // else as floats wide enough for it, NaN where no piece is.
      const std::size_t missing = uncovered(*parts, size);
      const SampleType stored = imageSampleType(*parts, missing);
      if (missing > 0)
        model->diagnostics.push_back({Severity::Warning,
                                      "image-gap",
                                      std::to_string(missing) + " of the " + std::to_string(entities) + " " +
                                          (location == FieldLocation::Node ? "points" : "cells") + " of \"" +
                                          key.substr(2) +
                                          "\" lie in no <Piece> (the pieces overlap or leave a gap): "
                                          "they have no value (drawn gray)",
                                      {}});
      // Every piece's values placed at its extent in the whole image.
      SampleLoader loader = [parts, size, low, comps, entities, stored, enc = enc_, path = path_](std::size_t) {
        SampleArray all(stored, entities * std::size_t(comps));
        if (stored == SampleType::Float32 || stored == SampleType::Float64)
          for (std::size_t i = 0; i < all.size(); ++i) all.set(i, NAN);
        for (const ImageArray& part : *parts) {
          const std::array<std::size_t, 3> n = part.extent.points();
          const std::size_t pieceValues = n[0] * n[1] * n[2] * std::size_t(comps);
          if (pieceValues == 0) continue;
          // Each run of values goes straight to its place in the image (no array of the
          // piece's values as doubles): value q is component q % comps of the piece's point
          // q / comps, x fastest.
          const auto place = [&](std::size_t first, const double* values, std::size_t count) {
            for (std::size_t q = first; q < first + count && q < pieceValues; ++q) {
              const std::size_t at = q / std::size_t(comps), c = q % std::size_t(comps);
              const std::size_t gi = std::size_t(part.extent.e[0] - low[0]) + at % n[0],
                                gj = std::size_t(part.extent.e[2] - low[1]) + at / n[0] % n[1],
                                gk = std::size_t(part.extent.e[4] - low[2]) + at / (n[0] * n[1]);
              const double x = values[q - first];
              // Text that does not fit its declared type ("300" in an Int8 array) is kept as written.
              if (!all.fitsExactly(x)) all = all.widenedTo(SampleType::Float64);
              all.set((gi + size[0] * (gj + size[1] * gk)) * std::size_t(comps) + c, x);
            }
          };
          try {
            vtuDoubleRuns(part.source, enc, place);
          } catch (const VtuArrayError& e) {
            throw ReadError(path, e.message);
          }
        }
        return all;
      };
      model->fields.push_back(Field::fromSamples(key.substr(2), location, comps, entities, std::vector<Step>{{"", 0.0}},
                                                 std::move(loader)));
    }
    return model;
  }

  struct PieceArray {
    VtuArraySource source;
    std::shared_ptr<VtkCellMapping> mapping;  // cell arrays of pieces with skipped cells
  };
  struct FieldParts {
    FieldLocation location;
    int components;
    std::vector<PieceArray> parts;
    std::size_t firstPiece;
    bool dropped = false;
    // A step of a field volpost wrote (VolpostField / VolpostStep / VolpostTime / VolpostStepLabel).
    std::string stepOf;
    long long stepNumber = 0;
    Step step;
  };

  void collectArrays(const pugi::xml_node& data, FieldLocation location, std::size_t count,
                     const VtkCellMapping* mapping, Model& model) {
    if (!data) return;
    for (pugi::xml_node array : data.children("DataArray")) {
      VtuArraySource s = source(array);
      if (s.name.empty()) failAt(array, "DataArray without a Name");
      const std::size_t values = guarded(array, [&] { return vtuValueCount(s, enc_); });
      const std::string key = std::string(location == FieldLocation::Node ? "n:" : "c:") + s.name;
      auto [it, inserted] = fields_.try_emplace(key, FieldParts{location, s.components, {}, pieceCount_, false, {}, 0, {}});
      FieldParts& f = it->second;
      if (inserted && array.attribute("VolpostField")) {
        f.stepOf = array.attribute("VolpostField").as_string();
        f.stepNumber = array.attribute("VolpostStep").as_llong(0);
        f.step.time = array.attribute("VolpostTime").as_double(0.0);
        f.step.label = array.attribute("VolpostStepLabel").as_string("");
      }
      if (f.dropped) continue;
      if (values != count * std::size_t(s.components) || f.components != s.components ||
          f.firstPiece + f.parts.size() != pieceCount_) {
        model.diagnostics.push_back({Severity::Warning, "field-dropped",
                                     "field " + s.name + " dropped: " + std::to_string(values / std::size_t(s.components)) +
                                         " values for " + std::to_string(count) +
                                         (location == FieldLocation::Node ? " points" : " cells") + " (line " +
                                         std::to_string(lineAt(xml_, std::size_t(array.offset_debug()))) + ")",
                                     {}});
        f.dropped = true;
        continue;
      }
      std::shared_ptr<VtkCellMapping> m;
      if (mapping && mapping->skipped) m = std::make_shared<VtkCellMapping>(*mapping);
      f.parts.push_back({std::move(s), std::move(m)});
      if (inserted) order_.push_back(key);
    }
  }

  // The values of one array over all pieces, read on first use.
  StepLoader arrayLoader(FieldParts& f) {
    auto parts = std::make_shared<std::vector<PieceArray>>(std::move(f.parts));
    const VtuEncoding enc = enc_;
    const int comps = f.components;
    return [parts, enc, comps, path = path_](std::size_t) {
      std::vector<double> all;
      for (const PieceArray& p : *parts) {
        std::vector<double> v;
        try {
          v = vtuDoubles(p.source, enc);
        } catch (const VtuArrayError& e) {
          throw ReadError(path, e.message);
        }
        if (p.mapping) v = selectModelCells(v, comps, *p.mapping);
        all.insert(all.end(), v.begin(), v.end());
      }
      return all;
    };
  }

  void finishFields(Model& model) {
    // Arrays volpost wrote as the steps of one field become that field again, its steps in
    // order, with their times and labels (what a plain VTU cannot say).
    struct Stepped {
      FieldLocation location;
      int components;
      std::vector<std::pair<long long, std::string>> keys;  // step number, array key
    };
    std::map<std::string, Stepped> stepped;
    std::vector<std::string> steppedOrder;
    for (const std::string& key : order_) {
      FieldParts& f = fields_[key];
      if (f.dropped || f.parts.size() != pieceCount_ || f.stepOf.empty()) continue;
      const std::string group = key.substr(0, 2) + f.stepOf;
      auto [it, inserted] = stepped.try_emplace(group, Stepped{f.location, f.components, {}});
      if (inserted) steppedOrder.push_back(group);
      if (it->second.components == f.components) it->second.keys.push_back({f.stepNumber, key});
      else f.stepOf.clear();  // not a step of that field after all: an array of its own
    }
    std::set<std::string> emitted;
    for (const std::string& key : order_) {
      FieldParts& f = fields_[key];
      if (f.dropped || f.parts.size() != pieceCount_) continue;
      const std::size_t entities = f.location == FieldLocation::Node ? model.nodeCount() : model.cellCount();
      if (!f.stepOf.empty()) {
        const std::string group = key.substr(0, 2) + f.stepOf;
        if (!emitted.insert(group).second) continue;
        Stepped& g = stepped[group];
        std::sort(g.keys.begin(), g.keys.end());
        std::vector<Step> steps;
        auto loaders = std::make_shared<std::vector<StepLoader>>();
        for (const auto& [number, k] : g.keys) {
          steps.push_back(fields_[k].step);
          loaders->push_back(arrayLoader(fields_[k]));
        }
        model.fields.push_back(std::make_shared<Field>(f.stepOf, g.location, g.components, entities, std::move(steps),
                                                       [loaders](std::size_t s) { return (*loaders)[s](0); }));
        continue;
      }
      auto field = std::make_shared<Field>(key.substr(2), f.location, f.components, entities,
                                           std::vector<Step>{{"", 0.0}}, arrayLoader(f));
      if (takeIds(*field, model)) continue;
      model.fields.push_back(std::move(field));
    }
  }

  // volpost (and meshio/Gmsh exports) keep the FE ids as "node_id" / "element_id" arrays:
  // they become the mesh's ids, not a field to color by.
  static bool takeIds(const Field& field, Model& model) {
    const bool nodes = field.name() == "node_id" && field.location() == FieldLocation::Node;
    const bool cells = field.name() == "element_id" && field.location() == FieldLocation::Cell;
    if ((!nodes && !cells) || field.components() != 1) return false;
    std::vector<std::int64_t> ids;
    try {
      for (double v : field.values(0)) {
        if (!(v >= 0 && v < 9.0e15) || v != std::floor(v)) return false;  // not ids: keep it as a field
        ids.push_back(std::int64_t(v));
      }
    } catch (const std::exception&) {
      return false;
    }
    (nodes ? model.mesh().nodeIds : model.mesh().cellIds) = std::move(ids);
    return true;
  }

  std::string path_;
  const Progress& progress_;
  std::uint64_t readInPlaceFrom_;
  std::shared_ptr<const std::string> bytes_;  ///< the file in memory (small files), or
  std::shared_ptr<const DiskFile> disk_;      ///< the file its appended arrays are read from
  std::string xml_;
  AppendedBlock appended_;
  VtuEncoding enc_;
  std::size_t pieceCount_ = 0;
  std::map<std::string, FieldParts> fields_;
  std::vector<std::string> order_;
  std::vector<std::size_t> appendedOffsets_;  ///< sorted, distinct
};

}  // namespace

int VtiReader::sniff(std::string_view head) const {
  const auto xml = head.find("<VTKFile");
  if (xml == std::string_view::npos) return 0;
  return head.find("ImageData", xml) != std::string_view::npos ? 100 : 0;
}

std::unique_ptr<Model> VtiReader::read(const std::string& path, const Progress& progress) const {
  auto model = VtuReading(path, progress, readInPlaceFrom_).run();
  if (!model->grid) throw ReadError(path, "this VTK XML file holds no <ImageData>; for unstructured grids use .vtu");
  model->formatName = formatName();
  progress.report(1.0);
  return model;
}

int VtuReader::sniff(std::string_view head) const {
  const auto xml = head.find("<VTKFile");
  if (xml == std::string_view::npos) return 0;
  return head.find("UnstructuredGrid", xml) != std::string_view::npos ? 100 : 30;
}

std::unique_ptr<Model> VtuReader::read(const std::string& path, const Progress& progress) const {
  auto model = VtuReading(path, progress, readInPlaceFrom_).run();
  model->formatName = model->grid ? "VTK XML image data" : formatName();
  progress.report(1.0);
  return model;
}

}  // namespace volpost::meshio

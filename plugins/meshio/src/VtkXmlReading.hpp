// SPDX-License-Identifier: MIT
// One read of a VTK XML file (.vtu or .vti): the XML head parsed, the encoding and the
// appended block found, data arrays decoded where they lie (in memory for small files, from
// the file for large ones) and gathered into fields over all pieces. The unstructured
// grid's pieces are read in VtuReader.cpp, the image data's extent and arrays in
// VtiReader.cpp; what both use is in VtkXmlReading.cpp.
#pragma once

#include "DiskFile.hpp"
#include "FileBytes.hpp"
#include "VtkCells.hpp"
#include "VtuDataArray.hpp"

#include <volpost/core/Model.hpp>
#include <volpost/core/Progress.hpp>

#include <pugixml.hpp>

#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace volpost::meshio {

struct AppendedBlock {
  bool present = false;
  bool base64 = false;
  std::size_t begin = 0, end = 0;  // data bytes in the file
};

class VtkXmlReading {
 public:
  VtkXmlReading(std::string path, const Progress& progress, std::uint64_t readInPlaceFrom)
      : path_(std::move(path)), progress_(progress), readInPlaceFrom_(readInPlaceFrom) {}

  std::unique_ptr<Model> run();

 private:
  [[noreturn]] void failAt(const pugi::xml_node& node, const std::string& message) const {
    throw ReadError::atLine(path_, lineAt(xml_, std::size_t(node.offset_debug())), message);
  }

  // A file under readInPlaceFrom_ bytes is read whole into memory (its lazy fields keep
  // it). A larger one is read up to its appended data, whose arrays are then decoded from
  // the file where they lie, a chunk at a time (a 12.6M-tet mesh's file is 550 MB, and
  // holding it while decoding was half of the read's peak memory); its lazy fields read
  // from the file when they are first shown.
  void openFile();

  // Where the last </AppendedData> starts, searched backwards from the file's end in chunks.
  std::uint64_t closingTagOffset(const DiskFile& disk, std::uint64_t dataBegin) const;

  // Raw appended data is not XML: cut it out before parsing and remember where it is.
  void splitAppended();

  void readEncoding(const pugi::xml_node& root);

  // Appended arrays each own a run of the appended data, from their offset to the next
  // array's: two arrays at one offset (or a run past the data) is a corrupt or hostile
  // file, and decoding every array from the same place to the end would take quadratic time.
  void checkAppendedOffsets(const pugi::xml_node& root);

  // The end of the run of the appended array starting at `offset`: the next array's offset.
  std::size_t appendedRunEnd(std::size_t offset) const;

  VtuArraySource source(const pugi::xml_node& array);

  template <typename F>
  auto guarded(const pugi::xml_node& node, F&& f) -> decltype(f()) {
    try {
      return f();
    } catch (const VtuArrayError& e) {
      failAt(node, e.message);
    }
  }

  pugi::xml_node arrayNamed(const pugi::xml_node& parent, const char* name);

  std::vector<std::int64_t> integers(const pugi::xml_node& node);

  // An unstructured grid's piece, in VtuReader.cpp.
  void readPiece(const pugi::xml_node& piece, Model& model);

  // ---- ImageData (.vti): a regular grid, in VtiReader.cpp ---------------------------

  // `count` numbers from an attribute ("0 10 0 10 0 5"), or the defaults when it is absent.
  std::vector<double> numbers(const pugi::xml_node& node, const char* attribute, std::vector<double> defaults);

  struct Extent {
    std::array<long long, 6> e{};
    std::array<std::size_t, 3> points() const {
      return {std::size_t(e[1] - e[0] + 1), std::size_t(e[3] - e[2] + 1), std::size_t(e[5] - e[4] + 1)};
    }
  };
  Extent extentOf(const pugi::xml_node& node, const char* attribute);

  std::unique_ptr<Model> readImage(const pugi::xml_node& image);

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
                     const VtkCellMapping* mapping, Model& model);

  // The values of one array over all pieces, read on first use.
  StepLoader arrayLoader(FieldParts& f);

  void finishFields(Model& model);

  // volpost (and meshio/Gmsh exports) keep the FE ids as "node_id" / "element_id" arrays:
  // they become the mesh's ids, not a field to color by.
  static bool takeIds(const Field& field, Model& model);

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

}  // namespace volpost::meshio

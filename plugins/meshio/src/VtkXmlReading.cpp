// SPDX-License-Identifier: MIT
#include "VtkXmlReading.hpp"

#include <volpost/core/ResourceLimits.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <set>
#include <sstream>

namespace volpost::meshio {

std::unique_ptr<Model> VtkXmlReading::run() {
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
  if (!grid)
    throw ReadError(path_, "this VTK XML file holds a " + std::string(root.attribute("type").as_string("?")) +
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

void VtkXmlReading::openFile() {
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

std::uint64_t VtkXmlReading::closingTagOffset(const DiskFile& disk, std::uint64_t dataBegin) const {
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

void VtkXmlReading::splitAppended() {
  const std::string& b = *bytes_;
  const std::size_t tag = b.find("<AppendedData");
  if (tag == std::string::npos) {
    xml_ = b;
    return;
  }
  const std::size_t tagEnd = b.find('>', tag);
  if (tagEnd == std::string::npos)
    throw ReadError::atOffset(path_, tag, "<AppendedData> tag is not closed (truncated)");
  const std::string tagText = b.substr(tag, tagEnd - tag);
  appended_.present = true;
  appended_.base64 = tagText.find("\"base64\"") != std::string::npos;
  const std::size_t underscore = b.find('_', tagEnd);
  if (underscore == std::string::npos)
    throw ReadError::atOffset(path_, tagEnd, "appended data has no '_' marker (truncated)");
  const std::size_t close = b.rfind("</AppendedData>");
  if (close == std::string::npos || close < underscore)
    throw ReadError::atOffset(path_, b.size(), "file ends inside the appended data: no </AppendedData> (truncated)");
  appended_.begin = underscore + 1;
  appended_.end = close;
  xml_ = b.substr(0, tagEnd + 1) + b.substr(close);
}

void VtkXmlReading::readEncoding(const pugi::xml_node& root) {
  const std::string order = root.attribute("byte_order").as_string("LittleEndian");
  if (order != "LittleEndian" && order != "BigEndian")
    failAt(root, "byte_order \"" + order + "\" is neither LittleEndian nor BigEndian");
  enc_.bigEndian = order == "BigEndian";
  const std::string header = root.attribute("header_type").as_string("UInt32");
  if (header == "UInt64") enc_.headerType = NumericType::UInt64;
  else if (header != "UInt32") failAt(root, "header_type \"" + header + "\" is not UInt32 or UInt64");
  const std::string compressor = root.attribute("compressor").as_string("");
  if (compressor == "vtkZLibDataCompressor") enc_.compressed = true;
  else if (!compressor.empty())
    failAt(root,
           "compressor " + compressor + " is not supported (volpost reads zlib-compressed and uncompressed files)");
}

void VtkXmlReading::checkAppendedOffsets(const pugi::xml_node& root) {
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

std::size_t VtkXmlReading::appendedRunEnd(std::size_t offset) const {
  const auto next = std::upper_bound(appendedOffsets_.begin(), appendedOffsets_.end(), offset);
  const std::size_t size = appended_.end - appended_.begin;
  return next == appendedOffsets_.end() ? size : std::min<std::size_t>(*next, size);
}

VtuArraySource VtkXmlReading::source(const pugi::xml_node& array) {
  VtuArraySource s;
  s.name = array.attribute("Name").as_string("");
  const std::string typeName = array.attribute("type").as_string("");
  const auto type = numericTypeFromXml(typeName);
  if (!type) failAt(array, "DataArray \"" + s.name + "\" has unknown type \"" + typeName + "\"");
  s.type = *type;
  s.components = array.attribute("NumberOfComponents").as_int(1);
  if (s.components < 1 || s.components > 4096)
    failAt(array, "DataArray \"" + s.name + "\" has a bad NumberOfComponents");
  const std::string format = array.attribute("format").as_string("ascii");
  if (format == "appended") {
    if (!appended_.present)
      failAt(array, "DataArray \"" + s.name + "\" is appended but the file has no <AppendedData>");
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

pugi::xml_node VtkXmlReading::arrayNamed(const pugi::xml_node& parent, const char* name) {
  for (pugi::xml_node a : parent.children("DataArray"))
    if (std::strcmp(a.attribute("Name").as_string(), name) == 0) return a;
  failAt(parent, std::string("<") + parent.name() + "> has no DataArray \"" + name + "\"");
}

std::vector<std::int64_t> VtkXmlReading::integers(const pugi::xml_node& node) {
  const VtuArraySource s = source(node);
  return guarded(node, [&] { return vtuIntegers(s, enc_); });
}

void VtkXmlReading::collectArrays(const pugi::xml_node& data, FieldLocation location, std::size_t count,
                                  const VtkCellMapping* mapping, Model& model) {
  if (!data) return;
  for (pugi::xml_node array : data.children("DataArray")) {
    VtuArraySource s = source(array);
    if (s.name.empty()) failAt(array, "DataArray without a Name");
    const std::size_t values = guarded(array, [&] { return vtuValueCount(s, enc_); });
    const std::string key = std::string(location == FieldLocation::Node ? "n:" : "c:") + s.name;
    auto [it, inserted] =
        fields_.try_emplace(key, FieldParts{location, s.components, {}, pieceCount_, false, {}, 0, {}});
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
      model.diagnostics.push_back(
          {Severity::Warning,
           "field-dropped",
           "field " + s.name + " dropped: " + std::to_string(values / std::size_t(s.components)) + " values for " +
               std::to_string(count) + (location == FieldLocation::Node ? " points" : " cells") + " (line " +
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

StepLoader VtkXmlReading::arrayLoader(FieldParts& f) {
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

void VtkXmlReading::finishFields(Model& model) {
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

bool VtkXmlReading::takeIds(const Field& field, Model& model) {
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

}  // namespace volpost::meshio

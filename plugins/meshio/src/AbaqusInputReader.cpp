// SPDX-License-Identifier: MIT
#include "AbaqusInputReader.hpp"

#include "CalculixElements.hpp"
#include "DeckSets.hpp"
#include "DeckSurfaces.hpp"
#include "FileBytes.hpp"
#include "NodeTable.hpp"
#include "TextScanner.hpp"

#include <volpost/core/ResourceLimits.hpp>

#include <array>
#include <filesystem>
#include <map>
#include <stdexcept>

namespace volpost::meshio {
namespace {

struct Keyword {
  std::string name;                          // upper case, no '*'
  std::map<std::string, std::string> params; // upper-case keys, values as written
};

// "*ELEMENT, TYPE=C3D4, ELSET=E1": the name up to the first comma (it may hold spaces,
// "*SOLID SECTION"), then comma-separated KEY or KEY=VALUE parameters.
Keyword parseKeyword(std::string_view line) {
  Keyword k;
  std::size_t at = 1;
  bool first = true;
  while (at <= line.size()) {
    const std::size_t comma = std::min(line.find(',', at), line.size());
    const auto part = trim(line.substr(at, comma - at));
    if (first) {
      k.name = toUpper(part);
      first = false;
    } else if (!part.empty()) {
      const auto eq = part.find('=');
      if (eq == std::string_view::npos) k.params[toUpper(part)] = "";
      else k.params[toUpper(trim(part.substr(0, eq)))] = std::string(trim(part.substr(eq + 1)));
    }
    at = comma + 1;
  }
  return k;
}

class DeckParser {
 public:
  DeckParser(const Progress& progress) : progress_(progress) {}

  std::unique_ptr<Model> parse(const std::string& path) {
    model_ = std::make_unique<Model>();
    readFile(path, 0, {});
    if (nodeIndex_.size() == 0) throw ReadError(path, "no *NODE data: this deck defines no mesh");
    if (model_->mesh().cellCount() == 0 && skipped_ == 0)
      throw ReadError(path, "no *ELEMENT data: this deck defines nodes but no elements");
    finish();
    return std::move(model_);
  }

 private:
  // Limits on *INCLUDE: nesting depth, the number of files read and their total size, so
  // that a fan-out of includes (8 files each including the next 20 times: 2.6e10 reads)
  // ends in a message instead of running for days.
  static constexpr int kMaxIncludeDepth = 16;
  static constexpr std::size_t kMaxFilesRead = 10000;

  void readFile(const std::string& path, int depth, std::vector<std::string> chain) {
    if (depth > kMaxIncludeDepth)
      throw ReadError(path, "*INCLUDE nested more than " + std::to_string(kMaxIncludeDepth) + " deep");
    std::error_code ec;
    const std::string canonical = std::filesystem::weakly_canonical(path, ec).string();
    for (const std::string& outer : chain)
      if (outer == canonical) throw ReadError(path, "includes itself (an *INCLUDE cycle)");
    chain.push_back(canonical);
    if (++filesRead_ > kMaxFilesRead)
      throw ReadError(path, "the deck's *INCLUDEs read more than " + std::to_string(kMaxFilesRead) +
                                " files (an include fan-out?)");
    auto bytes = readFileBytes(path, depth == 0 ? progress_ : Progress{});
    bytesRead_ += bytes->size();
    requireMemory(double(bytesRead_), path, "the deck and its *INCLUDEs");
    TextScanner s(std::move(bytes), path);
    if (s.bytes().find('\0') != std::string::npos || !looksLikeText(s.bytes()))
      throw ReadError(path, "binary data, not an Abaqus/CalculiX input deck (which is text)");
    enum class Block { None, Node, Element, Heading, Set, Surface } block = Block::None;
    std::optional<SolidElement> element;
    std::string elset;
    std::vector<std::string_view> pending;  // fields of an element record spread over lines
    std::size_t pendingOffset = 0;  // where the record began (its line is counted only for an error)
    bool sawKeyword = false;
    while (!s.atEnd()) {
      const auto raw = s.nextLine();
      const auto line = trim(raw);
      if (line.empty() || line.rfind("**", 0) == 0) continue;
      if (line.front() == '*') {
        if (!pending.empty()) {
          s.seek(pendingOffset);
          s.fail("this element record is incomplete: its type needs more nodes");
        }
        sawKeyword = true;
        const Keyword k = parseKeyword(line);
        block = Block::None;
        if (k.name == "NODE") {
          block = Block::Node;
          const auto set = k.params.find("NSET");
          nodeSet_ = set == k.params.end() ? "" : toUpper(set->second);
        } else if (k.name == "ELSET" || k.name == "NSET") {
          const auto set = k.params.find(k.name);
          if (set == k.params.end() || trim(set->second).empty()) s.fail("*" + k.name + " without " + k.name + "=");
          block = Block::Set;
          sets_.begin(k.name == "ELSET" ? SetKind::Cells : SetKind::Nodes, toUpper(trim(set->second)),
                      k.params.count("GENERATE") > 0);
        } else if (k.name == "SURFACE") {
          const auto name = k.params.find("NAME");
          if (name == k.params.end() || trim(name->second).empty()) s.fail("*SURFACE without NAME=");
          const auto type = k.params.find("TYPE");
          const std::string kind = type == k.params.end() ? "ELEMENT" : toUpper(trim(type->second));
          if (kind == "ELEMENT" || kind == "NODE") {  // analytical and cutting surfaces have no nodes to list
            block = Block::Surface;
            surfaces_.begin(toUpper(trim(name->second)), kind == "NODE");
          }
        } else if (k.name == "HEADING") block = Block::Heading;
        else if (k.name == "ELEMENT") {
          block = Block::Element;
          const auto type = k.params.find("TYPE");
          if (type == k.params.end()) s.fail("*ELEMENT without TYPE=");
          try {
            element = abaqusSolid(type->second);
          } catch (const std::invalid_argument& e) {
            s.fail(e.what());
          }
          if (!element) skippedTypes_[toUpper(type->second)] += 0;
          const auto set = k.params.find("ELSET");
          elset = set == k.params.end() ? "" : toUpper(set->second);
        } else if (k.name == "INCLUDE") {
          const auto input = k.params.find("INPUT");
          if (input == k.params.end() || input->second.empty()) s.fail("*INCLUDE without INPUT=");
          std::filesystem::path included = input->second;
          if (included.is_relative()) included = std::filesystem::path(path).parent_path() / included;
          try {
            readFile(included.string(), depth + 1, chain);
          } catch (const ReadError& e) {
            if (e.file() != included.string() || e.line() >= 0 || e.offset() >= 0) throw;  // already says where
            s.fail("*INCLUDE, INPUT=" + input->second + ": " + e.detail());
          }
        }
        continue;
      }
      if (!sawKeyword) s.fail("an input deck starts with a *KEYWORD line, found '" + std::string(line.substr(0, 40)) + "'");
      switch (block) {
        case Block::Node: readNode(s, line); break;
        case Block::Set:
          sets_.readLine(s, line);
          break;
        case Block::Surface:
          surfaces_.readLine(s, line);
          break;
        case Block::Heading:
          if (model_->title.empty()) model_->title = std::string(line);
          break;
        case Block::Element: {
          if (pending.empty()) pendingOffset = std::size_t(line.data() - s.bytes().data());
          for (auto f : splitFields(line, true))
            if (!trim(f).empty()) pending.push_back(f);  // a trailing comma leaves an empty field
          const std::size_t need = 1 + std::size_t(element ? element->fileNodes : 0);
          // A line ending in a comma continues the record unless the record is complete.
          if (element ? pending.size() < need : line.back() == ',') continue;
          readElement(s, pending, element, elset);
          pending.clear();
          break;
        }
        case Block::None: break;
      }
      if ((++lines_ & 0x3fff) == 0 && depth == 0) s.report(progress_, 0.2, 0.9);
    }
    if (!pending.empty())
      s.fail("file ends inside an element record (truncated): " + std::to_string(pending.size() - 1) + " of " +
             std::to_string(element ? element->fileNodes : 0) + " nodes");
  }

  static bool looksLikeText(const std::string& b) {
    std::size_t odd = 0;
    const std::size_t n = std::min<std::size_t>(b.size(), 4096);
    for (std::size_t i = 0; i < n; ++i) {
      const auto c = static_cast<unsigned char>(b[i]);
      if (c < 9 || (c > 13 && c < 32) || c == 127) ++odd;
    }
    return odd * 50 < n;
  }

  void readNode(TextScanner& s, std::string_view line) {
    const auto f = splitFields(line, true);
    if (f.size() < 2) s.fail("a *NODE record needs 'id, x[, y[, z]]'");
    const std::int64_t id = parseInteger(s, f[0], "a node id");
    glm::dvec3 p(0.0);
    for (std::size_t k = 1; k < f.size() && k < 4; ++k)
      p[int(k - 1)] = f[k].empty() ? 0.0 : parseFortranReal(s, f[k], "a node coordinate");
    if (!nodeIndex_.add(id, NodeIndex(model_->mesh().nodes.size()))) {
      s.fail("node " + std::to_string(id) + " is defined twice");
    }
    model_->mesh().nodes.push_back(p);
    model_->mesh().nodeIds.push_back(id);
    sets_.addId(SetKind::Nodes, nodeSet_, id);
  }

  void readElement(TextScanner& s, const std::vector<std::string_view>& f, const std::optional<SolidElement>& element,
                   const std::string& elset) {
    const std::int64_t id = parseInteger(s, f[0], "an element id");
    if (!element) {
      sets_.noteSkippedElement(id);
      sets_.addId(SetKind::Cells, elset, id);  // its set is then reported as empty, not silently absent
      ++skipped_;
      return;
    }
    std::vector<std::string_view> nodes;  // trailing empty fields ("..., 12,") are not nodes
    for (std::size_t k = 1; k < f.size(); ++k)
      if (!trim(f[k]).empty()) nodes.push_back(f[k]);
    if (nodes.size() != std::size_t(element->fileNodes))
      s.fail("element " + std::to_string(id) + " has " + std::to_string(nodes.size()) + " nodes, its type needs " +
             std::to_string(element->fileNodes));
    std::array<NodeIndex, 20> cell{};
    for (std::size_t k = 0; k < element->vtkOrder.size(); ++k) {
      const std::int64_t nodeId = parseInteger(s, nodes[std::size_t(element->vtkOrder[k])], "a node id");
      const auto index = nodeIndex_.find(nodeId);
      if (!index)
        s.fail("element " + std::to_string(id) + " (cell " + std::to_string(model_->mesh().cellCount()) +
               ") uses node " + std::to_string(nodeId) + ", which no *NODE defines");
      cell[k] = *index;
    }
    CellType type = element->cell;
    int count = int(element->vtkOrder.size());
    if (type == CellType::Hex8) {
      type = collapseDegenerateHex(std::span<std::uint32_t>(cell.data(), 8), count);
      if (type != CellType::Hex8) {
        ++collapsed_[type];
        surfaces_.noteCollapsed(id);
      }
    }
    model_->mesh().addCell(type, std::span<const NodeIndex>(cell.data(), std::size_t(count)));
    model_->mesh().cellIds.push_back(id);
    elementIndex_.add(id, std::uint32_t(model_->mesh().cellCount() - 1));  // a repeated id: sets mean the first
    sets_.addId(SetKind::Cells, elset, id);
    auto [it, added] = elsetIndex_.emplace(elset, elsetIndex_.size() + 1);
    if (added) elsetNames_.push_back(elset.empty() ? "(no ELSET)" : elset);
    elsets_.push_back(double(it->second));
  }

  void finish() {
    sets_.moveInto(*model_, nodeIndex_, elementIndex_);
    surfaces_.moveInto(*model_, nodeIndex_, elementIndex_, sets_.skippedElements());
    if (elsetNames_.size() > 1) {
      model_->fields.push_back(Field::fromValues("element set", FieldLocation::Cell, 1, {elsets_}));
      std::string names;
      for (std::size_t i = 0; i < elsetNames_.size(); ++i)
        names += (i ? ", " : "") + std::to_string(i + 1) + " " + elsetNames_[i];
      model_->diagnostics.push_back({Severity::Info, "element-sets", "field 'element set' numbers the *ELEMENT blocks: " + names, {}});
    }
    for (const auto& [type, count] : collapsed_)
      model_->diagnostics.push_back({Severity::Info, "collapsed-hexahedra",
                                     std::to_string(count) + " C3D8 with repeated nodes were read as " +
                                         std::string(cellTypeName(type)) + " (CalculiX's way of writing them)", {}});
    if (skipped_ > 0) {
      std::string types;
      for (const auto& [t, unused] : skippedTypes_) types += (types.empty() ? "" : ", ") + t;
      model_->diagnostics.push_back({Severity::Info, "skipped-non-solid-elements",
                                     std::to_string(skipped_) + " elements that are not solids (" + types +
                                         ") were not loaded: volpost shows volume cells", {}});
    }
  }

  const Progress& progress_;
  std::unique_ptr<Model> model_;
  IdIndex nodeIndex_, elementIndex_;
  DeckSets sets_;
  DeckSurfaces surfaces_;
  std::string nodeSet_;
  std::map<std::string, std::size_t> elsetIndex_;
  std::vector<std::string> elsetNames_;
  std::vector<double> elsets_;
  std::map<CellType, std::size_t> collapsed_;
  std::map<std::string, int> skippedTypes_;
  std::size_t skipped_ = 0, lines_ = 0;
  std::size_t filesRead_ = 0, bytesRead_ = 0;
};

}  // namespace

int AbaqusInputReader::sniff(std::string_view head) const {
  // A deck starts with comments (**) or keywords (*HEADING, *NODE, ...).
  std::size_t i = 0;
  while (i < head.size() && std::isspace(static_cast<unsigned char>(head[i]))) ++i;
  if (i >= head.size() || head[i] != '*') return 0;
  for (std::string_view key : {"*NODE", "*HEADING", "*ELEMENT", "*INCLUDE", "*PREPRINT", "*PART"}) {
    for (std::size_t at = head.find('*'); at != std::string_view::npos; at = head.find('*', at + 1)) {
      std::string word;
      for (std::size_t k = at; k < head.size() && k < at + key.size(); ++k) word += char(std::toupper(static_cast<unsigned char>(head[k])));
      if (word == key) return 80;
    }
  }
  return 20;
}

std::unique_ptr<Model> AbaqusInputReader::read(const std::string& path, const Progress& progress) const {
  auto model = DeckParser(progress).parse(path);
  model->formatName = formatName();
  return model;
}

}  // namespace volpost::meshio

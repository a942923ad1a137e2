// SPDX-License-Identifier: MIT
// Layout: the CalculiX cgx manual, "Result Format". Records are fixed columns: a 3-column
// key (" -1" ...), integers 5 wide in the short format and 10 wide in the long one, reals
// 12 wide; fields may touch ("1.0E+00-2.0E+00"), so they are cut by column, never split on
// spaces.
#include "FrdReader.hpp"

#include "SetsFromDeck.hpp"

#include "CalculixElements.hpp"
#include "FileBytes.hpp"
#include "NodeTable.hpp"
#include "ResultCollector.hpp"
#include "TextScanner.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <map>

namespace volpost::meshio {
namespace {

// CalculiX dataset names to the names the VTK and Exodus exports of the same run use.
std::string fieldName(const std::string& dataset) {
  static const std::map<std::string, std::string> names = {
      {"DISP", "U"}, {"STRESS", "S"}, {"TOSTRAIN", "E"}, {"MESTRAIN", "ME"}, {"NDTEMP", "T"},
      {"FLUX", "HFL"}, {"FORC", "RF"}, {"PE", "PEEQ"}, {"ENER", "ENER"}, {"VELO", "V"}};
  const auto it = names.find(dataset);
  return it == names.end() ? dataset : it->second;
}

class FrdParser {
 public:
  FrdParser(std::shared_ptr<const std::string> bytes, const std::string& path, const Progress& progress)
      : s_(std::move(bytes), path), progress_(progress) {}

  std::unique_ptr<Model> parse() {
    model_ = std::make_unique<Model>();
    bool ended = false;
    while (!s_.atEnd() && !ended) {
      line_ = s_.nextLine();
      const auto key = trim(line_.substr(0, std::min<std::size_t>(line_.size(), 6)));
      if (key.empty()) continue;
      if (key == "9999") ended = true;
      else if (key == "1C") sawHeader_ = true;
      else if (key == "1U") readUserHeader();
      else if (key == "2C") readNodes();
      else if (key == "3C") readElements();
      else if (key == "100C") readResults();
      else if (key == "1P") continue;  // parameters (1PSTEP ...)
      else if (!sawHeader_) s_.fail("not a CalculiX .frd file: it must begin with a '    1C' record");
      else if (key.front() == '-') s_.fail("record '" + std::string(key) + "' outside any block");
      else s_.fail("unknown record '" + std::string(line_.substr(0, 12)) + "'");
      s_.report(progress_, 0.2, 0.95);
    }
    if (!sawHeader_) s_.fail("not a CalculiX .frd file: it must begin with a '    1C' record");
    if (!sawNodes_) s_.fail("no node block (2C): this .frd holds no mesh");
    if (!sawElements_) s_.fail("no element block (3C): this .frd holds no mesh");
    if (!ended) s_.fail("file ends without the closing 9999 record (truncated)");
    if (const std::string wrong = results_.mismatch(model_->mesh()); !wrong.empty()) s_.fail(wrong);
    results_.moveInto(*model_);
    if (skipped_ > 0)
      model_->diagnostics.push_back({Severity::Info, "skipped-non-solid-elements",
                                     std::to_string(skipped_) + " shell, beam or other non-solid elements were not loaded", {}});
    if (collapsed_ > 0)
      model_->diagnostics.push_back({Severity::Info, "collapsed-hexahedra",
                                     std::to_string(collapsed_) + " he8 with repeated nodes were read as pyramids or wedges (CalculiX's way of writing them)", {}});
    return std::move(model_);
  }

 private:
  std::string_view column(std::size_t from, std::size_t width) const {
    if (from >= line_.size()) return {};
    return line_.substr(from, std::min(width, line_.size() - from));
  }
  std::int64_t intColumn(std::size_t from, std::size_t width, const char* what) const {
    const auto f = trim(column(from, width));
    if (f.empty()) s_.fail(std::string("missing ") + what);
    return parseInteger(s_, f, what);
  }
  // Block headers: "    2C" then free fields (count ... format).
  std::pair<std::int64_t, int> blockHeader(const char* what) {
    const auto f = splitFields(column(6, std::string_view::npos));
    if (f.empty()) s_.fail(std::string("the ") + what + " header has no count");
    const std::int64_t n = parseInteger(s_, f[0], "a count");
    if (n < 0 || n > (std::int64_t(1) << 34)) s_.fail(std::string("the ") + what + " count " + std::to_string(n) + " is out of range");
    const int format = f.size() >= 2 ? int(parseInteger(s_, f.back(), "the format flag")) : 0;
    if (format == 2) s_.fail("binary .frd blocks are not supported (write ASCII results: *NODE FILE without OUTPUT=...binary)");
    return {n, format};
  }
  std::size_t idWidth(int format) const { return format == 0 ? 5 : 10; }

  std::string_view recordLine(const char* where) {
    if (s_.atEnd())
      s_.fail(std::string("the file ends inside the ") + where +
              ": the line ' -3' that closes a block never comes (the file was cut short)");
    line_ = s_.nextLine();
    return trim(column(0, 3));
  }

  void readUserHeader() {
    const auto text = trim(column(6, 80));
    if (model_->title.empty() && !text.empty() && text.rfind("USER", 0) != 0) model_->title = std::string(text);
  }

  void readNodes() {
    sawNodes_ = true;
    const auto [n, format] = blockHeader("node block");
    const std::size_t w = idWidth(format);
    model_->mesh().nodes.reserve(std::size_t(std::min<std::int64_t>(n, 1 << 26)));
    std::int64_t seen = 0;
    for (auto key = recordLine("node block"); key != "-3"; key = recordLine("node block")) {
      if (key != "-1") s_.fail("expected a node record ' -1', found '" + std::string(line_.substr(0, 20)) + "'");
      const std::int64_t id = intColumn(3, w, "a node number");
      glm::dvec3 p;
      for (int k = 0; k < 3; ++k) p[k] = parseFortranReal(s_, column(3 + w + 12 * std::size_t(k), 12), "a coordinate");
      if (!nodeIndex_.add(id, NodeIndex(model_->mesh().nodes.size()))) s_.fail("node " + std::to_string(id) + " is defined twice");
      model_->mesh().nodes.push_back(p);
      model_->mesh().nodeIds.push_back(id);
      ++seen;
    }
    if (seen != n) s_.fail("the node block header (2C) says " + std::to_string(n) + " nodes, " + std::to_string(seen) + " follow");
  }

  void readElements() {
    sawElements_ = true;
    if (!sawNodes_) s_.fail("the element block (3C) comes before the node block (2C)");
    const auto [n, format] = blockHeader("element block");
    const std::size_t w = idWidth(format);
    std::int64_t seen = 0;
    auto key = recordLine("element block");
    while (key != "-3") {
      if (key != "-1") s_.fail("expected an element record ' -1', found '" + std::string(line_.substr(0, 20)) + "'");
      const std::int64_t id = intColumn(3, w, "an element number");
      const int code = int(intColumn(3 + w, 5, "an element type"));
      const auto solid = frdSolid(code);
      const int expected = solid ? solid->fileNodes : -1;
      std::vector<std::int64_t> nodes;
      for (key = recordLine("element block"); key == "-2"; key = recordLine("element block")) {
        for (std::size_t at = 3; at + 1 < line_.size(); at += w) {
          const auto f = trim(column(at, w));
          if (!f.empty()) nodes.push_back(parseInteger(s_, f, "a node number"));
        }
      }
      ++seen;
      if (!solid) {
        ++skipped_;
        continue;
      }
      if (int(nodes.size()) != expected)
        s_.fail("element " + std::to_string(id) + " (type " + std::to_string(code) + ") has " + std::to_string(nodes.size()) +
                " nodes, expected " + std::to_string(expected));
      std::array<NodeIndex, 20> cell{};
      for (std::size_t k = 0; k < solid->vtkOrder.size(); ++k) {
        const std::int64_t nodeId = nodes[std::size_t(solid->vtkOrder[k])];
        const auto index = nodeIndex_.find(nodeId);
        if (!index)
          s_.fail("element " + std::to_string(id) + " (cell " + std::to_string(model_->mesh().cellCount()) + ") uses node " +
                  std::to_string(nodeId) + ", which the node block (2C) does not define");
        cell[k] = *index;
      }
      CellType type = solid->cell;
      int count = int(solid->vtkOrder.size());
      if (type == CellType::Hex8) {
        type = collapseDegenerateHex(std::span<std::uint32_t>(cell.data(), 8), count);
        if (type != CellType::Hex8) ++collapsed_;
      }
      model_->mesh().addCell(type, std::span<const NodeIndex>(cell.data(), std::size_t(count)));
      model_->mesh().cellIds.push_back(id);
    }
    if (seen != n) s_.fail("the element block header (3C) says " + std::to_string(n) + " elements, " + std::to_string(seen) + " follow");
  }

  // "  100C" header (step value and number), "-4" dataset, "-5" components, "-1" records.
  void readResults() {
    const double value = parseFortranReal(s_, column(12, 12), "the step value");
    const std::int64_t numnod = intColumn(24, 12, "the node count of a result block");
    const std::int64_t numstp = line_.size() >= 63 ? intColumn(58, 5, "the step number") : 1;
    const int format = line_.size() >= 75 ? int(intColumn(73, 2, "the format flag")) : 0;
    if (format == 2) s_.fail("binary .frd result blocks are not supported");
    const std::size_t w = idWidth(format);
    if (recordLine("result block") != "-4") s_.fail("a result block must start with its dataset record ' -4'");
    const std::string dataset(trim(column(5, 8)));
    int components = 0;
    std::vector<std::string> names;
    for (auto key = recordLine("result block"); ; key = recordLine("result block")) {
      if (key != "-5") break;
      const bool computed = line_.size() >= 38 && trim(column(33, 5)) == "1";  // e.g. ALL = |U|, not stored
      if (!computed) {
        ++components;
        names.emplace_back(trim(column(5, 8)));
      }
    }
    if (components == 0) s_.fail("dataset " + dataset + " has no stored components");
    const std::size_t nc = std::size_t(components);
    s_.requireMemory(results_.bytesWith(model_->mesh().nodeCount() * nc), "dataset " + dataset + " (" + std::to_string(nc) + " components)");
    std::vector<double> values(model_->mesh().nodeCount() * nc, std::numeric_limits<double>::quiet_NaN());
    std::int64_t seen = 0;
    // The line read last is the first record (the loop above stopped on it).
    for (std::string_view key = trim(column(0, 3)); key != "-3"; key = recordLine("result block")) {
      if (key != "-1") s_.fail("expected a result record ' -1' in dataset " + dataset + ", found '" + std::string(line_.substr(0, 20)) + "'");
      const std::int64_t id = intColumn(3, w, "a node number");
      const auto index = nodeIndex_.find(id);
      if (!index) s_.fail("dataset " + dataset + " has a value for node " + std::to_string(id) + ", which the node block does not define");
      std::size_t k = 0;
      for (std::size_t at = 3 + w; k < nc && at < line_.size(); at += 12, ++k)
        values[*index * nc + k] = parseFortranReal(s_, column(at, 12), "a result value");
      while (k < nc) {  // more than 6 values continue on ' -2' lines
        if (recordLine("result block") != "-2") s_.fail("dataset " + dataset + ": node " + std::to_string(id) + " has too few values");
        for (std::size_t at = 3 + w; k < nc && at < line_.size(); at += 12, ++k)
          values[*index * nc + k] = parseFortranReal(s_, column(at, 12), "a result value");
      }
      ++seen;
    }
    if (seen != numnod)
      s_.fail("dataset " + dataset + " header says " + std::to_string(numnod) + " nodes, " + std::to_string(seen) + " follow");
    Step step{"step " + std::to_string(numstp) + ", t = " + shortNumber(value), value};
    results_.add(fieldName(dataset), FieldLocation::Node, components, std::move(step), std::move(values));
  }

  static std::string shortNumber(double v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%g", v);
    return buffer;
  }

  TextScanner s_;
  const Progress& progress_;
  std::string_view line_;
  std::unique_ptr<Model> model_;
  bool sawHeader_ = false, sawNodes_ = false, sawElements_ = false;
  IdIndex nodeIndex_;
  ResultCollector results_;
  std::size_t skipped_ = 0, collapsed_ = 0;
};

}  // namespace

int FrdReader::sniff(std::string_view head) const {
  return head.substr(0, 6) == "    1C" ? 100 : 0;
}

std::unique_ptr<Model> FrdReader::read(const std::string& path, const Progress& progress) const {
  FrdParser parser(readFileBytes(path, progress), path, progress);
  auto model = parser.parse();
  model->formatName = formatName();
  addSetsFromDeckBeside(path, *model);
  return model;
}

}  // namespace volpost::meshio

// SPDX-License-Identifier: MIT
// No official specification exists; the layout follows ../shared/docs/FORMATS.md, which
// reconstructs it from independent public readers and writers. Quadratic elements list
// corner and midside nodes alternating around the element; the tables below give, for
// each neutral-file position, the Abaqus node (1-based) it is, and Abaqus's order is
// volpost's (VTK's) for tet10 and hex20.
#include "NeutralFileReader.hpp"

#include "FileBytes.hpp"
#include "NodeTable.hpp"
#include "ResultCollector.hpp"
#include "TextScanner.hpp"

#include <array>
#include <cctype>
#include <limits>
#include <map>
#include <optional>
#include <set>

namespace volpost::meshio {
namespace {

struct NfElement {
  std::optional<CellType> cell;  // nullopt: a surface element, skipped
  int nodes;
  std::vector<int> vtkOrder;     // neutral-file position of each VTK node
};

std::vector<int> fromAbaqusPositions(std::initializer_list<int> abaqusOfNf) {
  std::vector<int> vtk(abaqusOfNf.size());
  int i = 0;
  for (int a : abaqusOfNf) vtk[std::size_t(a - 1)] = i++;
  return vtk;
}

const std::map<std::string, NfElement>& nfElements() {
  static const std::map<std::string, NfElement> types = {
      {"TETR4", {CellType::Tet4, 4, {0, 1, 2, 3}}},
      {"TET4", {CellType::Tet4, 4, {0, 1, 2, 3}}},
      {"TET10", {CellType::Tet10, 10, fromAbaqusPositions({2, 5, 1, 8, 4, 9, 6, 7, 10, 3})}},
      {"TETR10", {CellType::Tet10, 10, fromAbaqusPositions({2, 5, 1, 8, 4, 9, 6, 7, 10, 3})}},
      {"BRICK8", {CellType::Hex8, 8, {0, 1, 2, 3, 4, 5, 6, 7}}},
      {"BRICK20", {CellType::Hex20, 20,
                   fromAbaqusPositions({5, 17, 1, 9, 2, 18, 6, 13, 16, 12, 10, 14, 8, 20, 4, 11, 3, 19, 7, 15})}},
      {"T3", {std::nullopt, 3, {}}}, {"T6", {std::nullopt, 6, {}}},
      {"Q4", {std::nullopt, 4, {}}}, {"Q8", {std::nullopt, 8, {}}},
  };
  return types;
}

class NfParser {
 public:
  NfParser(std::shared_ptr<const std::string> bytes, const std::string& path, const Progress& progress)
      : s_(std::move(bytes), path), progress_(progress) {}

  std::unique_ptr<Model> parse() {
    model_ = std::make_unique<Model>();
    std::string_view t = token();
    if (t.empty() || t.front() != '%') s_.fail("not a neutral file: it must begin with a %TAG line");
    bool ended = false;
    while (!t.empty()) {
      if (t.front() != '%') s_.fail("expected a %TAG, found '" + std::string(t.substr(0, 40)) + "' (a block holds more records than its count)");
      const std::string tag = toUpper(t.substr(1));
      if (tag == "END") {
        ended = true;
        break;
      }
      t = dispatch(tag);
      s_.report(progress_, 0.2, 0.95);
    }
    if (!ended) s_.fail("file ends without %END (truncated)");
    if (nodeIndex_.size() == 0) s_.fail("no %NODE.COORD block: this neutral file holds no mesh");
    finish();
    return std::move(model_);
  }

 private:
  // A token, or a whole 'quoted string' (quotes removed).
  std::string_view token() {
    const std::string& b = s_.bytes();
    std::size_t at = s_.offset();
    while (at < b.size() && std::isspace(static_cast<unsigned char>(b[at]))) ++at;
    if (at < b.size() && b[at] == '\'') {
      const std::size_t close = b.find('\'', at + 1);
      const std::size_t eol = b.find('\n', at + 1);
      if (close == std::string::npos || close > eol) {
        s_.seek(at);
        s_.fail("a quoted string is not closed on its line");
      }
      s_.seek(close + 1);
      return std::string_view(b.data() + at + 1, close - at - 1);
    }
    s_.seek(at);
    return s_.nextToken();
  }
  std::int64_t integer(const char* what) {
    const auto t = token();
    if (t.empty()) s_.fail(std::string("file ends where ") + what + " was expected (truncated)");
    return parseInteger(s_, t, what);
  }
  std::int64_t count(const char* what) {
    const std::int64_t n = integer(what);
    if (n < 0 || n > (std::int64_t(1) << 34)) s_.fail(std::string(what) + " " + std::to_string(n) + " is out of range");
    return n;
  }
  double real(const char* what) {
    const auto t = token();
    if (t.empty()) s_.fail(std::string("file ends where ") + what + " was expected (truncated)");
    return parseFortranReal(s_, t, what);
  }
  // Skips the records of a block volpost does not use: up to the next %TAG.
  std::string_view skipBlock() {
    for (auto t = token(); ; t = token())
      if (t.empty() || t.front() == '%') return t;
  }

  std::string_view dispatch(const std::string& tag) {
    if (tag == "HEADER.TITLE") {
      model_->title = std::string(token());
      return skipBlock();
    }
    if (tag == "NODE.COORD") return readNodes();
    if (tag.rfind("ELEMENT.", 0) == 0 && tag != "ELEMENT") return readElements(tag.substr(8));
    if (tag == "RESULT.CASE.STEP") {
      stepNumber_ = integer("the step number");
      stepTime_ = double(stepNumber_);
      return skipBlock();
    }
    if (tag == "RESULT.CASE.STEP.TIME" || tag == "RESULT.CASE.STEP.FACTOR") {
      stepTime_ = real("the step time");
      return skipBlock();
    }
    if (tag == "RESULT.CASE.STEP.NODAL.DISPLACEMENT") return readDisplacement();
    if (tag == "RESULT.CASE.STEP.NODAL.SCALAR" || tag == "RESULT.CASE.STEP.NODAL.VECTOR" ||
        tag == "RESULT.CASE.STEP.ELEMENT.GAUSS.SCALAR" || tag == "RESULT.CASE.STEP.ELEMENT.NODAL.SCALAR")
      return readLabels();
    if (tag == "RESULT.CASE.STEP.NODAL.SCALAR.DATA") return readNodal(1);
    if (tag == "RESULT.CASE.STEP.NODAL.VECTOR.DATA") return readNodal(3);
    if (tag == "RESULT.CASE.STEP.ELEMENT.GAUSS.SCALAR.DATA") return readPerElement(false);
    if (tag == "RESULT.CASE.STEP.ELEMENT.NODAL.SCALAR.DATA") return readPerElement(true);
    return skipBlock();  // %HEADER, %MATERIAL..., %NODE, %ELEMENT, %RESULT, %RESULT.CASE...
  }

  std::string_view readNodes() {
    const std::int64_t n = count("the node count");
    model_->mesh().nodes.reserve(std::size_t(std::min<std::int64_t>(n, 1 << 26)));
    for (std::int64_t i = 0; i < n; ++i) {
      const std::int64_t id = integer("a node id");
      glm::dvec3 p;
      for (int k = 0; k < 3; ++k) p[k] = real("a node coordinate");
      if (!nodeIndex_.add(id, NodeIndex(model_->mesh().nodes.size()))) s_.fail("node " + std::to_string(id) + " is defined twice");
      model_->mesh().nodes.push_back(p);
      model_->mesh().nodeIds.push_back(id);
    }
    return skipBlockStrict("%NODE.COORD", n);
  }

  // After the declared records, the next token must be a tag: more records than the count
  // is an error, not something to skip.
  std::string_view skipBlockStrict(const std::string& block, std::int64_t n) {
    const auto t = token();
    if (!t.empty() && t.front() != '%')
      s_.fail(block + " holds more records than its count " + std::to_string(n) + " (found '" + std::string(t.substr(0, 30)) + "')");
    return t;
  }

  std::string_view readElements(const std::string& type) {
    const auto it = nfElements().find(type);
    const std::int64_t n = count("the element count");
    if (it == nfElements().end()) {
      unknownTypes_[type] += std::size_t(n);
      return skipBlock();
    }
    const NfElement& e = it->second;
    std::array<NodeIndex, 20> cell{};
    for (std::int64_t i = 0; i < n; ++i) {
      // id mat [thick] order n1..nk: one record per line, the thickness only on some
      const auto fields = splitFields(recordLine());
      if (fields.empty()) s_.fail("file ends inside %ELEMENT." + type + " (truncated)");
      const std::size_t properties = fields.size() - std::size_t(e.nodes) - 1;
      if (fields.size() < std::size_t(e.nodes) + 3 || properties > 3)
        s_.fail("%ELEMENT." + type + " record has " + std::to_string(fields.size()) + " fields; expected 'id mat [thick] order' and " +
                std::to_string(e.nodes) + " nodes");
      const std::int64_t id = parseInteger(s_, fields[0], "an element id");
      if (!e.cell) {
        ++skippedSurface_;
        continue;
      }
      const auto nodes = std::span(fields).subspan(1 + properties);
      for (std::size_t k = 0; k < e.vtkOrder.size(); ++k) {
        const std::int64_t nodeId = parseInteger(s_, nodes[std::size_t(e.vtkOrder[k])], "a node id");
        const auto index = nodeIndex_.find(nodeId);
        if (!index)
          s_.fail("element " + std::to_string(id) + " (cell " + std::to_string(model_->mesh().cellCount()) + ") uses node " +
                  std::to_string(nodeId) + ", which %NODE.COORD does not define");
        cell[k] = *index;
      }
      elementIndex_.add(id, NodeIndex(model_->mesh().cellCount()));
      nfTypeOfCell_.push_back(&e);
      model_->mesh().addCell(*e.cell, std::span<const NodeIndex>(cell.data(), e.vtkOrder.size()));
      model_->mesh().cellIds.push_back(id);
    }
    return skipBlockStrict("%ELEMENT." + type, n);
  }
  // The next non-blank line (after a count read as a token, the rest of its line is blank).
  std::string_view recordLine() {
    for (;;) {
      const auto line = s_.nextLine();
      if (!trim(line).empty() || s_.atEnd()) return line;
    }
  }

  Step step() const {
    char label[64];
    std::snprintf(label, sizeof label, "step %lld, t = %g", static_cast<long long>(stepNumber_), stepTime_);
    return {label, stepTime_};
  }

  std::string_view readDisplacement() {
    const std::int64_t n = count("the displacement count");
    token();  // its label
    s_.requireMemory(results_.bytesWith(model_->mesh().nodeCount() * 3), "the displacement");
    std::vector<double> u(model_->mesh().nodeCount() * 3, std::numeric_limits<double>::quiet_NaN());
    for (std::int64_t i = 0; i < n; ++i) {
      const auto index = node(integer("a node id"), "NODAL.DISPLACEMENT");
      for (int k = 0; k < 6; ++k) {
        const double v = real("a displacement");
        if (k < 3) u[*index * 3 + std::size_t(k)] = v;
      }
    }
    results_.add("U", FieldLocation::Node, 3, step(), std::move(u));
    return skipBlockStrict("%RESULT.CASE.STEP.NODAL.DISPLACEMENT", n);
  }

  std::optional<NodeIndex> node(std::int64_t id, const char* block) {
    const auto index = nodeIndex_.find(id);
    if (!index) s_.fail(std::string(block) + " has a value for node " + std::to_string(id) + ", which %NODE.COORD does not define");
    return index;
  }

  std::string_view readLabels() {
    const std::int64_t m = count("the number of result labels");
    if (m > 1000) s_.fail("more than 1000 result labels");
    labels_.clear();
    for (std::int64_t i = 0; i < m; ++i) labels_.emplace_back(token());
    return skipBlockStrict("the result labels", m);
  }

  std::string label(std::size_t i) const {
    return i < labels_.size() && !labels_[i].empty() ? labels_[i] : "result " + std::to_string(i + 1);
  }

  std::string_view readNodal(int width) {
    const std::int64_t n = count("the node count of a result");
    const std::size_t m = std::max<std::size_t>(labels_.size(), 1), w = std::size_t(width);
    s_.requireMemory(results_.bytesWith(m * model_->mesh().nodeCount() * w), "a nodal result of " + std::to_string(m) + " labels x " + std::to_string(w) + " components");
    std::vector<std::vector<double>> values(m, std::vector<double>(model_->mesh().nodeCount() * w, std::numeric_limits<double>::quiet_NaN()));
    for (std::int64_t i = 0; i < n; ++i) {
      const auto index = node(integer("a node id"), "a nodal result");
      for (std::size_t f = 0; f < m; ++f)
        for (std::size_t k = 0; k < w; ++k) values[f][*index * w + k] = real("a result value");
    }
    for (std::size_t f = 0; f < m; ++f) results_.add(label(f), FieldLocation::Node, width, step(), std::move(values[f]));
    return skipBlockStrict("a nodal result", n);
  }

  // Gauss points: averaged per element (their positions depend on an integration rule the
  // file does not state). Element-nodal: reordered like the element's nodes and averaged
  // at the nodes.
  std::string_view readPerElement(bool elementNodal) {
    const std::int64_t n = count("the element count of a result");
    const std::size_t m = std::max<std::size_t>(labels_.size(), 1), cells = model_->mesh().cellCount();
    s_.requireMemory(results_.bytesWith(m * cells * (elementNodal ? 28 : 1)), "an element result of " + std::to_string(m) + " labels");
    std::vector<std::vector<double>> perCell(m, std::vector<double>(cells, std::numeric_limits<double>::quiet_NaN()));
    std::vector<std::vector<std::vector<double>>> corners(m, std::vector<std::vector<double>>(elementNodal ? cells : 0));
    for (std::int64_t i = 0; i < n; ++i) {
      const std::int64_t id = integer("an element id");
      const std::int64_t points = count("the number of points");
      if (points > 64) s_.fail("element " + std::to_string(id) + ": " + std::to_string(points) + " points is not plausible");
      std::vector<double> v(std::size_t(points) * m);
      for (double& x : v) x = real("a result value");
      const auto cell = elementIndex_.find(id);
      if (!cell) {
        if (skippedSurface_ == 0)
          s_.fail("a result names element " + std::to_string(id) + ", which no %ELEMENT block defines");
        continue;
      }
      for (std::size_t f = 0; f < m; ++f) {
        if (!elementNodal) {
          double sum = 0.0;
          for (std::int64_t p = 0; p < points; ++p) sum += v[std::size_t(p) * m + f];
          perCell[f][*cell] = points > 0 ? sum / double(points) : std::numeric_limits<double>::quiet_NaN();
          continue;
        }
        const NfElement& e = *nfTypeOfCell_[*cell];
        if (points != e.nodes) s_.fail("element " + std::to_string(id) + " has " + std::to_string(points) + " element-nodal values for " + std::to_string(e.nodes) + " nodes");
        std::vector<double> c(e.vtkOrder.size());
        for (std::size_t k = 0; k < c.size(); ++k) c[k] = v[std::size_t(e.vtkOrder[k]) * m + f];
        corners[f][*cell] = std::move(c);
      }
    }
    for (std::size_t f = 0; f < m; ++f) {
      if (elementNodal) {
        results_.add(label(f), FieldLocation::Node, 1, step(), averageToNodes(model_->mesh(), corners[f], 1));
        averaged_.insert(label(f));
      } else {
        results_.add(label(f), FieldLocation::Cell, 1, step(), std::move(perCell[f]));
        gaussAveraged_.insert(label(f));
      }
    }
    return skipBlockStrict("an element result", n);
  }

  void finish() {
    if (const std::string wrong = results_.mismatch(model_->mesh()); !wrong.empty()) s_.fail(wrong);
    results_.moveInto(*model_);
    for (const auto& [type, n] : unknownTypes_)
      model_->diagnostics.push_back({Severity::Warning, "unknown-element-type",
                                     std::to_string(n) + " elements of block %ELEMENT." + type + " were not loaded: volpost does not know this type", {}});
    if (skippedSurface_ > 0)
      model_->diagnostics.push_back({Severity::Info, "skipped-lower-dimensional-cells",
                                     std::to_string(skippedSurface_) + " surface elements (T3/T6/Q4/Q8) were not loaded: volpost shows volume cells", {}});
    for (const auto& name : gaussAveraged_)
      model_->diagnostics.push_back({Severity::Info, "gauss-points-averaged", "'" + name + "' is given at Gauss points; it is shown as the element average", {}});
    for (const auto& name : averaged_)
      model_->diagnostics.push_back({Severity::Info, "element-nodal-averaged", "'" + name + "' is given per element node; it is shown averaged at the nodes", {}});
  }

  TextScanner s_;
  const Progress& progress_;
  std::unique_ptr<Model> model_;
  IdIndex nodeIndex_, elementIndex_;
  std::vector<const NfElement*> nfTypeOfCell_;
  std::vector<std::string> labels_;
  std::int64_t stepNumber_ = 1;
  double stepTime_ = 0.0;
  std::map<std::string, std::size_t> unknownTypes_;
  std::size_t skippedSurface_ = 0;
  std::set<std::string> gaussAveraged_, averaged_;
  ResultCollector results_;
};

}  // namespace

int NeutralFileReader::sniff(std::string_view head) const {
  std::size_t i = 0;
  while (i < head.size() && std::isspace(static_cast<unsigned char>(head[i]))) ++i;
  if (i >= head.size() || head[i] != '%') return 0;
  for (std::string_view tag : {"%HEADER", "%NODE", "%ELEMENT", "%RESULT"})
    if (head.find(tag) != std::string_view::npos) return 90;
  return 10;
}

std::unique_ptr<Model> NeutralFileReader::read(const std::string& path, const Progress& progress) const {
  NfParser parser(readFileBytes(path, progress), path, progress);
  auto model = parser.parse();
  model->formatName = formatName();
  return model;
}

}  // namespace volpost::meshio

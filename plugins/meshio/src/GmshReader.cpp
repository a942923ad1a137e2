// SPDX-License-Identifier: MIT
// Layout facts: gmsh reference manual, "MSH file format" (4.1) and "Legacy formats" (2.2).
// Element node orders: gmsh's "Node ordering" section; gmsh corners are VTK's except the
// prism, whose first triangle VTK wants facing away from the second; gmsh numbers the
// midside nodes by its own edge list, so they are placed through NodeOrder.
#include "GmshReader.hpp"

#include "FileBytes.hpp"
#include "NodeOrder.hpp"
#include "NodeTable.hpp"
#include "ResultCollector.hpp"
#include "TextScanner.hpp"

#include <array>
#include <cstring>
#include <map>
#include <optional>
#include <set>

namespace volpost::meshio {
namespace {

// A physical group without a $PhysicalNames entry, named as gmsh's own GUI shows it: its
// tag alone would be ambiguous, as a surface and a volume may share one.
std::string unnamedGroupName(std::int64_t dim, std::int64_t tag) {
  static const char* const kinds[] = {"point", "curve", "surface", "volume"};
  return std::string("physical ") + (dim >= 0 && dim <= 3 ? kinds[dim] : "group") + " " + std::to_string(tag);
}

struct GmshType {
  int nodes = 0;                     // nodes per element in the file
  int dimension = 0;
  std::optional<CellType> cell;      // volume cells volpost keeps
  std::vector<int> vtkOrder;         // file node of each VTK node
  bool dropsNodes = false;           // face/body nodes ignored (hex27, prism18, pyramid13/14)
};

const std::map<int, GmshType>& gmshTypes() {
  static const std::map<int, GmshType> types = [] {
    std::map<int, GmshType> t;
    const auto lower = [&](int id, int nodes, int dim) { t[id] = {nodes, dim, std::nullopt, {}, false}; };
    lower(15, 1, 0);
    lower(1, 2, 1); lower(8, 3, 1); lower(26, 4, 1); lower(27, 5, 1); lower(28, 6, 1);
    lower(2, 3, 2); lower(3, 4, 2); lower(9, 6, 2); lower(10, 9, 2); lower(16, 8, 2);
    lower(20, 9, 2); lower(21, 10, 2); lower(22, 12, 2); lower(23, 15, 2); lower(24, 15, 2); lower(25, 21, 2);
    const std::array<int, 4> tet{0, 1, 2, 3};
    const std::array<int, 8> hex{0, 1, 2, 3, 4, 5, 6, 7};
    const std::array<int, 6> prism{0, 2, 1, 3, 5, 4};
    const std::array<int, 5> pyramid{0, 1, 2, 3, 4};
    const std::array<CornerPair, 6> tetEdges{{{0, 1}, {1, 2}, {2, 0}, {3, 0}, {3, 2}, {3, 1}}};
    const std::array<CornerPair, 12> hexEdges{{{0, 1}, {0, 3}, {0, 4}, {1, 2}, {1, 5}, {2, 3},
                                               {2, 6}, {3, 7}, {4, 5}, {4, 7}, {5, 6}, {6, 7}}};
    const std::array<CornerPair, 9> prismEdges{{{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 4}, {2, 5},
                                                {3, 4}, {3, 5}, {4, 5}}};
    t[4] = {4, 3, CellType::Tet4, vtkOrderFrom(CellType::Tet4, tet, {}), false};
    t[5] = {8, 3, CellType::Hex8, vtkOrderFrom(CellType::Hex8, hex, {}), false};
    t[6] = {6, 3, CellType::Wedge6, vtkOrderFrom(CellType::Wedge6, prism, {}), false};
    t[7] = {5, 3, CellType::Pyramid5, vtkOrderFrom(CellType::Pyramid5, pyramid, {}), false};
    t[11] = {10, 3, CellType::Tet10, vtkOrderFrom(CellType::Tet10, tet, tetEdges), false};
    t[17] = {20, 3, CellType::Hex20, vtkOrderFrom(CellType::Hex20, hex, hexEdges), false};
    t[12] = {27, 3, CellType::Hex20, vtkOrderFrom(CellType::Hex20, hex, hexEdges), true};
    t[18] = {15, 3, CellType::Wedge15, vtkOrderFrom(CellType::Wedge15, prism, prismEdges), false};
    t[13] = {18, 3, CellType::Wedge15, vtkOrderFrom(CellType::Wedge15, prism, prismEdges), true};
    t[19] = {13, 3, CellType::Pyramid5, vtkOrderFrom(CellType::Pyramid5, pyramid, {}), true};
    t[14] = {14, 3, CellType::Pyramid5, vtkOrderFrom(CellType::Pyramid5, pyramid, {}), true};
    return t;
  }();
  return types;
}

// Reads binary numbers at the scanner's position, checking that they are there.
class BinaryCursor {
 public:
  BinaryCursor(TextScanner& s, bool swap) : s_(s), swap_(swap) {}
  template <typename T>
  T next(const char* what) {
    const std::string& b = s_.bytes();
    const std::size_t at = s_.offset();
    if (b.size() - at < sizeof(T))
      s_.failAtOffset(at, std::string("file ends inside binary ") + what + " (truncated)");
    T v;
    std::memcpy(&v, b.data() + at, sizeof(T));
    if (swap_) {
      auto* p = reinterpret_cast<unsigned char*>(&v);
      for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(p[i], p[sizeof(T) - 1 - i]);
    }
    s_.seek(at + sizeof(T));
    return v;
  }
  std::int64_t integer(const char* what) { return next<std::int32_t>(what); }
  std::int64_t size(const char* what) { return std::int64_t(next<std::uint64_t>(what)); }

 private:
  TextScanner& s_;
  bool swap_;
};

class GmshParser {
 public:
  GmshParser(std::shared_ptr<const std::string> bytes, const std::string& path, const Progress& progress)
      : s_(std::move(bytes), path), progress_(progress) {}

  std::unique_ptr<Model> parse() {
    model_ = std::make_unique<Model>();
    readFormat();
    for (std::string_view line = nextSectionLine(); !line.empty(); line = nextSectionLine()) {
      const std::string name(line.substr(1));
      if (name == "PhysicalNames") readPhysicalNames();
      else if (name == "Entities") readEntities();
      else if (name == "Nodes") readNodes();
      else if (name == "Elements") readElements();
      else if (name == "NodeData" || name == "ElementData" || name == "ElementNodeData") readData(name);
      else skipSection(name);
      s_.report(progress_, 0.2, 0.95);
    }
    if (!sawNodes_) s_.fail("no $Nodes section: this .msh file holds no mesh");
    if (!sawElements_) s_.fail("no $Elements section: this .msh file holds no mesh");
    finish();
    return std::move(model_);
  }

 private:
  std::int64_t integer(const char* what) {
    if (binary_) return binaryCursor().integer(what);
    const auto t = s_.nextToken();
    if (t.empty()) s_.fail(std::string("file ends where ") + what + " was expected (truncated)");
    return parseInteger(s_, t, what);
  }
  // A count: int in 2.2 binary, size_t in 4.1 binary, text otherwise; never negative.
  std::int64_t count(const char* what, bool sizeT) {
    const std::int64_t v = binary_ ? (sizeT ? binaryCursor().size(what) : binaryCursor().integer(what)) : integer(what);
    if (v < 0 || v > (std::int64_t(1) << 40)) s_.fail(std::string(what) + " " + std::to_string(v) + " is out of range");
    return v;
  }
  static std::size_t nc0(std::int64_t components) { return std::size_t(std::max<std::int64_t>(components, 1)); }
  std::int64_t tag(const char* what, bool sizeT) {
    return binary_ ? (sizeT ? binaryCursor().size(what) : binaryCursor().integer(what)) : integer(what);
  }
  double real(const char* what) {
    if (binary_) return binaryCursor().next<double>(what);
    const auto t = s_.nextToken();
    if (t.empty()) s_.fail(std::string("file ends where ") + what + " was expected (truncated)");
    return parseReal(s_, t, what);
  }
  BinaryCursor binaryCursor() { return BinaryCursor(s_, swap_); }
  bool v4() const { return version_ >= 4; }

  void readFormat() {
    const auto first = trim(s_.nextLine());
    if (first != "$MeshFormat") s_.fail("not a Gmsh file: it must begin with $MeshFormat");
    const auto fields = splitFields(s_.nextLine());
    if (fields.size() < 3) s_.fail("$MeshFormat needs 'version file-type data-size'");
    const double version = parseReal(s_, fields[0], "the format version");
    if (version == 2.2 || version == 2.1 || version == 2.0) version_ = 2;
    else if (version == 4.1) version_ = 4;
    else
      s_.fail("MSH version " + std::string(fields[0]) +
              " is not supported (volpost reads 2.2 and 4.1; gmsh -save -format msh41 converts)");
    binary_ = parseInteger(s_, fields[1], "the file type (0 ASCII, 1 binary)") == 1;
    const std::int64_t dataSize = parseInteger(s_, fields[2], "the data size");
    if (dataSize != 8) s_.fail("data size " + std::to_string(dataSize) + " is not supported (only 8-byte size_t/doubles)");
    if (binary_) {  // the integer 1, written in the file's byte order
      std::int32_t one = 0;
      if (s_.bytes().size() - s_.offset() < 4) s_.fail("file ends inside $MeshFormat (truncated)");
      std::memcpy(&one, s_.bytes().data() + s_.offset(), 4);
      if (one == 0x01000000) swap_ = true;
      else if (one != 1) s_.fail("binary $MeshFormat does not hold the byte-order marker 1");
      s_.seek(s_.offset() + 4);
      s_.nextLine();  // rest of the marker line
    }
    expectEnd("MeshFormat");
  }

  std::string_view nextSectionLine() {
    while (!s_.atEnd()) {
      const auto line = trim(s_.nextLine());
      if (line.empty()) continue;
      if (line.front() != '$') s_.fail("expected a section like $Nodes, found '" + std::string(line.substr(0, 40)) + "'");
      return line;
    }
    return {};
  }

  void expectEnd(const std::string& name) {
    if (binary_ && s_.offset() < s_.bytes().size() && s_.bytes()[s_.offset()] == '\n') s_.seek(s_.offset() + 1);
    std::string_view line;
    while (!s_.atEnd() && (line = trim(s_.nextLine())).empty()) {
    }
    if (line != "$End" + name) {
      if (line.empty())
        s_.fail("the file ends inside $" + name + ": its closing $End" + name +
                " never comes (the file was cut short)");
      s_.fail("expected $End" + name + ", found '" + std::string(line.substr(0, 40)) +
              "' (the section holds more or fewer records than its header says)");
    }
  }

  void skipSection(const std::string& name) {
    const std::string end = "\n$End" + name;
    const std::size_t at = s_.bytes().find(end, s_.offset() > 0 ? s_.offset() - 1 : 0);
    if (at == std::string::npos) s_.fail("file ends inside $" + name + " (no $End" + name + ")");
    s_.seek(at + 1);
    s_.nextLine();
  }

  void readPhysicalNames() {
    // Always text, even in binary files.
    const auto n = parseInteger(s_, s_.nextLine(), "the number of physical names");
    for (std::int64_t i = 0; i < n; ++i) {
      if (s_.atEnd()) s_.fail("file ends inside $PhysicalNames (truncated)");
      // dim tag "name": the name may hold spaces; a malformed line leaves the group unnamed.
      const auto line = trim(s_.nextLine());
      const auto f = splitFields(line);
      const auto open = line.find('"'), close = line.rfind('"');
      if (f.size() < 3 || open == std::string_view::npos || close <= open) continue;
      const std::int64_t dim = parseInteger(s_, f[0], "a physical group dimension");
      const std::int64_t tag = parseInteger(s_, f[1], "a physical tag");
      physicalNames_[{dim, tag}] = std::string(line.substr(open + 1, close - open - 1));
    }
    const bool b = binary_;
    binary_ = false;
    expectEnd("PhysicalNames");
    binary_ = b;
  }

  // 4.1: which physical group each volume entity belongs to (the "region" cell field).
  void readEntities() {
    std::array<std::int64_t, 4> counts{};
    for (auto& c : counts) c = count("an entity count", true);
    for (int dim = 0; dim < 4; ++dim) {
      for (std::int64_t e = 0; e < counts[std::size_t(dim)]; ++e) {
        const std::int64_t entity = binary_ ? binaryCursor().integer("an entity tag") : integer("an entity tag");
        for (int k = 0; k < (dim == 0 ? 3 : 6); ++k) real("an entity bounding box");
        const std::int64_t nPhysical = count("a physical tag count", true);
        std::vector<std::int64_t> physical;
        for (std::int64_t p = 0; p < nPhysical; ++p)
          physical.push_back(binary_ ? binaryCursor().integer("a physical tag") : integer("a physical tag"));
        if (!physical.empty()) entityPhysical_[{dim, entity}] = std::move(physical);
        if (dim > 0) {
          const std::int64_t nBounding = count("a bounding entity count", true);
          for (std::int64_t k = 0; k < nBounding; ++k)
            binary_ ? binaryCursor().integer("a bounding entity") : integer("a bounding entity");
        }
      }
    }
    expectEnd("Entities");
  }

  void addNode(std::int64_t id, const glm::dvec3& p) {
    if (!nodeIndex_.add(id, NodeIndex(model_->mesh().nodes.size())))
      s_.fail("node " + std::to_string(id) + " is defined twice");
    model_->mesh().nodes.push_back(p);
    model_->mesh().nodeIds.push_back(id);
  }

  void readNodes() {
    if (sawNodes_) s_.fail("a second $Nodes section (volpost reads one mesh per file)");
    sawNodes_ = true;
    if (!v4()) {
      const std::int64_t n = parseInteger(s_, s_.nextLine(), "the number of nodes");
      s_.requirePlausibleCount(n, binary_ ? 28 : 8, "the number of nodes");  // "1 0 0 0\n" at least
      model_->mesh().nodes.reserve(std::size_t(n));
      for (std::int64_t i = 0; i < n; ++i) {
        const std::int64_t id = tag("a node tag", false);
        glm::dvec3 p;
        for (int k = 0; k < 3; ++k) p[k] = real("a node coordinate");
        addNode(id, p);
        if ((i & 0xffff) == 0) s_.report(progress_, 0.2, 0.95);
      }
      expectEnd("Nodes");
      return;
    }
    const std::int64_t blocks = count("the number of node blocks", true);
    const std::int64_t total = count("the number of nodes", true);
    s_.requirePlausibleCount(total, binary_ ? 32 : 8, "the number of nodes");
    s_.requirePlausibleCount(blocks, binary_ ? 24 : 8, "the number of node blocks");
    count("the smallest node tag", true);
    count("the largest node tag", true);
    model_->mesh().nodes.reserve(std::size_t(std::min<std::int64_t>(total, 1 << 26)));
    std::int64_t seen = 0;
    for (std::int64_t b = 0; b < blocks; ++b) {
      for (int k = 0; k < 2; ++k) tag("a node block header", false);
      const std::int64_t parametric = tag("a node block header", false);
      if (parametric != 0 && parametric != 1)
        s_.fail("a node block's parametric flag is " + std::to_string(parametric) + ", not 0 or 1");
      const std::int64_t n = count("the node count of a block", true);
      if (n > total - seen)
        s_.fail("the node blocks hold more nodes than the $Nodes header says (" + std::to_string(total) + ")");
      s_.requirePlausibleCount(n, binary_ ? 32 : 8, "the node count of a block");
      std::vector<std::int64_t> ids(static_cast<std::size_t>(n));
      for (auto& id : ids) id = tag("a node tag", true);
      for (std::int64_t i = 0; i < n; ++i) {
        glm::dvec3 p;
        for (int k = 0; k < 3; ++k) p[k] = real("a node coordinate");
        for (std::int64_t k = 0; k < 3 * parametric && k < 3; ++k) real("a parametric coordinate");
        addNode(ids[std::size_t(i)], p);
      }
      seen += n;
      s_.report(progress_, 0.2, 0.95);
    }
    if (seen != total)
      s_.fail("the $Nodes header says " + std::to_string(total) + " nodes, the blocks hold " + std::to_string(seen));
    expectEnd("Nodes");
  }

  const GmshType& typeOf(std::int64_t type) {
    const auto it = gmshTypes().find(int(type));
    if (type < 0 || type > 1000 || it == gmshTypes().end())
      s_.fail("element type " + std::to_string(type) +
              " is not a Gmsh element type volpost knows (volume: 4 tet4, 5 hex8, 6 prism6, 7 pyramid5, "
              "11 tet10, 12 hex27, 13 prism18, 14 pyramid14, 17 hex20, 18 prism15, 19 pyramid13)");
    return it->second;
  }

  // `region` is the element's first physical tag (0: none); version 4 gives all of them in
  // `groups` (version 2.2 only the first, as `region`).
  void addElement(std::int64_t id, const GmshType& type, std::span<const std::int64_t> fileNodes, std::int64_t region,
                  int dim, std::span<const std::int64_t> groups) {
    const std::int64_t first = region;
    if (groups.empty() && first != 0) groups = std::span<const std::int64_t>(&first, 1);
    if (!type.cell) {
      ++skippedLower_;
      addToNodeGroups(id, fileNodes, dim, groups);
      return;
    }
    if (type.dropsNodes) ++droppedHighOrder_[int(fileNodes.size())];
    std::array<NodeIndex, 20> nodes{};
    for (std::size_t k = 0; k < type.vtkOrder.size(); ++k) {
      const std::int64_t nodeId = fileNodes[std::size_t(type.vtkOrder[k])];
      const auto index = nodeIndex_.find(nodeId);
      if (!index)
        s_.fail("element " + std::to_string(id) + " (cell " + std::to_string(model_->mesh().cellCount()) +
                ") uses node " + std::to_string(nodeId) + ", which $Nodes does not define");
      nodes[k] = *index;
    }
    model_->mesh().addCell(*type.cell, std::span<const NodeIndex>(nodes.data(), type.vtkOrder.size()));
    model_->mesh().cellIds.push_back(id);
    regions_.push_back(double(region));
    elementIndex_.add(id, NodeIndex(model_->mesh().cellCount() - 1));
    for (const std::int64_t g : groups) groupMembers_[{3, g}].push_back(std::uint32_t(model_->mesh().cellCount() - 1));
  }

  // A point, line or surface element of a physical group (a boundary, a load face) is not
  // loaded, but its nodes make the group's node set.
  void addToNodeGroups(std::int64_t id, std::span<const std::int64_t> fileNodes, int dim,
                       std::span<const std::int64_t> groups) {
    for (const std::int64_t g : groups) {
      auto& members = groupMembers_[{dim, g}];
      for (const std::int64_t n : fileNodes) {
        const auto index = nodeIndex_.find(n);
        if (!index)
          s_.fail("element " + std::to_string(id) + " of physical group " + std::to_string(g) + " uses node " +
                  std::to_string(n) + ", which $Nodes does not define");
        members.push_back(*index);
      }
    }
  }

  // Physical groups become the model's sets: volumes as element sets, lower dimensions as
  // the node sets of their elements' nodes.
  void addGroups() {
    for (auto& [key, members] : groupMembers_) {
      const auto [dim, tag] = key;
      const auto named = physicalNames_.find(key);
      EntitySet set{named != physicalNames_.end() ? named->second : unnamedGroupName(dim, tag),
                    dim == 3 ? SetKind::Cells : SetKind::Nodes, "physical group", std::move(members)};
      normalizeMembers(set.members);
      model_->sets.push_back(std::move(set));
    }
  }

  void readElements() {
    if (sawElements_) s_.fail("a second $Elements section (volpost reads one mesh per file)");
    sawElements_ = true;
    if (!sawNodes_) s_.fail("$Elements comes before $Nodes");
    std::vector<std::int64_t> nodes;
    if (!v4()) {
      const std::int64_t n = parseInteger(s_, s_.nextLine(), "the number of elements");
      if (n < 0) s_.fail("the number of elements is negative");
      if (!binary_) {
        for (std::int64_t i = 0; i < n; ++i) {
          const auto line = s_.nextLine();
          if (s_.atEnd() && trim(line).empty()) s_.fail("file ends inside $Elements (truncated)");
          const auto f = splitFields(line);
          if (f.size() < 3) s_.fail("an element needs 'tag type tag-count tags... nodes...'");
          const std::int64_t id = parseInteger(s_, f[0], "an element tag");
          const GmshType& type = typeOf(parseInteger(s_, f[1], "an element type"));
          const std::int64_t ntags = parseInteger(s_, f[2], "the tag count");
          if (ntags < 0 || ntags > std::int64_t(f.size()) || std::size_t(3 + ntags + type.nodes) != f.size())
            s_.fail("element " + std::to_string(id) + " should have " + std::to_string(type.nodes) + " nodes after " +
                    std::to_string(ntags) + " tags; the line has " + std::to_string(f.size()) + " fields");
          const std::int64_t region = ntags > 0 ? parseInteger(s_, f[3], "a physical tag") : 0;
          nodes.resize(std::size_t(type.nodes));
          for (int k = 0; k < type.nodes; ++k) nodes[std::size_t(k)] = parseInteger(s_, f[std::size_t(3 + ntags + k)], "a node tag");
          addElement(id, type, nodes, region, type.dimension, {});
        }
      } else {
        for (std::int64_t done = 0; done < n;) {
          const GmshType& type = typeOf(tag("an element type", false));
          const std::int64_t follow = count("an element count", false);
          const std::int64_t ntags = count("a tag count", false);
          if (follow == 0 || done + follow > n) s_.fail("binary element block overruns the element count");
          for (std::int64_t i = 0; i < follow; ++i) {
            const std::int64_t id = tag("an element tag", false);
            std::int64_t region = 0;
            for (std::int64_t t = 0; t < ntags; ++t) {
              const std::int64_t v = tag("an element tag", false);
              if (t == 0) region = v;
            }
            nodes.resize(std::size_t(type.nodes));
            for (auto& node : nodes) node = tag("a node tag", false);
            addElement(id, type, nodes, region, type.dimension, {});
          }
          done += follow;
        }
      }
      expectEnd("Elements");
      return;
    }
    const std::int64_t blocks = count("the number of element blocks", true);
    const std::int64_t total = count("the number of elements", true);
    count("the smallest element tag", true);
    count("the largest element tag", true);
    std::int64_t seen = 0;
    for (std::int64_t b = 0; b < blocks; ++b) {
      const std::int64_t dim = tag("an element block header", false);
      const std::int64_t entity = tag("an element block header", false);
      const GmshType& type = typeOf(tag("an element type", false));
      const std::int64_t n = count("the element count of a block", true);
      if (seen + n > total)
        s_.fail("the element blocks hold more elements than the $Elements header says (" + std::to_string(total) + ")");
      const auto found = entityPhysical_.find({dim, entity});
      static const std::vector<std::int64_t> kNone;
      const std::vector<std::int64_t>& physical = found == entityPhysical_.end() ? kNone : found->second;
      const std::int64_t region = dim == 3 && !physical.empty() ? physical.front() : 0;
      nodes.resize(std::size_t(type.nodes));
      for (std::int64_t i = 0; i < n; ++i) {
        const std::int64_t id = tag("an element tag", true);
        for (auto& node : nodes) node = tag("a node tag", true);
        if (!binary_) {  // a record is one line: more or fewer nodes means the type is wrong
          const auto rest = trim(s_.peekLine());
          if (!rest.empty())
            s_.fail("element " + std::to_string(id) + " has more nodes than its type " + std::to_string(type.nodes));
        }
        addElement(id, type, nodes, region, int(dim), physical);
        if ((i & 0xffff) == 0) s_.report(progress_, 0.2, 0.95);
      }
      seen += n;
    }
    if (seen != total)
      s_.fail("the $Elements header says " + std::to_string(total) + " elements, the blocks hold " + std::to_string(seen));
    expectEnd("Elements");
  }

  // A result view: string tags (name), real tags (time), integer tags (step, components,
  // entity count), then one record per node or element.
  void readData(const std::string& section) {
    const bool wasBinary = binary_;
    binary_ = false;  // the tags are text in binary files too
    std::string name = section;
    const auto lineInteger = [&](const char* what) {
      const auto line = trim(s_.nextLine());
      if (line.empty() && s_.atEnd()) s_.fail("file ends inside $" + section + " (truncated)");
      return parseInteger(s_, line, what);
    };
    const std::int64_t nStrings = lineInteger("the number of string tags");
    s_.requirePlausibleCount(nStrings, 1, "the number of string tags");
    for (std::int64_t i = 0; i < nStrings; ++i) {
      if (s_.atEnd()) s_.fail("file ends inside the string tags of $" + section + " (truncated)");
      auto line = trim(s_.nextLine());
      if (line.size() >= 2 && line.front() == '"' && line.back() == '"') line = line.substr(1, line.size() - 2);
      if (i == 0) name = std::string(line);
    }
    const std::int64_t nReals = lineInteger("the number of real tags");
    s_.requirePlausibleCount(nReals, 2, "the number of real tags");
    double time = 0.0;
    for (std::int64_t i = 0; i < nReals; ++i) {
      const double v = parseReal(s_, s_.nextLine(), "a real tag");
      if (i == 0) time = v;
    }
    const std::int64_t nIntegers = lineInteger("the number of integer tags");
    s_.requirePlausibleCount(nIntegers, 2, "the number of integer tags");
    std::array<std::int64_t, 3> ints{0, 1, 0};
    for (std::int64_t i = 0; i < nIntegers; ++i) {
      const std::int64_t v = lineInteger("an integer tag");
      if (i < 3) ints[std::size_t(i)] = v;
    }
    if (nIntegers < 3) s_.fail("$" + section + " needs 3 integer tags (step, components, count)");
    const std::int64_t components = ints[1], n = ints[2];
    if (components < 1 || components > 64) s_.fail("$" + section + " '" + name + "': " + std::to_string(components) + " components is not plausible");
    if (n < 0 || n > (std::int64_t(1) << 36)) s_.fail("$" + section + " '" + name + "': count " + std::to_string(n) + " is out of range");
    s_.requirePlausibleCount(n, 2 * (nc0(components) + 1), "$" + section + " '" + name + "': the count");
    binary_ = wasBinary;  // the records: binary right after the last tag's line
    const std::size_t nc = std::size_t(components);
    char label[64];
    // The file's step index counted from 1, as a double: any 64-bit index plus one is written.
    std::snprintf(label, sizeof label, nReals > 0 ? "step %.0f, t = %g" : "step %.0f", double(ints[0]) + 1.0, time);
    const Step step{label, time};
    if (section == "NodeData") {
      std::vector<double> values(model_->mesh().nodeCount() * nc, std::numeric_limits<double>::quiet_NaN());
      for (std::int64_t i = 0; i < n; ++i) {
        const std::int64_t id = tag("a node tag", false);
        const auto index = nodeIndex_.find(id);
        if (!index) s_.fail("$NodeData '" + name + "' has a value for node " + std::to_string(id) + ", which $Nodes does not define");
        for (std::size_t k = 0; k < nc; ++k) values[*index * nc + k] = real("a value");
      }
      results_.add(name, FieldLocation::Node, int(components), step, std::move(values));
    } else {
      const bool perCorner = section == "ElementNodeData";
      std::vector<double> values(model_->mesh().cellCount() * nc, std::numeric_limits<double>::quiet_NaN());
      std::vector<std::vector<double>> corners(perCorner ? model_->mesh().cellCount() : 0);
      for (std::int64_t i = 0; i < n; ++i) {
        const std::int64_t id = tag("an element tag", false);
        const std::int64_t perElement = perCorner ? count("the nodes per element", false) : 1;
        if (perElement < 1 || perElement > 64)
          s_.fail("$" + section + " '" + name + "': " + std::to_string(perElement) + " nodes per element is not plausible");
        const auto index = elementIndex_.find(id);
        std::vector<double> v(std::size_t(perElement) * nc);
        for (double& x : v) x = real("a value");
        if (!index) {  // values on boundary elements volpost skipped; an unknown id is an error
          if (skippedLower_ == 0)
            s_.fail("$" + section + " '" + name + "' has a value for element " + std::to_string(id) + ", which $Elements does not define");
          continue;
        }
        if (perCorner) corners[*index] = reorderCorners(*index, v, nc);
        else std::copy(v.begin(), v.end(), values.begin() + std::ptrdiff_t(*index * nc));
      }
      if (perCorner) {
        results_.add(name, FieldLocation::Node, int(components), step, averageToNodes(model_->mesh(), corners, int(components)));
        averagedNames_.insert(name);
      } else {
        results_.add(name, FieldLocation::Cell, int(components), step, std::move(values));
      }
    }
    expectEnd(section);
  }

  // $ElementNodeData lists values in the file's node order: put them in the cell's.
  std::vector<double> reorderCorners(std::size_t cell, const std::vector<double>& v, std::size_t nc) {
    const auto& type = gmshTypes().at(fileTypeOfCell(cell));
    std::vector<double> out(type.vtkOrder.size() * nc);
    for (std::size_t k = 0; k < type.vtkOrder.size(); ++k)
      for (std::size_t i = 0; i < nc; ++i)
        if (std::size_t(type.vtkOrder[k]) * nc + i < v.size()) out[k * nc + i] = v[std::size_t(type.vtkOrder[k]) * nc + i];
    return out;
  }
  int fileTypeOfCell(std::size_t cell) const {
    switch (model_->mesh().cellType(cell)) {
      case CellType::Tet4: return 4;
      case CellType::Tet10: return 11;
      case CellType::Hex8: return 5;
      case CellType::Hex20: return 17;
      case CellType::Wedge6: return 6;
      case CellType::Wedge15: return 18;
      case CellType::Pyramid5: return 7;
    }
    return 4;
  }

  void finish() {
    addGroups();
    bool anyRegion = false;
    for (double r : regions_) anyRegion = anyRegion || r != 0.0;
    if (anyRegion) model_->fields.push_back(Field::fromValues("region", FieldLocation::Cell, 1, {regions_}));
    if (const std::string wrong = results_.mismatch(model_->mesh()); !wrong.empty()) s_.fail(wrong);
    results_.moveInto(*model_);
    if (skippedLower_ > 0)
      model_->diagnostics.push_back({Severity::Info, "skipped-lower-dimensional-cells",
                                     std::to_string(skippedLower_) +
                                         " points, lines and surface elements (boundary groups) were not loaded: volpost shows volume cells",
                                     {}});
    for (const auto& [nodes, count] : droppedHighOrder_)
      model_->diagnostics.push_back({Severity::Warning, "high-order-nodes-dropped",
                                     std::to_string(count) + " elements with " + std::to_string(nodes) +
                                         " nodes were read through their corner and edge nodes only (face, body and pyramid midside nodes are not used)",
                                     {}});
    for (const auto& name : averagedNames_)
      model_->diagnostics.push_back({Severity::Info, "element-nodal-averaged",
                                     "'" + name + "' is given per element node; it is shown averaged at the nodes", {}});
  }

  TextScanner s_;
  const Progress& progress_;
  std::unique_ptr<Model> model_;
  int version_ = 4;
  bool binary_ = false, swap_ = false, sawNodes_ = false, sawElements_ = false;
  IdIndex nodeIndex_, elementIndex_;
  std::map<std::pair<std::int64_t, std::int64_t>, std::vector<std::int64_t>> entityPhysical_;  // (dim, entity)
  std::map<std::pair<std::int64_t, std::int64_t>, std::string> physicalNames_;                 // (dim, tag)
  std::map<std::pair<std::int64_t, std::int64_t>, std::vector<std::uint32_t>> groupMembers_;   // (dim, tag)
  std::vector<double> regions_;
  std::size_t skippedLower_ = 0;
  std::map<int, std::size_t> droppedHighOrder_;
  std::set<std::string> averagedNames_;
  ResultCollector results_;
};

}  // namespace

int GmshReader::sniff(std::string_view head) const {
  std::size_t i = 0;
  while (i < head.size() && std::isspace(static_cast<unsigned char>(head[i]))) ++i;
  return head.substr(i, 11) == "$MeshFormat" ? 100 : 0;
}

std::unique_ptr<Model> GmshReader::read(const std::string& path, const Progress& progress) const {
  GmshParser parser(readFileBytes(path, progress), path, progress);
  auto model = parser.parse();
  model->formatName = formatName();
  return model;
}

}  // namespace volpost::meshio

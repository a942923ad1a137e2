// SPDX-License-Identifier: MIT
// The Exodus II data model as netCDF names it (Sandia's "Exodus II: a finite element data
// model"): dimensions num_nodes, num_el_blk, num_el_in_blk<b>, num_nod_per_el<b>,
// time_step; variables coordx/y/z (or coord), connect<b> (attribute elem_type),
// node_num_map, elem_num_map, eb_prop1 (block ids), time_whole, name_nod_var,
// vals_nod_var<v> (or the older vals_nod_var[t][v][n]), name_elem_var,
// vals_elem_var<v>eb<b>. Node orders: Exodus corners are VTK's except the wedge (its
// first triangle faces the second); its hex20/wedge15 list vertical edges before the top.
#include "ExodusReader.hpp"

#include "FaceNodes.hpp"
#include "NetcdfClassicLayout.hpp"
#include "NodeOrder.hpp"
#include "ResultCollector.hpp"

#include <netcdf.h>

#include <volpost/core/ResourceLimits.hpp>

#include <array>
#include <cctype>
#include <cmath>
#include <limits>
#include <map>
#include <optional>

namespace volpost::meshio {
namespace {

struct ExodusType {
  CellType cell;
  std::vector<int> vtkOrder;
};

std::optional<ExodusType> exodusType(std::string name, int nodesPerElement) {
  for (char& c : name) c = char(std::toupper(static_cast<unsigned char>(c)));
  const std::array<int, 4> tet{0, 1, 2, 3};
  const std::array<int, 8> hex{0, 1, 2, 3, 4, 5, 6, 7};
  const std::array<int, 6> wedge{0, 2, 1, 3, 5, 4};
  const std::array<int, 5> pyramid{0, 1, 2, 3, 4};
  const std::array<CornerPair, 6> tetEdges{{{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}}};
  const std::array<CornerPair, 12> hexEdges{{{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 4}, {1, 5},
                                             {2, 6}, {3, 7}, {4, 5}, {5, 6}, {6, 7}, {7, 4}}};
  const std::array<CornerPair, 9> wedgeEdges{{{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 4}, {2, 5},
                                              {3, 4}, {4, 5}, {5, 3}}};
  const auto is = [&](std::initializer_list<const char*> names) {
    for (const char* n : names)
      if (name.rfind(n, 0) == 0) return true;
    return false;
  };
  if (is({"TET", "TETRA"})) {
    if (nodesPerElement == 4) return ExodusType{CellType::Tet4, vtkOrderFrom(CellType::Tet4, tet, {})};
    if (nodesPerElement >= 10) return ExodusType{CellType::Tet10, vtkOrderFrom(CellType::Tet10, tet, tetEdges)};
  } else if (is({"HEX"})) {
    if (nodesPerElement == 8) return ExodusType{CellType::Hex8, vtkOrderFrom(CellType::Hex8, hex, {})};
    if (nodesPerElement >= 20) return ExodusType{CellType::Hex20, vtkOrderFrom(CellType::Hex20, hex, hexEdges)};
  } else if (is({"WEDGE"})) {
    if (nodesPerElement == 6) return ExodusType{CellType::Wedge6, vtkOrderFrom(CellType::Wedge6, wedge, {})};
    if (nodesPerElement >= 15) return ExodusType{CellType::Wedge15, vtkOrderFrom(CellType::Wedge15, wedge, wedgeEdges)};
  } else if (is({"PYRAMID"})) {
    if (nodesPerElement >= 5) return ExodusType{CellType::Pyramid5, vtkOrderFrom(CellType::Pyramid5, pyramid, {})};
  }
  return std::nullopt;
}

// Exodus's side numbering (the manual's element side tables) as the element's corners,
// 0-based in the file's node order; VTK's corners are the file's except the wedge's, whose
// triangles run the other way (its own inverse).
std::vector<int> exodusSide(CellType type, long long side) {
  static const std::vector<std::vector<int>> tet{{0, 1, 3}, {1, 2, 3}, {0, 3, 2}, {0, 2, 1}};
  static const std::vector<std::vector<int>> hex{{0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6},
                                                 {0, 4, 7, 3}, {0, 3, 2, 1}, {4, 5, 6, 7}};
  static const std::vector<std::vector<int>> wedge{{0, 1, 4, 3}, {1, 2, 5, 4}, {0, 3, 5, 2}, {0, 2, 1}, {3, 4, 5}};
  static const std::vector<std::vector<int>> pyramid{{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {0, 4, 3}, {0, 3, 2, 1}};
  constexpr int kWedgeToVtk[6] = {0, 2, 1, 3, 5, 4};
  const bool isWedge = type == CellType::Wedge6 || type == CellType::Wedge15;
  const std::vector<std::vector<int>>& sides = type == CellType::Tet4 || type == CellType::Tet10   ? tet
                                               : type == CellType::Hex8 || type == CellType::Hex20 ? hex
                                               : isWedge                                           ? wedge
                                                                                                   : pyramid;
  if (side < 1 || std::size_t(side) > sides.size()) return {};
  std::vector<int> corners = sides[std::size_t(side - 1)];
  if (isWedge)
    for (int& c : corners) c = kWedgeToVtk[c];
  return corners;
}

// A read-only netCDF file; every call checked, errors name the file and the variable.
class NcFile {
 public:
  explicit NcFile(const std::string& path) : path_(path) {
    const int status = nc_open(path.c_str(), NC_NOWRITE, &id_);
    if (status != NC_NOERR)
      throw ReadError(path, std::string("cannot read as netCDF/Exodus (truncated or damaged?): ") + nc_strerror(status));
  }
  ~NcFile() { nc_close(id_); }
  NcFile(const NcFile&) = delete;
  NcFile& operator=(const NcFile&) = delete;

  [[noreturn]] void fail(const std::string& message) const { throw ReadError(path_, message); }
  void check(int status, const std::string& what) const {
    if (status != NC_NOERR) fail(what + ": " + nc_strerror(status));
  }
  std::optional<std::size_t> dimension(const std::string& name) const {
    int dim = 0;
    if (nc_inq_dimid(id_, name.c_str(), &dim) != NC_NOERR) return std::nullopt;
    std::size_t len = 0;
    check(nc_inq_dimlen(id_, dim, &len), "dimension " + name);
    return len;
  }
  std::optional<int> variable(const std::string& name) const {
    int var = 0;
    if (nc_inq_varid(id_, name.c_str(), &var) != NC_NOERR) return std::nullopt;
    return var;
  }
  int variableCount() const {
    int n = 0;
    check(nc_inq_nvars(id_, &n), "the variable list");
    return n;
  }
  const std::string& path() const { return path_; }
  /// A variable's shape must be what the data model says it is.
  void requireShape(int var, const std::string& name, const std::vector<std::size_t>& expected) const {
    const auto actual = shape(var, name);
    std::size_t total = 1, wanted = 1;
    for (std::size_t d : actual) total *= d;
    for (std::size_t d : expected) wanted *= d;
    if (total != wanted)
      fail("variable " + name + " holds " + std::to_string(total) + " values where its dimensions say " +
           std::to_string(wanted) + " (damaged file)");
  }
  std::vector<std::size_t> shape(int var, const std::string& name) const {
    int ndims = 0;
    check(nc_inq_varndims(id_, var, &ndims), name);
    std::vector<int> dims(std::size_t(std::max(ndims, 0)));
    check(nc_inq_vardimid(id_, var, dims.data()), name);
    std::vector<std::size_t> out;
    for (int d : dims) {
      std::size_t len = 0;
      check(nc_inq_dimlen(id_, d, &len), name);
      out.push_back(len);
    }
    return out;
  }
  std::vector<double> doubles(const std::string& name) const {
    const auto var = variable(name);
    if (!var) fail("variable " + name + " is missing");
    std::size_t n = 1;
    for (std::size_t len : shape(*var, name)) n = checkedProduct(n, len, path_, "variable " + name);
    requireMemory(double(n) * 8.0, path_, "variable " + name);
    std::vector<double> out(n);
    if (n) check(nc_get_var_double(id_, *var, out.data()), "reading " + name);
    return out;
  }
  std::vector<double> slab(int var, const std::string& name, std::vector<std::size_t> start, std::vector<std::size_t> count) const {
    std::size_t n = 1;
    for (std::size_t c : count) n *= c;
    std::vector<double> out(n);
    if (n) check(nc_get_vara_double(id_, var, start.data(), count.data(), out.data()), "reading " + name);
    return out;
  }
  std::vector<long long> integers(const std::string& name) const {
    const auto var = variable(name);
    if (!var) fail("variable " + name + " is missing");
    std::size_t n = 1;
    for (std::size_t len : shape(*var, name)) n = checkedProduct(n, len, path_, "variable " + name);
    requireMemory(double(n) * 8.0, path_, "variable " + name);
    std::vector<long long> out(n);
    if (n) check(nc_get_var_longlong(id_, *var, out.data()), "reading " + name);
    return out;
  }
  /// Rows [first, first + rows) of a 2-D integer variable of `columns` columns.
  std::vector<long long> integerRows(int var, const std::string& name, std::size_t first, std::size_t rows,
                                     std::size_t columns) const {
    std::vector<long long> out(rows * columns);
    const std::size_t start[2] = {first, 0}, count[2] = {rows, columns};
    if (!out.empty()) check(nc_get_vara_longlong(id_, var, start, count, out.data()), "reading " + name);
    return out;
  }
  std::string textAttribute(int var, const char* attribute) const {
    std::size_t len = 0;
    if (nc_inq_attlen(id_, var, attribute, &len) != NC_NOERR) return {};
    std::string s(len, '\0');
    check(nc_get_att_text(id_, var, attribute, s.data()), attribute);
    return s.substr(0, s.find('\0'));
  }
  std::vector<std::string> names(const std::string& variableName) const {
    const auto var = variable(variableName);
    if (!var) return {};
    const auto sh = shape(*var, variableName);
    if (sh.size() != 2) fail(variableName + " is not a list of names");
    requireMemory(double(sh[0]) * double(sh[1]), path_, variableName);
    std::vector<char> chars(checkedProduct(sh[0], sh[1], path_, variableName));
    if (!chars.empty()) check(nc_get_var_text(id_, *var, chars.data()), "reading " + variableName);
    std::vector<std::string> out;
    for (std::size_t i = 0; i < sh[0]; ++i) {
      std::string s(chars.data() + i * sh[1], sh[1]);
      s = s.substr(0, s.find('\0'));
      while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.pop_back();
      out.push_back(s);
    }
    return out;
  }

 private:
  std::string path_;
  int id_ = -1;
};

// Exodus stores components as scalars (UX UY UZ, SXX ... SZX); VTK and meshio regroup them.
// Returns groups of variable indices: vectors (X,Y,Z), symmetric tensors (XX,YY,ZZ,XY,YZ,ZX)
// and the rest as scalars, with their names.
struct VariableGroup {
  std::string name;
  std::vector<std::size_t> members;
};

std::vector<VariableGroup> groupComponents(const std::vector<std::string>& names) {
  std::vector<VariableGroup> groups;
  std::vector<bool> used(names.size(), false);
  const auto findName = [&](const std::string& n) -> std::optional<std::size_t> {
    for (std::size_t i = 0; i < names.size(); ++i)
      if (!used[i] && names[i] == n) return i;
    return std::nullopt;
  };
  const auto tryGroup = [&](std::size_t i, const std::vector<std::string>& first, const std::vector<std::vector<std::string>>& suffixes) {
    for (const auto& s0 : first) {
      const std::string& n = names[i];
      if (n.size() <= s0.size() || n.compare(n.size() - s0.size(), s0.size(), s0) != 0) continue;
      const std::string prefix = n.substr(0, n.size() - s0.size());
      std::vector<std::size_t> members{i};
      for (const auto& alternatives : suffixes) {
        std::optional<std::size_t> m;
        for (const auto& s : alternatives)
          if (!m) m = findName(prefix + s);
        if (!m) break;
        members.push_back(*m);
      }
      if (members.size() == suffixes.size() + 1) {
        for (std::size_t m : members) used[m] = true;
        std::string name = prefix;
        while (!name.empty() && (name.back() == '_' || name.back() == '-')) name.pop_back();
        groups.push_back({name.empty() ? n : name, members});
        return true;
      }
    }
    return false;
  };
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (used[i]) continue;
    if (tryGroup(i, {"XX", "xx", "_XX", "_xx"}, {{"YY"}, {"ZZ"}, {"XY"}, {"YZ"}, {"ZX", "XZ"}})) continue;
    if (tryGroup(i, {"xx"}, {{"yy"}, {"zz"}, {"xy"}, {"yz"}, {"zx", "xz"}})) continue;
    if (tryGroup(i, {"X"}, {{"Y"}, {"Z"}})) continue;
    if (tryGroup(i, {"x"}, {{"y"}, {"z"}})) continue;
    used[i] = true;
    groups.push_back({names[i], {i}});
  }
  return groups;
}

class ExodusParser {
 public:
  ExodusParser(const std::string& path, const Progress& progress) : nc_(path), progress_(progress) {}

  std::unique_ptr<Model> parse() {
    model_ = std::make_unique<Model>();
    const auto nodes = nc_.dimension("num_nodes");
    const auto blocks = nc_.dimension("num_el_blk");
    if (!nodes || !blocks) nc_.fail("a netCDF file, but not Exodus II (no num_nodes / num_el_blk)");
    // Every block has its own connect variable: more blocks than variables is a lie.
    if (*blocks > std::size_t(nc_.variableCount()))
      nc_.fail("num_el_blk is " + std::to_string(*blocks) + ", but the file has only " +
               std::to_string(nc_.variableCount()) + " variables (damaged file)");
    requireMemory(double(*nodes) * 48.0, nc_.path(), std::to_string(*nodes) + " nodes");
    readNodes(*nodes);
    progress_.report(0.3);
    readBlocks(*blocks);
    readNodeSets();
    readSideSets();
    progress_.report(0.5);
    readTimes();
    readNodalVariables();
    readElementVariables(*blocks);
    results_.moveInto(*model_);
    return std::move(model_);
  }

 private:
  void readNodes(std::size_t n) {
    const std::size_t dims = nc_.dimension("num_dim").value_or(3);
    std::array<std::vector<double>, 3> xyz;
    if (nc_.variable("coordx")) {
      xyz[0] = nc_.doubles("coordx");
      if (dims > 1) xyz[1] = nc_.doubles("coordy");
      if (dims > 2) xyz[2] = nc_.doubles("coordz");
    } else {
      const auto var = nc_.variable("coord");
      if (!var) nc_.fail("no node coordinates (neither coordx nor coord)");
      nc_.requireShape(*var, "coord", {dims, n});
      const auto all = nc_.doubles("coord");
      for (std::size_t d = 0; d < dims && d < 3; ++d) xyz[d].assign(all.begin() + std::ptrdiff_t(d * n), all.begin() + std::ptrdiff_t((d + 1) * n));
    }
    model_->mesh().nodes.resize(n, glm::dvec3(0.0));
    for (std::size_t d = 0; d < 3; ++d) {
      if (xyz[d].empty()) continue;
      if (xyz[d].size() != n) nc_.fail("coordinate array " + std::to_string(d) + " has " + std::to_string(xyz[d].size()) + " values for " + std::to_string(n) + " nodes");
      for (std::size_t i = 0; i < n; ++i) model_->mesh().nodes[i][int(d)] = xyz[d][i];
    }
    if (nc_.variable("node_num_map")) {
      const auto map = nc_.integers("node_num_map");
      if (map.size() == n) model_->mesh().nodeIds.assign(map.begin(), map.end());
    }
  }

  void readBlocks(std::size_t blocks) {
    std::vector<long long> blockIds;
    if (nc_.variable("eb_prop1")) blockIds = nc_.integers("eb_prop1");
    const std::vector<long long> elementIds = nc_.variable("elem_num_map") ? nc_.integers("elem_num_map") : std::vector<long long>{};
    std::size_t fileElement = 0;
    blockCells_.resize(blocks);
    cellOfFileElement_.assign(nc_.dimension("num_elem").value_or(0), kNoCell);
    for (std::size_t b = 0; b < blocks; ++b) {
      const std::string suffix = std::to_string(b + 1);
      const std::size_t count = nc_.dimension("num_el_in_blk" + suffix).value_or(0);
      const std::size_t perElement = nc_.dimension("num_nod_per_el" + suffix).value_or(0);
      const auto var = nc_.variable("connect" + suffix);
      if (count == 0 || !var) continue;
      const std::string typeName = nc_.textAttribute(*var, "elem_type");
      const auto type = exodusType(typeName, int(perElement));
      const long long blockId = b < blockIds.size() ? blockIds[b] : (long long)(b + 1);
      if (!type) {
        skipped_ += count;
        skippedTypes_ += (skippedTypes_.empty() ? "" : ", ") + typeName;
        fileElement += count;
        continue;
      }
      const std::vector<std::size_t> shape = nc_.shape(*var, "connect" + suffix);
      if (shape.size() != 2 || shape[0] != count || shape[1] != perElement) nc_.fail("connect" + suffix + " has the wrong size");
      // A chunk of elements at a time: no 64-bit copy of a whole block's connectivity (at
      // 100M tets that was 3.2 GB).
      constexpr std::size_t kChunk = std::size_t(1) << 16;
      std::vector<long long> connect;
      std::array<NodeIndex, 20> cell{};
      for (std::size_t e = 0; e < count; ++e, ++fileElement) {
        if (e % kChunk == 0) connect = nc_.integerRows(*var, "connect" + suffix, e, std::min(kChunk, count - e), perElement);
        for (std::size_t k = 0; k < type->vtkOrder.size(); ++k) {
          const long long node = connect[(e % kChunk) * perElement + std::size_t(type->vtkOrder[k])];
          if (node < 1 || std::size_t(node) > model_->mesh().nodeCount())
            nc_.fail("element block " + std::to_string(blockId) + ", element " + std::to_string(e + 1) + " (cell " +
                     std::to_string(model_->mesh().cellCount()) + ") uses node " + std::to_string(node) + " of " +
                     std::to_string(model_->mesh().nodeCount()) + (node == 0 ? " (the file is probably truncated: netCDF reads missing data as 0)" : ""));
          cell[k] = NodeIndex(node - 1);
        }
        blockCells_[b].push_back(model_->mesh().cellCount());
        if (fileElement >= cellOfFileElement_.size()) cellOfFileElement_.resize(fileElement + 1, kNoCell);
        cellOfFileElement_[fileElement] = std::uint32_t(model_->mesh().cellCount());
        model_->mesh().addCell(type->cell, std::span<const NodeIndex>(cell.data(), type->vtkOrder.size()));
        model_->mesh().cellIds.push_back(fileElement < elementIds.size() ? elementIds[fileElement] : (long long)(fileElement + 1));
        blockOfCell_.push_back(double(blockId));
      }
    }
    if (blocks > 1) model_->fields.push_back(Field::fromValues("element block", FieldLocation::Cell, 1, {blockOfCell_}));
    addBlockSets(blockIds);
    if (skipped_ > 0)
      model_->diagnostics.push_back({Severity::Info, "skipped-non-solid-elements",
                                     std::to_string(skipped_) + " elements of non-solid blocks (" + skippedTypes_ + ") were not loaded", {}});
  }

  // Each loaded block is an element set, named as the file names it (eb_names) or by its id.
  void addBlockSets(const std::vector<long long>& blockIds) {
    const std::vector<std::string> names = nc_.names("eb_names");
    for (std::size_t b = 0; b < blockCells_.size(); ++b) {
      if (blockCells_[b].empty()) continue;
      const long long id = b < blockIds.size() ? blockIds[b] : (long long)(b + 1);
      EntitySet set{b < names.size() && !names[b].empty() ? names[b] : "block " + std::to_string(id),
                    SetKind::Cells,
                    "element block",
                    {}};
      set.members.assign(blockCells_[b].begin(), blockCells_[b].end());
      model_->sets.push_back(std::move(set));
    }
  }

  // Node sets: node_ns<k> (1-based node numbers), named by ns_names or their id (ns_prop1).
  void readNodeSets() {
    const std::size_t count = nc_.dimension("num_node_sets").value_or(0);
    if (count == 0) return;
    const std::vector<std::string> names = nc_.names("ns_names");
    const std::vector<long long> ids = nc_.variable("ns_prop1") ? nc_.integers("ns_prop1") : std::vector<long long>{};
    for (std::size_t k = 0; k < count && k < std::size_t(nc_.variableCount()); ++k) {
      const std::string variable = "node_ns" + std::to_string(k + 1);
      if (!nc_.variable(variable)) continue;
      const long long id = k < ids.size() ? ids[k] : (long long)(k + 1);
      EntitySet set{k < names.size() && !names[k].empty() ? names[k] : "node set " + std::to_string(id),
                    SetKind::Nodes,
                    "node set",
                    {}};
      for (const long long node : nc_.integers(variable)) {
        if (node < 1 || std::size_t(node) > model_->mesh().nodeCount())
          nc_.fail(variable + " (" + set.name + ") names node " + std::to_string(node) + " of " +
                   std::to_string(model_->mesh().nodeCount()));
        set.members.push_back(std::uint32_t(node - 1));
      }
      normalizeMembers(set.members);
      if (!set.members.empty()) model_->sets.push_back(std::move(set));
    }
  }

  // Side sets: elem_ss<k> (the file's element numbers, 1-based) and side_ss<k> (each
  // element's side), kept as the node set of those sides' nodes, named by ss_names or
  // their id (ss_prop1).
  void readSideSets() {
    const std::size_t count = nc_.dimension("num_side_sets").value_or(0);
    if (count == 0) return;
    const std::vector<std::string> names = nc_.names("ss_names");
    const std::vector<long long> ids = nc_.variable("ss_prop1") ? nc_.integers("ss_prop1") : std::vector<long long>{};
    for (std::size_t k = 0; k < count && k < std::size_t(nc_.variableCount()); ++k) {
      const std::string suffix = std::to_string(k + 1);
      if (!nc_.variable("elem_ss" + suffix) || !nc_.variable("side_ss" + suffix)) continue;
      const long long id = k < ids.size() ? ids[k] : (long long)(k + 1);
      EntitySet set{k < names.size() && !names[k].empty() ? names[k] : "side set " + std::to_string(id),
                    SetKind::Nodes,
                    "side set",
                    {}};
      const std::vector<long long> elements = nc_.integers("elem_ss" + suffix);
      const std::vector<long long> sides = nc_.integers("side_ss" + suffix);
      if (elements.size() != sides.size())
        nc_.fail("elem_ss" + suffix + " and side_ss" + suffix + " (" + set.name + ") differ in length");
      for (std::size_t i = 0; i < elements.size(); ++i) {
        const long long e = elements[i];
        if (e < 1 || std::size_t(e) > cellOfFileElement_.size())
          nc_.fail("elem_ss" + suffix + " (" + set.name + ") names element " + std::to_string(e) + " of " +
                   std::to_string(cellOfFileElement_.size()));
        const std::uint32_t cell = cellOfFileElement_[std::size_t(e - 1)];
        if (cell == kNoCell) continue;  // a side of an element not loaded (a shell's)
        const std::vector<int> corners = exodusSide(model_->mesh().cellType(cell), sides[i]);
        if (corners.empty())
          nc_.fail("side_ss" + suffix + " (" + set.name + ") names side " + std::to_string(sides[i]) + " of a " +
                   std::string(cellTypeName(model_->mesh().cellType(cell))));
        appendFaceNodes(model_->mesh(), cell, corners, set.members);
      }
      normalizeMembers(set.members);
      if (!set.members.empty()) model_->sets.push_back(std::move(set));
    }
  }

  void readTimes() {
    const std::size_t steps = nc_.dimension("time_step").value_or(0);
    requireMemory(double(steps) * 64.0, nc_.path(), std::to_string(steps) + " time steps");
    times_ = steps && nc_.variable("time_whole") ? nc_.doubles("time_whole") : std::vector<double>(steps, 0.0);
    times_.resize(steps, 0.0);
  }

  Step step(std::size_t t) const {
    char buffer[48];
    std::snprintf(buffer, sizeof buffer, "step %zu, t = %g", t + 1, times_[t]);
    return {buffer, times_[t]};
  }

  void readNodalVariables() {
    const auto names = nc_.names("name_nod_var");
    const std::size_t n = model_->mesh().nodeCount();
    const auto oldStyle = nc_.variable("vals_nod_var");
    for (const auto& group : groupComponents(names)) {
      const std::size_t nc = group.members.size();
      for (std::size_t t = 0; t < times_.size(); ++t) {
        std::vector<double> values(n * nc);
        for (std::size_t c = 0; c < nc; ++c) {
          const std::size_t v = group.members[c];
          std::vector<double> column;
          if (const auto var = nc_.variable("vals_nod_var" + std::to_string(v + 1)))
            column = nc_.slab(*var, names[v], {t, 0}, {1, n});
          else if (oldStyle)
            column = nc_.slab(*oldStyle, names[v], {t, v, 0}, {1, 1, n});
          else
            nc_.fail("nodal variable " + names[v] + " has no values");
          for (std::size_t i = 0; i < n; ++i) values[i * nc + c] = column[i];
        }
        results_.add(group.name, FieldLocation::Node, int(nc), step(t), std::move(values));
      }
      progress_.report(0.8);
    }
  }

  void readElementVariables(std::size_t blocks) {
    const auto names = nc_.names("name_elem_var");
    const std::size_t cells = model_->mesh().cellCount();
    for (const auto& group : groupComponents(names)) {
      const std::size_t nc = group.members.size();
      for (std::size_t t = 0; t < times_.size(); ++t) {
        std::vector<double> values(cells * nc, std::numeric_limits<double>::quiet_NaN());
        for (std::size_t b = 0; b < blocks; ++b) {
          const auto& cellsOfBlock = blockCells_[b];
          for (std::size_t c = 0; c < nc; ++c) {
            const std::size_t v = group.members[c];
            const auto var = nc_.variable("vals_elem_var" + std::to_string(v + 1) + "eb" + std::to_string(b + 1));
            if (!var || cellsOfBlock.empty()) continue;  // the truth table leaves it out
            const auto column = nc_.slab(*var, names[v], {t, 0}, {1, cellsOfBlock.size()});
            for (std::size_t e = 0; e < cellsOfBlock.size(); ++e) values[cellsOfBlock[e] * nc + c] = column[e];
          }
        }
        results_.add(group.name, FieldLocation::Cell, int(nc), step(t), std::move(values));
      }
    }
  }

  NcFile nc_;
  const Progress& progress_;
  std::unique_ptr<Model> model_;
  std::vector<double> times_;
  std::vector<std::vector<std::size_t>> blockCells_;
  static constexpr std::uint32_t kNoCell = 0xffffffffu;
  std::vector<std::uint32_t> cellOfFileElement_;  ///< by the file's element number - 1; kNoCell: not loaded
  std::vector<double> blockOfCell_;
  std::size_t skipped_ = 0;
  std::string skippedTypes_;
  ResultCollector results_;
};

}  // namespace

int ExodusReader::sniff(std::string_view head) const {
  const auto starts = [&](std::string_view magic) { return head.substr(0, magic.size()) == magic; };
  return starts("CDF\x01") || starts("CDF\x02") || starts("CDF\x05") || starts("\x89HDF\r\n") ? 60 : 0;
}

std::unique_ptr<Model> ExodusReader::read(const std::string& path, const Progress& progress) const {
  progress.report(0.0);
  checkClassicNetcdfExtent(path);
  auto model = ExodusParser(path, progress).parse();
  model->formatName = formatName();
  return model;
}

}  // namespace volpost::meshio

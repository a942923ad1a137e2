// SPDX-License-Identifier: MIT
#include "TetraReader.hpp"

#include <fstream>
#include <sstream>

using namespace volpost;

namespace {

class Lines {
 public:
  explicit Lines(const std::string& path) : path_(path), in_(path) {
    if (!in_) throw ReadError(path, "cannot open");
  }
  // The next line that is not empty or a comment; false at the end of the file.
  bool next(std::istringstream& out) {
    std::string line;
    while (std::getline(in_, line)) {
      ++number_;
      if (line.empty() || line[0] == '#') continue;
      out = std::istringstream(line);
      return true;
    }
    return false;
  }
  std::istringstream require(const char* what) {
    std::istringstream s;
    if (!next(s)) fail(std::string("file ends where ") + what + " was expected");
    return s;
  }
  [[noreturn]] void fail(const std::string& message) const { throw ReadError::atLine(path_, number_, message); }

 private:
  std::string path_;
  std::ifstream in_;
  std::int64_t number_ = 0;
};

}  // namespace

std::unique_ptr<Model> TetraReader::read(const std::string& path, const Progress& progress) const {
  auto model = std::make_unique<Model>();
  Lines lines(path);
  std::string word;
  std::size_t count = 0;
  if (auto header = lines.require("the TETRA 1 header"); !(header >> word >> count) || word != "TETRA" || count != 1)
    lines.fail("not a TETRA 1 file");
  if (auto h = lines.require("'nodes N'"); !(h >> word >> count) || word != "nodes") lines.fail("expected 'nodes N'");
  for (std::size_t i = 0; i < count; ++i) {
    glm::dvec3 p;
    if (auto s = lines.require("a node"); !(s >> p.x >> p.y >> p.z)) lines.fail("expected three coordinates");
    model->mesh().nodes.push_back(p);
  }
  progress.report(0.5);
  if (auto h = lines.require("'tets M'"); !(h >> word >> count) || word != "tets") lines.fail("expected 'tets M'");
  for (std::size_t i = 0; i < count; ++i) {
    NodeIndex n[4];
    auto s = lines.require("a tet");
    if (!(s >> n[0] >> n[1] >> n[2] >> n[3])) lines.fail("expected four node indices");
    for (NodeIndex k : n)
      if (k >= model->mesh().nodeCount()) lines.fail("node " + std::to_string(k) + " does not exist");
    model->mesh().addCell(CellType::Tet4, n);
  }
  std::istringstream s;
  while (lines.next(s)) {
    std::string name, where;
    if (!(s >> word >> name >> where) || word != "field" || (where != "node" && where != "cell"))
      lines.fail("expected 'field NAME node|cell'");
    const auto location = where == "node" ? FieldLocation::Node : FieldLocation::Cell;
    const std::size_t n = location == FieldLocation::Node ? model->mesh().nodeCount() : model->mesh().cellCount();
    std::vector<double> values(n);
    for (double& v : values)
      if (auto line = lines.require("a field value"); !(line >> v)) lines.fail("expected a number");
    model->fields.push_back(Field::fromValues(name, location, 1, {values}));
  }
  progress.report(1.0);
  return model;
}

// SPDX-License-Identifier: MIT
// `volpost probe MODEL --at X,Y,Z [--field Q ...] [--csv out.csv]`: what the model holds at
// points: the element, its type, the node when the point is one, and the quantities
// interpolated with the element's shape functions, at full precision.
#include "../core/Probe.hpp"
#include "../core/ProbeTable.hpp"
#include "../core/SetMembership.hpp"
#include "../core/VolumeSpecs.hpp"
#include "CliSupport.hpp"
#include "Commands.hpp"

#include "host/AtomicFile.hpp"
#include "host/TextFile.hpp"

#include <QCommandLineParser>

#include <algorithm>
#include <cstdio>
#include <optional>
#include <sstream>

namespace volpost::app {

namespace {

// Points from a text file: X Y Z (or X,Y,Z) per line; blank lines, lines starting with #
// and a first line of column names are skipped. Throws naming the file and line.
std::vector<glm::dvec3> readPoints(const std::string& path) {
  const std::string text = readTextFile(path);
  std::vector<glm::dvec3> points;
  std::istringstream in(text);
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    for (char& c : line)
      if (c == ',' || c == ';' || c == '\t' || c == '\r') c = ' ';
    const auto first = line.find_first_not_of(' ');
    if (first == std::string::npos || line[first] == '#') continue;
    const auto p = parsePoint(QString::fromStdString(line).simplified().replace(' ', ','));
    if (!p) {
      if (number == 1 && points.empty()) continue;  // a header
      throw std::runtime_error(path + ":" + std::to_string(number) + ": '" + line.substr(0, 60) + "' is not X Y Z");
    }
    points.push_back(*p);
    if (points.size() > 10'000'000) throw std::runtime_error(path + ": more than 10 million points");
  }
  if (points.empty()) throw std::runtime_error(path + ": no points (X Y Z per line)");
  return points;
}

std::string pointText(const glm::dvec3& p) {
  return exactNumber(p.x) + ", " + exactNumber(p.y) + ", " + exactNumber(p.z);
}

void printValues(const ProbeResult& r, const std::vector<std::string>& keys, const char* indent) {
  for (const std::string& key : keys) {
    const auto v = r.value(key);
    std::printf("%s%s = %s\n", indent, key.c_str(), v ? exactNumber(*v).c_str() : "not probed");
  }
}

// "  sets: E_HEXAHEDRON, EALL" where the model's sets hold the element (or the node).
void printSets(const char* what, const std::vector<std::string>& names) {
  if (!names.empty()) std::printf("  %s sets: %s\n", what, setNameList(names).c_str());
}

void printResult(const std::vector<EntitySet>& sets, const ProbeResult& r, const std::vector<std::string>& keys) {
  if (r.method == ProbeMethod::AtNode && r.nodeId) {
    std::printf("node %lld at %s: in element %lld (%s), %s\n", static_cast<long long>(*r.nodeId),
                pointText(r.point).c_str(), static_cast<long long>(r.cellId),
                std::string(cellTypeName(r.cellType)).c_str(), describe(r.method));
    printSets("node", setsHolding(sets, SetKind::Nodes, r.nearestNode));
    printSets("element", setsHolding(sets, SetKind::Cells, r.cell));
    printValues(r, keys, "  ");
    return;
  }
  std::printf("point %s: ", pointText(r.point).c_str());
  if (!r.inside()) {
    std::printf("outside the mesh\n");
    return;
  }
  std::printf("element %lld (%s)", static_cast<long long>(r.cellId), std::string(cellTypeName(r.cellType)).c_str());
  if (r.nodeId) std::printf(", node %lld", static_cast<long long>(*r.nodeId));
  std::printf(", %s\n", describe(r.method));
  if (!r.gridPosition.empty()) std::printf("  %s\n", r.gridPositionText().c_str());
  printSets("element", setsHolding(sets, SetKind::Cells, r.cell));
  printValues(r, keys, "  ");
}

// An element asked for by id: its centre's values, then each of its nodes' own (node
// results only: an element result is the element's).
void printElement(const ModelSession& session, const std::vector<EntitySet>& sets, const ProbeResult& r,
                  const std::vector<std::string>& keys) {
  std::printf("element %lld (%s), centre %s: %s\n", static_cast<long long>(r.cellId),
              std::string(cellTypeName(r.cellType)).c_str(), pointText(r.point).c_str(), describe(r.method));
  std::string ids;
  for (std::int64_t id : r.nodeIds) ids += (ids.empty() ? "" : ", ") + std::to_string(id);
  std::printf("  nodes: %s\n", ids.c_str());
  printSets("element", setsHolding(sets, SetKind::Cells, r.cell));
  printValues(r, keys, "  ");
  std::vector<std::string> nodeKeys;
  for (const std::string& key : keys)
    if (session.fieldOf(session.findQuantity(key)).location() == FieldLocation::Node) nodeKeys.push_back(key);
  if (nodeKeys.empty()) return;
  for (std::int64_t id : r.nodeIds) {
    const ProbeResult node = probeNode(session, id, r.step);
    std::printf("  at node %lld (%s):\n", static_cast<long long>(id), pointText(node.point).c_str());
    printValues(node, nodeKeys, "    ");
  }
}

}  // namespace

int runProbe(const QStringList& args) {
  QCommandLineParser parser;
  parser.setApplicationDescription(
      "volpost probe: what MODEL holds at points: the element there, and the quantities interpolated with the "
      "element's shape functions (element results as stored), at full precision.");
  parser.addPositionalArgument("MODEL", "mesh or results file");
  const QCommandLineOption field("field", "A quantity: S.xx, S.mises, U.magnitude, T ... (repeatable; default: all).",
                                 "Q");
  const QCommandLineOption at("at", "A point X,Y,Z in model units (repeatable).", "X,Y,Z");
  const QCommandLineOption node("node", "A node by its id in the file: its own values (repeatable).", "ID");
  const QCommandLineOption element("element",
                                   "An element by its id in the file: its results, node results at its centre and at "
                                   "each of its nodes (repeatable).",
                                   "ID");
  const QCommandLineOption pointsFile("points", "A text file of points, X Y Z (or X,Y,Z) per line.", "FILE");
  const QCommandLineOption step("step", "Load case / time step, 1-based (default 1).", "K", "1");
  const QCommandLineOption csv("csv", "Write a table (x, y, z, element, element_type, node, the quantities) to this "
                                      "CSV file, or - for the terminal.", "FILE");
  const QCommandLineOption readerOption = readerOptionOption();
  const QCommandLineOption formula = formulaOption();
  parser.addOptions({field, at, pointsFile, node, element, step, csv, readerOption, formula});
  if (const auto code = parseArguments(parser, "volpost probe", args)) return *code;
  if (parser.positionalArguments().size() != 1 ||
      (!parser.isSet(at) && !parser.isSet(pointsFile) && !parser.isSet(node) && !parser.isSet(element))) {
    printError(
        "probe needs MODEL and --at X,Y,Z, --points FILE, --node ID or --element ID (volpost probe MODEL "
        "--field S.xx --at 5,0.5,0.5)");
    return 2;
  }
  std::vector<std::int64_t> nodeIds, elementIds;
  for (const auto& [option, ids] : {std::pair{&node, &nodeIds}, std::pair{&element, &elementIds}})
    for (const QString& text : parser.values(*option)) {
      bool ok = false;
      const qlonglong id = text.toLongLong(&ok);
      if (!ok) {
        printError(QString("--%1 %2 is not an id (a whole number)").arg(option->names().first(), text));
        return 2;
      }
      ids->push_back(id);
    }
  std::vector<glm::dvec3> points;
  for (const QString& text : parser.values(at)) {
    const auto p = parsePoint(text);
    if (!p) {
      printError(QString("--at %1 is not X,Y,Z").arg(text));
      return 2;
    }
    points.push_back(*p);
  }
  const auto stepIndex = parseStep(parser, step);
  if (!stepIndex) return 2;
  const std::string csvPath = parser.isSet(csv) && parser.value(csv) != "-" ? pathBytes(parser.value(csv)) : std::string();
  auto plugins = loadPluginsForCli();
  return exitCodeOf([&] {
    if (!csvPath.empty()) checkWritable(csvPath);
    if (parser.isSet(pointsFile))
      for (const glm::dvec3& p : readPoints(pathBytes(parser.value(pointsFile)))) points.push_back(p);
    const auto session = loadWithFormulas(plugins->readers(), pathBytes(parser.positionalArguments().first()), parser,
                                          readerOption, formula);
    std::vector<std::string> keys = quantityKeys(*session, parser.values(field));
    if (keys.empty()) keys = allQuantityKeys(*session);
    checkStepExists(*session, keys, *stepIndex);
    // Nodes and elements by id, all found before anything is written: an id the model does
    // not have is an option it cannot honour.
    std::vector<ProbeResult> byId;
    // The sets each printed element or node is in (made once: a region field's groups scan it).
    const std::vector<EntitySet> sets = parser.isSet(csv) ? std::vector<EntitySet>{} : modelSets(session->model());
    try {
      for (std::int64_t id : nodeIds) byId.push_back(probeNode(*session, id, *stepIndex));
      for (std::int64_t id : elementIds) byId.push_back(probeElement(*session, id, *stepIndex));
    } catch (const std::invalid_argument& e) {
      throw OptionError(e.what());
    }
    // Probed and written a chunk at a time: a result holds every quantity at its point, so a
    // million points kept together took gigabytes.
    std::optional<AtomicFile> file;
    if (!csvPath.empty()) file.emplace(csvPath);
    const auto put = [&](const std::string& text) {
      if (file) file->write(text);
      else std::fwrite(text.data(), 1, text.size(), stdout);
    };
    if (parser.isSet(csv)) put(probeTableHeader(keys));
    std::size_t outside = 0, done = 0;
    Progress progress = terminalProgress("probing");
    constexpr std::size_t kChunk = 4096;
    std::vector<ProbeResult> results;
    for (std::size_t first = 0; first < points.size(); first += kChunk) {
      results.clear();
      for (std::size_t i = first; i < std::min(points.size(), first + kChunk); ++i) {
        results.push_back(probeAt(*session, points[i], *stepIndex));
        outside += !results.back().inside();
      }
      done += results.size();
      if (parser.isSet(csv)) put(probeTableRows(results, keys));
      else
        for (const ProbeResult& r : results) printResult(sets, r, keys);
      if (points.size() > kChunk) progress.report(double(done) / double(points.size()));
    }
    if (parser.isSet(csv)) put(probeTableRows(byId, keys));
    else
      for (const ProbeResult& r : byId)
        if (r.method == ProbeMethod::ElementCentre) printElement(*session, sets, r, keys);
        else printResult(sets, r, keys);
    done += byId.size();
    if (file) file->commit();
    if (!csvPath.empty())
      std::printf("%s: %zu point%s, %zu quantit%s\n", csvPath.c_str(), done, done == 1 ? "" : "s", keys.size(),
                  keys.size() == 1 ? "y" : "ies");
    if (outside) std::fprintf(stderr, "volpost: %zu of %zu points are outside the mesh\n", outside, done);
    return outside == 0 ? 0 : 1;
  });
}

}  // namespace volpost::app

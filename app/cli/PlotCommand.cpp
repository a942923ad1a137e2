// SPDX-License-Identifier: MIT
// `volpost plot MODEL --from X,Y,Z --to X,Y,Z [--field Q ...] [--samples N] [--csv F] [-o plot.png]`:
// plot over line: quantities sampled along a segment, as a table and as a chart.
// `volpost plot MODEL --history --node ID [--element ID] [--at X,Y,Z] [--field Q ...]`: the
// quantities against the step or time at those places.
#include "../core/History.hpp"
#include "../core/LinePlot.hpp"
#include "../core/LineSampling.hpp"
#include "../core/PictureFile.hpp"
#include "../core/SetVisibility.hpp"
#include "../core/VolumeSpecs.hpp"
#include "CliSupport.hpp"
#include "Commands.hpp"

#include "host/AtomicFile.hpp"

#include <QCommandLineParser>
#include <QFileInfo>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace volpost::app {
namespace {

// The places of a history: --node and --element ids, --at points, the sets' extremes, in
// that order.
std::vector<HistoryPlace> historyPlaces(const QCommandLineParser& parser, const QCommandLineOption& node,
                                        const QCommandLineOption& element, const QCommandLineOption& at,
                                        const QCommandLineOption& maxOf, const QCommandLineOption& minOf) {
  std::vector<HistoryPlace> places;
  for (const auto& [option, kind] :
       {std::pair{&node, HistoryPlace::Kind::Node}, std::pair{&element, HistoryPlace::Kind::Element}})
    for (const QString& text : parser.values(*option)) {
      bool ok = false;
      const qlonglong id = text.toLongLong(&ok);
      if (!ok)
        throw OptionError(
            QString("--%1 %2 is not an id (a whole number)").arg(option->names().first(), text).toStdString());
      places.push_back({kind, id, {}, {}});
    }
  for (const QString& text : parser.values(at)) {
    const auto p = parsePoint(text);
    if (!p) throw OptionError(QString("--at %1 is not X,Y,Z").arg(text).toStdString());
    places.push_back({HistoryPlace::Kind::Point, 0, *p, {}});
  }
  for (const auto& [option, kind] :
       {std::pair{&maxOf, HistoryPlace::Kind::SetMax}, std::pair{&minOf, HistoryPlace::Kind::SetMin}})
    for (const QString& name : parser.values(*option)) places.push_back({kind, 0, {}, name.toStdString()});
  return places;
}

}  // namespace

int runPlot(const QStringList& args) {
  QCommandLineParser parser;
  parser.setApplicationDescription(
      "volpost plot: quantities along a line (plot over line): evenly spaced samples from A to B, each "
      "interpolated with its element's shape functions, as a CSV table and a chart.");
  parser.addPositionalArgument("MODEL", "mesh or results file");
  const QCommandLineOption from("from", "The line's first end X,Y,Z.", "X,Y,Z");
  const QCommandLineOption to("to", "The line's other end X,Y,Z.", "X,Y,Z");
  const QCommandLineOption field("field", "A quantity to plot (repeatable; default: the model's first).", "Q");
  const QCommandLineOption samples("samples", "Samples along the line, ends included (default 200).", "N", "200");
  const QCommandLineOption step("step", "Load case / time step, 1-based (default 1).", "K", "1");
  const QCommandLineOption csv("csv", "Write the samples (arc_length, x, y, z, element, quantities) to this CSV "
                                      "file, or - for the terminal.", "FILE");
  const QCommandLineOption output(QStringList{"o", "output"}, "The chart as a picture (.png, .jpg).", "FILE");
  const QCommandLineOption size("size", "The chart's size (default 800x500).", "WxH", "800x500");
  const QCommandLineOption readerOption = readerOptionOption();
  const QCommandLineOption formula = formulaOption();
  const QCommandLineOption history("history",
                                   "Plot the quantities against the step (or the time, where the steps' times "
                                   "increase) at --node, --element or --at places instead of along a line.");
  const QCommandLineOption node("node", "With --history: a node by its id in the file (repeatable).", "ID");
  const QCommandLineOption element("element", "With --history: an element by its id, at its centre (repeatable).",
                                   "ID");
  const QCommandLineOption at("at", "With --history: a point X,Y,Z (repeatable).", "X,Y,Z");
  const QCommandLineOption maxOf("max-of",
                                 "With --history: the largest value over this set at each step (a node set's "
                                 "nodes, an element set's elements; repeatable).",
                                 "SET");
  const QCommandLineOption minOf("min-of", "With --history: the smallest value over this set (repeatable).", "SET");
  const QCommandLineOption showSet("show-set",
                                   "Sample only this element set's elements (repeatable; `volpost info` lists "
                                   "the sets); the line is off the model elsewhere.",
                                   "NAME");
  const QCommandLineOption hideSet("hide-set", "Leave this element set's elements out (repeatable).", "NAME");
  parser.addOptions({from, to, field, samples, step, csv, output, size, readerOption, formula, history, node, element,
                     at, maxOf, minOf, showSet, hideSet});
  if (const auto code = parseArguments(parser, "volpost plot", args)) return *code;
  if (parser.isSet(history)) {
    for (const QCommandLineOption* o : {&from, &to, &samples, &step, &showSet, &hideSet})
      if (parser.isSet(*o)) {
        printError(QString("--%1 is for a plot over a line; --history plots every step at --node, --element, --at, "
                           "--max-of or --min-of")
                       .arg(o->names().first()));
        return 2;
      }
    if (parser.positionalArguments().size() != 1 ||
        (!parser.isSet(node) && !parser.isSet(element) && !parser.isSet(at) && !parser.isSet(maxOf) &&
         !parser.isSet(minOf)) ||
        (!parser.isSet(csv) && !parser.isSet(output))) {
      printError(
          "plot --history needs MODEL, --node ID, --element ID, --at X,Y,Z or --max-of/--min-of SET, and --csv "
          "FILE or -o chart.png "
          "(volpost plot model.frd --history --node 5484 --field S.mises -o history.png)");
      return 2;
    }
  } else {
    for (const QCommandLineOption* o : {&node, &element, &at, &maxOf, &minOf})
      if (parser.isSet(*o)) {
        printError(QString("--%1 goes with --history (a plot over the steps)").arg(o->names().first()));
        return 2;
      }
  }
  if (!parser.isSet(history) && (parser.positionalArguments().size() != 1 || !parser.isSet(from) || !parser.isSet(to) ||
                                 (!parser.isSet(csv) && !parser.isSet(output)))) {
    printError("plot needs MODEL, --from, --to and --csv FILE or -o chart.png "
               "(volpost plot bar.vtu --from 0,0.5,0.5 --to 10,0.5,0.5 --field S.xx -o plot.png)");
    return 2;
  }
  const auto a = parsePoint(parser.value(from)), b = parsePoint(parser.value(to));
  if (!parser.isSet(history) && (!a || !b)) {
    printError(QString("--from %1 / --to %2: not X,Y,Z").arg(parser.value(from), parser.value(to)));
    return 2;
  }
  bool countOk = false;
  const long long count = parser.value(samples).toLongLong(&countOk);
  if (!countOk || count < 2 || count > static_cast<long long>(kMaxLineSamples)) {
    printError(QString("--samples %1 is not a count from 2 to %2").arg(parser.value(samples)).arg(kMaxLineSamples));
    return 2;
  }
  int width = 0, height = 0;
  if (!parseSize(parser.value(size), width, height)) {
    printError(QString("--size %1 is not WIDTHxHEIGHT within 1..16384").arg(parser.value(size)));
    return 2;
  }
  const QString picture = parser.value(output);
  if (parser.isSet(output)) {
    try {
      pictureFormatOf(picture);
    } catch (const std::invalid_argument& e) {
      printError(QString("-o %1").arg(e.what()));
      return 2;
    }
  }
  const auto stepIndex = parseStep(parser, step);
  if (!stepIndex) return 2;
  const std::string csvPath = parser.isSet(csv) && parser.value(csv) != "-" ? pathBytes(parser.value(csv)) : std::string();
  auto plugins = loadPluginsForCli();
  return exitCodeOf([&] {
    if (!csvPath.empty()) checkWritable(csvPath);
    if (parser.isSet(output)) checkWritable(pathBytes(picture));
    std::shared_ptr<const ModelSession> session = loadWithFormulas(
        plugins->readers(), pathBytes(parser.positionalArguments().first()), parser, readerOption, formula);
    if (parser.isSet(showSet) || parser.isSet(hideSet)) {  // the line crosses the chosen sets only
      SetVisibility v;
      for (const QString& name : parser.values(showSet)) v.shown.push_back(name.toStdString());
      for (const QString& name : parser.values(hideSet)) v.hidden.push_back(name.toStdString());
      try {
        checkSetVisibility(*session, v);
      } catch (const std::invalid_argument& e) {
        throw OptionError(e.what());  // a set the model does not have: a usage error
      }
      session = setVisibleSession(session, v);
    }
    std::vector<std::string> keys = quantityKeys(*session, parser.values(field));
    if (keys.empty()) {
      const auto first = session->defaultQuantity();
      if (!first) throw std::invalid_argument("the model has no result to plot");
      keys.push_back(first->key());
    }
    if (parser.isSet(history)) {
      History h;
      try {
        h = sampleHistory(*session, historyPlaces(parser, node, element, at, maxOf, minOf), keys,
                          terminalProgress("sampling"));
      } catch (const std::invalid_argument& e) {  // an id or place count the model cannot honour
        throw OptionError(e.what());
      }
      std::size_t outside = 0;
      for (const History::Curve& c : h.curves)
        outside += std::all_of(c.values.begin(), c.values.end(), [](double v) { return std::isnan(v); });
      if (outside == h.curves.size()) throw std::runtime_error("no curve has a value: the places lie outside the mesh");
      if (parser.isSet(csv)) {
        const std::string table = historyTable(h);
        if (csvPath.empty()) std::fwrite(table.data(), 1, table.size(), stdout);
        else writeFileAtomically(csvPath, table);
      }
      if (parser.isSet(output)) {
        savePicture(chartImage(historyChart(h), width, height), picture);
        std::printf("%s\n", qPrintable(QFileInfo(picture).absoluteFilePath()));
      }
      if (!csvPath.empty())
        std::printf("%s: %zu steps, %zu curves\n", csvPath.c_str(), h.times.size(), h.curves.size());
      if (outside)
        std::fprintf(stderr, "volpost: note: %zu of the %zu curves have no value (a point outside the mesh)\n", outside,
                     h.curves.size());
      return 0;
    }
    checkStepExists(*session, keys, *stepIndex);
    const LineSamples line = sampleLine(*session, *a, *b, std::size_t(count), keys, *stepIndex, terminalProgress("sampling"));
    std::size_t outside = 0;
    for (const ProbeResult& r : line.points) outside += !r.inside();
    if (outside == line.points.size()) throw std::runtime_error("the whole line lies outside the mesh");
    if (parser.isSet(csv)) {
      const std::string table = lineTable(line);
      if (csvPath.empty()) std::fwrite(table.data(), 1, table.size(), stdout);
      else writeFileAtomically(csvPath, table);
    }
    if (parser.isSet(output)) {
      savePicture(linePlotImage(line, width, height), picture);
      std::printf("%s\n", qPrintable(QFileInfo(picture).absoluteFilePath()));
    }
    if (!csvPath.empty()) std::printf("%s: %zu samples\n", csvPath.c_str(), line.points.size());
    if (outside)
      std::fprintf(stderr, "volpost: note: %zu of the %zu samples lie outside the mesh (gaps in the chart)\n", outside,
                   line.points.size());
    return 0;
  });
}

}  // namespace volpost::app

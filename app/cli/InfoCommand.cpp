// SPDX-License-Identifier: MIT
// `volpost info MODEL`: counts, bounds, fields and defects of a model, as text.
#include "CliSupport.hpp"
#include "Commands.hpp"

#include "../core/ProbeTable.hpp"

#include <QCommandLineParser>

#include <cstdio>
#include <cstring>

namespace volpost::app {
namespace {

// The written forms a field can be colored, probed or plotted by, wrapped at about 100
// columns: "quantities: S.mises S.p1 S.p2 ..." (nothing for a field that is one scalar).
void printQuantities(const Field& field) {
  const std::vector<Quantity> quantities = quantitiesOf(field);
  if (quantities.size() < 2) return;
  std::string line = "      quantities:";
  for (const Quantity& q : quantities) {
    if (line.size() + 1 + q.key().size() > 100) {
      std::printf("%s\n", line.c_str());
      line = "                 ";
    }
    line += " " + q.key();
  }
  std::printf("%s\n", line.c_str());
}

// Returns how many steps could not be read (each said where it is listed).
std::size_t printFields(const Model& model) {
  std::size_t unreadable = 0;
  std::printf("fields:   %zu\n", model.fields.size());
  for (const auto& f : model.fields) {
    const Quantity headline = quantitiesOf(*f).front();
    std::printf("  %-16s %-4s  %s (%d component%s), %zu step%s\n", f->name().c_str(), toString(f->location()),
                toString(f->kind()), f->components(), f->components() == 1 ? "" : "s", f->stepCount(),
                f->stepCount() == 1 ? "" : "s");
    printQuantities(*f);
    if (!f->units().empty()) std::printf("      units: %s (as the file states them)\n", f->units().c_str());
    if (f->storesSamples() && f->stepCount() > 0) {
      try {  // what the field holds in memory: the file's own type, not doubles
        const SampleType type = f->samples(0).type();
        std::printf("      kept as %s values (%zu byte%s each)\n", toString(type), bytesPerSample(type),
                    bytesPerSample(type) == 1 ? "" : "s");
      } catch (const std::exception&) {
      }  // a step that cannot be read says so below
    }
    for (std::size_t s = 0; s < f->stepCount(); ++s) {
      if (f->stepCount() > 12 && s == 5) {
        std::printf("      ... %zu more steps ...\n", f->stepCount() - 10);
        s = f->stepCount() - 5;
      }
      try {
        const ValueRange r = isStoredSamples(*f, headline) ? rangeOf(f->samples(s)) : rangeOf(evaluate(*f, headline, s));
        const std::string& label = f->steps()[s].label;
        if (r.valid())
          std::printf("      %-14s %s [%.6g, %.6g]", label.empty() ? "" : label.c_str(), headline.displayName().c_str(),
                      r.min, r.max);
        else  // every value NaN or infinite: there is no range to print
          std::printf("      %-14s %s: no finite value", label.empty() ? "" : label.c_str(),
                      headline.displayName().c_str());
        if (r.nanCount) std::printf("  (%zu NaN/inf values)", r.nanCount);
        std::printf("\n");
      } catch (const std::exception& e) {
        std::printf("      step %zu: cannot be read: %s\n", s + 1, e.what());
        ++unreadable;
      }
    }
  }
  return unreadable;
}

// "sets:     3", then one line per set: its name, what it holds, how many, how the file
// defines it. Names with spaces are quoted, as --show-set takes them.
void printSets(const Model& model) {
  const std::vector<EntitySet> sets = modelSets(model);
  if (sets.empty()) return;
  std::printf("sets:     %zu\n", sets.size());
  for (const EntitySet& s : sets) {
    const bool quote = s.name.find(' ') != std::string::npos;
    const std::string name = quote ? "\"" + s.name + "\"" : s.name;
    const std::string kind = s.members.size() == 1
                                 ? std::string(setKindName(s.kind)).substr(0, std::strlen(setKindName(s.kind)) - 1)
                                 : setKindName(s.kind);
    std::printf("  %-24s %9zu %-8s (%s)\n", name.c_str(), s.members.size(), kind.c_str(), s.origin.c_str());
  }
}

std::string exactPoint(const glm::dvec3& p) {
  return "(" + exactNumber(p.x) + ", " + exactNumber(p.y) + ", " + exactNumber(p.z) + ")";
}

// "grid:     23 inline (111 .. 133 by 1) x 18 crossline (...) x 75 time (ms) (4 .. 300 by 4)",
// then where the grid lies, every number as the shortest text that reads back to it
// (UTM coordinates of a survey need 8 or more digits).
void printGrid(const RegularGrid& grid) {
  std::printf("grid:     ");
  for (int a = 0; a < 3; ++a)
    std::printf("%s%zu %s (%s .. %s by %s)", a ? " x " : "", grid.dims[a], grid.axisNames[a].c_str(),
                exactNumber(grid.label(a, 0.0)).c_str(), exactNumber(grid.label(a, double(grid.dims[a] - 1))).c_str(),
                exactNumber(grid.labelStep[a]).c_str());
  std::printf("\n");
  std::printf("  %-12s %s model units (the first point)\n", "origin", exactPoint(grid.origin).c_str());
  for (int a = 0; a < 3; ++a)
    std::printf("  %-12s step %s model units\n", grid.axisNames[a].c_str(), exactPoint(grid.axes[a]).c_str());
  if (!grid.sampleStorage.empty()) std::printf("samples:  %s in the file\n", grid.sampleStorage.c_str());
}

// The options of each reader (all readers, or the one that reads `path`).
int printReaderOptions(const ReaderRegistry& readers, const std::string& path) {
  std::vector<const MeshReader*> list = readers.readers();
  if (!path.empty()) list = {&readers.choose(path)};
  bool any = false;
  for (const MeshReader* reader : list) {
    const std::vector<ReaderOption> options = reader->options();
    if (options.empty() && path.empty()) continue;
    any = true;
    std::printf("%s:%s\n", reader->formatName().c_str(), options.empty() ? " no reader options" : "");
    for (const ReaderOption& o : options)
      std::printf("  %-26s %s\n", (o.name + "=" + o.valueName).c_str(), o.description.c_str());
  }
  if (!any) std::printf("no loaded reader takes options\n");
  return 0;
}

}  // namespace

int runInfo(const QStringList& args) {
  QCommandLineParser parser;
  parser.setApplicationDescription("Prints the node and cell counts, bounds, fields and defects of a model.");
  parser.addPositionalArgument("MODEL", "mesh or results file");
  const QCommandLineOption readerOption = readerOptionOption();
  const QCommandLineOption listOptions("reader-options",
                                       "List the settings the readers take (with MODEL: its reader's), for "
                                       "--reader-option.");
  const QCommandLineOption formula = formulaOption();
  parser.addOptions({readerOption, listOptions, formula});
  if (const auto code = parseArguments(parser, "volpost info", args)) return *code;
  if (parser.isSet(listOptions) && parser.positionalArguments().size() <= 1) {
    auto plugins = loadPluginsForCli();
    return exitCodeOf([&] {
      return printReaderOptions(plugins->readers(), parser.positionalArguments().isEmpty()
                                                        ? std::string()
                                                        : pathBytes(parser.positionalArguments().first()));
    });
  }
  if (parser.positionalArguments().size() != 1) {
    printError("info needs exactly one MODEL file (volpost info MODEL)");
    return 2;
  }
  const std::string path = pathBytes(parser.positionalArguments().first());
  auto plugins = loadPluginsForCli();
  try {
    const ReaderOptions options = readerOptionsFrom(parser, readerOption);
    const std::vector<FormulaSpec> formulas = formulasFrom(parser, formula);
    const auto model = plugins->readers().load(path, options, terminalProgress("reading"));
    appendFormulas(*model, formulas);
    std::printf("file:     %s\nformat:   %s\n", path.c_str(), model->formatName.c_str());
    if (!model->title.empty()) std::printf("title:    %s\n", model->title.c_str());
    std::printf("nodes:    %zu\ncells:    %zu\n", model->nodeCount(), model->cellCount());
    for (const auto& [type, count] : model->countsByType())
      std::printf("  %-9s %zu\n", std::string(cellTypeName(type)).c_str(), count);
    const Bounds b = model->bounds();
    if (b.valid)
      std::printf("bounds:   x [%s, %s]  y [%s, %s]  z [%s, %s]\n", exactNumber(b.min.x).c_str(),
                  exactNumber(b.max.x).c_str(), exactNumber(b.min.y).c_str(), exactNumber(b.max.y).c_str(),
                  exactNumber(b.min.z).c_str(), exactNumber(b.max.z).c_str());
    else
      std::printf("bounds:   (empty model)\n");
    if (model->grid) printGrid(*model->grid);
    const std::size_t unreadable = printFields(*model);
    printSets(*model);
    std::printf("defects:  %s\n", model->diagnostics.empty() ? "none found" : "");
    for (const Diagnostic& d : model->diagnostics)
      std::printf("  %-7s %-22s %s\n", d.severity == Severity::Warning ? "warning" : "info", d.code.c_str(),
                  d.message.c_str());
    if (unreadable > 0) {  // listed, but the model is not whole: not a success
      printError(QString::fromStdString(std::to_string(unreadable) + " field step" + (unreadable == 1 ? "" : "s") +
                                        " of " + path + " could not be read (said above)"));
      return 1;
    }
    return 0;
  } catch (const OptionError& e) {
    printError(e.what());
    return 2;
  } catch (const ReaderOptionError& e) {
    printError(e.what());
    return 2;
  } catch (const std::exception& e) {
    printError(e.what());
    return 1;
  }
}

int runPlugins(const QStringList& args) {
  QCommandLineParser parser;
  parser.setApplicationDescription("Lists the plugins found, what they provide, and why any was refused.");
  if (const auto code = parseArguments(parser, "volpost plugins", args)) return *code;
  PluginManager plugins;
  const QStringList dirs = PluginManager::defaultSearchPaths();
  plugins.loadFrom(dirs);
  std::printf("searched: %s\n", qPrintable(dirs.join(", ")));
  for (const PluginRecord& r : plugins.records()) {
    if (r.loaded)
      std::printf("  loaded   %-12s %-8s sdk %-4s provides %s  (%s)\n", qPrintable(r.id), qPrintable(r.version),
                  qPrintable(r.sdkVersion), qPrintable(r.provides.join(", ")), qPrintable(r.path));
    else
      std::printf("  refused  %s: %s\n", qPrintable(r.path), qPrintable(r.error));
  }
  std::printf("readers:");
  for (const MeshReader* reader : plugins.readers().readers()) std::printf(" [%s]", reader->formatName().c_str());
  std::printf("\n");
  return 0;
}

}  // namespace volpost::app

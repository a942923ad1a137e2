// SPDX-License-Identifier: MIT
// `volpost streamlines MODEL --field velocity --seeds SPEC -o lines.vtp`: streamlines traced
// headless and written for ParaView (.vtp) or a spreadsheet (.csv), with a summary of how
// the lines ended.
#include "../core/PluginRenderers.hpp"
#include "../core/Scene.hpp"
#include "CliSupport.hpp"
#include "Commands.hpp"
#include "StreamlineOptions.hpp"

#include "host/AtomicFile.hpp"
#include "host/PolylineWriter.hpp"

#include <QCommandLineParser>

#include <cstdio>
#include <map>

namespace volpost::app {

int runStreamlines(const QStringList& args) {
  QCommandLineParser parser;
  parser.setApplicationDescription("volpost streamlines: traces streamlines of a vector field and writes them as "
                                   ".vtp (VTK PolyData, for ParaView) or .csv.");
  parser.addPositionalArgument("MODEL", "mesh and results file");
  const QCommandLineOption field("field", "The vector field to follow (velocity, U, HFL ...).", "NAME");
  const QCommandLineOption step("step", "Load case / time step, 1-based (default 1).", "K", "1");
  const QCommandLineOption output(QStringList{"o", "output"}, "Output: lines.vtp or lines.csv.", "FILE");
  const StreamlineOptions lineOptions;
  const QCommandLineOption readerOption = readerOptionOption();
  const QCommandLineOption formula = formulaOption();
  const QCommandLineOption interpolation(
      "interpolation",
      "How the vectors vary inside a cell: tetrahedra (default): linear on the tetrahedra each cell is split into; "
      "element: each cell's own shape functions, as the solver computed the field (trilinear in a hex8, quadratic "
      "in a tet10 or hex20). The colors follow too.",
      "HOW");
  parser.addOptions({field, step, output, readerOption, formula, interpolation});
  for (const auto& o : lineOptions.all()) parser.addOption(o);
  if (const auto code = parseArguments(parser, "volpost streamlines", args)) return *code;
  if (parser.positionalArguments().size() != 1 || !parser.isSet(field) || !parser.isSet(lineOptions.seeds) ||
      !parser.isSet(output)) {
    printError("streamlines needs MODEL, --field NAME, --seeds SPEC and -o FILE (.vtp or .csv)");
    return 2;
  }
  bool okStep = false;
  const int stepNumber = parser.value(step).toInt(&okStep);
  if (!okStep || stepNumber < 1) {
    printError(QString("--step %1 is not a step number (1, 2, ...)").arg(parser.value(step)));
    return 2;
  }
  const auto how = fieldInterpolationFromString(parser.value(interpolation).toStdString());
  if (parser.isSet(interpolation) && !how) {
    printError(
        QString("--interpolation %1 is not one of: %2").arg(parser.value(interpolation), kFieldInterpolationChoices));
    return 2;
  }
  const std::string out = pathBytes(parser.value(output));
  try {
    checkPolylineFormat(out);
  } catch (const std::invalid_argument& e) {
    printError(QString("-o %1").arg(e.what()));
    return 2;
  }
  auto plugins = loadPluginsForCli();
  return exitCodeOf([&] {
    checkWritable(out);
    const auto session = loadWithFormulas(plugins->readers(), pathBytes(parser.positionalArguments().first()), parser,
                                          readerOption, formula);
    Scene scene(volumeRendererFactory(*plugins));
    scene.setSession(session);
    StreamlineLayer layer;
    layer.shown = true;
    layer.field = parser.value(field).toStdString();
    try {
      lineOptions.apply(parser, layer);
      if (const Field* f = session->model().findField(layer.field); f && std::size_t(stepNumber) > f->stepCount())
        throw std::invalid_argument("field " + layer.field + " has " + std::to_string(f->stepCount()) + " step(s)");
      scene.setResult({}, 0);
      SceneState state = scene.state();
      state.step = std::size_t(stepNumber - 1);
      state.quantity.clear();
      state.streamlines = layer;
      if (how) state.volume.interpolation = *how;
      scene.applyState(state);
    } catch (const std::invalid_argument& e) {
      printError(e.what());
      return 2;
    }
    const auto result = scene.traceStreamlines(terminalProgress("tracing"));
    PolylineSet set;
    set.vectorName = layer.field;
    set.valueName = result->valueName;
    std::map<std::string, int> endings;
    std::size_t points = 0;
    for (std::size_t i = 0; i < result->lines.size(); ++i) {
      const Streamline& l = result->lines[i];
      set.points.push_back(l.points);
      set.vectors.push_back(l.velocity);
      set.values.push_back(result->values[i]);
      set.lengths.push_back(l.length);
      set.stops.push_back(int(l.forwardStop));
      points += l.points.size();
      if (layer.settings.direction != StreamlineDirection::Backward) ++endings[describe(l.forwardStop)];
      if (layer.settings.direction != StreamlineDirection::Forward) ++endings[describe(l.backwardStop)];
    }
    writePolylines(set, out);
    std::printf("%s: %zu streamlines, %zu points (%s, %.0f ms)\n", out.c_str(), result->lines.size(), points,
                toString(layer.settings.method), result->milliseconds);
    if (result->outside) std::printf("  %zu seeds outside the mesh: no line\n", result->outside);
    for (const auto& [why, n] : endings) std::printf("  %d line ends %s\n", n, why.c_str());
    return 0;
  });
}

}  // namespace volpost::app

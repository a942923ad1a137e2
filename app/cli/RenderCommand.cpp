// SPDX-License-Identifier: MIT
// `volpost render MODEL --field Q -o out.png`: an image with no window and no X server.
#include "../core/ImageRender.hpp"
#include "CliSupport.hpp"
#include "Commands.hpp"

#include <QCommandLineParser>
#include <QFileInfo>

#include <cstdio>

namespace volpost::app {
namespace {

bool parseSize(const QString& text, int& w, int& h) {
  const QStringList parts = text.toLower().split('x');
  if (parts.size() != 2) return false;
  bool okW = false, okH = false;
  w = parts[0].toInt(&okW);
  h = parts[1].toInt(&okH);
  return okW && okH && w > 0 && h > 0 && w <= 16384 && h <= 16384;
}

bool parseRange(const QString& text, DisplayRange& range) {
  const int colon = text.indexOf(':', 1);  // skip a leading minus sign
  if (colon < 0) return false;
  bool okA = false, okB = false;
  range.min = text.left(colon).toDouble(&okA);
  range.max = text.mid(colon + 1).toDouble(&okB);
  return okA && okB && range.max > range.min;
}

}  // namespace

int runRender(const QStringList& args) {
  QCommandLineParser parser;
  parser.setApplicationDescription("Renders MODEL to a PNG headless (EGL), with the window's renderer.");
  parser.addPositionalArgument("MODEL", "mesh or results file");
  parser.addHelpOption();
  const QCommandLineOption field("field", "Quantity to color by: S.mises, U.magnitude, U.x, S.xx, S.p1, T ... "
                                          "(volpost info lists the fields). Default: plain surface.", "Q");
  const QCommandLineOption step("step", "Load case / time step, 1-based (default 1).", "K", "1");
  const QCommandLineOption camera("camera", "View: iso, +x, -x, +y, -y, +z, -z; then az=DEG, el=DEG, zoom=F, "
                                            "ortho or persp, comma-separated (default iso).", "SPEC", "iso");
  const QCommandLineOption size("size", "Image size (default 800x600).", "WxH", "800x600");
  const QCommandLineOption colormap("colormap", "cool-warm (default), viridis, rainbow, grayscale.", "NAME", "cool-warm");
  const QCommandLineOption range("range", "Fixed color range instead of the data's.", "MIN:MAX");
  const QCommandLineOption noEdges("no-edges", "Hide element edges.");
  const QCommandLineOption noLegend("no-legend", "Hide the color legend.");
  const QCommandLineOption output(QStringList{"o", "output"}, "Output PNG file.", "FILE");
  parser.addOptions({field, step, camera, size, colormap, range, noEdges, noLegend, output});
  parser.process(QStringList{"volpost render"} + args);

  if (parser.positionalArguments().size() != 1) {
    printError("render needs exactly one MODEL file (volpost render MODEL -o out.png)");
    return 2;
  }
  if (!parser.isSet(output)) {
    printError("render needs an output file: -o out.png");
    return 2;
  }
  ImageRequest request;
  if (!parseSize(parser.value(size), request.width, request.height)) {
    printError(QString("--size %1 is not WIDTHxHEIGHT within 1..16384").arg(parser.value(size)));
    return 2;
  }
  bool okStep = false;
  const int stepNumber = parser.value(step).toInt(&okStep);
  if (!okStep || stepNumber < 1) {
    printError(QString("--step %1 is not a step number (1, 2, ...)").arg(parser.value(step)));
    return 2;
  }
  request.step = std::size_t(stepNumber - 1);
  if (parser.isSet(range)) {
    DisplayRange r;
    if (!parseRange(parser.value(range), r)) {
      printError(QString("--range %1 is not MIN:MAX with MIN < MAX").arg(parser.value(range)));
      return 2;
    }
    request.range = r;
  }
  request.camera = parser.value(camera).toStdString();
  request.colorMap = parser.value(colormap).toStdString();
  request.edges = !parser.isSet(noEdges);
  request.legend = !parser.isSet(noLegend);

  const QString path = parser.positionalArguments().first();
  auto plugins = loadPluginsForCli();
  try {
    const auto session = ModelSession::load(plugins->readers(), path.toStdString(), terminalProgress("reading"));
    if (parser.isSet(field)) request.quantity = session->findQuantity(parser.value(field).toStdString());
    const QImage image = renderImage(*session, request);
    const QString out = parser.value(output);
    if (!image.save(out, "PNG")) {
      printError(QString("cannot write %1 (check the folder exists and is writable)").arg(out));
      return 1;
    }
    std::printf("%s\n", qPrintable(QFileInfo(out).absoluteFilePath()));
    return 0;
  } catch (const std::exception& e) {
    printError(e.what());
    return 1;
  }
}

}  // namespace volpost::app

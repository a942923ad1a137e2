// SPDX-License-Identifier: MIT
// `volpost render MODEL --field Q -o out.png`: an image with no window and no X server.
#include "../core/ImageRender.hpp"
#include "../core/GpuVolumeImage.hpp"
#include "../core/VolumeImage.hpp"
#include "CliSupport.hpp"
#include "../core/VolumeSpecs.hpp"
#include "Commands.hpp"

#include <QCommandLineParser>
#include <QFileInfo>

#include <QFile>

#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>

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

std::string readText(const QString& path) {
  std::ifstream in(path.toStdString());
  if (!in) throw std::runtime_error("cannot open " + path.toStdString());
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
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
  const QCommandLineOption renderer("renderer", "surface (default): the boundary colored by the result; "
                                                "reference: exact CPU volume rendering (tetrahedra); a GPU volume "
                                                "renderer from a plugin, e.g. raycast.", "NAME", "surface");
  const QCommandLineOption modeOption("mode", "GPU volume integration: linear (exact cuts, default), iso-table "
                                              "(the seed's), preintegrated, sampling.", "MODE", "linear");
  const QCommandLineOption tfFile("tf", "Transfer function (volpost TF JSON) for volume rendering; default: a "
                                        "cool-warm ramp over the result's range.", "FILE");
  const QCommandLineOption clip("clip", "Clip plane px,py,pz,nx,ny,nz keeping the side the normal points to "
                                        "(repeatable; volume rendering).", "PLANE");
  const QCommandLineOption clipBox("clip-box", "Keep the inside of the box xmin,xmax,ymin,ymax,zmin,zmax (six clip "
                                              "planes; volume rendering).", "BOX");
  const QCommandLineOption isoOption("iso", "Iso-surface VALUE[:r,g,b[:opacity]] (colors and opacity 0..1; "
                                            "repeatable, up to 8; volume rendering).", "ISO");
  const QCommandLineOption volumeEdges("volume-edges", "GPU volume rendering: draw the boundary's element edges, "
                                                     "which hide what lies behind them.");
  const QCommandLineOption floatOut("float", "Also write the volume image as 32-bit float RGB (PFM).", "FILE");
  const QCommandLineOption threads("threads", "Threads for the reference renderer (default: all cores).", "N", "0");
  parser.addOptions({field, step, camera, size, colormap, range, noEdges, noLegend, output, renderer, modeOption,
                     tfFile, clip, clipBox, isoOption, volumeEdges, floatOut, threads});
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

  const QString rendererName = parser.value(renderer);
  const QString modeName = parser.value(modeOption);
  const std::map<QString, IntegrationMode> modes = {{"linear", IntegrationMode::LinearSegments},
                                                    {"iso-table", IntegrationMode::LinearSegmentsIsoTable},
                                                    {"preintegrated", IntegrationMode::PreIntegrated},
                                                    {"sampling", IntegrationMode::Sampling}};
  if (!modes.count(modeName)) {
    printError(QString("--mode %1 is not one of: linear, iso-table, preintegrated, sampling").arg(modeName));
    return 2;
  }
  std::vector<ClipPlane> clipPlanes;
  for (const QString& c : parser.values(clip)) {
    const auto plane = parseClipPlane(c);
    if (!plane) {
      printError(QString("--clip %1 is not px,py,pz,nx,ny,nz with a non-zero normal").arg(c));
      return 2;
    }
    clipPlanes.push_back(*plane);
  }
  if (parser.isSet(clipBox)) {
    const auto box = parseClipBox(parser.value(clipBox));
    if (!box) {
      printError(QString("--clip-box %1 is not xmin,xmax,ymin,ymax,zmin,zmax with min < max").arg(parser.value(clipBox)));
      return 2;
    }
    clipPlanes.insert(clipPlanes.end(), box->begin(), box->end());
  }
  if (clipPlanes.size() > 6) {
    printError(QString("%1 clip planes: the volume renderers take at most 6 (a box is 6)").arg(clipPlanes.size()));
    return 2;
  }
  std::vector<optics::IsoSurface> isoSurfaces;
  for (const QString& text : parser.values(isoOption)) {
    const auto iso = parseIsoSurface(text);
    if (!iso || isoSurfaces.size() == 8) {
      printError(QString("--iso %1 is not VALUE[:r,g,b[:opacity]] with colors and opacity in 0..1 (at most 8)").arg(text));
      return 2;
    }
    isoSurfaces.push_back(*iso);
  }
  if (rendererName != "surface" && !parser.isSet(field)) {
    printError(QString("--renderer %1 needs --field (the quantity to render)").arg(rendererName));
    return 2;
  }

  const QString path = parser.positionalArguments().first();
  auto plugins = loadPluginsForCli();
  std::unique_ptr<VolumeRenderer> gpuRenderer;
  if (rendererName != "surface" && rendererName != "reference") {
    QStringList known = {"surface", "reference"};
    for (RendererPlugin* p : plugins->rendererPlugins()) {
      known << p->rendererNames();
      if (!gpuRenderer && p->rendererNames().contains(rendererName)) {
        std::unique_ptr<Renderer> r = p->createRenderer(rendererName);
        if (auto* v = dynamic_cast<VolumeRenderer*>(r.get())) {
          r.release();
          gpuRenderer.reset(v);
        }
      }
    }
    if (!gpuRenderer) {
      printError(QString("--renderer %1 is not one of: %2").arg(rendererName, known.join(", ")));
      return 2;
    }
  }
  try {
    const auto session = ModelSession::load(plugins->readers(), path.toStdString(), terminalProgress("reading"));
    if (parser.isSet(field)) request.quantity = session->findQuantity(parser.value(field).toStdString());
    QImage image;
    VolumeRequest volume{request.quantity.value_or(Quantity{}), request.step, request.camera, request.width,
                         request.height, {}, clipPlanes, isoSurfaces, parser.value(threads).toInt()};
    if (parser.isSet(tfFile)) volume.transferFunction = TransferFunction::fromJson(readText(parser.value(tfFile)));
    volume.edges = parser.isSet(volumeEdges);
    if (gpuRenderer) {
      image = renderGpuVolume(*session, volume, *gpuRenderer, modes.at(modeName), request.legend);
    } else if (rendererName == "reference") {
      const auto reference = renderVolumeReference(*session, volume, terminalProgress("rendering"));
      const glm::dvec3 background(1.0);
      image = toQImage(reference, background);
      if (parser.isSet(floatOut) && !writePfm(reference, background, parser.value(floatOut).toStdString())) {
        printError(QString("cannot write %1").arg(parser.value(floatOut)));
        return 1;
      }
    } else {
      image = renderImage(*session, request);
    }
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

// SPDX-License-Identifier: MIT
// `volpost convert` and `volpost surface`: models out to other tools
// (VTU for ParaView, OBJ/PLY/STL surfaces).
#include "../core/SceneState.hpp"
#include "../core/VolumeSpecs.hpp"
#include "CliSupport.hpp"
#include "Commands.hpp"

#include "host/AtomicFile.hpp"
#include "host/ElementRefinement.hpp"
#include "host/IsoSurfaceExtraction.hpp"
#include "host/SurfaceWriter.hpp"
#include "host/VtuWriter.hpp"

#include <QCommandLineParser>
#include <QFileInfo>

#include <cmath>
#include <cstdio>

namespace volpost::app {
int runConvert(const QStringList& args) {
  QCommandLineParser parser;
  parser.setApplicationDescription("Writes MODEL as a VTK XML unstructured grid (every field, every step).");
  parser.addPositionalArgument("MODEL", "mesh or results file");
  parser.addPositionalArgument("OUT.vtu", "file to write");
  const QCommandLineOption readerOption = readerOptionOption();
  const QCommandLineOption formula = formulaOption();
  const QCommandLineOption layout(
      "layout",
      "Where the arrays' bytes go: inline (default; base64 inside each array, read by every VTK and "
      "ParaView) or appended (one raw block after the XML: a quarter smaller and quicker, but VTK 9.2 "
      "and ParaView 5.11 cannot read it where the system's XML parser defers parsing, as Debian 12's does).",
      "LAYOUT", "inline");
  parser.addOptions({readerOption, formula, layout});
  if (const auto code = parseArguments(parser, "volpost convert", args)) return *code;
  const QStringList files = parser.positionalArguments();
  if (files.size() != 2 || !files[1].endsWith(".vtu", Qt::CaseInsensitive)) {
    printError("convert needs MODEL and OUT.vtu (volpost convert MODEL OUT.vtu)");
    return 2;
  }
  const QString layoutName = parser.value(layout);
  if (layoutName != "inline" && layoutName != "appended") {
    printError(QString("--layout %1: the layout is inline or appended").arg(layoutName));
    return 2;
  }
  const VtuLayout vtuLayout = layoutName == "appended" ? VtuLayout::Appended : VtuLayout::Inline;
  auto plugins = loadPluginsForCli();
  return exitCodeOf([&] {
    checkWritable(pathBytes(files[1]));  // before the reading, not after it
    const std::vector<FormulaSpec> formulas = formulasFrom(parser, formula);
    const auto model =
        plugins->readers().load(pathBytes(files[0]), readerOptionsFrom(parser, readerOption), terminalProgress("reading"));
    appendFormulas(*model, formulas);
    writeVtu(*model, pathBytes(files[1]), terminalProgress("writing"), vtuLayout);
    std::printf("%s: %zu nodes, %zu cells, %zu fields\n", qPrintable(files[1]), model->nodeCount(),
                model->cellCount(), model->fields.size());
    return 0;
  });
}

namespace {

// The boundary as it is stored (flat faces through the nodes), or with `ownShapes` in the
// cells' own shapes: a quadratic cell's faces curved through its midside nodes.
template <typename SaidHow>
int writeBoundary(const ModelSession& session, bool ownShapes, const RefinementLimits& limits, const QStringList& files,
                  const SaidHow& saidHow) {
  const Model& model = session.model();
  if (!ownShapes || !model.meshBuilt() || !hasNonlinearCells(model.mesh())) {
    if (ownShapes && !model.meshBuilt())
      std::fprintf(stderr,
                   "volpost: note: %s is a regular grid: its faces are flat, --interpolation element changes "
                   "nothing\n",
                   qPrintable(files[0]));
    saidHow(writeSurface(session.surface().mesh, session.surface().origin, pathBytes(files[1])));
    std::printf("%s: boundary, %zu triangles\n", qPrintable(files[1]), session.surface().mesh.n_faces());
    return 0;
  }
  const std::vector<double> noValues(model.mesh().nodeCount(), 0.0);
  const optics::ElementField shapes(model.mesh(), noValues, session.tetrahedra(), glm::dvec3(0.0));
  const RefinedSurface curved =
      refineBoundary(shapes, session.surface(), limits, terminalProgress("following the cells' shapes"));
  if (!curved.toleranceReached)
    std::fprintf(stderr,
                 "volpost: warning: the cells' faces are followed to %.2g of their size, not %.2g: the surface "
                 "has too many faces to refine further\n",
                 curved.deviation, limits.tolerance);
  saidHow(writeSurface(curved.surface.mesh, curved.surface.origin, pathBytes(files[1])));
  if (curved.level == 1)
    std::printf("%s: boundary in the cells' own shapes, %zu triangles (its faces are flat: drawn as they are)\n",
                qPrintable(files[1]), curved.surface.mesh.n_faces());
  else
    std::printf(
        "%s: boundary in the cells' own shapes, %zu triangles (each of the faces' triangles cut as finely as "
        "it needs, up to %d times along a side)\n",
        qPrintable(files[1]), curved.surface.mesh.n_faces(), curved.level);
  return 0;
}

}  // namespace

int runSurface(const QStringList& args) {
  QCommandLineParser parser;
  parser.setApplicationDescription(
      "Writes the boundary surface of MODEL, or an iso-surface of a quantity, as .obj, .ply, .stl or .off.");
  parser.addPositionalArgument("MODEL", "mesh or results file");
  parser.addPositionalArgument("OUT", "surface file (.obj, .ply, .stl, .off)");
  const QCommandLineOption field("field", "Quantity of the iso-surface: S.mises, U.magnitude, T ...", "Q");
  const QCommandLineOption iso("iso", "Iso-value (with --field): the surface where Q = VALUE.", "VALUE");
  const QCommandLineOption step("step", "Load case / time step, 1-based (default 1).", "K", "1");
  const QCommandLineOption readerOption = readerOptionOption();
  const QCommandLineOption formula = formulaOption();
  const QCommandLineOption interpolation(
      "interpolation",
      "Meshes: the shapes and field the surface follows. tetrahedra (default): the boundary's faces flat through "
      "their nodes, the level set linear on the tetrahedra each cell is split into; element: each cell's own shape "
      "functions, as the solver computed the field (trilinear in a hex8, quadratic in a tet10 or hex20): the "
      "boundary's curved faces and the level set followed to 1/1000 of the cell's size and of the values' range "
      "(a tenth of --element-tolerance).",
      "HOW");
  const QCommandLineOption elementTolerance(
      "element-tolerance",
      "With --interpolation element: the most a color channel of a picture of it may stray (default 0.01; 0: as "
      "finely as the limits allow; at least 1e-05 otherwise); the surface follows the cells' shapes and field to a "
      "tenth of it, as volpost render's surfaces do.",
      "E");
  parser.addOptions({field, iso, step, readerOption, formula, interpolation, elementTolerance});
  if (const auto code = parseArguments(parser, "volpost surface", args)) return *code;
  const QStringList files = parser.positionalArguments();
  if (files.size() != 2) {
    printError("surface needs MODEL and OUT (volpost surface MODEL OUT.obj [--field Q --iso VALUE])");
    return 2;
  }
  if (parser.isSet(field) != parser.isSet(iso)) {
    printError("--field and --iso go together (the iso-surface Q = VALUE)");
    return 2;
  }
  bool okIso = true;
  const double isoValue = parser.isSet(iso) ? parser.value(iso).toDouble(&okIso) : 0.0;
  if (!okIso || !std::isfinite(isoValue)) {  // Qt reads "nan" and "inf" as numbers
    printError(QString("--iso %1 is not a number").arg(parser.value(iso)));
    return 2;
  }
  const auto stepIndex = parseStep(parser, step);
  if (!stepIndex) return 2;
  const auto how = fieldInterpolationFromString(parser.value(interpolation).toStdString());
  if (parser.isSet(interpolation) && !how) {
    printError(
        QString("--interpolation %1 is not one of: %2").arg(parser.value(interpolation), kFieldInterpolationChoices));
    return 2;
  }
  bool ownField = how == FieldInterpolation::Element;
  RefinementLimits limits;
  if (parser.isSet(elementTolerance)) {
    bool isNumber = false;  // Qt reads "nan" and "inf" as numbers: the range refuses them
    const double e = parser.value(elementTolerance).toDouble(&isNumber);
    if (!isNumber) {
      printError(QString("--element-tolerance %1 is not a number").arg(parser.value(elementTolerance)));
      return 2;
    }
    if (!validElementTolerance(e)) {
      printError(QString("--element-tolerance %1: the tolerance of the cells' own field %2")
                     .arg(parser.value(elementTolerance), kElementToleranceRule));
      return 2;
    }
    if (!ownField) {
      printError("--element-tolerance applies to the cells' own field: add --interpolation element");
      return 2;
    }
    limits = limitsForElementTolerance(e);
  }
  auto plugins = loadPluginsForCli();
  const auto saidHow = [&](const SurfaceWriteResult& r) {
    const QString ext = QFileInfo(files[1]).suffix().toLower();
    if ((ext == "stl" || ext == "ply") && !r.binary)
      std::fprintf(stderr, "volpost: note: %s written as text: float32 (binary %s) would move the vertices of "
                           "this model (coordinates far from the origin)\n",
                   qPrintable(files[1]), qPrintable(ext.toUpper()));
  };
  return exitCodeOf([&] {
    checkWritable(pathBytes(files[1]));  // before the reading, not after it
    const auto session = loadWithFormulas(plugins->readers(), pathBytes(files[0]), parser, readerOption, formula);
    if (!parser.isSet(field)) return writeBoundary(*session, ownField, limits, files, saidHow);
    const Quantity q = session->findQuantity(parser.value(field).toStdString());
    const ScalarView view = session->evaluate(q, *stepIndex);
    if (view.location != FieldLocation::Node) {
      printError(QString("%1 is an element result (constant per cell): iso-surfaces need a nodal result").arg(parser.value(field)));
      return 1;
    }
    const Model& model = session->model();
    if (ownField && !model.meshBuilt()) {
      printError(QString("--interpolation element works on meshes; %1 is a regular grid, whose iso-surfaces are "
                         "found on six tetrahedra in each cell: leave the option out")
                     .arg(files[0]));
      return 2;
    }
    ownField = ownField && hasNonlinearCells(model.mesh());  // tet4 cells: their split is their own field
    std::vector<double> converted;
    const auto surface =
        !model.meshBuilt()  // a grid: its cells split on the fly, no tetrahedra built
            ? extractIsoSurface(*model.grid, view.values, isoValue, terminalProgress("extracting"))
            : ownField ? extractIsoSurface(optics::ElementField(model.mesh(), view.values.doubles(converted),
                                                                session->tetrahedra(), glm::dvec3(0.0)),
                                           isoValue, limits, terminalProgress("extracting"))
                       : extractIsoSurface(session->tetrahedra(), session->tetValues(view), isoValue,
                                           terminalProgress("extracting"));
    if (ownField && !surface.toleranceReached)
      std::fprintf(stderr,
                   "volpost: warning: the cells' own field is followed to %.2g of the values' range, not %.2g: "
                   "the cells crossed are too many or too curved to refine further\n",
                   surface.deviation, limits.tolerance);
    if (surface.mesh.n_faces() == 0)
      std::fprintf(stderr, "volpost: warning: %s = %g is outside the values [%g, %g]: the iso-surface is empty\n",
                   qPrintable(parser.value(field)), isoValue, view.range.min, view.range.max);
    saidHow(writeSurface(surface.mesh, surface.origin, pathBytes(files[1])));
    std::printf("%s: %s = %g, %zu triangles%s\n", qPrintable(files[1]), qPrintable(parser.value(field)), isoValue,
                surface.mesh.n_faces(),
                ownField ? qPrintable(QString(", the cells' own field (the split's tetrahedra cut %1 times along each "
                                              "edge)")
                                          .arg(surface.refinement))
                         : "");
    return 0;
  });
}

}  // namespace volpost::app

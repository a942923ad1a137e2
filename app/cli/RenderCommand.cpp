// SPDX-License-Identifier: MIT
// `volpost render MODEL --field Q -o out.png`: a picture with no window and no X server.
// The options (or a state file saved by the window) make a SceneState; the Scene draws it
// exactly as the window does.
#include "../core/AnimationFrames.hpp"
#include "../core/CameraSpec.hpp"
#include "../core/FloatImageFile.hpp"
#include "../core/PictureFile.hpp"
#include "../core/PluginRenderers.hpp"
#include "../core/Probe.hpp"
#include "../core/RefinedElementVolume.hpp"
#include "../core/SceneImage.hpp"
#include "../core/VolumeDefaults.hpp"
#include "../core/VolumeSpecs.hpp"
#include "CliSupport.hpp"
#include "Commands.hpp"
#include "StreamlineOptions.hpp"

#include "host/AtomicFile.hpp"
#include "host/TextFile.hpp"

#include <QCommandLineParser>
#include <QFileInfo>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>

namespace volpost::app {
namespace {

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

std::optional<DisplayRange> parseRange(const QString& text) {
  const int colon = text.indexOf(':', 1);  // skip a leading minus sign
  if (colon < 0) return std::nullopt;
  bool okA = false, okB = false;
  const DisplayRange r{text.left(colon).toDouble(&okA), text.mid(colon + 1).toDouble(&okB)};
  if (!okA || !okB || !std::isfinite(r.min) || !std::isfinite(r.max) || !(r.max > r.min)) return std::nullopt;
  return r;
}

struct Options {
  QCommandLineOption field{"field", "Quantity to color by: S.mises, U.magnitude, U.x, S.xx, S.p1, T ... "
                                    "(volpost info lists the fields). Default: plain surface.", "Q"};
  QCommandLineOption step{"step", "Load case / time step, 1-based (default 1).", "K"};
  QCommandLineOption camera{"camera", "View: iso, +x, -x, +y, -y, +z, -z; then az=DEG, el=DEG, zoom=F, "
                                      "ortho or persp, comma-separated (default iso).", "SPEC"};
  QCommandLineOption view{"view",
                          "A view saved in the state file under NAME (the window's View > Saved Views), "
                          "before --camera and --eye change it.",
                          "NAME"};
  QCommandLineOption eye{"eye", "Explicit camera: where the eye is (model coordinates; after --camera).", "X,Y,Z"};
  QCommandLineOption target{"target", "Explicit camera: the point looked at (default: the model's centre).", "X,Y,Z"};
  QCommandLineOption up{"up", "Explicit camera: the direction that is up in the picture.", "X,Y,Z"};
  QCommandLineOption viewAngle{"view-angle", "Angle of view across the picture's narrower side, degrees (default 30).",
                               "DEG"};
  QCommandLineOption size{"size", "Image size (default 800x600).", "WxH", "800x600"};
  QCommandLineOption colormap{"colormap",
                              "cool-warm (default), viridis, rainbow, grayscale, seismic, each also "
                              "NAME-reversed; also the colors of the default volume transfer function.",
                              "NAME"};
  QCommandLineOption bands{"bands",
                           "Discrete contour bands of equal width on the surface, sections and slices (12 "
                           "is the Abaqus default; 0: continuous colors).",
                           "N"};
  QCommandLineOption units{"units",
                           "Units of a field, shown after its name in the legend: FIELD=TEXT, e.g. S=MPa "
                           "(repeatable).",
                           "FIELD=TEXT"};
  QCommandLineOption legendTitle{"legend-title", "The legend's title for the shown result, instead of its name.",
                                 "TEXT"};
  QCommandLineOption legendNumbers{"legend-numbers",
                                   "How the legend writes numbers: auto[:DIGITS] (significant, "
                                   "default auto:4), fixed[:DIGITS] or scientific[:DIGITS].",
                                   "STYLE"};
  QCommandLineOption legendLabels{"legend-labels",
                                  "About how many values a continuous legend labels (2..20, default 6).", "N"};
  QCommandLineOption belowColor{"below-color",
                                "Values below the color range in this color (R,G,B each 0..1) instead "
                                "of the map's end color.",
                                "R,G,B"};
  QCommandLineOption aboveColor{"above-color", "Values above the color range in this color (R,G,B each 0..1).",
                                "R,G,B"};
  QCommandLineOption background{"background",
                                "Behind the model: R,G,B (each 0..1), #RRGGBB or a name such as white or black "
                                "(default a light gray); the words over the picture turn light on a dark one.",
                                "COLOR"};
  QCommandLineOption textScale{"text-scale",
                               "Words and numbers over the picture (legend, title, labels) this many times their "
                               "usual size, which follows the picture's height (0.25..8; default 1).",
                               "F"};
  QCommandLineOption transparent{"transparent",
                                 "A transparent background (a .png, .tif or .webp picture): the model over nothing, "
                                 "for a report's page; edges and see-through parts keep their partial cover."};
  QCommandLineOption glyphs{"glyphs",
                            "Glyphs at the nodes: arrows of a nodal vector field (U, velocity) or, for a "
                            "symmetric tensor field (S), three bars along its principal directions colored by "
                            "the principal values (tension and compression on either side of the map's middle).",
                            "FIELD"};
  QCommandLineOption glyphColor{"glyph-color", "Color the glyphs by this nodal quantity (default: their length).", "Q"};
  QCommandLineOption glyphScale{"glyph-scale",
                                "Model units per unit of the glyphs' field (with --glyph-fixed: the arrows' "
                                "length); default: the longest is 6% of the model's size.",
                                "F"};
  QCommandLineOption glyphFixed{"glyph-fixed", "Arrows all the same length: the direction only."};
  QCommandLineOption glyphEvery{"glyph-every",
                                "Glyphs at every K-th node (default: as many as keep them under 20,000).", "K"};
  QCommandLineOption glyphNodes{"glyph-nodes",
                                "surface (default: the nodes an opaque model shows) or all (inside too, for a "
                                "see-through surface or a clip).",
                                "WHICH"};
  QCommandLineOption stepText{"step-text",
                              "Write the shown result and its step (or time) under the title: each frame of "
                              "--all-steps says which step it is."};
  QCommandLineOption title{"title", "A line of text at the picture's top left (a report's caption).", "TEXT"};
  QCommandLineOption logScale{"log-scale",
                              "Colors by the value's logarithm, the legend in powers of ten (values of 0 and below "
                              "lie below the range, which then starts at the smallest positive value)."};
  QCommandLineOption ownRange{"no-symmetric",
                              "The values' own range even on a diverging map (by default a diverging map such as "
                              "cool-warm spans -M..M for values of both signs)."};
  QCommandLineOption symmetric{"symmetric",
                               "Widen the values' own color range to -M..M, M the larger of |min| and "
                               "|max|: zero in the middle of a diverging map."};
  QCommandLineOption range{"range", "Fixed color range MIN:MAX instead of the step's own, or all-steps: the range "
                                    "over every step (also the default transfer function's range).", "MIN:MAX"};
  QCommandLineOption noEdges{"no-edges", "Hide element edges on the surface."};
  QCommandLineOption noLegend{"no-legend", "Hide the color legend."};
  QCommandLineOption deform{"deform", "Draw the model deformed by a nodal vector field (a displacement) times a "
                                      "scale: FIELD (largest displacement 10 % of the model's size) or FIELD:SCALE.",
                             "FIELD[:SCALE]"};
  QCommandLineOption undeformed{"undeformed", "With --deform (or a deformed state): also the undeformed model's "
                                              "element edges, in gray (surface pictures)."};
  QCommandLineOption noTriad{"no-triad", "Hide the orientation axes in the lower left corner."};
  QCommandLineOption flat{"flat", "No shading on the surface: the color map's exact colors."};
  QCommandLineOption output{QStringList{"o", "output"}, "Output picture (.png; .jpg and others by extension).", "FILE"};
  // The renderers' own words and what they take are filled in from their traits
  // (describeRenderers), so the help names what is loaded.
  QCommandLineOption renderer{"renderer", "surface (default): the boundary colored by the result.", "NAME"};
  QCommandLineOption mode{"mode", QString("GPU volume integration: %1 (default linear: exact cuts at every control "
                                          "point).").arg(QString::fromStdString(integrationModeChoices())), "MODE"};
  QCommandLineOption tf{"tf", "Transfer function (volpost TF JSON) for volume rendering; default: a ramp of the "
                              "color map over the result's range.", "FILE"};
  QCommandLineOption tf2d{"tf2d", "Regular grids: a 2D transfer function instead of --tf.", "FILE"};
  QCommandLineOption clip{"clip", "Clip plane px,py,pz,nx,ny,nz keeping the side the normal points to "
                                  "(repeatable; the surface shows the cut face colored by the result).", "PLANE"};
  QCommandLineOption clipBox{"clip-box", "Keep the inside of the box xmin,xmax,ymin,ymax,zmin,zmax (the "
                                         "surface shows the cut faces).", "BOX"};
  QCommandLineOption iso{"iso", "Iso-surface VALUE[:r,g,b[:opacity]] (colors and opacity 0..1; repeatable, up to 8; "
                                "opaque surfaces in the surface view).", "ISO"};
  QCommandLineOption volumeEdges{"volume-edges", "Volume rendering: draw the boundary's element edges, which hide "
                                                 "what lies behind them."};
  QCommandLineOption samplingStep{"sampling-step", "Sampling mode's step in model units (default: a quarter of the "
                                                   "mean edge); on regular grids the step of the march or the slice "
                                                   "spacing of every mode (default: half the shortest grid spacing).",
                                  "H"};
  QCommandLineOption shading{"shading",
                             "Regular grids: light the volume's emission by the gradient, the light at the "
                             "eye."};
  QCommandLineOption termination{"termination", "Rays stop when the light left behind is below this fraction "
                                                "(default 0.002; 0: never).", "T"};
  QCommandLineOption interpolation{
      "interpolation",
      "Meshes: how node values vary inside a cell, in the volume, the boundary surface, sections, slices, "
      "iso-surfaces and streamlines. tetrahedra (default): linear on the tetrahedra each cell is split into, the "
      "faces flat; element: each cell's own shape functions, as the solver computed the field (trilinear in a hex8, "
      "quadratic in a tet10 or hex20), and the cells' own curved shapes.",
      "HOW"};
  QCommandLineOption elementTolerance{
      "element-tolerance",
      "With --interpolation element: the most each pixel's color or opacity (0..1) may differ from the exact "
      "picture of the cells' own field (default 0.01, a bound the pictures stay well under; 0: exact, slower; "
      "at least 1e-05 otherwise). Renderers that draw it exactly (reference) take no tolerance. The boundary, "
      "sections and iso-surfaces follow the cells' shapes and field to a tenth of it, and so does the volume of "
      "renderers that draw tetrahedra only (raycast, vicp: the cells are cut into pieces that small, an estimate "
      "rather than a bound on pixels; they cannot draw 0).",
      "E"};
  QCommandLineOption floatOut{"float", "Also write the volume's float image: FILE.npy (premultiplied RGBA) or "
                                       "FILE.pfm (RGB over the background).", "FILE"};
  QCommandLineOption threads{"threads", "Threads for the reference renderer (default: all cores).", "N"};
  QCommandLineOption state{"state", "Start from a state file saved by the window (File > Save State); other "
                                    "options change it. MODEL may then be left out.", "FILE"};
  QCommandLineOption saveState{"save-state", "Write the state of this picture, for the window (File > Open "
                                             "State) or a later render.", "FILE"};
  QCommandLineOption streamlines{"streamlines", "Draw streamlines of this vector field (with --seeds; see "
                                                "volpost streamlines --help for the integrator options).", "FIELD"};
  QCommandLineOption lineWidth{"line-width", "Streamline width in pixels (default 2).", "PX"};
  QCommandLineOption tubes{"tubes", "Streamlines as shaded tubes instead of lit lines."};
  QCommandLineOption tubeRadius{"tube-radius", "Tube radius, model units (default 0.3% of the model).", "R"};
  QCommandLineOption radiusByValue{"radius-by-value", "Tube radius grows with the value the lines are colored by."};
  QCommandLineOption arrows{"arrows", "Arrow glyphs along the streamlines, pointing downstream."};
  QCommandLineOption noSurface{"no-surface", "Hide the model's surface (streamlines, iso-surfaces show alone)."};
  QCommandLineOption surfaceOpacity{"surface-opacity", "See-through surface, 0..1 (streamlines show inside).", "A"};
  QCommandLineOption probe{"probe", "Mark a probed point, numbered, with the shown value there (repeatable).", "X,Y,Z"};
  QCommandLineOption markExtremes{"mark-extremes", "Mark where the shown quantity is smallest and largest."};
  QCommandLineOption measure{"measure",
                             "Draw the distance between two probes (their numbers, as --probe gives them in "
                             "order), and with three the angle at the second: --measure 1,2,3.",
                             "I,J[,K]"};
  QCommandLineOption threshold{"threshold",
                               "Draw only the cells whose Q lies in MIN..MAX (an element result by its own value, "
                               "a nodal one by all of the cell's nodes; see --threshold-nodes), in the surface, "
                               "the sections and the volume.",
                               "Q:MIN:MAX"};
  QCommandLineOption showSet{"show-set",
                             "Draw only this element set (an ELSET, a physical group, an element block; "
                             "repeatable; `volpost info` lists the sets).",
                             "NAME"};
  QCommandLineOption hideSet{"hide-set", "Do not draw this element set (repeatable).", "NAME"};
  QCommandLineOption markSet{"mark-set",
                             "Mark this set's nodes in the picture (a node set, or the nodes of an element "
                             "set's drawn elements).",
                             "NAME"};
  QCommandLineOption setNumbers{"set-numbers",
                                "Write the marked set's numbers beside it: node ids, or element ids at the "
                                "elements' centres (at most 300)."};
  QCommandLineOption selectElements{"select-elements",
                                    "Select these elements (the file's ids: 101,105-110): they become the set "
                                    "\"selected elements\", marked in the picture unless --mark-set names another.",
                                    "IDS"};
  QCommandLineOption selectNodes{"select-nodes",
                                 "Select these nodes (ids: 7,12-20): the set \"selected nodes\", marked as "
                                 "--select-elements is.",
                                 "IDS"};
  QCommandLineOption colorBySet{"color-by-set",
                                "Color each drawn element set plainly in a color of its own (the legend names "
                                "them) instead of by the result: the surface, sections and slices."};
  QCommandLineOption thresholdNodes{
      "threshold-nodes", "all (default: every node of a cell in the range) or any (one is enough).", "WHICH"};
  QCommandLineOption sweep{"deformation-sweep",
                           "N pictures (or one video, as --all-steps) of the deformed shape growing from the "
                           "undeformed model to the scale shown (--deform), for how a part moves.",
                           "N"};
  QCommandLineOption allSteps{"all-steps", "One picture per step of the result: OUT_001.png, OUT_002.png, ... "
                                           "or one video when OUT is .mp4, .mkv, .webm or .avi (colors span every "
                                           "step unless --range is given)."};
  QCommandLineOption framesBetween{"frames-between",
                                   "With --all-steps: N frames between each step and the next, the values and "
                                   "the deformed shape interpolated linearly (a smoother video).",
                                   "N"};
  QCommandLineOption readerOption = readerOptionOption();
  QCommandLineOption formula = formulaOption();
  QCommandLineOption slice{"slice",
                           "A slice drawn in the result's colors without cutting the model away: a plane "
                           "px,py,pz,nx,ny,nz on any model, or a regular grid's AXIS=VALUE, e.g. inline=1005, "
                           "crossline=2003, time=80 (ms), or i/j/k=LABEL for image data (repeatable); drawn in the "
                           "surface view and, opaque, in the volume.",
                           "PLANE|AXIS=VALUE"};
  QCommandLineOption representation{"representation",
                                    "How the model's boundary is drawn: surface (default), wireframe (element "
                                    "edges), points (nodes, in the result's colors), feature-edges (creases and "
                                    "borders) or outline (the bounding box).",
                                    "NAME"};
  QCommandLineOption pointSize{"point-size", "Points' size in pixels with --representation points (default 4).", "PX"};
  QCommandLineOption volumeOutline{"volume-outline",
                                   "Volume rendering: draw the model's feature edges (creases and borders) over the "
                                   "volume."};
  QCommandLineOption fps{"fps", "Frames (steps) per second of an --all-steps video (default 4).", "N"};
  StreamlineOptions lineOptions;
};

// --all-steps: the scene at each step of its result, one numbered picture each or one
// video, the colors over every step unless a range was given. Each path is printed when it
// is written (a video's once, at the end).
int renderEveryStep(Scene& scene, const QString& out, double framesPerSecond, bool rangeGiven, std::size_t between,
                    const std::function<SceneImage()>& draw) {
  if (!scene.view()) throw UsageError("--all-steps needs --field (the result whose steps to show)");
  const std::string quantity = scene.state().quantity;
  const std::size_t count = scene.session()->fieldOf(scene.view()->quantity).stepCount();
  if (!rangeGiven && !scene.state().fixedRange) scene.setRangeOverSteps(true);
  const std::size_t frames = count + (count - 1) * between;  // each step, and `between` after all but the last
  AnimationOutput output(out, frames, framesPerSecond);
  const auto printPath = [](const QString& path) {
    std::printf("%s\n", qPrintable(QFileInfo(path).absoluteFilePath()));
    std::fflush(stdout);
  };
  std::size_t frame = 0;
  for (std::size_t step = 0; step < count; ++step) {
    scene.setResult(quantity, step);
    for (std::size_t k = 0; k <= (step + 1 < count ? between : 0); ++k) {
      scene.setStepBlend(double(k) / double(between + 1));
      if (between == 0) std::fprintf(stderr, "volpost: step %zu of %zu\n", step + 1, count);
      else std::fprintf(stderr, "volpost: frame %zu of %zu (step %zu)\n", ++frame, frames, step + 1);
      const QString path = output.add(draw().picture);
      if (!output.isVideo()) printPath(path);
    }
  }
  const QString video = output.finish();
  if (output.isVideo()) printPath(video);
  return 0;
}

// --show-set / --hide-set, over the state file's choice.
void applySetOptions(const QCommandLineParser& p, const Options& o, Scene& scene) {
  if (p.isSet(o.selectElements) || p.isSet(o.selectNodes)) {
    Selection selection = scene.selection();
    const auto ids = [&](const QCommandLineOption& option, SetKind kind, std::vector<std::int64_t>& out) {
      if (!p.isSet(option)) return;
      try {
        out = idsInModel(p.value(option).toStdString(), *scene.baseSession(), kind);
      } catch (const std::invalid_argument& e) {
        throw std::invalid_argument("--" + option.names().front().toStdString() + " " + p.value(option).toStdString() +
                                    ": " + e.what());
      }
    };
    ids(o.selectElements, SetKind::Cells, selection.elements);
    ids(o.selectNodes, SetKind::Nodes, selection.nodes);
    scene.setSelection(selection);  // invalid_argument (an id the model lacks): a usage error
    if (!p.isSet(o.markSet)) {      // what was selected shows
      SetVisibility v = scene.setVisibility();
      v.marked = p.isSet(o.selectElements) ? kSelectedElements : kSelectedNodes;
      scene.setSetVisibility(v);
    }
  }
  if (!p.isSet(o.showSet) && !p.isSet(o.hideSet) && !p.isSet(o.markSet) && !p.isSet(o.setNumbers) &&
      !p.isSet(o.colorBySet))
    return;
  SetVisibility v = scene.setVisibility();
  const auto names = [&](const QCommandLineOption& option) {
    std::vector<std::string> out;
    for (const QString& name : p.values(option)) out.push_back(name.toStdString());
    return out;
  };
  if (p.isSet(o.showSet)) v.shown = names(o.showSet);
  if (p.isSet(o.hideSet)) v.hidden = names(o.hideSet);
  if (p.isSet(o.markSet)) v.marked = p.value(o.markSet).toStdString();
  if (p.isSet(o.setNumbers)) {
    if (v.marked.empty())
      throw std::invalid_argument("--set-numbers writes the marked set's numbers: add --mark-set NAME");
    v.numbers = true;
  }
  if (p.isSet(o.colorBySet)) v.colors = true;
  scene.setSetVisibility(v);  // invalid_argument (unknown set, a node set, nothing left): a usage error
  // Without a camera of the state's, the picture frames the sets drawn (a small part of a
  // large model was a speck in the whole model's frame).
  if ((p.isSet(o.showSet) || p.isSet(o.hideSet)) && !p.isSet(o.state)) scene.fitCamera();
}

// --threshold Q:MIN:MAX, over the state file's.
void applyThresholdOptions(const QCommandLineParser& p, const Options& o, Scene& scene) {
  if (!p.isSet(o.threshold) && !p.isSet(o.thresholdNodes)) return;
  ThresholdLayer t = scene.threshold();
  if (p.isSet(o.threshold)) {
    const QString text = p.value(o.threshold);
    const QStringList parts = text.split(':');
    bool okMin = false, okMax = false;
    if (parts.size() == 3) {
      t.quantity = parts[0].trimmed().toStdString();
      t.min = parts[1].toDouble(&okMin);
      t.max = parts[2].toDouble(&okMax);
    }
    if (parts.size() != 3 || t.quantity.empty() || !okMin || !okMax)
      throw UsageError(
          QString("--threshold %1 is not Q:MIN:MAX (for example S.mises:100:250)").arg(text).toStdString());
    t.shown = true;
  }
  if (!t.shown) throw UsageError("--threshold-nodes needs --threshold Q:MIN:MAX");
  if (p.isSet(o.thresholdNodes)) {
    const QString which = p.value(o.thresholdNodes);
    if (which != "all" && which != "any")
      throw UsageError(QString("--threshold-nodes %1 is not all or any").arg(which).toStdString());
    t.allNodes = which == "all";
  }
  scene.setThreshold(t);  // invalid_argument (unknown quantity, no cell kept): a usage error
}

// --glyphs FIELD and how they look, over the state file's glyphs.
void applyGlyphOptions(const QCommandLineParser& p, const Options& o, Scene& scene) {
  GlyphLayer g = scene.glyphLayer();
  if (p.isSet(o.glyphs)) {
    g.shown = true;
    g.field = p.value(o.glyphs).toStdString();
  }
  const bool styled = p.isSet(o.glyphColor) || p.isSet(o.glyphScale) || p.isSet(o.glyphFixed) ||
                      p.isSet(o.glyphEvery) || p.isSet(o.glyphNodes);
  if (!styled && !p.isSet(o.glyphs)) return;
  if (!g.shown) throw UsageError("glyph options need --glyphs FIELD (the vector or tensor field to draw)");
  if (p.isSet(o.glyphColor)) g.colorBy = p.value(o.glyphColor).toStdString();
  if (p.isSet(o.glyphFixed)) g.fixedLength = true;
  if (p.isSet(o.glyphScale)) {
    bool ok = false;
    g.scale = p.value(o.glyphScale).toDouble(&ok);
    if (!ok || !(*g.scale > 0.0) || !std::isfinite(*g.scale))
      throw UsageError(QString("--glyph-scale %1 is not a positive number").arg(p.value(o.glyphScale)).toStdString());
  }
  if (p.isSet(o.glyphEvery)) {
    bool ok = false;
    g.every = p.value(o.glyphEvery).toInt(&ok);
    if (!ok || g.every < 1)
      throw UsageError(
          QString("--glyph-every %1 is not a count of 1 or more").arg(p.value(o.glyphEvery)).toStdString());
  }
  if (p.isSet(o.glyphNodes)) {
    const QString which = p.value(o.glyphNodes);
    if (which != "surface" && which != "all")
      throw UsageError(QString("--glyph-nodes %1 is not surface or all").arg(which).toStdString());
    g.allNodes = which == "all";
  }
  scene.setGlyphs(g);  // invalid_argument (not a vector or tensor field, too many): a usage error
}

// --slice: AXIS=VALUE on a regular grid's axis, or a free plane px,py,pz,nx,ny,nz on any model.
void applySliceOptions(const QStringList& values, Scene& scene) {
  const auto& grid = scene.session()->model().grid;
  std::array<std::optional<double>, 3> labels = scene.state().gridSlices;
  std::vector<ClipPlane> planes = scene.state().slicePlanes;
  for (const QString& text : values) {
    if (!text.contains('=')) {
      const auto plane = parseClipPlane(text);
      if (!plane)
        throw UsageError(QString("--slice %1 is not a plane px,py,pz,nx,ny,nz with a non-zero normal%2")
                             .arg(text, grid ? " nor AXIS=VALUE" : "")
                             .toStdString());
      planes.push_back(*plane);
      continue;
    }
    if (!grid)
      throw UsageError(QString("--slice %1: AXIS=VALUE slices a regular grid (SEG-Y, image data, NRRD); this model is "
                               "a mesh: give the plane as px,py,pz,nx,ny,nz")
                           .arg(text)
                           .toStdString());
    const int a = gridAxisNamed(*grid, text.section('=', 0, 0).trimmed().toStdString());
    bool ok = false;
    const double value = text.section('=', 1).toDouble(&ok);
    if (a < 0 || !ok || !std::isfinite(value))
      throw UsageError(QString("--slice %1 is not AXIS=VALUE with AXIS one of %2, %3, %4 (or i, j, k)")
                           .arg(text, QString::fromStdString(grid->axisNames[0]),
                                QString::fromStdString(grid->axisNames[1]), QString::fromStdString(grid->axisNames[2]))
                           .toStdString());
    labels[std::size_t(a)] = value;
  }
  if (grid) scene.setGridSlices(labels);  // invalid_argument (outside the grid): a usage error
  scene.setSlicePlanes(planes);
}

// --deformation-sweep: the deformed shape from scale 0 to the scale shown, in `count`
// frames (pictures or one video); the caption names each frame's factor.
int renderDeformationSweep(Scene& scene, const QString& out, double framesPerSecond, std::size_t count,
                           const std::function<SceneImage()>& draw) {
  if (!scene.deformation().shown)
    throw UsageError("--deformation-sweep grows the deformed shape: add --deform FIELD[:SCALE]");
  const double full = scene.deformationScale();
  AnimationOutput output(out, count, framesPerSecond);
  for (std::size_t i = 0; i < count; ++i) {
    std::fprintf(stderr, "volpost: frame %zu of %zu\n", i + 1, count);
    DeformationLayer d = scene.deformation();
    d.scale = full * double(i) / double(count - 1);
    scene.setDeformation(d);
    const QString path = output.add(draw().picture);
    if (!output.isVideo()) std::printf("%s\n", qPrintable(QFileInfo(path).absoluteFilePath()));
  }
  const QString video = output.finish();
  if (output.isVideo()) std::printf("%s\n", qPrintable(QFileInfo(video).absoluteFilePath()));
  return 0;
}

// The state the options describe: a state file's, or the defaults, changed by every option
// that is set.
void applyResultOptions(const QCommandLineParser& p, const Options& o, Scene& scene) {
  std::string quantity = scene.state().quantity;
  std::size_t step = scene.state().step;
  if (p.isSet(o.field)) quantity = p.value(o.field).toStdString();
  if (p.isSet(o.step)) {
    bool ok = false;
    const int n = p.value(o.step).toInt(&ok);
    if (!ok || n < 1) throw UsageError(QString("--step %1 is not a step number (1, 2, ...)").arg(p.value(o.step)).toStdString());
    step = std::size_t(n - 1);
  }
  scene.setResult(quantity, step);
}

void applyVolumeOptions(const QCommandLineParser& p, const Options& o, Scene& scene) {
  if (p.isSet(o.mode)) {
    const auto mode = integrationModeFromString(p.value(o.mode).toStdString());
    if (!mode)
      throw UsageError(QString("--mode %1 is not one of: %2").arg(p.value(o.mode), QString::fromStdString(integrationModeChoices())).toStdString());
    scene.setIntegrationMode(*mode);
  }
  if (p.isSet(o.tf)) {
    const std::string path = pathBytes(p.value(o.tf));
    try {
      scene.setTransferFunction(TransferFunction::fromJson(readTextFile(path, 16u << 20)));
    } catch (const ReadError&) {
      throw;
    } catch (const std::exception& e) {
      throw std::runtime_error(path + ": " + e.what());
    }
  }
  if (p.isSet(o.tf2d)) {
    const std::string path = pathBytes(p.value(o.tf2d));
    try {
      scene.setTransferFunction2D(TransferFunction2D::fromJson(readTextFile(path, 16u << 20)));
    } catch (const ReadError&) {
      throw;
    } catch (const std::exception& e) {
      throw std::runtime_error(path + ": " + e.what());
    }
  }
  if (p.isSet(o.clip)) {
    std::vector<ClipPlane> planes;
    for (const QString& c : p.values(o.clip)) {
      const auto plane = parseClipPlane(c);
      if (!plane) throw UsageError(QString("--clip %1 is not px,py,pz,nx,ny,nz with a non-zero normal").arg(c).toStdString());
      planes.push_back(*plane);
    }
    scene.setClipPlanes(planes);
  }
  if (p.isSet(o.clipBox)) {
    const auto box = parseClipBox(p.value(o.clipBox));
    if (!box)
      throw UsageError(QString("--clip-box %1 is not xmin,xmax,ymin,ymax,zmin,zmax with min < max").arg(p.value(o.clipBox)).toStdString());
    scene.setClipBox(*box);
  }
  if (p.isSet(o.iso)) {
    std::vector<optics::IsoSurface> surfaces;
    for (const QString& text : p.values(o.iso)) {
      const auto iso = parseIsoSurface(text);
      if (!iso) throw UsageError(QString("--iso %1 is not VALUE[:r,g,b[:opacity]] with colors and opacity in 0..1").arg(text).toStdString());
      surfaces.push_back(*iso);
    }
    scene.setIsoSurfaces(surfaces);
  }
  if (p.isSet(o.volumeEdges)) scene.setVolumeEdges(true);
  if (p.isSet(o.volumeOutline)) scene.setVolumeOutline(true);
  const auto number = [&](const QCommandLineOption& option, const char* name) {
    bool ok = false;
    const double v = p.value(option).toDouble(&ok);
    if (!ok || !std::isfinite(v)) throw UsageError(QString("--%1 %2 is not a number").arg(name, p.value(option)).toStdString());
    return v;
  };
  if (p.isSet(o.samplingStep)) scene.setSamplingStep(number(o.samplingStep, "sampling-step"));
  if (p.isSet(o.termination)) scene.setTermination(number(o.termination, "termination"));
  if (p.isSet(o.shading)) scene.setShading(true);
  if (p.isSet(o.interpolation)) {
    const auto interpolation = fieldInterpolationFromString(p.value(o.interpolation).toStdString());
    if (!interpolation)
      throw UsageError(QString("--interpolation %1 is not one of: %2")
                           .arg(p.value(o.interpolation), kFieldInterpolationChoices)
                           .toStdString());
    scene.setInterpolation(*interpolation);
  }
  if (p.isSet(o.elementTolerance)) scene.setElementTolerance(number(o.elementTolerance, "element-tolerance"));
}

// The renderer a picture is drawn with: the surface (no entry) or a volume renderer.
struct ChosenRenderer {
  QString name;
  std::optional<RendererEntry> volume;  ///< nullopt: the surface picture
  std::vector<RendererEntry> all;       ///< every volume renderer, for messages
  /// "texture-raymarch, texture-slices, cpu, reference": the renderers `has` is true for.
  QString namesWhere(bool (*has)(const RendererEntry&)) const { return rendererNamesWhere(all, has); }
};

// Every volume renderer loaded and the exact reference, in menu order.
std::vector<RendererEntry> allVolumeRenderers(const PluginManager& plugins) {
  std::vector<RendererEntry> all = volumeRenderers(plugins);
  all.push_back(referenceRenderer());
  return all;
}

// --renderer lists each renderer in its own words; --shading, --tf2d and --sampling-step
// name the renderers that take them.
void describeRenderers(Options& o, const std::vector<RendererEntry>& all) {
  QString renderers = "surface (default): the boundary colored by the result";
  for (const RendererEntry& r : all)
    renderers += QString("; %1: %2").arg(r.name, QString::fromStdString(r.traits.label));
  o.renderer.setDescription(renderers + " (volpost plugins lists the plugins that offer them).");
  const auto drawnBy = [&](bool (*has)(const RendererEntry&)) {
    const QString names = rendererNamesWhere(all, has);
    return names.isEmpty() ? QString(" (no renderer loaded draws it)") : " (drawn by " + names + ")";
  };
  o.shading.setDescription("Regular grids: light the volume's emission by the gradient, the light at the eye" +
                           drawnBy([](const RendererEntry& r) { return r.traits.shading; }) + ".");
  o.tf2d.setDescription(
      "Regular grids: a 2D transfer function over the value and its gradient magnitude "
      "(volpost-tf2d JSON: rectangles and triangles), instead of --tf" +
      drawnBy([](const RendererEntry& r) { return r.traits.transferFunction2D; }) + ".");
}

// The renderer `name` (from --renderer or the state file), or a usage error listing them.
ChosenRenderer chooseRenderer(const PluginManager& plugins, const QString& name, const QCommandLineParser& p,
                              const Options& o) {
  ChosenRenderer chosen{name, std::nullopt, allVolumeRenderers(plugins)};
  if (name == "surface") return chosen;
  for (const RendererEntry& r : chosen.all)
    if (r.name == name) chosen.volume = r;
  if (chosen.volume) return chosen;
  const QString known = "surface, " + chosen.namesWhere([](const RendererEntry&) { return true; });
  if (p.isSet(o.renderer)) throw UsageError(QString("--renderer %1 is not one of: %2").arg(name, known).toStdString());
  throw UsageError(QString("%1: \"volume\": {\"renderer\": \"%2\"} names no volume renderer; the renderers are: %3")
                       .arg(p.value(o.state), name, known)
                       .toStdString());
}

// Options a chosen renderer cannot honour are errors, never silently ignored; what each
// renderer honours is what it says of itself (its traits).
void refuseWhatTheRendererIgnores(const QCommandLineParser& p, const Options& o, const ChosenRenderer& chosen) {
  const auto refuse = [&](const QCommandLineOption& option, const QString& why) {
    if (p.isSet(option)) throw UsageError(QString("--%1 %2").arg(option.names().constLast(), why).toStdString());
  };
  if (!chosen.volume) {
    const QString why =
        "works with volume renderers (--renderer " + chosen.namesWhere([](const RendererEntry&) { return true; }) + ")";
    for (const QCommandLineOption* option : {&o.mode, &o.tf, &o.tf2d, &o.volumeEdges, &o.volumeOutline, &o.samplingStep,
                                             &o.termination, &o.shading, &o.floatOut, &o.threads})
      refuse(*option, why);
    // The surface picture's boundary, sections, slices, iso-surfaces and streamlines
    // follow the interpolation, and its boundary, sections and iso-surfaces the element
    // tolerance.
    return;
  }
  refuse(o.noEdges, "hides the surface's edges; volume pictures have none unless --volume-edges asks");
  refuse(o.bands, "bands the surface's colors; a volume's colors come from its transfer function");
  refuse(o.logScale, "colors the surface by the logarithm; a volume's colors come from its transfer function");
  refuse(o.belowColor,
         "colors the surface's values below the range; a volume's colors come from its transfer function");
  refuse(o.aboveColor,
         "colors the surface's values above the range; a volume's colors come from its transfer function");
  refuse(o.flat, "turns the surface's shading off; volume pictures have no surface");
  refuse(o.representation,
         "chooses how the surface is drawn; volume pictures have no surface (--volume-outline "
         "draws the model's feature edges over a volume)");
  refuse(o.pointSize, "sizes the surface's points; volume pictures have no surface");
  refuse(o.undeformed, "is drawn in surface pictures only, not with a volume renderer");
  const RendererEntry& r = *chosen.volume;
  const VolumeRendererTraits& t = r.traits;
  const QString name = r.name;
  if (!r.takesThreadCount)
    refuse(o.threads, "sets the threads of " + chosen.namesWhere([](const RendererEntry& e) {
      return e.takesThreadCount;
    }) + ", not of " + name);
  if (!t.shading)
    refuse(o.shading, "is drawn by the regular-grid renderers that shade (" +
                          chosen.namesWhere([](const RendererEntry& e) { return e.traits.shading; }) + "), not by " +
                          name);
  if (!t.transferFunction2D)
    refuse(o.tf2d, "is drawn by the regular-grid renderers that take it (" +
                       chosen.namesWhere([](const RendererEntry& e) { return e.traits.transferFunction2D; }) +
                       "), not by " + name);
  if (t.modes.empty())
    refuse(o.mode, "chooses how the transfer function is integrated; " + name + " integrates exactly (no modes)");
  if (p.isSet(o.mode))
    if (const auto mode = integrationModeFromString(p.value(o.mode).toStdString());
        mode && std::find(t.modes.begin(), t.modes.end(), *mode) == t.modes.end())
      refuse(o.mode, p.value(o.mode) + " is not a mode of " + name);
  if (!r.drawsSceneLayers) refuse(o.volumeEdges, "is not drawn by " + name + ", which draws the volume alone");
  if (!r.drawsSceneLayers) refuse(o.volumeOutline, "is not drawn by " + name + ", which draws the volume alone");
  if (!r.drawsSceneLayers) refuse(o.glyphs, "are not drawn by " + name + ", which draws the volume alone");
  if (!t.samplingStepOnMeshes && !t.samplingStepOnGrids)
    refuse(o.samplingStep, "is not used by " + name + " (it integrates exactly)");
  if (!t.earlyTermination) refuse(o.termination, "is not used by " + name + " (it never stops early)");
  if (!t.elementTolerance && t.elementInterpolation)
    refuse(o.elementTolerance, "is not used by " + name + " (it draws the cells' own field exactly)");
  if (p.isSet(o.tf2d) && p.isSet(o.tf))
    throw UsageError("--tf and --tf2d: a volume is drawn with one transfer function; give one");
  if (p.isSet(o.tf2d) && (p.isSet(o.colormap) || p.isSet(o.range)))
    throw UsageError("--colormap and --range color the default transfer function; with --tf2d the file's widgets "
                     "give the colors: leave them out");
  if (p.isSet(o.tf) && (p.isSet(o.colormap) || p.isSet(o.range)))
    throw UsageError("--colormap and --range color the default transfer function; with --tf the file's colors "
                     "and values are used: leave them out");
}

// A renderer that draws the volume alone (the reference, with the legend and markers over
// it) refuses the layers of the state drawn with GL, from the command line or a state file.
void refuseLayersTheRendererCannotDraw(const SceneState& state, const ChosenRenderer& chosen) {
  if (!chosen.volume) return;
  const QString name = chosen.volume->name;
  if (state.volume.interpolation == FieldInterpolation::Element && !chosen.volume->traits.elementInterpolation &&
      !chosen.volume->drawsSceneLayers)
    throw UsageError(
        ("the cells' own interpolation (--interpolation element, or \"volume.interpolation\" in a state "
         "file) is drawn by " +
         chosen.namesWhere([](const RendererEntry& e) { return e.traits.elementInterpolation || e.drawsSceneLayers; }) +
         ", not by " + name + ": choose one of those, or --interpolation tetrahedra")
            .toStdString());
  if (chosen.volume->drawsSceneLayers) return;
  const bool slices =
      std::any_of(state.gridSlices.begin(), state.gridSlices.end(), [](const auto& s) { return bool(s); });
  if (!state.slicePlanes.empty())
    throw UsageError(("slices (--slice, or \"slicePlanes\" in a state file) are not drawn by " + name +
                      ", which draws the volume alone: choose " + chosen.namesWhere([](const RendererEntry& e) {
                        return e.drawsSceneLayers;
                      })).toStdString());
  if (state.glyphs.shown)
    throw UsageError(("glyphs (--glyphs, or \"glyphs\" in a state file) are not drawn by " + name +
                      ", which draws the volume alone: choose " + chosen.namesWhere([](const RendererEntry& e) {
                        return e.drawsSceneLayers;
                      })).toStdString());
  if (state.volume.outline)
    throw UsageError(("the model's outline over the volume (--volume-outline, or \"volume.outline\" in a state "
                      "file) is not drawn by " +
                      name + ", which draws the volume alone: choose " + chosen.namesWhere([](const RendererEntry& e) {
                        return e.drawsSceneLayers;
                      })).toStdString());
  if (slices)
    throw UsageError(("grid slices (--slice, or \"gridSlices\" in a state file) are not drawn by " + name +
                      ", which draws the volume alone: choose " + chosen.namesWhere([](const RendererEntry& e) {
                        return e.drawsSceneLayers && e.traits.drawsGrids;
                      })).toStdString());
  if (state.streamlines.shown)
    throw UsageError(("streamlines (--streamlines, or \"streamlines\" in a state file) are not drawn by " + name +
                      ", which draws the volume alone: choose " + chosen.namesWhere([](const RendererEntry& e) {
                        return e.drawsSceneLayers && e.traits.drawsMeshes;
                      })).toStdString());
}

// The model is known: options this renderer takes on one kind of model but not the other.
void refuseWhatTheRendererIgnoresOnThisModel(const QCommandLineParser& p, const Options& o,
                                             const ChosenRenderer& chosen, bool grid) {
  // A mesh's boundary follows the interpolation; a regular grid's flat faces do not.
  if (!chosen.volume && grid && p.isSet(o.interpolation) && !p.isSet(o.clip) && !p.isSet(o.clipBox) &&
      !p.isSet(o.iso) && !p.isSet(o.slice) && !p.isSet(o.streamlines) && !p.isSet(o.state))
    throw UsageError(
        "--interpolation changes a mesh's surface, its sections, slices, iso-surfaces and streamlines, "
        "or a volume; this model is a regular grid, whose surface picture it does not change");
  if (!chosen.volume || !p.isSet(o.samplingStep)) return;
  const VolumeRendererTraits& t = chosen.volume->traits;
  if (!grid && !t.samplingStepOnMeshes)
    throw UsageError(("--sampling-step is not used by " + chosen.volume->name +
                      " on meshes (it integrates exactly); on regular grids it sets the step of its march")
                         .toStdString());
  if (grid && !t.samplingStepOnGrids)
    throw UsageError(("--sampling-step is not used by " + chosen.volume->name + " on regular grids").toStdString());
}

// --eye, --target, --up, --view-angle: each replaces that part of the camera so far (the
// state file's, --camera's or the default view).
void applyExplicitCamera(const QCommandLineParser& p, const Options& o, Camera& camera) {
  const auto point = [&](const QCommandLineOption& option, glm::dvec3 fallback) {
    if (!p.isSet(option)) return fallback;
    const auto v = parsePoint(p.value(option));
    if (!v) throw UsageError(QString("--%1 %2 is not X,Y,Z").arg(option.names().first(), p.value(option)).toStdString());
    return *v;
  };
  if (p.isSet(o.viewAngle)) {
    bool ok = false;
    const double degrees = p.value(o.viewAngle).toDouble(&ok);
    if (!ok || !(degrees > 0.0 && degrees < 180.0))
      throw UsageError(QString("--view-angle %1 is not an angle between 0 and 180 degrees").arg(p.value(o.viewAngle)).toStdString());
    camera.setFieldOfView(degrees);
  }
  if (!p.isSet(o.eye) && !p.isSet(o.target) && !p.isSet(o.up)) return;
  const glm::dvec3 target = point(o.target, camera.target());
  const glm::dvec3 eye = point(o.eye, target - camera.viewDirection() * glm::length(camera.eye() - camera.target()));
  camera.lookAt(eye, target, point(o.up, camera.up()));  // invalid_argument (eye at target, up along view): usage
}

void applyOptions(const QCommandLineParser& p, const Options& o, const SceneState& base, Scene& scene) {
  if (p.isSet(o.state)) scene.applyState(base);
  else if (!base.formulas.empty()) scene.setFormulas(base.formulas);
  applyResultOptions(p, o, scene);
  applySetOptions(p, o, scene);  // before the camera options: they frame what is drawn
  if (p.isSet(o.colormap)) scene.setColorMap(p.value(o.colormap).toStdString());
  if (p.isSet(o.range) && p.value(o.range) == "all-steps") {
    scene.setRangeOverSteps(true);
  } else if (p.isSet(o.range)) {
    const auto r = parseRange(p.value(o.range));
    if (!r) throw UsageError(QString("--range %1 is not MIN:MAX with finite MIN < MAX, nor all-steps").arg(p.value(o.range)).toStdString());
    scene.setFixedRange(*r);
  }
  if (p.isSet(o.logScale)) {
    if (p.isSet(o.symmetric)) throw UsageError("--log-scale and --symmetric: a log scale has no zero to center");
    scene.setLogScale(true);  // invalid_argument (a typed range not above 0): a usage error
  }
  if (p.isSet(o.ownRange)) {
    if (p.isSet(o.symmetric)) throw UsageError("--symmetric and --no-symmetric: give one");
    scene.setSymmetricRange(false);
  }
  if (p.isSet(o.symmetric)) {
    if (p.isSet(o.range) && p.value(o.range) != "all-steps")
      throw UsageError("--symmetric widens the values' own range; a typed --range is used as it is");
    scene.setSymmetricRange(true);
  }
  if (p.isSet(o.bands)) {
    bool ok = false;
    const int n = p.value(o.bands).toInt(&ok);
    if (!ok || n < 0 || n == 1 || n > kMaxColorBands)
      throw UsageError(QString("--bands %1 is not 0 (continuous) or a count from 2 to %2")
                           .arg(p.value(o.bands))
                           .arg(kMaxColorBands)
                           .toStdString());
    scene.setColorBands(n);
  }
  for (const QString& text : p.values(o.units)) {
    const qsizetype eq = text.indexOf('=');
    if (eq <= 0) throw UsageError(QString("--units %1 is not FIELD=TEXT (S=MPa)").arg(text).toStdString());
    const std::string field = text.left(eq).toStdString();
    if (!scene.session()->model().findField(field))
      throw UsageError(QString("--units %1: the model has no field named %2").arg(text, text.left(eq)).toStdString());
    scene.setUnits(field, text.mid(eq + 1).toStdString());
  }
  if (p.isSet(o.legendTitle)) {
    if (!scene.view()) throw UsageError("--legend-title names the shown result's legend; give --field");
    scene.setLegendTitle(scene.view()->quantity.key(), p.value(o.legendTitle).toStdString());
  }
  if (p.isSet(o.belowColor) || p.isSet(o.aboveColor)) {
    const auto colorOf = [&](const QCommandLineOption& option) -> std::optional<glm::dvec3> {
      if (!p.isSet(option)) return std::nullopt;
      const auto c = parseColor(p.value(option));
      if (!c)
        throw UsageError(QString("--%1 %2 is not a color: R,G,B with each from 0 to 1, #RRGGBB or a name")
                             .arg(option.names().first(), p.value(option))
                             .toStdString());
      return c;
    };
    scene.setOutOfRangeColors(colorOf(o.belowColor), colorOf(o.aboveColor));
  }
  if (p.isSet(o.title)) scene.setTitle(p.value(o.title).toStdString());
  if (p.isSet(o.stepText)) {
    if (!scene.view()) throw UsageError("--step-text writes the shown result's step: add --field Q");
    scene.setStepText(true);
  }
  if (p.isSet(o.background)) {
    const auto c = parseColor(p.value(o.background));
    if (!c)
      throw UsageError(QString("--background %1 is not a color: R,G,B with each from 0 to 1, #RRGGBB or a name")
                           .arg(p.value(o.background))
                           .toStdString());
    scene.setBackground(*c);
  }
  if (p.isSet(o.textScale)) {
    bool ok = false;
    const double scale = p.value(o.textScale).toDouble(&ok);
    if (!ok || !(scale >= kMinTextScale && scale <= kMaxTextScale))
      throw UsageError(
          QString("--text-scale %1 is not a factor from 0.25 to 8").arg(p.value(o.textScale)).toStdString());
    scene.setTextScale(scale);
  }
  if (p.isSet(o.legendNumbers)) scene.setLegendNumbers(p.value(o.legendNumbers).toStdString());
  if (p.isSet(o.legendLabels)) {
    bool ok = false;
    const int n = p.value(o.legendLabels).toInt(&ok);
    if (!ok) throw UsageError(QString("--legend-labels %1 is not a count").arg(p.value(o.legendLabels)).toStdString());
    scene.setLegendLabels(n);
  }
  if (p.isSet(o.noEdges)) scene.setShowEdges(false);
  if (p.isSet(o.noLegend)) scene.setShowLegend(false);
  if (p.isSet(o.noTriad)) scene.setShowTriad(false);
  if (p.isSet(o.slice)) applySliceOptions(p.values(o.slice), scene);
  if (p.isSet(o.deform)) {
    const QString text = p.value(o.deform);
    DeformationLayer d;
    d.shown = true;
    d.field = text.section(':', 0, 0).toStdString();
    if (text.contains(':')) {
      bool ok = false;
      d.scale = text.section(':', 1).toDouble(&ok);
      if (!ok || !std::isfinite(*d.scale))
        throw UsageError(QString("--deform %1: the scale after ':' is not a number").arg(text).toStdString());
    }
    scene.setDeformation(d);  // invalid_argument (not a nodal vector field): a usage error
  }
  if (p.isSet(o.flat)) scene.setLighting(false);
  if (p.isSet(o.view)) {
    if (p.isSet(o.camera)) throw UsageError("--view and --camera both choose the view: give one");
    scene.showView(p.value(o.view).toStdString());  // invalid_argument naming the saved views: a usage error
  }
  if (p.isSet(o.camera)) {
    scene.camera().setView(StandardView::Isometric);
    scene.fitCamera();
    applyCameraSpec(scene.camera(), p.value(o.camera).toStdString());  // invalid_argument: a usage error
  }
  applyExplicitCamera(p, o, scene.camera());
  applyVolumeOptions(p, o, scene);
  if (p.isSet(o.undeformed)) {
    if (!scene.deformation().shown) throw UsageError("--undeformed draws the undeformed outline of a deformed shape: add --deform FIELD");
    DeformationLayer d = scene.deformation();
    d.undeformedOutline = true;
    scene.setDeformation(d);
  }
  if (p.isSet(o.noSurface)) scene.setSurfaceShown(false);
  if (p.isSet(o.representation)) {
    const auto r = surfaceRepresentationFromString(p.value(o.representation).toStdString());
    if (!r)
      throw UsageError(QString("--representation %1 is not one of: %2")
                           .arg(p.value(o.representation), QString::fromStdString(surfaceRepresentationChoices()))
                           .toStdString());
    scene.setRepresentation(*r);
  }
  if (p.isSet(o.pointSize)) {
    bool ok = false;
    const double px = p.value(o.pointSize).toDouble(&ok);
    if (!ok || !(px >= 1.0 && px <= kMaxPointSize))
      throw UsageError(
          QString("--point-size %1 is not a size from 1 to 64 pixels").arg(p.value(o.pointSize)).toStdString());
    if (scene.shown().representation != SurfaceRepresentation::Points)
      throw UsageError("--point-size sizes the points of --representation points");
    scene.setPointSize(px);
  }
  if (p.isSet(o.surfaceOpacity)) {
    bool ok = false;
    const double a = p.value(o.surfaceOpacity).toDouble(&ok);
    if (!ok) throw UsageError(QString("--surface-opacity %1 is not a number").arg(p.value(o.surfaceOpacity)).toStdString());
    scene.setSurfaceOpacity(a);
  }
  StreamlineLayer lines = scene.streamlines();
  if (p.isSet(o.streamlines)) {
    lines.shown = true;
    lines.field = p.value(o.streamlines).toStdString();
  }
  o.lineOptions.apply(p, lines);
  if (p.isSet(o.lineWidth)) {
    bool ok = false;
    const double w = p.value(o.lineWidth).toDouble(&ok);
    if (!ok || !(w >= 1.0 && w <= 64.0))
      throw UsageError(QString("--line-width %1 is not a width from 1 to 64 pixels").arg(p.value(o.lineWidth)).toStdString());
    lines.style.width = float(w);
  }
  if (p.isSet(o.tubes)) lines.style.tubes = true;
  if (p.isSet(o.tubeRadius)) {
    bool ok = false;
    lines.style.tubeRadius = p.value(o.tubeRadius).toDouble(&ok);
    if (!ok || !(lines.style.tubeRadius > 0.0) || !std::isfinite(lines.style.tubeRadius))
      throw UsageError(QString("--tube-radius %1 is not a positive length").arg(p.value(o.tubeRadius)).toStdString());
  }
  if (p.isSet(o.radiusByValue)) lines.style.radiusByValue = true;
  if (p.isSet(o.arrows)) lines.style.arrows = true;
  const bool styled = p.isSet(o.lineWidth) || p.isSet(o.tubes) || p.isSet(o.tubeRadius) || p.isSet(o.radiusByValue) ||
                      p.isSet(o.arrows) || p.isSet(o.lineOptions.seeds) || p.isSet(o.lineOptions.integrator);
  if (styled && !lines.shown)
    throw UsageError("streamline options need --streamlines FIELD (the vector field to follow)");
  if (lines.shown && lines.seeds.empty()) throw UsageError("--streamlines needs --seeds (where the lines start)");
  scene.setStreamlines(lines);
  applyThresholdOptions(p, o, scene);
  applyGlyphOptions(p, o, scene);
  if (p.isSet(o.probe)) {
    std::vector<glm::dvec3> points;
    for (const QString& text : p.values(o.probe)) {
      const auto point = parsePoint(text);
      if (!point) throw UsageError(QString("--probe %1 is not X,Y,Z").arg(text).toStdString());
      points.push_back(*point);
    }
    scene.setProbes(points);
  }
  if (p.isSet(o.measure)) {
    std::vector<std::size_t> numbers;
    for (const QString& part : p.value(o.measure).split(',')) {
      bool ok = false;
      const int n = part.trimmed().toInt(&ok);
      if (!ok || n < 1)
        throw UsageError(QString("--measure %1 is not probe numbers I,J[,K]").arg(p.value(o.measure)).toStdString());
      numbers.push_back(std::size_t(n - 1));
    }
    scene.setMeasure(numbers);  // invalid_argument (a count other than 2 or 3, a missing probe): a usage error
  }
  if (p.isSet(o.markExtremes)) {
    if (!scene.view()) throw UsageError("--mark-extremes needs --field (the quantity whose min and max to mark)");
    scene.setMarkExtremes(true);
  }
}

}  // namespace

int runRender(const QStringList& args) {
  QCommandLineParser parser;
  parser.setApplicationDescription("volpost render: draws MODEL headless (EGL) as the window would, to a picture.");
  parser.addPositionalArgument("MODEL", "mesh or results file (optional with --state)");
  auto plugins = loadPluginsForCli();
  Options o;
  describeRenderers(o, allVolumeRenderers(*plugins));
  parser.addOptions({o.field,
                     o.step,
                     o.camera,
                     o.view,
                     o.eye,
                     o.target,
                     o.up,
                     o.viewAngle,
                     o.size,
                     o.colormap,
                     o.range,
                     o.bands,
                     o.symmetric,
                     o.ownRange,
                     o.noEdges,
                     o.noLegend,
                     o.noTriad,
                     o.deform,
                     o.undeformed,
                     o.flat,
                     o.output,
                     o.renderer,
                     o.mode,
                     o.tf,
                     o.tf2d,
                     o.clip,
                     o.clipBox,
                     o.iso,
                     o.volumeEdges,
                     o.samplingStep,
                     o.termination,
                     o.shading,
                     o.interpolation,
                     o.elementTolerance,
                     o.floatOut,
                     o.threads,
                     o.state,
                     o.saveState,
                     o.streamlines,
                     o.lineWidth,
                     o.tubes,
                     o.tubeRadius,
                     o.radiusByValue,
                     o.arrows,
                     o.noSurface,
                     o.surfaceOpacity,
                     o.probe,
                     o.markExtremes,
                     o.allSteps,
                     o.framesBetween,
                     o.fps,
                     o.readerOption,
                     o.slice,
                     o.representation,
                     o.pointSize,
                     o.volumeOutline,
                     o.background,
                     o.textScale,
                     o.transparent,
                     o.formula,
                     o.units,
                     o.legendTitle,
                     o.legendNumbers,
                     o.legendLabels,
                     o.belowColor,
                     o.aboveColor,
                     o.title,
                     o.glyphs,
                     o.glyphColor,
                     o.glyphScale,
                     o.glyphFixed,
                     o.glyphEvery,
                     o.glyphNodes,
                     o.sweep,
                     o.threshold,
                     o.thresholdNodes,
                     o.showSet,
                     o.markSet,
                     o.measure,
                     o.setNumbers,
                     o.colorBySet,
                     o.selectElements,
                     o.selectNodes,
                     o.hideSet,
                     o.logScale,
                     o.stepText});
  for (const auto& option : o.lineOptions.all()) parser.addOption(option);
  if (const auto code = parseArguments(parser, "volpost render", args)) return *code;
  try {
    const QStringList positional = parser.positionalArguments();
    if (positional.size() > 1 || (positional.isEmpty() && !parser.isSet(o.state)))
      throw UsageError("render needs one MODEL file, or --state FILE (volpost render MODEL -o out.png)");
    if (!parser.isSet(o.output)) throw UsageError("render needs an output file: -o out.png");
    int width = 0, height = 0;
    if (!parseSize(parser.value(o.size), width, height))
      throw UsageError(QString("--size %1 is not WIDTHxHEIGHT within 1..16384").arg(parser.value(o.size)).toStdString());
    const QString out = parser.value(o.output);
    const bool video = VideoFile::isVideoPath(out);
    const bool animated = parser.isSet(o.allSteps) || parser.isSet(o.sweep);
    if (parser.isSet(o.allSteps) && parser.isSet(o.sweep))
      throw UsageError("--all-steps and --deformation-sweep each make an animation: give one");
    if (video && !animated)
      throw UsageError(QString("-o %1 is a video: it needs --all-steps (one frame per step) or --deformation-sweep N; "
                               "a single picture is .png or .jpg")
                           .arg(out)
                           .toStdString());
    int sweepFrames = 0;
    if (parser.isSet(o.sweep)) {
      bool ok = false;
      sweepFrames = parser.value(o.sweep).toInt(&ok);
      if (!ok || sweepFrames < 2 || sweepFrames > 10000)
        throw UsageError(QString("--deformation-sweep %1 is not a frame count of 2 to 10000")
                             .arg(parser.value(o.sweep))
                             .toStdString());
    }
    if (!video) try {
        pictureFormatOf(out);
      } catch (const std::invalid_argument& e) {
        throw UsageError(QString("-o %1 (or a video: .%2 with --all-steps)")
                             .arg(e.what(), VideoFile::extensions().join(", .")).toStdString());
      }
    if (parser.isSet(o.transparent) && (video || !formatKeepsTransparency(out)))
      throw UsageError(QString("--transparent needs a picture that keeps transparency (.png, .tif, .webp); -o %1 "
                               "has none")
                           .arg(out)
                           .toStdString());
    double framesPerSecond = AnimationOutput::kDefaultFramesPerSecond;
    if (parser.isSet(o.fps)) {
      if (!video)
        throw UsageError(
            "--fps is the rate of a video: -o must be .mp4, .mkv, .webm or .avi with --all-steps or "
            "--deformation-sweep");
      bool ok = false;
      framesPerSecond = parser.value(o.fps).toDouble(&ok);
      if (!ok || !std::isfinite(framesPerSecond) || framesPerSecond < 0.1 || framesPerSecond > 120)
        throw UsageError(QString("--fps %1 is not a rate of 0.1 to 120 frames per second").arg(parser.value(o.fps)).toStdString());
    }

    if (parser.isSet(o.allSteps))
      for (const auto* option : {&o.step, &o.floatOut, &o.saveState})
        if (parser.isSet(*option))
          throw UsageError(QString("--%1 is for one picture; --all-steps writes one per step").arg(option->names().first()).toStdString());
    std::size_t framesBetween = 0;
    if (parser.isSet(o.framesBetween)) {
      if (!parser.isSet(o.allSteps))
        throw UsageError("--frames-between goes between the steps of an animation: add --all-steps");
      bool ok = false;
      const int n = parser.value(o.framesBetween).toInt(&ok);
      if (!ok || n < 0 || n > 100)
        throw UsageError(
            QString("--frames-between %1 is not a count of 0 to 100").arg(parser.value(o.framesBetween)).toStdString());
      framesBetween = std::size_t(n);
    }
    if (parser.isSet(o.sweep))
      for (const auto* option : {&o.floatOut, &o.saveState})
        if (parser.isSet(*option))
          throw UsageError(QString("--%1 is for one picture; --deformation-sweep writes one per frame")
                               .arg(option->names().first())
                               .toStdString());

    SceneState base;
    if (parser.isSet(o.state)) base = SceneState::load(pathBytes(parser.value(o.state)));
    if (!positional.isEmpty()) base.modelPath = pathBytes(positional.first());
    try {  // the command line's reader options over the state file's
      for (const auto& [name, value] : readerOptionsFrom(parser, o.readerOption)) base.readerOptions[name] = value;
    } catch (const OptionError& e) {
      throw UsageError(e.what());
    }
    try {  // the command line's formulas over the state file's of the same name
      for (const FormulaSpec& f : formulasFrom(parser, o.formula)) {
        auto same = std::find_if(base.formulas.begin(), base.formulas.end(),
                                 [&](const FormulaSpec& g) { return g.name == f.name; });
        if (same != base.formulas.end()) *same = f;
        else base.formulas.push_back(f);
      }
    } catch (const OptionError& e) {
      throw UsageError(e.what());
    }
    QString rendererName = parser.isSet(o.renderer) ? parser.value(o.renderer)
                           : base.volume.shown      ? QString::fromStdString(base.volume.renderer)
                                                    : QString("surface");
    const ChosenRenderer chosen = chooseRenderer(*plugins, rendererName, parser, o);
    refuseWhatTheRendererIgnores(parser, o, chosen);
    bool threadsOk = true;
    const int threads = parser.isSet(o.threads) ? parser.value(o.threads).toInt(&threadsOk) : 0;
    if (!threadsOk || threads < 0 || threads > 1024)
      throw UsageError(QString("--threads %1 is not a thread count (1..1024, 0: all cores)").arg(parser.value(o.threads)).toStdString());

    // Outputs are checked before the work: a missing folder is said at once, not after it.
    checkWritable(pathBytes(animated && !video ? framePath(out, 0, 1) : out));
    if (parser.isSet(o.floatOut)) checkWritable(pathBytes(parser.value(o.floatOut)));
    if (parser.isSet(o.saveState)) checkWritable(pathBytes(parser.value(o.saveState)));
    // The plugins' renderers draw with the scene's GL layers; the reference draws alone.
    const bool glVolume = chosen.volume && chosen.volume->drawsSceneLayers;
    if (chosen.volume && parser.isSet(o.colorBySet))
      throw UsageError(QString("--color-by-set colors the surface, sections and slices; the volume renderer %1 "
                               "colors by the transfer function (leave out --renderer for the surface)")
                           .arg(rendererName)
                           .toStdString());
    {
      Scene scene(volumeRendererFactory(*plugins));
      // A volume picture never draws the boundary surface: it is left unextracted.
      std::shared_ptr<ModelSession> session;
      try {
        session = ModelSession::load(plugins->readers(), base.modelPath, terminalProgress("reading"),
                                     !chosen.volume ? ModelSession::Boundary::Now : ModelSession::Boundary::OnFirstUse,
                                     base.readerOptions);
      } catch (const ReaderOptionError& e) {
        throw UsageError(e.what());
      }
      scene.setSession(session);
      try {  // an option (or a state file) this model cannot honour is a usage error
        applyOptions(parser, o, base, scene);
      } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());
      }
      refuseLayersTheRendererCannotDraw(scene.state(), chosen);
      if (chosen.volume && !scene.view())
        throw UsageError(QString("--renderer %1 needs --field (the quantity to render)").arg(rendererName).toStdString());
      refuseWhatTheRendererIgnoresOnThisModel(parser, o, chosen, session->model().grid.has_value());
      if (parser.isSet(o.elementTolerance) && scene.state().volume.interpolation != FieldInterpolation::Element)
        throw UsageError("--element-tolerance applies to the cells' own field: add --interpolation element");
      if (chosen.volume && chosen.volume->drawsSceneLayers && scene.state().volume.elementTolerance == 0.0 &&
          app::drawsCellsFieldOnPieces(chosen.volume->traits, scene.state().volume.interpolation,
                                       scene.view()->location, session->model()))
        throw UsageError(("--element-tolerance 0 (exact): " + rendererName +
                          " draws the cells' own field on tetrahedra refined to a tolerance above 0; the exact "
                          "field is drawn by " +
                          chosen.namesWhere([](const RendererEntry& e) {
                            return e.traits.elementInterpolation;
                          })).toStdString());
      if (parser.isSet(o.elementTolerance) && !chosen.volume && session->model().grid)
        throw UsageError(
            "--element-tolerance: a regular grid's surface picture draws its cells as they are "
            "(nothing follows the tolerance); it applies to its volume");
      try {
        if (glVolume) scene.setVolumeRenderer(rendererName.toStdString());
      } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());
      }
      scene.setVolumeShown(chosen.volume.has_value());
      const bool transparent = parser.isSet(o.transparent);
      const auto drawOnce = [&](bool overlay) {
        return chosen.volume && !glVolume
                   ? renderReferenceSceneImage(scene, width, height, threads, terminalProgress("rendering"), overlay)
                   : renderSceneImage(scene, width, height, overlay);
      };
      const auto draw = [&] {
        return transparent ? renderTransparent(scene, [&] { return drawOnce(false); }) : drawOnce(true);
      };
      if (parser.isSet(o.allSteps))
        return renderEveryStep(scene, out, framesPerSecond, parser.isSet(o.range), framesBetween, draw);
      if (sweepFrames > 0) return renderDeformationSweep(scene, out, framesPerSecond, std::size_t(sweepFrames), draw);
      const SceneImage image = draw();
      for (const std::string& note : image.notes) std::fprintf(stderr, "volpost: note: %s\n", note.c_str());
      if (const auto lines = scene.streamlineResult()) {
        if (lines->outside)
          std::fprintf(stderr, "volpost: note: %zu of the %zu seeds lie outside the mesh and start no streamline\n",
                       lines->outside, lines->seeds);
        const auto spent = std::count_if(lines->lines.begin(), lines->lines.end(), [](const Streamline& l) {
          return l.forwardStop == StreamlineStop::PointBudget || l.backwardStop == StreamlineStop::PointBudget;
        });
        if (spent)
          std::fprintf(stderr, "volpost: note: %zu streamline%s %s\n", std::size_t(spent), spent == 1 ? "" : "s",
                       describe(StreamlineStop::PointBudget));
      }
      if (!scene.setVisibility().marked.empty())
        std::fprintf(stderr, "volpost: note: %zu nodes of %s are marked%s\n", scene.markedSet().nodeCount,
                     scene.setVisibility().marked.c_str(),
                     scene.setVisibility().numbers && scene.markedSet().numbers.empty()
                         ? (", too many to number (" + std::to_string(scene.markedSet().numbered) + "; at most " +
                            std::to_string(Scene::kMaxNumbers) + ")")
                               .c_str()
                         : "");
      if (const SetColoring* c = scene.volumeShown() ? nullptr : scene.setColoring())
        std::fprintf(
            stderr, "volpost: note: colored by %zu element set%s%s\n", c->entries.size(),
            c->entries.size() == 1 ? "" : "s",
            c->cellsInNoSet ? (", " + std::to_string(c->cellsInNoSet) + " cells in no set (gray)").c_str() : "");
      if (scene.setVisibility().active() && !scene.threshold().shown)
        std::fprintf(stderr, "volpost: note: the chosen sets hold %zu of the %zu cells\n",
                     scene.session()->model().cellCount(), scene.baseSession()->model().cellCount());
      if (scene.threshold().shown)
        std::fprintf(stderr, "volpost: note: the threshold keeps %zu of the %zu cells (%s within %g .. %g)\n",
                     scene.session()->model().cellCount(), scene.baseSession()->model().cellCount(),
                     scene.threshold().quantity.c_str(), scene.threshold().min, scene.threshold().max);
      if (scene.deformation().shown)
        std::fprintf(stderr, "volpost: note: drawn deformed: %s x %.6g%s\n", scene.deformation().field.c_str(),
                     scene.deformationScale(),
                     scene.deformation().scale ? "" : " (automatic: the largest displacement is 10% of the model's size)");
      if (const auto& view = scene.view(); view && view->range.nanCount)
        std::fprintf(stderr, "volpost: note: %zu values of %s are not numbers (NaN or infinite): %s\n",
                     view->range.nanCount, view->quantity.displayName().c_str(),
                     scene.volumeShown() ? "the volume leaves out the tetrahedra that have one"
                                         : "drawn gray, outside the color map");
      if (scene.volumeShown() && scene.view() && scene.state().volume.transferFunction)
        if (const auto note = transferFunctionRangeNote(scene.transferFunction(), *scene.view()))
          std::fprintf(stderr, "volpost: warning: %s\n", note->c_str());
      for (std::size_t i = 0; i < scene.probes().size(); ++i) {  // drawn, labelled "outside": say so here too
        const glm::dvec3& at = scene.probes()[i];
        if (!probeAt(*scene.session(), at, scene.state().step).inside())
          std::fprintf(stderr, "volpost: note: probed point %zu (%.9g, %.9g, %.9g) lies outside the mesh\n", i + 1,
                       at.x, at.y, at.z);
      }
      // The picture, its float image and its state are written together: all or none.
      std::vector<std::pair<std::string, std::string>> outputs{{pathBytes(out), pictureBytes(image.picture, out)}};
      if (parser.isSet(o.floatOut)) {
        const std::string floatPath = pathBytes(parser.value(o.floatOut));
        outputs.emplace_back(floatPath, floatImageBytes(floatPath, image.width, image.height, image.volumeRgba,
                                                        glm::dvec3(scene.background())));
      }
      if (parser.isSet(o.saveState)) {
        const std::string statePath = pathBytes(parser.value(o.saveState));
        SceneState saved = scene.state();
        // The renderer that drew the picture: the reference draws apart from the scene's GL
        // renderers, and `render --state` draws with it again.
        if (chosen.volume) saved.volume.renderer = rendererName.toStdString();
        outputs.emplace_back(statePath, saved.toJson(std::filesystem::absolute(statePath).parent_path().string()));
      }
      writeFilesTogether(outputs);
      std::printf("%s\n", qPrintable(QFileInfo(out).absoluteFilePath()));
      return 0;
    }
  } catch (const UsageError& e) {
    printError(e.what());
    return 2;
  } catch (const Cancelled&) {
    printError("cancelled");
    return 1;
  } catch (const std::exception& e) {
    printError(e.what());
    return 1;
  }
}

}  // namespace volpost::app

// SPDX-License-Identifier: MIT
// Everything a picture is made of, as plain data: the model file, the result and step, the
// camera, the colors, and the layers (boundary surface, volume with its renderer, mode,
// transfer function, clip planes and box, iso-surfaces; streamlines; probed points and
// min/max markers; legend). The window's File > Save
// State writes it, `volpost render --state FILE` reads it: both draw the same picture.
// Serialized as versioned JSON ("volpost-state", version 1).
#pragma once

#include "DisplayRange.hpp"
#include "Formula.hpp"
#include "Glyphs.hpp"
#include "Selection.hpp"
#include "SetVisibility.hpp"
#include "SurfaceRepresentation.hpp"
#include "Threshold.hpp"

#include "host/StreamlineStyle.hpp"
#include "host/Streamlines.hpp"

#include <volpost/core/ClipPlane.hpp>
#include <volpost/core/MeshReader.hpp>
#include <volpost/core/TransferFunction.hpp>
#include <volpost/core/TransferFunction2D.hpp>
#include <volpost/core/optics/IsoTables.hpp>
#include <volpost/render/FieldInterpolation.hpp>
#include <volpost/render/IntegrationMode.hpp>
#include <volpost/render/VolumeLimits.hpp>

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace volpost::app {

/// An explicit camera (model coordinates).
struct CameraState {
  glm::dvec3 eye{0.0, 0.0, 1.0};
  glm::dvec3 target{0.0};
  glm::dvec3 up{0.0, 1.0, 0.0};
  double fieldOfView = 30.0;  ///< vertical, degrees
  bool orthographic = false;
  /// The rotation (w, x, y, z) and the eye's distance as the camera holds them: eye - target
  /// rounded at a georeferenced model's coordinates (1e6 and more) loses the direction's
  /// last bits, and a restored view would differ in a few edge pixels. Used when they agree
  /// with eye, target and up (a hand-edited eye or up wins).
  std::optional<glm::dquat> rotation;
  std::optional<double> distance;
  bool operator==(const CameraState&) const = default;
};

/// A view saved under a name (View > Saved Views, `render --view NAME`): the camera as it was.
struct NamedView {
  std::string name;
  CameraState camera;
  bool operator==(const NamedView&) const = default;
};
inline constexpr std::size_t kMaxViews = 100;
inline constexpr int kMaxColorBands = 256;
/// The most slice planes a scene holds; the largest point size (logical pixels).
inline constexpr std::size_t kMaxSlicePlanes = 16;
inline constexpr double kMaxPointSize = 64.0;
inline constexpr double kMinTextScale = 0.25, kMaxTextScale = 8.0;
/// The most formulas a scene (and its state file) holds.
inline constexpr std::size_t kMaxFormulas = 100;
/// The cells' own field's tolerance per pixel channel: a bound the pictures stay well under
/// (docs/methods/element_field.md); 0 draws it exactly; below the least, the fast path's own
/// rounding would not stay within it.
inline constexpr double kDefaultElementTolerance = 0.01;
inline constexpr double kLeastElementTolerance = 1e-5, kMostElementTolerance = 0.1;
inline constexpr const char* kElementToleranceRule = "must be 0 (exact) or lie in [1e-05, 0.1]";
inline bool validElementTolerance(double e) {
  return e == 0.0 || (e >= kLeastElementTolerance && e <= kMostElementTolerance);
}
inline constexpr std::size_t kMaxViewNameBytes = 200;
/// Why `name` cannot name a view (empty, too long, a control character), or empty.
std::string viewNameProblem(const std::string& name);

/// A box the volume is cut to: xmin, xmax, ymin, ymax, zmin, zmax (model units).
using ClipBox = std::array<double, 6>;
/// The six planes that keep the inside of the box.
std::vector<ClipPlane> clipBoxPlanes(const ClipBox& box);

struct VolumeLayer {
  bool shown = false;
  std::string renderer = "raycast";  ///< a renderer plugin's name (volpost plugins lists them)
  IntegrationMode mode = IntegrationMode::LinearSegments;
  std::optional<TransferFunction> transferFunction;  ///< nullopt: the default for the result
  /// Regular grids: over the value and its gradient magnitude, used instead of the 1D one.
  std::optional<TransferFunction2D> transferFunction2D;
  std::vector<ClipPlane> clipPlanes;                  ///< free planes (the window's dragged one)
  std::optional<ClipBox> clipBox;                     ///< also culls: the GPU holds only its inside
  std::vector<optics::IsoSurface> isoSurfaces;
  /// The quantity the iso-surfaces are of ("T", "S.mises"); empty: the shown one. Another
  /// quantity's iso-surfaces are drawn in the surface view (a volume contours what it renders).
  std::string isoQuantity;
  double samplingStep = 0.0;    ///< sampling mode; 0: a quarter of the mean edge
  double termination = 0.002;   ///< rays stop below this transmittance
  /// Meshes: how node values vary inside a cell (the cells' own shape functions, or linear
  /// on the tetrahedra they are split into).
  FieldInterpolation interpolation = FieldInterpolation::Tetrahedra;
  /// With the cells' own interpolation: the most each pixel channel may differ from its
  /// exact picture, for renderers that take a tolerance (0: exact).
  double elementTolerance = kDefaultElementTolerance;
  bool shading = false;         ///< regular grids: the emission lit by the gradient (headlight)
  bool edges = false;           ///< element edges over the volume (they end the rays)
  bool outline = false;         ///< the model's feature edges over the volume (they end the rays)
  /// All the planes the renderer cuts with: the box's six, then the free ones.
  std::vector<ClipPlane> allClipPlanes() const;
};

/// Streamlines of a vector field, drawn as lit lines or tubes.
struct StreamlineLayer {
  bool shown = false;
  std::string field;               ///< a vector field's name ("velocity", "U")
  std::vector<std::string> seeds;  ///< where lines start (StreamlineSeeds.hpp's forms)
  StreamlineSettings settings;     ///< integrator, direction, tolerance, limits
  std::string colorBy;             ///< a quantity ("T", "pressure.magnitude"); empty: the speed |v|
  StreamlineStyle style;           ///< width, tubes, radius, arrows
  bool averageCellVectors = false; ///< a field given per element, averaged at the nodes (an approximation)
  /// What the lines themselves depend on (not how they are drawn): a change re-traces.
  bool sameLinesAs(const StreamlineLayer& o) const {
    return field == o.field && seeds == o.seeds && settings == o.settings && colorBy == o.colorBy &&
           averageCellVectors == o.averageCellVectors;
  }
};

/// At most this many probed points in a view (and a state file).
inline constexpr std::size_t kMaxProbes = 10000;

/// The deformed shape: nodes moved by a displacement field times a scale.
struct DeformationLayer {
  bool shown = false;
  std::string field = "U";
  std::optional<double> scale;  ///< nullopt: automatic (the largest displacement is 10 % of the model's size)
  bool undeformedOutline = false;  ///< the undeformed model's outline (feature edges) drawn too, in gray
  bool operator==(const DeformationLayer&) const = default;
};

struct SceneState {
  static constexpr int kVersion = 1;

  std::string modelPath;
  /// A regular grid's slices along each of its axes (inline, crossline, time for a survey)
  /// at these labels (an inline number, a time in ms ...); nullopt: no slice on that axis.
  /// "gridSlices" in the file: [inline or null, crossline or null, time or null].
  std::array<std::optional<double>, 3> gridSlices;
  ReaderOptions readerOptions;  ///< what the model was read with (SEG-Y header bytes ...); "readerOptions" in the file
  /// The calculator's formulas, in order (each may read the ones before it); "formulas"
  /// in the file as [{"name": ..., "expression": ...}]. Their fields follow the file's own.
  std::vector<FormulaSpec> formulas;
  std::string quantity;       ///< written form ("S.mises"); empty: the plain surface
  std::size_t step = 0;       ///< 0-based here, 1-based in the file
  std::optional<CameraState> camera;  ///< nullopt: the isometric view fitted to the model
  /// Views saved under names, in the order saved; "views" in the file.
  std::vector<NamedView> views;
  std::string colorMap = "cool-warm";
  std::optional<DisplayRange> fixedRange;  ///< nullopt: the values' own range
  /// Without a fixed range: the range over every step (one scale for an animation)
  /// instead of each step's own.
  bool rangeOverSteps = false;
  /// The values' own range widened to [-m, m], m the larger of |min| and |max|: zero in
  /// the middle of a diverging map (not with a fixed range). "colors.symmetric" in the file.
  bool symmetricRange = false;
  /// Automatic (until the user chooses): symmetric on a diverging map (cool-warm, seismic)
  /// for values of both signs, the values' own range otherwise. "colors.symmetric": "auto".
  bool symmetricAuto = true;
  /// Discrete contour bands of equal width (0: continuous colors; kMaxColorBands at most);
  /// "colors.bands" in the file.
  int colorBands = 0;
  /// Colors by the value's logarithm (the range must be positive); "colors.log" in the file.
  bool logScale = false;
  /// Values below (above) the range in this color instead of the map's end color;
  /// "colors.below" / "colors.above" in the file: [r, g, b] (0..1) or null.
  std::optional<glm::dvec3> belowColor, aboveColor;
  bool edges = true;          ///< element edges on the surface view
  bool lighting = true;       ///< shading; off: the color map's exact colors
  bool surfaceShown = true;   ///< the boundary surface (off: only what is inside shows)
  /// How the boundary is drawn; "surface.representation" in the file.
  SurfaceRepresentation representation = SurfaceRepresentation::Surface;
  /// Node points' size in the points representation, logical pixels; "surface.pointSize".
  double pointSize = 4.0;
  /// Planes through a mesh whose cross-sections are drawn without cutting anything away
  /// (a section beside the model; clip planes cut it); "slicePlanes" in the file.
  std::vector<ClipPlane> slicePlanes;
  double surfaceOpacity = 1.0;  ///< below 1 the surface is see-through (streamlines show)
  bool legend = true;
  /// A line of text at the picture's top left (a report's caption); "title" in the file.
  std::string title;
  /// The shown result's name and step (or time) written under the title; "stepText".
  bool stepText = false;
  /// The legend's words and numbers; "legendText" in the file: {"titles": {"S.mises":
  /// "Equivalent stress"}, "units": {"S": "MPa"}, "numbers": "fixed:2", "labels": 6}.
  std::map<std::string, std::string> legendTitles;  ///< by quantity (written form)
  std::map<std::string, std::string> units;         ///< by field name
  std::string legendNumbers = "auto:4";             ///< LegendNumbers::parse
  int legendLabels = 6;                             ///< about how many values a bar labels (2..20)
  bool triad = true;          ///< the orientation axes in the lower left corner
  /// Behind the model, 0..1 each; "background" in the file.
  glm::dvec3 background{0.96, 0.96, 0.97};
  /// The size of the words and numbers painted over the picture (legend, title, labels),
  /// times their size in proportion to the picture; "textScale" in the file.
  double textScale = 1.0;
  VolumeLayer volume;
  StreamlineLayer streamlines;
  GlyphLayer glyphs;  ///< arrows or principal bars at the nodes; "glyphs" in the file
  /// Only the cells whose value lies in a range; "threshold" in the file:
  /// {"shown": true, "quantity": "S.mises", "range": [100, 200], "nodes": "all"}.
  ThresholdLayer threshold;
  /// Element sets drawn alone or hidden, and the set marked; "sets" in the file:
  /// {"shown": ["EALL"], "hidden": [], "marked": "FIXED"}.
  SetVisibility sets;
  /// The elements and nodes picked (file ids), the model's sets "selected elements" and
  /// "selected nodes"; "selection" in the file: {"elements": "101,105-110", "nodes": "7"}.
  Selection selection;
  /// Points probed (the window's Probe panel), marked and numbered in the view.
  std::vector<glm::dvec3> probes;
  /// Probes measured in the picture (their indices in `probes`): two give their distance,
  /// three also the angle at the second; "markers": {"measure": [1, 2, 3]} counts from 1.
  std::vector<std::size_t> measure;
  /// The line the Plot Over Line panel samples, drawn over the picture; "plotLine" in the file.
  std::optional<std::array<glm::dvec3, 2>> plotLine;
  bool markExtremes = false;
  DeformationLayer deformation;  ///< the shown quantity's smallest and largest values marked where they are

  /// The file's text. `relativeTo`: a folder; a model path inside it is written relative
  /// to it, so the state and the model can move together.
  std::string toJson(const std::string& relativeTo = {}) const;
  /// Parses a state file's text; `fileName` names it in messages, and a relative model
  /// path is resolved against its folder. Throws std::runtime_error naming the file, the
  /// key and what is wrong with it.
  static SceneState fromJson(const std::string& text, const std::string& fileName);
  /// Reads and parses a state file (regular files only).
  static SceneState load(const std::string& path);
  /// Writes the file through a temporary one in the same folder, renamed when complete:
  /// a failed write leaves the previous file as it was. Throws std::runtime_error.
  void save(const std::string& path) const;
};

}  // namespace volpost::app

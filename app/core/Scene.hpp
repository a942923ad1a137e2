// SPDX-License-Identifier: MIT
// What a picture shows, as state: a model (ModelSession), a SceneState (result, step,
// colors, layers) and a live camera. The window's viewport and `volpost render` change it;
// a SceneDrawing (with a GL context) draws it. No GL here: the command-line verbs and the
// panels use a scene without a context.
//
// Setters check their input, record it and count what kind of thing changed (the model,
// the values, the colors, the transfer-function tables, the plane parameters, the
// renderer) in revisions(); a drawing compares those counts with what it last drew and
// hands each layer only what changed: a dragged plane reaches the volume renderer as a
// new plane and nothing else.
#pragma once

#include "GridSlices.hpp"
#include "Legend.hpp"
#include "ModelSession.hpp"
#include "SceneState.hpp"
#include "SetColors.hpp"
#include "StreamlineTracing.hpp"
#include "VolumeRendererFactory.hpp"

#include <volpost/core/Camera.hpp>

#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <tuple>

namespace volpost::app {

/// What the legend shows: the colors and the words.
struct LegendPicture {
  ColorMap colors;
  LegendContent content;
};

/// The scene's light gray behind the model, in pictures and the window alike.
inline constexpr glm::vec3 kSceneBackground{0.96f, 0.96f, 0.97f};

/// How often each kind of thing has changed; a drawing keeps the counts it last drew and
/// uploads only what differs. Counts only grow.
struct SceneRevisions {
  std::uint64_t scene = 0;    ///< which scene: each one made has its own number
  std::uint64_t model = 0;    ///< the drawn model: a new one, or deformed anew
  std::uint64_t scalars = 0;  ///< the surface's values or color range
  std::uint64_t colorMap = 0;
  std::uint64_t renderer = 0;     ///< the volume renderer chosen
  std::uint64_t geometry = 0;     ///< what the volume's cells are (model, per node or per cell)
  std::uint64_t values = 0;       ///< the volume's values
  std::uint64_t tables = 0;       ///< the transfer functions
  std::uint64_t planes = 0;       ///< clip planes and box
  std::uint64_t iso = 0;          ///< iso-surfaces
  std::uint64_t mode = 0;         ///< integration mode, sampling step, termination, shading
  std::uint64_t streamlines = 0;  ///< the lines shown or how they look
};

/// Values with a count of their changes (the count tells a cache whether it is stale).
struct VersionedView {
  const ScalarView* view = nullptr;
  std::uint64_t version = 0;
};

class Scene {
 public:
  explicit Scene(VolumeRendererFactory factory);
  ~Scene();
  Scene(const Scene&) = delete;
  Scene& operator=(const Scene&) = delete;

  // ---- the model ----
  /// A new model: the result is cleared, the camera fitted, the volume's planes and
  /// iso-surfaces dropped (they belong to the old model); the rest of the state stays.
  void setSession(std::shared_ptr<const ModelSession> session);
  /// The model as drawn, probed and picked: deformed while a deformation is shown.
  const ModelSession* session() const { return session_.get(); }
  std::shared_ptr<const ModelSession> sharedSession() const { return session_; }
  /// The model as read.
  const ModelSession* baseSession() const { return baseSession_.get(); }
  std::shared_ptr<const ModelSession> sharedBaseSession() const { return baseSession_; }

  /// Shows the model deformed (nodes moved by the field at the shown step times the scale)
  /// or not. Throws std::invalid_argument (not a nodal vector field) and changes nothing then.
  void setDeformation(const DeformationLayer& layer);
  const DeformationLayer& deformation() const { return state_.deformation; }
  /// Shows only the cells whose value lies in a range (see Threshold.hpp); the drawn,
  /// probed and picked model is then theirs. Throws std::invalid_argument (unknown
  /// quantity, bad range, no cell kept at this step) and changes nothing then.
  void setThreshold(const ThresholdLayer& layer);
  const ThresholdLayer& threshold() const { return state_.threshold; }
  /// Draws only some element sets, or hides some (see SetVisibility.hpp); throws
  /// std::invalid_argument, changing nothing, for unknown names, node sets, or no cell left.
  void setSetVisibility(const SetVisibility& sets);
  const SetVisibility& setVisibility() const { return state_.sets; }
  /// The elements and nodes picked (Selection.hpp): they become the model's sets "selected
  /// elements" and "selected nodes" (an empty list: no such set; the choices that named a
  /// set that is gone forget it). Throws std::invalid_argument for an id the model lacks,
  /// changing nothing.
  void setSelection(Selection selection);
  const Selection& selection() const { return state_.selection; }
  /// The marked set as drawn now (deformed when the shape is); empty without one.
  struct MarkedSet {
    std::vector<glm::dvec3> nodes;  ///< at most kMaxMarkedNodes, evenly taken from a larger set
    std::size_t nodeCount = 0;      ///< all of its drawn nodes
    struct Number {
      glm::dvec3 at;
      std::int64_t id = 0;
    };
    /// With the numbers on: a node set's node ids, an element set's element ids at their
    /// centres; none when more than kMaxNumbers would cover the picture (`numbered` says how many).
    std::vector<Number> numbers;
    std::size_t numbered = 0;
  };
  const MarkedSet& markedSet() const;
  static constexpr std::size_t kMaxMarkedNodes = 50000;
  static constexpr std::size_t kMaxNumbers = 300;
  /// The factor the nodes are moved by now (the automatic one worked out), 0 when undeformed.
  double deformationScale() const { return deformationScale_; }

  // ---- what is shown (a drawing applies it) ----
  /// Throws std::invalid_argument (no such quantity or step) and changes nothing then.
  void setResult(const std::string& quantity, std::size_t step);
  /// An animation's in-between frame: the shown values and the deformed shape taken `t` of
  /// the way from the shown step to the next, linearly (0: the step itself; the last step
  /// has no next and stays). Not kept in the state; setResult and another model set it
  /// back to 0. Throws std::invalid_argument outside [0, 1).
  void setStepBlend(double t);
  double stepBlend() const { return stepBlend_; }
  void setColorMap(const std::string& name);
  /// A fixed color range (nullopt: the values' own). Setting one turns the range over
  /// steps off.
  void setFixedRange(std::optional<DisplayRange> range);
  /// Colors (and the default transfer function) span the quantity's range over every step
  /// (on) or each step's own (off); either turns a fixed range off.
  void setRangeOverSteps(bool on);
  /// The values' own range widened to be symmetric about zero (see SceneState).
  void setSymmetricRange(bool on);
  /// Back to the automatic choice: symmetric on a diverging map for values of both signs.
  void setSymmetricRangeAutomatic();
  /// Whether the range shown is widened to be symmetric now (chosen, or automatic).
  bool symmetricRangeShown() const;
  /// The color map is a diverging one (cool-warm, seismic, either way round).
  bool divergingMap() const;
  /// Discrete contour bands (0: continuous); std::invalid_argument outside 0, 2..kMaxColorBands.
  void setColorBands(int bands);
  /// Colors by the value's logarithm: the range's lower end is the smallest positive value
  /// when the values reach 0 or below (those are then below the range); a typed range must
  /// be positive (std::invalid_argument otherwise, nothing changed). Overrides the
  /// symmetric range.
  void setLogScale(bool on);
  /// Values below (above) the range in their own color (nullopt: the map's end color);
  /// std::invalid_argument for a component outside 0..1.
  void setOutOfRangeColors(std::optional<glm::dvec3> below, std::optional<glm::dvec3> above);
  void setShowEdges(bool show);
  /// Off: the surface shows the color map's exact colors (no shading).
  void setLighting(bool on) { state_.lighting = on; }
  void setShowLegend(bool show) { state_.legend = show; }
  /// A line of text at the picture's top left (empty: none); std::invalid_argument over 200
  /// bytes or with a line break.
  void setTitle(const std::string& title);
  /// The shown result and its step (or time) written under the title: an animation's frames
  /// say which step each is.
  void setStepText(bool on) { state_.stepText = on; }
  /// The legend's title for a quantity (empty: its own name); units of a field, shown after
  /// the title ("S von Mises [MPa]"); std::invalid_argument for text over 200 bytes.
  void setLegendTitle(const std::string& quantity, const std::string& title);
  void setUnits(const std::string& field, const std::string& units);
  /// The units a field's values are shown in: those typed (setUnits), else the file's
  /// (Field::units), else none.
  std::string unitsOf(const std::string& field) const;
  /// unitsOf for every field of the model that has some.
  std::map<std::string, std::string> unitsByField() const;
  /// "auto[:N]", "fixed[:N]", "scientific[:N]"; std::invalid_argument otherwise.
  void setLegendNumbers(const std::string& style);
  /// About how many values a continuous bar labels, 2..20.
  void setLegendLabels(int labels);
  /// The orientation axes (x red, y green, z blue) in the lower left corner.
  void setShowTriad(bool show) { state_.triad = show; }
  /// Throws std::invalid_argument when there is no result to show as a volume.
  void setVolumeShown(bool shown);
  /// Throws std::invalid_argument naming the choices when no plugin offers `name`.
  void setVolumeRenderer(const std::string& name);
  void setIntegrationMode(IntegrationMode mode);
  /// nullopt: the default for the result.
  void setTransferFunction(std::optional<TransferFunction> tf);
  /// A 2D transfer function (value x gradient magnitude) instead of the 1D one, for regular
  /// grids drawn by a grid renderer; nullopt: the 1D one again. A mesh refuses it when drawn.
  void setTransferFunction2D(std::optional<TransferFunction2D> tf);
  /// Free planes and the box together must stay within kMaxClipPlanes (throws otherwise).
  void setClipPlanes(std::vector<ClipPlane> planes);
  void setClipBox(std::optional<ClipBox> box);
  void setIsoSurfaces(std::vector<optics::IsoSurface> surfaces);
  /// The quantity the iso-surfaces are of (empty: the shown one). Throws
  /// std::invalid_argument for an unknown quantity or one given per element.
  void setIsoQuantity(const std::string& key);
  /// The Plot Over Line panel's line, drawn over the picture (nullopt: none).
  void setPlotLine(std::optional<std::array<glm::dvec3, 2>> line);
  const std::optional<std::array<glm::dvec3, 2>>& plotLine() const { return state_.plotLine; }
  /// A regular grid's slices (inline, crossline, time for a survey) at these labels,
  /// drawn in the surface view and, opaque, in the volume. Throws std::invalid_argument
  /// for a model that is not a grid or a label outside its axis (naming both).
  void setGridSlices(const std::array<std::optional<double>, 3>& labels);
  /// The planes of the slices now set, in model coordinates.
  std::vector<ClipPlane> gridSlicePlanes() const;
  /// Free slices: each plane's cross-section drawn in the result's colors without cutting
  /// the model away (the clip planes and box cut them). Throws std::invalid_argument over
  /// kMaxSlicePlanes or for a plane that is not finite with a non-zero normal.
  void setSlicePlanes(std::vector<ClipPlane> planes);
  /// Every slice drawn: the grid's, then the free ones.
  std::vector<ClipPlane> slicePlanes() const;
  void setSamplingStep(double step);
  void setTermination(double transmittance);
  /// Meshes: how node values vary inside a cell when the volume is drawn.
  void setInterpolation(FieldInterpolation interpolation);
  /// The cells' own field's tolerance per pixel channel: 0 (exact) or within
  /// [kLeastElementTolerance, kMostElementTolerance]; throws std::invalid_argument otherwise.
  void setElementTolerance(double tolerance);
  /// Regular grids: the volume's emission lit by the trilinear gradient (light at the eye).
  /// Throws std::invalid_argument, changing nothing, to turn it on for a mesh.
  void setShading(bool on);
  void setVolumeEdges(bool show);
  /// The model's feature edges (creases and borders) over the volume, opaque.
  void setVolumeOutline(bool show) { state_.volume.outline = show; }
  /// How the boundary is drawn (surface, wireframe, points, feature edges, outline).
  void setRepresentation(SurfaceRepresentation r) { state_.representation = r; }
  /// Node points' size in logical pixels, 1..kMaxPointSize; std::invalid_argument otherwise.
  void setPointSize(double pixels);
  void setSurfaceShown(bool shown) { state_.surfaceShown = shown; }
  /// 0..1; below 1 the surface is see-through. Throws std::invalid_argument otherwise.
  void setSurfaceOpacity(double opacity);
  /// Checks the field, the seeds and the coloring quantity first (std::invalid_argument
  /// saying what is wrong, nothing changed). The lines are traced by updateStreamlines()
  /// (a headless picture does), or by the caller with traceStreamlines() on a worker thread
  /// and setStreamlineResult() (the window).
  void setStreamlines(StreamlineLayer layer);
  const StreamlineLayer& streamlines() const { return state_.streamlines; }
  /// True when the lines shown do not belong to the current model, step or layer.
  bool streamlinesNeedTracing() const;
  /// Traces the current layer's lines (no GL; safe on a worker thread while the scene
  /// is not changed). Cancelled on request.
  std::shared_ptr<const StreamlineResult> traceStreamlines(const Progress& progress = {}) const;
  void setStreamlineResult(std::shared_ptr<const StreamlineResult> result);
  std::shared_ptr<const StreamlineResult> streamlineResult() const { return streamlineResult_; }
  /// Traces the lines here and now when they need it (pictures; the window traces on a
  /// worker thread instead).
  void updateStreamlines();
  /// Lines are shown and the ones held belong to the current model, step and layer.
  bool streamlinesDrawn() const;
  /// Arrows (vector field) or principal bars (tensor field) at the nodes. Checks the field,
  /// the coloring quantity, the scale and the count first (std::invalid_argument, nothing
  /// changed).
  void setGlyphs(GlyphLayer layer);
  const GlyphLayer& glyphLayer() const { return state_.glyphs; }
  /// The glyphs at the shown step on the drawn (perhaps deformed) model, built once per
  /// change of the layer, step or model; nullptr when none are shown. Throws
  /// std::invalid_argument when there would be too many.
  std::shared_ptr<const GlyphGeometry> glyphs() const;
  // ---- probed points and min/max markers (painted over the picture: paintSceneOverlay) ----
  /// Throws std::invalid_argument for more than kMaxProbes points or one not finite.
  void setProbes(std::vector<glm::dvec3> points);
  const std::vector<glm::dvec3>& probes() const { return state_.probes; }
  /// Measures between probes in the picture (indices into probes(): two for a distance,
  /// three for the angle at the second too; none: off). Throws std::invalid_argument,
  /// changing nothing, for another count, a repeated or a missing probe. New probes that
  /// lack one of them turn the measure off.
  void setMeasure(std::vector<std::size_t> probes);
  /// An element of the drawn model outlined in the picture, and one of its nodes ringed
  /// (what the hover names); not saved, and gone when the drawn model changes.
  struct Highlight {
    std::size_t cell = 0;
    std::optional<std::size_t> node;
  };
  void setHighlight(std::optional<Highlight> h);
  std::optional<Highlight> highlight() const;
  const std::vector<std::size_t>& measure() const { return state_.measure; }
  void setMarkExtremes(bool on) { state_.markExtremes = on; }
  bool marksExtremes() const { return state_.markExtremes; }
  bool showsTriad() const { return state_.triad; }
  /// The window's handles on the free clip planes (outline and normal handle, PlaneWidget);
  /// pictures never show it.
  void setPlaneWidgetShown(bool on) { planeWidgetShown_ = on; }
  /// The window's handles as set (whether or not there is a plane, box or rake to show).
  struct Handles {
    bool plane = false, box = false, rakes = false;
  };
  Handles handles() const { return {planeWidgetShown_, boxWidgetShown_, rakesShown_}; }
  void setHandles(const Handles& h) {
    planeWidgetShown_ = h.plane;
    boxWidgetShown_ = h.box;
    rakesShown_ = h.rakes;
  }
  bool showsPlaneWidget() const { return planeWidgetShown_ && session_ && !state_.volume.clipPlanes.empty(); }
  /// The window's handles on the clip box (BoxWidget); pictures never show them.
  void setBoxWidgetShown(bool on) { boxWidgetShown_ = on; }
  bool showsBoxWidget() const { return boxWidgetShown_ && session_ && shownClipBox().has_value(); }
  /// The window's rakes (the streamlines' line seeds) drawn over the picture; pictures never show them.
  void setRakesShown(bool on) { rakesShown_ = on; }
  bool showsRakes() const { return rakesShown_ && session_ && state_.streamlines.shown; }
  /// The box being dragged, drawn instead of the clip box until the window applies it.
  void setClipBoxPreview(std::optional<ClipBox> box) { clipBoxPreview_ = box; }
  std::optional<ClipBox> shownClipBox() const { return clipBoxPreview_ ? clipBoxPreview_ : state_.volume.clipBox; }
  std::size_t step() const { return state_.step; }  ///< 0-based
  /// Where the shown quantity is smallest and largest: a node, or an element's centre for
  /// element results (the first of equal values). nullopt without a result or values.
  struct Extremes {
    glm::dvec3 minAt{0.0}, maxAt{0.0};
    double min = 0.0, max = 0.0;
    std::int64_t minId = 0, maxId = 0;  ///< the node's or element's id
  };
  std::optional<Extremes> extremes() const;
  /// The shown quantity at each probed point (nullopt: outside the mesh, or no result),
  /// probed once per change of the points, result, step or geometry, not per frame.
  const std::vector<std::optional<double>>& probedValues() const;

  Camera& camera() { return camera_; }
  const Camera& camera() const { return camera_; }
  void fitCamera();

  // ---- saved views, and the views before (View > Saved Views, Previous View) ----
  /// Saves the camera as it is under `name`, replacing a view of that name. Throws
  /// std::invalid_argument for a name that cannot be one or past kMaxViews views.
  void saveView(const std::string& name);
  /// Turns the camera to the view saved as `name` (remembered first, for previousView).
  /// Throws std::invalid_argument naming the saved views when there is no such view.
  void showView(const std::string& name);
  void removeView(const std::string& name);
  const std::vector<NamedView>& views() const { return state_.views; }
  /// Remembers the camera before the user moves it (a drag, a standard view, a saved view),
  /// for previousView; the last kViewHistory are kept.
  void rememberView();
  /// Back to the camera remembered last that differs from the present one; false when
  /// none is left.
  bool previousView();
  static constexpr std::size_t kViewHistory = 50;

  /// The whole state (camera included) and back. applyState needs the model of
  /// state.modelPath already set with setSession; it checks everything first (quantity,
  /// step, renderer, color map) and throws std::invalid_argument, changing nothing.
  SceneState state() const;
  void applyState(const SceneState& state);
  /// The calculator's formulas (replacing the ones before): their fields join the model's
  /// for every view, probe, plot and picture. What showed a formula that is gone falls back
  /// (the result to the default, its iso-surfaces and streamlines off). Throws FormulaError
  /// (or std::invalid_argument) naming the formula at fault, changing nothing.
  void setFormulas(std::vector<FormulaSpec> formulas);
  const std::vector<FormulaSpec>& formulas() const { return state_.formulas; }

  // ---- derived ----
  const std::optional<ScalarView>& view() const { return view_; }
  DisplayRange displayRange() const;
  /// The transfer function the volume uses: the state's, or the result's default.
  TransferFunction transferFunction() const;
  bool volumeShown() const { return state_.volume.shown; }
  const VolumeLayer& volume() const { return state_.volume; }
  /// The first of legends() (nullopt: none shown).
  std::optional<LegendPicture> legend() const;
  /// What the legend strip shows, top to bottom: the result's key (surface or volume) and
  /// the streamlines' when they are drawn.
  std::vector<LegendPicture> legends() const;
  /// The camera for a picture of this size (logical pixels): the view keeps clear of the
  /// legend's strip at the right when the legend is shown. Everything that draws, projects
  /// or picks in a picture uses it, so markers and picks land where the model is drawn.
  Camera pictureCamera(double width, double height) const;
  /// Device pixels per logical pixel of the pictures drawn (the window's HiDPI
  /// factor; 1 headless): the legend strip is measured in logical pixels.
  void setDevicePixelRatio(double ratio) { devicePixelRatio_ = ratio > 0.0 ? ratio : 1.0; }
  glm::vec3 background() const { return glm::vec3(state_.background); }
  /// Behind the model (0..1 each); std::invalid_argument otherwise.
  void setBackground(const glm::dvec3& rgb);
  /// The words' size over the picture, kMinTextScale..kMaxTextScale; std::invalid_argument otherwise.
  void setTextScale(double scale);
  double devicePixelRatio() const { return devicePixelRatio_; }

  // ---- for a drawing ----
  /// The state without the camera (state() adds it): what each layer shows.
  const SceneState& shown() const { return state_; }
  const SceneRevisions& revisions() const { return revisions_; }
  const VolumeRendererFactory& volumeRenderers() const { return factory_; }
  /// The shown values and the count of their changes.
  VersionedView shownValues() const { return {view_ ? &*view_ : nullptr, viewVersion_}; }
  /// The drawn model colored by its element sets (SetVisibility::colors; built once per
  /// drawn model); nullptr when the sets do not color it.
  const SetColoring* setColoring() const;
  /// What the surface, the sections and the slices are colored by: the sets' colors when
  /// they color the model, else the shown values.
  VersionedView surfaceValues() const;
  /// Their range: the sets' palette, or displayRange().
  DisplayRange surfaceRange() const;
  /// The values the iso-surfaces are of: the shown result's, or another quantity's at the
  /// shown step (evaluated once per quantity, step and model).
  VersionedView isoSurfaceValues() const;
  /// Why a renderer that draws grids' point values cannot draw the shown per-cell field.
  std::string perCellRefusal(const std::string& renderer) const;

 private:
  /// applyState with the model carrying the state's formulas (nullptr: the formulas shown now).
  void applyState(const SceneState& state, std::shared_ptr<const ModelSession> withFormulas);
  void checkStreamlines(const StreamlineLayer& layer) const;
  void checkStreamlines(const StreamlineLayer& layer, const ModelSession& session) const;
  void checkProbes(const std::vector<glm::dvec3>& points) const;
  static void checkMeasure(const std::vector<std::size_t>& measure, std::size_t probes);
  void checkSamplingStep(double step) const;
  CameraState cameraState() const;
  /// The camera a saved one describes, fitted to the model first (clipping range).
  Camera cameraAt(const CameraState& c) const;
  std::vector<CameraState> viewHistory_;  ///< remembered cameras, the last one newest
  std::size_t stepCountOf(const std::string& quantityKey) const;
  mutable std::optional<ScalarView> isoView_;          ///< another quantity's values, for its iso-surfaces
  mutable std::string isoViewFor_;                     ///< the quantity, step and view version isoView_ is of
  mutable std::uint64_t isoViewVersion_ = 1ull << 62;  ///< apart from viewVersion_'s counts
  /// The most samples a ray takes across the model's diagonal in the sampling mode.
  static constexpr double kMaxSamplesAcross = 65536.0;
  /// Every kind of thing changed: a new or newly deformed model.
  void changeEverything();

  VolumeRendererFactory factory_;
  std::shared_ptr<const ModelSession> session_;      ///< drawn: baseSession_ or its deformed copy
  std::shared_ptr<const ModelSession> baseSession_;  ///< as read
  double deformationScale_ = 0.0;
  std::size_t deformedStep_ = 0;
  void rebuildDeformation();
  SceneState state_;
  bool planeWidgetShown_ = false;
  bool boxWidgetShown_ = false;
  bool rakesShown_ = false;
  std::optional<ClipBox> clipBoxPreview_;
  Camera camera_;
  double devicePixelRatio_ = 1.0;
  std::optional<ScalarView> view_;
  std::uint64_t viewVersion_ = 0;  ///< counts changes of view_ (what extremes_ was found for)
  double stepBlend_ = 0.0;         ///< setStepBlend
  /// The quantity at the shown step on `session`, or between it and the next (stepBlend_).
  ScalarView evaluateShown(const ModelSession& session, const Quantity& q, std::size_t step) const;
  mutable std::optional<Extremes> extremes_;
  mutable std::optional<double> smallestPositive_;  ///< of view_, for a log scale
  mutable std::uint64_t smallestPositiveVersion_ = ~std::uint64_t(0);
  mutable std::uint64_t extremesVersion_ = ~std::uint64_t(0);
  /// The marked set's points, and for which model part and name they were found.
  mutable MarkedSet marked_;
  std::optional<Highlight> highlight_;
  std::weak_ptr<const ModelSession> highlightOn_;  ///< the drawn model the highlight names cells of
  mutable bool markedNumbers_ = false;
  mutable std::weak_ptr<const ModelSession> markedFor_;  // weak: a freed part's address may be reused
  mutable std::string markedName_;
  mutable std::optional<SetColoring> coloring_;
  mutable std::weak_ptr<const ModelSession> coloringFor_;  ///< the drawn model coloring_ is of
  mutable std::vector<std::optional<double>> probedValues_;
  mutable std::uint64_t probedVersion_ = ~std::uint64_t(0);  ///< viewVersion_ probedValues_ is for
  mutable std::vector<glm::dvec3> probedPoints_;              ///< and the points
  SceneRevisions revisions_;

  std::shared_ptr<const StreamlineResult> streamlineResult_;
  mutable std::shared_ptr<const GlyphGeometry> glyphs_;
  /// What glyphs_ was built for: the model, step, layer, the planes cutting it and whether
  /// its cut faces are drawn (the surface view).
  mutable std::tuple<const ModelSession*, std::size_t, GlyphLayer, std::vector<ClipPlane>, bool> glyphsFor_;
};

}  // namespace volpost::app

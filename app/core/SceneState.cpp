// SPDX-License-Identifier: MIT
#include "SceneState.hpp"

#include "Legend.hpp"

#include "host/AtomicFile.hpp"
#include "host/TextFile.hpp"

#include <volpost/core/ParseJson.hpp>

#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>

namespace volpost::app {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

// Reads keys with messages that name the file and the key ("volume.mode").
class Reader {
 public:
  explicit Reader(std::string file) : file_(std::move(file)) {}

  [[noreturn]] void fail(const std::string& key, const std::string& what) const {
    throw std::runtime_error(file_ + ": \"" + key + "\" " + what);
  }

  const json* find(const json& object, const std::string& name) const {
    const auto it = object.find(name);
    return it == object.end() || it->is_null() ? nullptr : &*it;
  }

  double number(const json& value, const std::string& key) const {
    if (!value.is_number()) fail(key, "must be a number");
    const double v = value.get<double>();
    if (!std::isfinite(v)) fail(key, "must be a finite number");
    return v;
  }
  bool boolean(const json& value, const std::string& key) const {
    if (!value.is_boolean()) fail(key, "must be true or false");
    return value.get<bool>();
  }
  std::string text(const json& value, const std::string& key) const {
    if (!value.is_string()) fail(key, "must be a string");
    return value.get<std::string>();
  }
  glm::dvec3 vec3(const json& value, const std::string& key) const {
    if (!value.is_array() || value.size() != 3) fail(key, "must be three numbers [x, y, z]");
    return {number(value[0], key + "[0]"), number(value[1], key + "[1]"), number(value[2], key + "[2]")};
  }
  const json& object(const json& value, const std::string& key) const {
    if (!value.is_object()) fail(key, "must be an object {...}");
    return value;
  }
  const json& array(const json& value, const std::string& key) const {
    if (!value.is_array()) fail(key, "must be a list [...]");
    return value;
  }

 private:
  std::string file_;
};

json jsonOf(const glm::dvec3& v) { return json::array({v.x, v.y, v.z}); }

json jsonOf(const std::vector<ClipPlane>& planes) {
  json out = json::array();
  for (const ClipPlane& p : planes) out.push_back({{"point", jsonOf(p.point)}, {"normal", jsonOf(p.normal)}});
  return out;
}

json jsonOf(const VolumeLayer& v) {
  json out;
  out["shown"] = v.shown;
  out["renderer"] = v.renderer;
  out["mode"] = std::string(toString(v.mode));
  out["transferFunction"] = v.transferFunction ? json::parse(v.transferFunction->toJson()) : json(nullptr);
  out["clipPlanes"] = jsonOf(v.clipPlanes);
  out["clipBox"] = v.clipBox ? json(*v.clipBox) : json(nullptr);
  json isos = json::array();
  for (const optics::IsoSurface& s : v.isoSurfaces)
    isos.push_back({{"value", s.value}, {"color", jsonOf(s.color)}, {"opacity", s.opacity}});
  out["isoSurfaces"] = isos;
  if (!v.isoQuantity.empty()) out["isoQuantity"] = v.isoQuantity;
  out["samplingStep"] = v.samplingStep;
  out["termination"] = v.termination;
  out["interpolation"] = toString(v.interpolation);
  out["elementTolerance"] = v.elementTolerance;
  out["shading"] = v.shading;
  if (v.transferFunction2D) out["transferFunction2D"] = json::parse(v.transferFunction2D->toJson());
  out["edges"] = v.edges;
  out["outline"] = v.outline;
  return out;
}

// Planes as [{"point": [x, y, z], "normal": [x, y, z]}, ...] under `name`.
std::vector<ClipPlane> planesFrom(const Reader& r, const json& in, const std::string& name) {
  std::vector<ClipPlane> out;
  const json& planes = r.array(in, name);
  for (std::size_t i = 0; i < planes.size(); ++i) {
    const std::string key = name + "[" + std::to_string(i) + "]";
    const json& p = r.object(planes[i], key);
    const json* point = r.find(p, "point");
    const json* normal = r.find(p, "normal");
    if (!point || !normal) r.fail(key, "needs \"point\" and \"normal\"");
    ClipPlane plane{r.vec3(*point, key + ".point"), r.vec3(*normal, key + ".normal")};
    if (!(glm::length(plane.normal) > 0.0) || !std::isfinite(glm::length(plane.normal)))
      r.fail(key + ".normal", "must be a finite, non-zero direction");
    out.push_back(plane);
  }
  return out;
}

VolumeLayer volumeFrom(const Reader& r, const json& in, const std::string& fileName) {
  VolumeLayer v;
  if (const json* x = r.find(in, "shown")) v.shown = r.boolean(*x, "volume.shown");
  if (const json* x = r.find(in, "renderer")) v.renderer = r.text(*x, "volume.renderer");
  if (const json* x = r.find(in, "mode")) {
    const auto mode = integrationModeFromString(r.text(*x, "volume.mode"));
    if (!mode) r.fail("volume.mode", "must be one of: " + integrationModeChoices());
    v.mode = *mode;
  }
  if (const json* x = r.find(in, "transferFunction")) {
    try {
      v.transferFunction = TransferFunction::fromJson(r.object(*x, "volume.transferFunction").dump());
    } catch (const std::runtime_error& e) {
      throw std::runtime_error(fileName + ": \"volume.transferFunction\": " + e.what());
    }
  }
  if (const json* x = r.find(in, "transferFunction2D")) {
    try {
      if (!x->is_null())
        v.transferFunction2D = TransferFunction2D::fromJson(r.object(*x, "volume.transferFunction2D").dump());
    } catch (const std::runtime_error& e) {
      throw std::runtime_error(fileName + ": \"volume.transferFunction2D\": " + e.what());
    }
  }
  if (const json* x = r.find(in, "clipPlanes")) v.clipPlanes = planesFrom(r, *x, "volume.clipPlanes");
  if (const json* x = r.find(in, "clipBox")) {
    const json& box = r.array(*x, "volume.clipBox");
    if (box.size() != 6) r.fail("volume.clipBox", "must be six numbers [xmin, xmax, ymin, ymax, zmin, zmax]");
    ClipBox b{};
    for (std::size_t i = 0; i < 6; ++i) b[i] = r.number(box[i], "volume.clipBox[" + std::to_string(i) + "]");
    for (std::size_t i = 0; i < 6; i += 2)
      if (!(b[i] < b[i + 1])) r.fail("volume.clipBox", "needs min < max on every axis");
    v.clipBox = b;
  }
  if (const json* x = r.find(in, "isoQuantity")) v.isoQuantity = r.text(*x, "volume.isoQuantity");
  if (const json* x = r.find(in, "isoSurfaces")) {
    const json& isos = r.array(*x, "volume.isoSurfaces");
    for (std::size_t i = 0; i < isos.size(); ++i) {
      const std::string key = "volume.isoSurfaces[" + std::to_string(i) + "]";
      const json& s = r.object(isos[i], key);
      const json* value = r.find(s, "value");
      if (!value) r.fail(key, "needs a \"value\"");
      optics::IsoSurface iso{r.number(*value, key + ".value"), glm::dvec3(1.0), 1.0};
      if (const json* c = r.find(s, "color")) iso.color = r.vec3(*c, key + ".color");
      if (const json* o = r.find(s, "opacity")) iso.opacity = r.number(*o, key + ".opacity");
      for (int k = 0; k < 3; ++k)
        if (iso.color[k] < 0.0 || iso.color[k] > 1.0) r.fail(key + ".color", "components must lie in 0..1");
      if (iso.opacity < 0.0 || iso.opacity > 1.0) r.fail(key + ".opacity", "must lie in 0..1");
      v.isoSurfaces.push_back(iso);
    }
    if (v.isoSurfaces.size() > std::size_t(kMaxIsoSurfaces))
      r.fail("volume.isoSurfaces", "has " + std::to_string(v.isoSurfaces.size()) + " entries; at most " +
                                       std::to_string(kMaxIsoSurfaces));
  }
  if (v.allClipPlanes().size() > std::size_t(kMaxClipPlanes))
    r.fail("volume.clipPlanes", "with the clip box makes " + std::to_string(v.allClipPlanes().size()) +
                                    " planes; at most " + std::to_string(kMaxClipPlanes));
  if (const json* x = r.find(in, "samplingStep")) {
    v.samplingStep = r.number(*x, "volume.samplingStep");
    if (v.samplingStep < 0.0) r.fail("volume.samplingStep", "must be >= 0 (0: automatic)");
  }
  if (const json* x = r.find(in, "termination")) {
    v.termination = r.number(*x, "volume.termination");
    if (v.termination < 0.0 || v.termination >= 1.0) r.fail("volume.termination", "must lie in [0, 1)");
  }
  if (const json* x = r.find(in, "interpolation")) {
    const auto interpolation = fieldInterpolationFromString(r.text(*x, "volume.interpolation"));
    if (!interpolation) r.fail("volume.interpolation", std::string("must be one of: ") + kFieldInterpolationChoices);
    v.interpolation = *interpolation;
  }
  if (const json* x = r.find(in, "elementTolerance")) {
    v.elementTolerance = r.number(*x, "volume.elementTolerance");
    if (!validElementTolerance(v.elementTolerance)) r.fail("volume.elementTolerance", kElementToleranceRule);
  }
  if (const json* x = r.find(in, "edges")) v.edges = r.boolean(*x, "volume.edges");
  if (const json* x = r.find(in, "outline")) v.outline = r.boolean(*x, "volume.outline");
  if (const json* x = r.find(in, "shading")) v.shading = r.boolean(*x, "volume.shading");
  return v;
}

json jsonOf(const StreamlineLayer& l) {
  return {{"shown", l.shown},
          {"field", l.field},
          {"seeds", l.seeds},
          {"integrator", toString(l.settings.method)},
          {"direction", toString(l.settings.direction)},
          {"tolerance", l.settings.tolerance},
          {"maxSteps", l.settings.maxSteps},
          {"maxLength", l.settings.maxLength},
          {"pointSpacing", l.settings.pointSpacing},
          {"stagnation", l.settings.stagnation},
          {"closedOrbits", l.settings.stopOnClosedOrbits},
          {"colorBy", l.colorBy},
          {"width", l.style.width},
          {"tubes", l.style.tubes},
          {"tubeRadius", l.style.tubeRadius},
          {"radiusByValue", l.style.radiusByValue},
          {"arrows", l.style.arrows},
          {"arrowSpacing", l.style.arrowSpacing},
          {"averageCellVectors", l.averageCellVectors}};
}

StreamlineLayer streamlinesFrom(const Reader& r, const json& in) {
  StreamlineLayer l;
  const auto text = [&](const char* key, std::string& out) {
    if (const json* x = r.find(in, key)) out = r.text(*x, std::string("streamlines.") + key);
  };
  const auto flag = [&](const char* key, bool& out) {
    if (const json* x = r.find(in, key)) out = r.boolean(*x, std::string("streamlines.") + key);
  };
  const auto number = [&](const char* key, double& out, double min) {
    if (const json* x = r.find(in, key)) {
      out = r.number(*x, std::string("streamlines.") + key);
      if (!(out >= min)) r.fail(std::string("streamlines.") + key, "must be at least " + std::to_string(min));
    }
  };
  flag("shown", l.shown);
  text("field", l.field);
  if (const json* x = r.find(in, "seeds")) {
    for (std::size_t i = 0; i < r.array(*x, "streamlines.seeds").size(); ++i)
      l.seeds.push_back(r.text((*x)[i], "streamlines.seeds[" + std::to_string(i) + "]"));
  }
  std::string method = toString(l.settings.method), direction = toString(l.settings.direction);
  text("integrator", method);
  text("direction", direction);
  if (method == "rk2") l.settings.method = StreamlineMethod::RK2;
  else if (method == "rk4") l.settings.method = StreamlineMethod::RK4;
  else if (method == "rk45") l.settings.method = StreamlineMethod::RK45;
  else r.fail("streamlines.integrator", "must be rk2, rk4 or rk45");
  if (direction == "forward") l.settings.direction = StreamlineDirection::Forward;
  else if (direction == "backward") l.settings.direction = StreamlineDirection::Backward;
  else if (direction == "both") l.settings.direction = StreamlineDirection::Both;
  else r.fail("streamlines.direction", "must be forward, backward or both");
  number("tolerance", l.settings.tolerance, 1e-14);
  double steps = double(l.settings.maxSteps);
  number("maxSteps", steps, 1.0);
  l.settings.maxSteps = std::size_t(std::min(steps, 1e8));
  number("maxLength", l.settings.maxLength, 0.0);
  number("pointSpacing", l.settings.pointSpacing, 0.0);
  number("stagnation", l.settings.stagnation, 0.0);
  flag("closedOrbits", l.settings.stopOnClosedOrbits);
  text("colorBy", l.colorBy);
  double width = l.style.width;
  number("width", width, 1.0);
  l.style.width = float(std::min(width, 64.0));
  flag("tubes", l.style.tubes);
  number("tubeRadius", l.style.tubeRadius, 0.0);
  flag("radiusByValue", l.style.radiusByValue);
  flag("arrows", l.style.arrows);
  number("arrowSpacing", l.style.arrowSpacing, 0.0);
  flag("averageCellVectors", l.averageCellVectors);
  if (l.shown && (l.field.empty() || l.seeds.empty())) r.fail("streamlines", "are shown but name no field or no seeds");
  return l;
}

json jsonOf(const GlyphLayer& g) {
  return {{"shown", g.shown},
          {"field", g.field},
          {"colorBy", g.colorBy},
          {"fixedLength", g.fixedLength},
          {"scale", g.scale ? json(*g.scale) : json("auto")},
          {"every", g.every},
          {"allNodes", g.allNodes}};
}

GlyphLayer glyphsFrom(const Reader& r, const json& in) {
  GlyphLayer g;
  if (const json* x = r.find(in, "shown")) g.shown = r.boolean(*x, "glyphs.shown");
  if (const json* x = r.find(in, "field")) g.field = r.text(*x, "glyphs.field");
  if (const json* x = r.find(in, "colorBy")) g.colorBy = r.text(*x, "glyphs.colorBy");
  if (const json* x = r.find(in, "fixedLength")) g.fixedLength = r.boolean(*x, "glyphs.fixedLength");
  if (const json* x = r.find(in, "allNodes")) g.allNodes = r.boolean(*x, "glyphs.allNodes");
  if (const json* x = r.find(in, "scale"); x && !(x->is_string() && x->get<std::string>() == "auto")) {
    g.scale = r.number(*x, "glyphs.scale");
    if (!(*g.scale > 0.0)) r.fail("glyphs.scale", "must be a positive number or \"auto\"");
  }
  if (const json* x = r.find(in, "every")) {
    const double every = r.number(*x, "glyphs.every");
    if (!(every >= 0.0 && every <= 1e9) || every != std::floor(every))
      r.fail("glyphs.every", "must be a whole number >= 0 (0: automatic)");
    g.every = int(every);
  }
  if (g.shown && g.field.empty()) r.fail("glyphs", "are shown but name no field");
  return g;
}

json jsonOf(const ThresholdLayer& t) {
  return {{"shown", t.shown},
          {"quantity", t.quantity},
          {"range", json::array({t.min, t.max})},
          {"nodes", t.allNodes ? "all" : "any"}};
}

ThresholdLayer thresholdFrom(const Reader& r, const json& in) {
  ThresholdLayer t;
  if (const json* x = r.find(in, "shown")) t.shown = r.boolean(*x, "threshold.shown");
  if (const json* x = r.find(in, "quantity")) t.quantity = r.text(*x, "threshold.quantity");
  if (const json* x = r.find(in, "range")) {
    if (!x->is_array() || x->size() != 2) r.fail("threshold.range", "must be [min, max]");
    t.min = r.number((*x)[0], "threshold.range[0]");
    t.max = r.number((*x)[1], "threshold.range[1]");
    if (!(t.min <= t.max)) r.fail("threshold.range", "needs min <= max");
  }
  if (const json* x = r.find(in, "nodes")) {
    const std::string nodes = r.text(*x, "threshold.nodes");
    if (nodes != "all" && nodes != "any") r.fail("threshold.nodes", "must be \"all\" or \"any\"");
    t.allNodes = nodes == "all";
  }
  if (t.shown && t.quantity.empty()) r.fail("threshold", "is shown but names no quantity");
  return t;
}

json jsonOf(const SetVisibility& v) {
  json out = {{"shown", v.shown}, {"hidden", v.hidden}};
  if (!v.marked.empty()) out["marked"] = v.marked;
  if (v.numbers) out["numbers"] = true;
  if (v.colors) out["colors"] = true;
  return out;
}

SetVisibility setsFrom(const Reader& r, const json& in) {
  SetVisibility v;
  const auto names = [&](const char* key, std::vector<std::string>& out) {
    const json* x = r.find(in, key);
    if (!x) return;
    const std::string where = std::string("sets.") + key;
    for (std::size_t i = 0; i < r.array(*x, where).size(); ++i)
      out.push_back(r.text((*x)[i], where + "[" + std::to_string(i) + "]"));
  };
  names("shown", v.shown);
  names("hidden", v.hidden);
  if (const json* x = r.find(in, "marked")) v.marked = r.text(*x, "sets.marked");
  if (const json* x = r.find(in, "numbers")) v.numbers = r.boolean(*x, "sets.numbers");
  if (const json* x = r.find(in, "colors")) v.colors = r.boolean(*x, "sets.colors");
  if (v.numbers && v.marked.empty()) r.fail("sets.numbers", "writes the marked set's numbers: name one in sets.marked");
  return v;
}

json jsonOf(const CameraState& camera) {
  json out = {{"eye", jsonOf(camera.eye)},
              {"target", jsonOf(camera.target)},
              {"up", jsonOf(camera.up)},
              {"fieldOfView", camera.fieldOfView},
              {"projection", camera.orthographic ? "orthographic" : "perspective"}};
  if (camera.rotation && camera.distance) {
    const glm::dquat& q = *camera.rotation;
    out["rotation"] = json::array({q.w, q.x, q.y, q.z});
    out["distance"] = *camera.distance;
  }
  return out;
}

// A camera object of the file; `key` names it in messages ("camera", "views[2].camera").
CameraState cameraFrom(const Reader& r, const json& camera, const std::string& key) {
  r.object(camera, key);
  CameraState c;
  const json* eye = r.find(camera, "eye");
  const json* target = r.find(camera, "target");
  const json* up = r.find(camera, "up");
  if (!eye || !target || !up) r.fail(key, "needs \"eye\", \"target\" and \"up\"");
  c.eye = r.vec3(*eye, key + ".eye");
  c.target = r.vec3(*target, key + ".target");
  c.up = r.vec3(*up, key + ".up");
  if (const json* f = r.find(camera, "fieldOfView")) c.fieldOfView = r.number(*f, key + ".fieldOfView");
  if (!(c.fieldOfView > 0.0 && c.fieldOfView < 180.0))
    r.fail(key + ".fieldOfView", "must lie between 0 and 180 degrees");
  if (const json* p = r.find(camera, "projection")) {
    const std::string projection = r.text(*p, key + ".projection");
    if (projection != "perspective" && projection != "orthographic")
      r.fail(key + ".projection", "must be \"perspective\" or \"orthographic\"");
    c.orthographic = projection == "orthographic";
  }
  const json* rotation = r.find(camera, "rotation");
  const json* distance = r.find(camera, "distance");
  if (bool(rotation) != bool(distance)) r.fail(key, "needs \"rotation\" and \"distance\" together");
  if (rotation) {
    if (!rotation->is_array() || rotation->size() != 4) r.fail(key + ".rotation", "must be [w, x, y, z]");
    double q[4];
    for (std::size_t i = 0; i < 4; ++i) q[i] = r.number((*rotation)[i], key + ".rotation");
    c.rotation = glm::dquat(q[0], q[1], q[2], q[3]);
    c.distance = r.number(*distance, key + ".distance");
    if (!(glm::length(*c.rotation) > 0.0) || !(*c.distance > 0.0) || !std::isfinite(*c.distance))
      r.fail(key, "has a zero rotation or a distance that is not positive");
  }
  if (!(glm::length(c.eye - c.target) > 0.0)) r.fail(key, "has the eye on the target");
  if (!(glm::length(glm::cross(c.target - c.eye, c.up)) > 0.0))
    r.fail(key + ".up", "is parallel to the view direction");
  return c;
}

}  // namespace

std::string viewNameProblem(const std::string& name) {
  if (name.empty() || name.find_first_not_of(" \t") == std::string::npos) return "is empty";
  if (name.size() > kMaxViewNameBytes) return "is longer than " + std::to_string(kMaxViewNameBytes) + " bytes";
  for (const unsigned char c : name)
    if (c < 0x20) return "holds a control character";
  return {};
}

std::vector<ClipPlane> clipBoxPlanes(const ClipBox& b) {
  return {{{b[0], 0, 0}, {1, 0, 0}}, {{b[1], 0, 0}, {-1, 0, 0}}, {{0, b[2], 0}, {0, 1, 0}},
          {{0, b[3], 0}, {0, -1, 0}}, {{0, 0, b[4]}, {0, 0, 1}}, {{0, 0, b[5]}, {0, 0, -1}}};
}

std::vector<ClipPlane> VolumeLayer::allClipPlanes() const {
  std::vector<ClipPlane> planes = clipBox ? clipBoxPlanes(*clipBox) : std::vector<ClipPlane>{};
  planes.insert(planes.end(), clipPlanes.begin(), clipPlanes.end());
  return planes;
}

std::string SceneState::toJson(const std::string& relativeTo) const {
  json out;
  out["format"] = "volpost-state";
  out["version"] = kVersion;
  std::string model = modelPath;
  if (!relativeTo.empty() && !model.empty()) {
    // Compared with links resolved: a model reached through a linked folder (a home on
    // another disk) still lies below the state's folder.
    std::error_code error;
    fs::path absolute = fs::weakly_canonical(fs::absolute(model), error);
    if (error) absolute = fs::absolute(model).lexically_normal();
    fs::path folder = fs::weakly_canonical(fs::absolute(relativeTo), error);
    if (error) folder = fs::absolute(relativeTo).lexically_normal();
    // Below the state's folder: relative to it (the two move together); elsewhere: absolute
    // (a path relative to where the command ran would be read relative to the state).
    const fs::path relative = absolute.lexically_relative(folder);
    model = !relative.empty() && *relative.begin() != ".." ? relative.string() : absolute.string();
  }
  out["model"] = model;
  if (!readerOptions.empty()) out["readerOptions"] = readerOptions;
  if (gridSlices[0] || gridSlices[1] || gridSlices[2]) {
    json slices = json::array();
    for (const auto& s : gridSlices) slices.push_back(s ? json(*s) : json(nullptr));
    out["gridSlices"] = slices;
  }
  if (!formulas.empty()) {
    json list = json::array();
    for (const FormulaSpec& f : formulas) list.push_back({{"name", f.name}, {"expression", f.expression}});
    out["formulas"] = list;
  }
  out["result"] = {{"quantity", quantity.empty() ? json(nullptr) : json(quantity)}, {"step", step + 1}};
  out["camera"] = camera ? jsonOf(*camera) : json(nullptr);
  if (!views.empty()) {
    json named = json::array();
    for (const NamedView& v : views) named.push_back({{"name", v.name}, {"camera", jsonOf(v.camera)}});
    out["views"] = named;
  }
  out["colors"] = {{"map", colorMap},
                   {"range", fixedRange       ? json::array({fixedRange->min, fixedRange->max})
                             : rangeOverSteps ? json("all-steps")
                                              : json("auto")},
                   {"symmetric", symmetricAuto ? json("auto") : json(symmetricRange)},
                   {"bands", colorBands},
                   {"log", logScale},
                   {"below", belowColor ? jsonOf(*belowColor) : json(nullptr)},
                   {"above", aboveColor ? jsonOf(*aboveColor) : json(nullptr)}};
  out["surface"] = {{"shown", surfaceShown},  {"representation", toString(representation)},
                    {"pointSize", pointSize}, {"edges", edges},
                    {"lighting", lighting},   {"opacity", surfaceOpacity}};
  if (!slicePlanes.empty()) out["slicePlanes"] = jsonOf(slicePlanes);
  out["legend"] = legend;
  if (!title.empty()) out["title"] = title;
  if (stepText) out["stepText"] = true;
  out["legendText"] = {
      {"titles", legendTitles}, {"units", units}, {"numbers", legendNumbers}, {"labels", legendLabels}};
  out["triad"] = triad;
  out["background"] = jsonOf(background);
  out["textScale"] = textScale;
  out["volume"] = jsonOf(volume);
  out["streamlines"] = jsonOf(streamlines);
  if (glyphs != GlyphLayer{}) out["glyphs"] = jsonOf(glyphs);
  if (threshold != ThresholdLayer{}) out["threshold"] = jsonOf(threshold);
  if (sets.active() || !sets.marked.empty() || sets.colors) out["sets"] = jsonOf(sets);
  if (!selection.empty()) {
    json picked = json::object();
    if (!selection.elements.empty()) picked["elements"] = idListText(selection.elements);
    if (!selection.nodes.empty()) picked["nodes"] = idListText(selection.nodes);
    out["selection"] = picked;
  }
  out["deformation"] = {{"shown", deformation.shown},
                        {"field", deformation.field},
                        {"scale", deformation.scale ? json(*deformation.scale) : json("auto")},
                        {"undeformedOutline", deformation.undeformedOutline}};
  json points = json::array();
  for (const glm::dvec3& p : probes) points.push_back(jsonOf(p));
  out["markers"] = {{"probes", points}, {"extremes", markExtremes}};
  if (!measure.empty()) {
    json numbers = json::array();
    for (const std::size_t i : measure) numbers.push_back(i + 1);
    out["markers"]["measure"] = numbers;
  }
  if (plotLine) out["plotLine"] = {{"from", jsonOf((*plotLine)[0])}, {"to", jsonOf((*plotLine)[1])}};
  return out.dump(2) + "\n";
}

SceneState SceneState::fromJson(const std::string& text, const std::string& fileName) {
  const json in = parseJson(text, fileName + ": not valid JSON");
  const Reader r(fileName);
  const auto format = in.is_object() ? in.find("format") : in.end();
  if (!in.is_object() || format == in.end() || !format->is_string() || format->get<std::string>() != "volpost-state")
    throw std::runtime_error(fileName + ": not a volpost state file (no \"format\": \"volpost-state\")");
  const json* version = r.find(in, "version");
  if (!version || !version->is_number_integer()) r.fail("version", "must be an integer");
  if (version->get<long long>() > kVersion || version->get<long long>() < 1)
    r.fail("version", "is " + version->dump() + "; this volpost reads state files up to version " +
                          std::to_string(kVersion));
  SceneState s;
  const json* model = r.find(in, "model");
  if (!model) r.fail("model", "is missing (the model file to open)");
  s.modelPath = r.text(*model, "model");
  if (!s.modelPath.empty() && fs::path(s.modelPath).is_relative())
    s.modelPath = (fs::absolute(fileName).parent_path() / s.modelPath).lexically_normal().string();
  if (const json* x = r.find(in, "slicePlanes")) {
    s.slicePlanes = planesFrom(r, *x, "slicePlanes");
    if (s.slicePlanes.size() > kMaxSlicePlanes)
      r.fail("slicePlanes",
             "has " + std::to_string(s.slicePlanes.size()) + " planes; at most " + std::to_string(kMaxSlicePlanes));
  }
  if (const json* slices = r.find(in, "gridSlices")) {
    if (!slices->is_array() || slices->size() != 3)
      r.fail("gridSlices", "must be [inline, crossline, time]: a number or null for each grid axis");
    for (std::size_t a = 0; a < 3; ++a)
      if (!(*slices)[a].is_null()) s.gridSlices[a] = r.number((*slices)[a], "gridSlices");
  }
  if (const json* options = r.find(in, "readerOptions")) {
    r.object(*options, "readerOptions");
    for (const auto& [name, value] : options->items())
      s.readerOptions[name] = r.text(value, "readerOptions." + name);
  }
  if (const json* formulas = r.find(in, "formulas")) {
    const json& list = r.array(*formulas, "formulas");
    if (list.size() > kMaxFormulas)
      r.fail("formulas", "holds " + std::to_string(list.size()) + " formulas; at most " + std::to_string(kMaxFormulas));
    for (std::size_t i = 0; i < list.size(); ++i) {
      const std::string key = "formulas[" + std::to_string(i) + "]";
      const json& f = r.object(list[i], key);
      const json* name = r.find(f, "name");
      const json* expression = r.find(f, "expression");
      if (!name || !expression) r.fail(key, "needs \"name\" and \"expression\"");
      s.formulas.push_back({r.text(*name, key + ".name"), r.text(*expression, key + ".expression")});
    }
  }
  if (const json* result = r.find(in, "result")) {
    r.object(*result, "result");
    if (const json* q = r.find(*result, "quantity")) s.quantity = r.text(*q, "result.quantity");
    if (const json* st = r.find(*result, "step")) {
      if (!st->is_number_integer() || st->get<long long>() < 1) r.fail("result.step", "must be a step number (1, 2, ...)");
      s.step = std::size_t(st->get<long long>() - 1);
    }
  }
  if (const json* camera = r.find(in, "camera")) s.camera = cameraFrom(r, *camera, "camera");
  if (const json* views = r.find(in, "views")) {
    const json& named = r.array(*views, "views");
    if (named.size() > kMaxViews)
      r.fail("views", "holds " + std::to_string(named.size()) + " views; at most " + std::to_string(kMaxViews));
    for (std::size_t i = 0; i < named.size(); ++i) {
      const std::string key = "views[" + std::to_string(i) + "]";
      const json& v = r.object(named[i], key);
      const json* name = r.find(v, "name");
      const json* camera = r.find(v, "camera");
      if (!name || !camera) r.fail(key, "needs \"name\" and \"camera\"");
      NamedView view{r.text(*name, key + ".name"), cameraFrom(r, *camera, key + ".camera")};
      if (const std::string why = viewNameProblem(view.name); !why.empty()) r.fail(key + ".name", why);
      for (const NamedView& earlier : s.views)
        if (earlier.name == view.name) r.fail(key + ".name", "repeats the name \"" + view.name + "\"");
      s.views.push_back(std::move(view));
    }
  }
  if (const json* t = r.find(in, "title")) {
    s.title = r.text(*t, "title");
    if (s.title.size() > 200) r.fail("title", "is longer than 200 bytes");
  }
  if (const json* words = r.find(in, "legendText")) {
    r.object(*words, "legendText");
    for (const char* key : {"titles", "units"})
      if (const json* map = r.find(*words, key)) {
        r.object(*map, std::string("legendText.") + key);
        for (const auto& [name, value] : map->items()) {
          std::string entry = r.text(value, std::string("legendText.") + key + "." + name);
          if (entry.size() > 200) r.fail(std::string("legendText.") + key + "." + name, "is longer than 200 bytes");
          (std::string(key) == "titles" ? s.legendTitles : s.units)[name] = std::move(entry);
        }
      }
    if (const json* numbers = r.find(*words, "numbers")) {
      s.legendNumbers = r.text(*numbers, "legendText.numbers");
      if (!LegendNumbers::parse(s.legendNumbers))
        r.fail("legendText.numbers", "must be auto[:DIGITS], fixed[:DIGITS] or scientific[:DIGITS]");
    }
    if (const json* labels = r.find(*words, "labels")) {
      if (!labels->is_number_integer() || labels->get<long long>() < 2 || labels->get<long long>() > 20)
        r.fail("legendText.labels", "must be a count from 2 to 20");
      s.legendLabels = int(labels->get<long long>());
    }
  }
  if (const json* colors = r.find(in, "colors")) {
    r.object(*colors, "colors");
    if (const json* m = r.find(*colors, "map")) s.colorMap = r.text(*m, "colors.map");
    if (const json* symmetric = r.find(*colors, "symmetric")) {
      s.symmetricAuto = symmetric->is_string() && symmetric->get<std::string>() == "auto";
      if (!s.symmetricAuto) s.symmetricRange = r.boolean(*symmetric, "colors.symmetric");
    }
    for (const char* key : {"below", "above"})
      if (const json* c = r.find(*colors, key); c && !c->is_null()) {
        const std::string name = std::string("colors.") + key;
        if (!c->is_array() || c->size() != 3) r.fail(name, "must be [r, g, b] with each 0..1, or null");
        glm::dvec3 rgb;
        for (int i = 0; i < 3; ++i) {
          rgb[i] = r.number((*c)[std::size_t(i)], name);
          if (!(rgb[i] >= 0.0 && rgb[i] <= 1.0)) r.fail(name, "must be [r, g, b] with each 0..1, or null");
        }
        (std::string(key) == "below" ? s.belowColor : s.aboveColor) = rgb;
      }
    if (const json* log = r.find(*colors, "log")) s.logScale = r.boolean(*log, "colors.log");
    if (const json* bands = r.find(*colors, "bands")) {
      if (!bands->is_number_integer() || bands->get<long long>() < 0 || bands->get<long long>() > kMaxColorBands ||
          bands->get<long long>() == 1)
        r.fail("colors.bands",
               "must be 0 (continuous colors) or a band count from 2 to " + std::to_string(kMaxColorBands));
      s.colorBands = int(bands->get<long long>());
    }
    if (const json* range = r.find(*colors, "range")) {
      if (range->is_string() && (range->get<std::string>() == "auto" || range->get<std::string>() == "all-steps")) {
        s.fixedRange.reset();
        s.rangeOverSteps = range->get<std::string>() == "all-steps";
      } else {
        if (!range->is_array() || range->size() != 2)
          r.fail("colors.range", "must be \"auto\" (each step's own), \"all-steps\" or [min, max]");
        DisplayRange d{r.number((*range)[0], "colors.range[0]"), r.number((*range)[1], "colors.range[1]")};
        if (!(d.max > d.min)) r.fail("colors.range", "needs min < max");
        s.fixedRange = d;
      }
    }
  }
  if (const json* surface = r.find(in, "surface")) {
    r.object(*surface, "surface");
    if (const json* e = r.find(*surface, "edges")) s.edges = r.boolean(*e, "surface.edges");
    if (const json* l = r.find(*surface, "lighting")) s.lighting = r.boolean(*l, "surface.lighting");
    if (const json* v = r.find(*surface, "shown")) s.surfaceShown = r.boolean(*v, "surface.shown");
    if (const json* x = r.find(*surface, "representation")) {
      const auto representation = surfaceRepresentationFromString(r.text(*x, "surface.representation"));
      if (!representation) r.fail("surface.representation", "must be one of: " + surfaceRepresentationChoices());
      s.representation = *representation;
    }
    if (const json* x = r.find(*surface, "pointSize")) {
      s.pointSize = r.number(*x, "surface.pointSize");
      if (!(s.pointSize >= 1.0 && s.pointSize <= kMaxPointSize)) r.fail("surface.pointSize", "must lie in 1..64");
    }
    if (const json* o = r.find(*surface, "opacity")) {
      s.surfaceOpacity = r.number(*o, "surface.opacity");
      if (!(s.surfaceOpacity >= 0.0 && s.surfaceOpacity <= 1.0)) r.fail("surface.opacity", "must lie in 0..1");
    }
  }
  if (const json* legend = r.find(in, "legend")) s.legend = r.boolean(*legend, "legend");
  if (const json* triad = r.find(in, "triad")) s.triad = r.boolean(*triad, "triad");
  if (const json* x = r.find(in, "stepText")) s.stepText = r.boolean(*x, "stepText");
  if (const json* x = r.find(in, "background")) {
    s.background = r.vec3(*x, "background");
    for (int k = 0; k < 3; ++k)
      if (!(s.background[k] >= 0.0 && s.background[k] <= 1.0)) r.fail("background", "components must lie in 0..1");
  }
  if (const json* x = r.find(in, "textScale")) {
    s.textScale = r.number(*x, "textScale");
    if (!(s.textScale >= kMinTextScale && s.textScale <= kMaxTextScale)) r.fail("textScale", "must lie in 0.25..8");
  }
  if (const json* volume = r.find(in, "volume")) s.volume = volumeFrom(r, r.object(*volume, "volume"), fileName);
  if (const json* lines = r.find(in, "streamlines")) s.streamlines = streamlinesFrom(r, r.object(*lines, "streamlines"));
  if (const json* g = r.find(in, "glyphs")) s.glyphs = glyphsFrom(r, r.object(*g, "glyphs"));
  if (const json* t = r.find(in, "threshold")) s.threshold = thresholdFrom(r, r.object(*t, "threshold"));
  if (const json* v = r.find(in, "sets")) s.sets = setsFrom(r, r.object(*v, "sets"));
  if (const json* v = r.find(in, "selection")) {
    const auto ids = [&](const char* key) {
      const json* x = r.find(r.object(*v, "selection"), key);
      if (!x) return std::vector<std::int64_t>{};
      const std::string where = std::string("selection.") + key;
      try {
        return parseIdList(r.text(*x, where));
      } catch (const std::invalid_argument& e) {
        r.fail(where, e.what());
      }
    };
    s.selection.elements = ids("elements");
    s.selection.nodes = ids("nodes");
  }
  if (const json* d = r.find(in, "deformation")) {
    r.object(*d, "deformation");
    if (const json* x = r.find(*d, "shown")) s.deformation.shown = r.boolean(*x, "deformation.shown");
    if (const json* x = r.find(*d, "field")) s.deformation.field = r.text(*x, "deformation.field");
    if (const json* x = r.find(*d, "undeformedOutline"))
      s.deformation.undeformedOutline = r.boolean(*x, "deformation.undeformedOutline");
    if (const json* x = r.find(*d, "scale")) {
      if (x->is_string() && x->get<std::string>() == "auto") s.deformation.scale.reset();
      else s.deformation.scale = r.number(*x, "deformation.scale");
    }
  }
  if (const json* line = r.find(in, "plotLine")) {
    r.object(*line, "plotLine");
    const json* from = r.find(*line, "from");
    const json* to = r.find(*line, "to");
    if (!from || !to) r.fail("plotLine", "needs \"from\" and \"to\"");
    s.plotLine = std::array<glm::dvec3, 2>{r.vec3(*from, "plotLine.from"), r.vec3(*to, "plotLine.to")};
  }
  if (const json* markers = r.find(in, "markers")) {
    r.object(*markers, "markers");
    if (const json* e = r.find(*markers, "extremes")) s.markExtremes = r.boolean(*e, "markers.extremes");
    if (const json* probes = r.find(*markers, "probes")) {
      const json& list = r.array(*probes, "markers.probes");
      if (list.size() > kMaxProbes) r.fail("markers.probes", "has more than " + std::to_string(kMaxProbes) + " points");
      for (std::size_t i = 0; i < list.size(); ++i)
        s.probes.push_back(r.vec3(list[i], "markers.probes[" + std::to_string(i) + "]"));
    }
    if (const json* measure = r.find(*markers, "measure")) {
      const json& list = r.array(*measure, "markers.measure");
      for (std::size_t i = 0; i < list.size() && i < 3; ++i) {
        const double n = r.number(list[i], "markers.measure[" + std::to_string(i) + "]");
        if (!(n >= 1.0 && n <= double(s.probes.size()) && n == std::floor(n)))
          r.fail("markers.measure[" + std::to_string(i) + "]",
                 "is no probe's number (1 to " + std::to_string(s.probes.size()) + ")");
        s.measure.push_back(std::size_t(n) - 1);
      }
      if (list.size() != 2 && list.size() != 3) r.fail("markers.measure", "names two probes, or three for an angle");
    }
  }
  return s;
}

SceneState SceneState::load(const std::string& path) { return fromJson(readTextFile(path, 64u << 20), path); }

void SceneState::save(const std::string& path) const {
  writeFileAtomically(path, toJson(fs::absolute(path).parent_path().string()));
}

}  // namespace volpost::app

// SPDX-License-Identifier: MIT
#include <volpost/core/TransferFunction.hpp>

#include <volpost/core/ParseJson.hpp>

#include <volpost/core/ColorMap.hpp>

#include <glm/common.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace volpost {
namespace {

using Json = nlohmann::json;

void validate(const ControlPoint& p, std::size_t index) {
  const std::string where = "transfer function point " + std::to_string(index) + ": ";
  if (!std::isfinite(p.value)) throw std::invalid_argument(where + "value is not a finite number");
  if (!(p.extinction >= 0.0) || !std::isfinite(p.extinction))
    throw std::invalid_argument(where + "extinction " + std::to_string(p.extinction) + " must be finite and >= 0");
  for (int k = 0; k < 3; ++k)
    if (!(p.color[k] >= 0.0 && p.color[k] <= 1.0))
      throw std::invalid_argument(where + "color component " + std::to_string(p.color[k]) + " is outside 0..1");
}

// Index i such that points[i].value <= s < points[i+1].value, clamped to the ends.
template <typename F>
auto interpolate(const std::vector<ControlPoint>& pts, double s, F member) {
  using T = decltype(member(pts.front()));
  if (pts.empty()) return T{};
  if (s <= pts.front().value) return member(pts.front());
  if (s >= pts.back().value) return member(pts.back());
  const auto hi = std::upper_bound(pts.begin(), pts.end(), s, [](double v, const ControlPoint& p) { return v < p.value; });
  const auto lo = hi - 1;
  const double w = (s - lo->value) / (hi->value - lo->value);
  return T(member(*lo) * (1.0 - w) + member(*hi) * w);
}

double number(const Json& j, const std::string& where) {
  if (!j.is_number()) throw std::runtime_error(where + " must be a number");
  return j.get<double>();
}

}  // namespace

double opacityToExtinction(double opacity, double referenceLength) {
  if (!(opacity >= 0.0 && opacity < 1.0)) throw std::invalid_argument("opacity must be in [0, 1)");
  if (!(referenceLength > 0.0)) throw std::invalid_argument("reference length must be > 0");
  return -std::log1p(-opacity) / referenceLength;
}

double extinctionToOpacity(double extinction, double referenceLength) {
  return -std::expm1(-extinction * referenceLength);
}

TransferFunction::TransferFunction(std::vector<ControlPoint> points) : points_(std::move(points)) {
  if (points_.size() > kMaxPoints)
    throw std::invalid_argument(std::to_string(points_.size()) + " control points: a transfer function has at most " +
                                std::to_string(kMaxPoints));
  std::stable_sort(points_.begin(), points_.end(), [](const auto& a, const auto& b) { return a.value < b.value; });
  for (std::size_t i = 0; i < points_.size(); ++i) validate(points_[i], i);
}

glm::dvec3 TransferFunction::color(double s) const {
  return interpolate(points_, s, [](const ControlPoint& p) { return p.color; });
}

double TransferFunction::extinction(double s) const {
  return interpolate(points_, s, [](const ControlPoint& p) { return p.extinction; });
}

// Binary search to the first point beyond the lower end: the cost follows the points
// crossed, not the function's size (functions of thousands of points stay fast).
bool TransferFunction::transparentOver(double lo, double hi) const {
  if (points_.empty()) return true;
  if (extinction(lo) != 0.0 || extinction(hi) != 0.0) return false;
  // Linear between points: zero throughout when zero at every point in between (and at
  // both sides of a step there).
  for (const ControlPoint& p : points_)
    if (p.value >= lo && p.value <= hi && p.extinction != 0.0) return false;
  return true;
}

std::vector<double> TransferFunction::crossings(double a, double b) const {
  std::vector<double> out;
  const double lo = std::min(a, b), hi = std::max(a, b);
  auto it = std::upper_bound(points_.begin(), points_.end(), lo, [](double v, const ControlPoint& p) { return v < p.value; });
  for (; it != points_.end() && it->value < hi; ++it)
    if (out.empty() || out.back() != it->value) out.push_back(it->value);
  if (a > b) std::reverse(out.begin(), out.end());
  return out;
}

TransferFunction TransferFunction::ramp(double min, double max, const std::string& colorMap, double maxExtinction,
                                        int points) {
  const ColorMap map = ColorMap::named(colorMap);
  std::vector<ControlPoint> pts;
  if (!(max > min)) max = min + 1.0;
  for (int i = 0; i < points; ++i) {
    const double t = double(i) / (points - 1);
    pts.push_back({min + t * (max - min), map.at(t), maxExtinction * t});
  }
  return TransferFunction(std::move(pts));
}

TransferFunction TransferFunction::fromJson(const std::string& text) {
  Json j = parseJson(text, "transfer function JSON");
  const auto isString = [&](const char* key, const char* wanted) {
    return j.contains(key) && j[key].is_string() && j[key].get<std::string>() == wanted;
  };
  if (!j.is_object() || !isString("format", "volpost-tf"))
    throw std::runtime_error("transfer function JSON: not a volpost transfer function (\"format\" must be the string "
                             "\"volpost-tf\")");
  if (!j.contains("version") || !j["version"].is_number_integer() || j["version"].get<long long>() != 1)
    throw std::runtime_error("transfer function JSON: \"version\" " + (j.contains("version") ? j["version"].dump() : std::string("(missing)")) +
                             " is not supported (1 is)");
  if (!j.contains("points") || !j["points"].is_array()) throw std::runtime_error("transfer function JSON: no \"points\" array");
  if (j["points"].empty())
    throw std::runtime_error("transfer function JSON: \"points\" is empty: a transfer function needs at least one "
                             "control point (a volume with none would be invisible)");
  if (j["points"].size() > kMaxPoints)
    throw std::runtime_error("transfer function JSON: " + std::to_string(j["points"].size()) +
                             " points; at most " + std::to_string(kMaxPoints));
  std::vector<ControlPoint> pts;
  for (std::size_t i = 0; i < j["points"].size(); ++i) {
    const Json& p = j["points"][i];
    const std::string where = "transfer function JSON: points[" + std::to_string(i) + "]";
    if (!p.is_object() || !p.contains("value") || !p.contains("color") || !p.contains("extinction"))
      throw std::runtime_error(where + " needs value, color and extinction");
    if (!p["color"].is_array() || p["color"].size() != 3) throw std::runtime_error(where + ".color must be [r, g, b]");
    ControlPoint cp{number(p["value"], where + ".value"),
                    {number(p["color"][0], where + ".color"), number(p["color"][1], where + ".color"),
                     number(p["color"][2], where + ".color")},
                    number(p["extinction"], where + ".extinction")};
    pts.push_back(cp);
  }
  try {
    return TransferFunction(std::move(pts));
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(std::string("transfer function JSON: ") + e.what());
  }
}

std::string TransferFunction::toJson(const std::string& lengthUnit) const {
  Json j = {{"format", "volpost-tf"}, {"version", 1}};
  if (!lengthUnit.empty()) j["lengthUnit"] = lengthUnit;
  j["points"] = Json::array();
  for (const ControlPoint& p : points_)
    j["points"].push_back({{"value", p.value}, {"color", {p.color.r, p.color.g, p.color.b}}, {"extinction", p.extinction}});
  return j.dump(2);
}

TransferFunction TransferFunction::withParaViewColors(const std::string& presetJson, const std::string& presetName,
                                                      std::optional<std::pair<double, double>> range) const {
  Json j = parseJson(presetJson, "ParaView preset");
  Json preset;
  if (j.is_array()) {
    for (const Json& p : j)
      if (p.is_object() && p.contains("RGBPoints") && (presetName.empty() || p.value("Name", "") == presetName)) {
        preset = p;
        break;
      }
    if (preset.is_null())
      throw std::runtime_error("ParaView preset: " + (presetName.empty() ? std::string("no preset with RGBPoints")
                                                                         : "no preset named \"" + presetName + "\""));
  } else {
    preset = j;
  }
  if (!preset.contains("RGBPoints") || !preset["RGBPoints"].is_array() || preset["RGBPoints"].size() < 8 ||
      preset["RGBPoints"].size() % 4 != 0)
    throw std::runtime_error("ParaView preset: \"RGBPoints\" must hold x, r, g, b for at least two points");
  const Json& rgb = preset["RGBPoints"];
  std::vector<ControlPoint> pts;
  const double x0 = number(rgb[0], "RGBPoints[0]"), x1 = number(rgb[rgb.size() - 4], "RGBPoints");
  for (std::size_t i = 0; i < rgb.size(); i += 4) {
    double x = number(rgb[i], "RGBPoints[" + std::to_string(i) + "]");
    if (range && x1 > x0) x = range->first + (x - x0) / (x1 - x0) * (range->second - range->first);
    const glm::dvec3 c(number(rgb[i + 1], "RGBPoints"), number(rgb[i + 2], "RGBPoints"), number(rgb[i + 3], "RGBPoints"));
    pts.push_back({x, glm::clamp(c, 0.0, 1.0), points_.empty() ? 0.0 : extinction(x)});
  }
  // Keep this function's extinction shape: its own points stay, colored by the preset.
  const std::vector<ControlPoint> presetPoints = pts;
  for (const ControlPoint& p : points_)
    pts.push_back({p.value, interpolate(presetPoints, p.value, [](const ControlPoint& q) { return q.color; }), p.extinction});
  return TransferFunction(std::move(pts));
}

}  // namespace volpost

// SPDX-License-Identifier: MIT
#include <volpost/core/TransferFunction2D.hpp>

#include <volpost/core/TransferFunction.hpp>

#include <volpost/core/ParseJson.hpp>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace volpost {
namespace {

using Json = nlohmann::json;

void validate(const TfWidget2D& w, std::size_t index) {
  const std::string where = "2D transfer function widget " + std::to_string(index) + ": ";
  for (const double x : {w.value, w.width, w.gradientLow, w.gradientHigh, w.extinction})
    if (!std::isfinite(x)) throw std::invalid_argument(where + "a number is not finite");
  if (!(w.width > 0.0)) throw std::invalid_argument(where + "width " + std::to_string(w.width) + " must be > 0");
  if (!(w.gradientLow >= 0.0))
    throw std::invalid_argument(where + "gradient " + std::to_string(w.gradientLow) + " must be >= 0 (a magnitude)");
  if (!(w.gradientHigh > w.gradientLow))
    throw std::invalid_argument(where + "the gradient range " + std::to_string(w.gradientLow) + " .. " +
                                std::to_string(w.gradientHigh) + " is empty");
  if (!(w.extinction >= 0.0))
    throw std::invalid_argument(where + "extinction " + std::to_string(w.extinction) + " must be >= 0");
  for (int k = 0; k < 3; ++k)
    if (!(w.color[k] >= 0.0 && w.color[k] <= 1.0))
      throw std::invalid_argument(where + "color component " + std::to_string(w.color[k]) + " is outside 0..1");
}

double number(const Json& j, const std::string& where) {
  if (!j.is_number()) throw std::runtime_error(where + " must be a number");
  return j.get<double>();
}

}  // namespace

double TfWidget2D::weight(double v, double g) const {
  if (g < gradientLow || g > gradientHigh) return 0.0;
  double half = 0.5 * width;
  if (shape == Shape::Triangle) half *= (g - gradientLow) / (gradientHigh - gradientLow);
  return std::abs(v - value) <= half ? 1.0 : 0.0;
}

TransferFunction2D::TransferFunction2D(std::vector<TfWidget2D> widgets) : widgets_(std::move(widgets)) {
  if (widgets_.size() > kMaxWidgets)
    throw std::invalid_argument(std::to_string(widgets_.size()) + " widgets: a 2D transfer function has at most " +
                                std::to_string(kMaxWidgets));
  for (std::size_t i = 0; i < widgets_.size(); ++i) validate(widgets_[i], i);
  buildTable();
}

void TransferFunction2D::buildTable() {
  table_.assign(std::size_t(kValueNodes) * kGradientNodes, glm::vec4(0.0f));
  if (widgets_.empty()) return;
  double lo = 1e300, hi = -1e300, top = 0.0;
  for (const TfWidget2D& w : widgets_) {
    lo = std::min(lo, w.value - 0.5 * w.width);
    hi = std::max(hi, w.value + 0.5 * w.width);
    top = std::max(top, w.gradientHigh);
  }
  // One empty node beyond the widgets on each side of the values and above the gradients:
  // the function falls to zero within one node of a widget's edge.
  const double dv = (hi - lo) / double(kValueNodes - 3), dg = top / double(kGradientNodes - 2);
  valueLow_ = lo - dv;
  valueHigh_ = hi + dv;
  gradientHigh_ = top + dg;
  // The table spans every widget: widgets 1e308 apart give a span beyond a double, and every
  // lookup in it would be NaN.
  if (!std::isfinite(valueHigh_ - valueLow_) || !std::isfinite(gradientHigh_)) {
    char text[240];
    std::snprintf(text, sizeof text,
                  "2D transfer function: its widgets span values %g .. %g and gradients 0 .. %g, too wide for one "
                  "table (the span is beyond a double): keep the widgets within the data's range",
                  lo, hi, top);
    widgets_.clear();
    throw std::invalid_argument(text);
  }
  for (int j = 0; j < kGradientNodes; ++j)
    for (int i = 0; i < kValueNodes; ++i) {
      const double v = valueLow_ + (valueHigh_ - valueLow_) * double(i) / double(kValueNodes - 1);
      const double g = gradientHigh_ * double(j) / double(kGradientNodes - 1);
      glm::dvec4 node(0.0);
      for (const TfWidget2D& w : widgets_)
        if (const double k = w.weight(v, g) * w.extinction; k > 0.0) node += glm::dvec4(w.color * k, k);
      if (node.a > kMaxFloatExtinction) node *= kMaxFloatExtinction / node.a;  // float nodes; the color kept
      table_[std::size_t(j) * kValueNodes + std::size_t(i)] = glm::vec4(node);
    }
}

glm::dvec4 TransferFunction2D::evaluate(double value, double gradient) const {
  if (widgets_.empty() || !(value >= valueLow_ && value <= valueHigh_) || !(gradient >= 0.0 && gradient <= gradientHigh_))
    return glm::dvec4(0.0);
  const double x = (value - valueLow_) / (valueHigh_ - valueLow_) * double(kValueNodes - 1);
  const double y = gradient / gradientHigh_ * double(kGradientNodes - 1);
  if (!(x >= 0.0 && y >= 0.0)) return glm::dvec4(0.0);  // NaN: no node to read
  const int i = std::min(int(x), kValueNodes - 2), j = std::min(int(y), kGradientNodes - 2);
  const double fx = x - double(i), fy = y - double(j);
  const auto node = [&](int a, int b) { return glm::dvec4(table_[std::size_t(b) * kValueNodes + std::size_t(a)]); };
  const glm::dvec4 e = (node(i, j) * (1.0 - fx) + node(i + 1, j) * fx) * (1.0 - fy) +
                       (node(i, j + 1) * (1.0 - fx) + node(i + 1, j + 1) * fx) * fy;
  if (!(e.a > 0.0)) return glm::dvec4(0.0);
  return glm::dvec4(glm::dvec3(e) / e.a, e.a);
}

TransferFunction2D TransferFunction2D::fromJson(const std::string& text) {
  Json j = parseJson(text, "2D transfer function JSON");
  if (!j.is_object() || !j.contains("format") || j["format"] != "volpost-tf2d")
    throw std::runtime_error("2D transfer function JSON: not a volpost 2D transfer function (\"format\" must be the "
                             "string \"volpost-tf2d\")");
  if (!j.contains("version") || !j["version"].is_number_integer() || j["version"].get<long long>() != 1)
    throw std::runtime_error("2D transfer function JSON: \"version\" " +
                             (j.contains("version") ? j["version"].dump() : std::string("(missing)")) +
                             " is not supported (1 is)");
  if (!j.contains("widgets") || !j["widgets"].is_array() || j["widgets"].empty())
    throw std::runtime_error("2D transfer function JSON: needs a non-empty \"widgets\" array");
  if (j["widgets"].size() > kMaxWidgets)
    throw std::runtime_error("2D transfer function JSON: " + std::to_string(j["widgets"].size()) +
                             " widgets; at most " + std::to_string(kMaxWidgets));
  std::vector<TfWidget2D> widgets;
  for (std::size_t i = 0; i < j["widgets"].size(); ++i) {
    const Json& w = j["widgets"][i];
    const std::string where = "2D transfer function JSON: widgets[" + std::to_string(i) + "]";
    if (!w.is_object()) throw std::runtime_error(where + " is not an object");
    for (const char* key : {"shape", "value", "width", "gradient", "color", "extinction"})
      if (!w.contains(key)) throw std::runtime_error(where + " has no \"" + key + "\"");
    TfWidget2D widget;
    if (w["shape"] == "rectangle") widget.shape = TfWidget2D::Shape::Rectangle;
    else if (w["shape"] == "triangle") widget.shape = TfWidget2D::Shape::Triangle;
    else throw std::runtime_error(where + ".shape " + w["shape"].dump() + " is not \"rectangle\" or \"triangle\"");
    widget.value = number(w["value"], where + ".value");
    widget.width = number(w["width"], where + ".width");
    if (!w["gradient"].is_array() || w["gradient"].size() != 2)
      throw std::runtime_error(where + ".gradient must be [low, high]");
    widget.gradientLow = number(w["gradient"][0], where + ".gradient");
    widget.gradientHigh = number(w["gradient"][1], where + ".gradient");
    if (!w["color"].is_array() || w["color"].size() != 3) throw std::runtime_error(where + ".color must be [r, g, b]");
    widget.color = {number(w["color"][0], where + ".color"), number(w["color"][1], where + ".color"),
                    number(w["color"][2], where + ".color")};
    widget.extinction = number(w["extinction"], where + ".extinction");
    widgets.push_back(widget);
  }
  try {
    return TransferFunction2D(std::move(widgets));
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(std::string("2D transfer function JSON: ") + e.what());
  }
}

std::string TransferFunction2D::toJson() const {
  Json widgets = Json::array();
  for (const TfWidget2D& w : widgets_)
    widgets.push_back({{"shape", w.shape == TfWidget2D::Shape::Triangle ? "triangle" : "rectangle"},
                       {"value", w.value},
                       {"width", w.width},
                       {"gradient", {w.gradientLow, w.gradientHigh}},
                       {"color", {w.color.r, w.color.g, w.color.b}},
                       {"extinction", w.extinction}});
  return Json{{"format", "volpost-tf2d"}, {"version", 1}, {"widgets", widgets}}.dump(2);
}

}  // namespace volpost

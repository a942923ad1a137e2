// SPDX-License-Identifier: MIT
// A two-dimensional transfer function over the scalar and its gradient magnitude (Kniss et
// al. 2002): where a 1D transfer function can only say "this value", a 2D one can say
// "this value where it changes fast" - the boundaries between materials (a reflector in a
// seismic cube) apart from the materials' insides of the same value.
//
// It is made of widgets, each a region of the (value, gradient magnitude) plane with a
// color and an extinction coefficient (1 / model length unit, as TransferFunction's):
// rectangles, and triangles whose apex sits at the low gradient (a boundary's values spread
// around its middle value as the gradient grows). Where widgets overlap their extinctions
// add and their colors mix by extinction.
//
// What is rendered is the table: the widgets sampled on a lattice of kValueNodes x
// kGradientNodes nodes over their extent (one empty node beyond it on each side) and
// interpolated bilinearly - emission (color x extinction) and extinction separately, the
// color their quotient. evaluate() is that interpolation in double, the GPU's table holds
// the same nodes, so the reference and the renderers integrate one and the same function,
// and a widget's edge is a ramp one node wide (no aliasing of hard edges).
#pragma once

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <string>
#include <vector>

namespace volpost {

struct TfWidget2D {
  enum class Shape { Rectangle, Triangle };
  Shape shape = Shape::Rectangle;
  double value = 0.0;         ///< the middle value (a triangle's apex)
  double width = 1.0;         ///< across the values (a triangle's at its top), > 0
  double gradientLow = 0.0;   ///< gradient magnitudes covered, field units per length unit (a triangle's apex)
  double gradientHigh = 1.0;  ///< > gradientLow
  glm::dvec3 color{1.0};      ///< linear RGB 0..1
  double extinction = 1.0;    ///< 1 / model length unit, >= 0
  bool operator==(const TfWidget2D&) const = default;
  /// 1 inside the widget's region, 0 outside.
  double weight(double value, double gradient) const;
};

class TransferFunction2D {
 public:
  static constexpr int kValueNodes = 256, kGradientNodes = 128;
  static constexpr std::size_t kMaxWidgets = 64;

  TransferFunction2D() = default;
  /// Throws std::invalid_argument naming the widget for non-finite numbers, a width or
  /// gradient range that is empty, a negative gradient, a negative extinction, colors
  /// outside 0..1, or more than kMaxWidgets widgets.
  explicit TransferFunction2D(std::vector<TfWidget2D> widgets);

  const std::vector<TfWidget2D>& widgets() const { return widgets_; }
  bool empty() const { return widgets_.empty(); }

  /// The table's extent: values valueLow()..valueHigh(), gradients 0..gradientHigh() (the
  /// widgets' with one node to spare on each side); outside it the function is zero.
  double valueLow() const { return valueLow_; }
  double valueHigh() const { return valueHigh_; }
  double gradientHigh() const { return gradientHigh_; }
  /// The table's nodes, value fastest: (emission r, g, b = color x extinction, extinction).
  const std::vector<glm::vec4>& table() const { return table_; }

  /// Color (rgb) and extinction (a) at a value and gradient magnitude: the bilinear
  /// interpolation of the table, in double.
  glm::dvec4 evaluate(double value, double gradient) const;

  /// {"format":"volpost-tf2d","version":1,"widgets":[{"shape":"rectangle"|"triangle",
  /// "value":..,"width":..,"gradient":[low,high],"color":[r,g,b],"extinction":..},...]}.
  /// Throws std::runtime_error naming the offending entry.
  static TransferFunction2D fromJson(const std::string& text);
  std::string toJson() const;

  bool operator==(const TransferFunction2D& o) const { return widgets_ == o.widgets_; }

 private:
  void buildTable();
  std::vector<TfWidget2D> widgets_;
  double valueLow_ = 0.0, valueHigh_ = 1.0, gradientHigh_ = 1.0;
  std::vector<glm::vec4> table_;
};

}  // namespace volpost

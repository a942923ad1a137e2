// SPDX-License-Identifier: MIT
// The color legend drawn over the view (window and PNG alike).
#pragma once

#include <volpost/core/ColorMap.hpp>
#include <volpost/core/Quantity.hpp>

#include <glm/vec3.hpp>

#include <QColor>
#include <QRect>
#include <QString>

#include <optional>
#include <vector>

class QPainter;

namespace volpost::app {

/// How the legend writes its numbers: "auto" (significant digits, 4 unless given:
/// "auto:6"), "fixed:N" (N digits after the point), "scientific:N" (N after the point, then
/// the exponent).
struct LegendNumbers {
  enum class Style { Automatic, Fixed, Scientific };
  Style style = Style::Automatic;
  int digits = 4;
  QString text(double value) const;
  /// The widest text a label can take in this style (the legend strip is sized by it).
  QString widest() const;
  /// nullopt when the text is none of the forms above (digits 0..12; automatic 1..12).
  static std::optional<LegendNumbers> parse(const std::string& text);
  std::string written() const;
  bool operator==(const LegendNumbers&) const = default;
};

struct LegendContent {
  QString title;      ///< quantity, e.g. "S von Mises"
  QString subtitle;   ///< step label and location, e.g. "step 1 · per node"
  double min = 0.0, max = 1.0;   ///< the bar's range (a typed range, or the data's)
  std::size_t noValueCount = 0;  ///< NaN values, drawn in the no-value color
  /// Where those values show: gray on surfaces; a volume leaves the cells touching them out.
  QString noValueShown = "gray";
  /// The data's own extremes, named in the footer whatever the bar's range.
  std::optional<double> dataMin, dataMax;
  /// No color bar (a 2D transfer function's colors depend on more than the value): this
  /// line says where the colors come from instead.
  QString noBarNote;
  /// Discrete bands of equal width (0: a continuous bar); ticks then mark their bounds.
  int bands = 0;
  LegendNumbers numbers;
  int labels = 6;
  /// The colors of values below / above the bar's range, drawn as boxes at its ends.
  std::optional<glm::dvec3> belowColor, aboveColor;  ///< about how many values a continuous bar labels
  /// The words and numbers' size, times the size in proportion to the picture.
  double textScale = 1.0;
  /// Light words for a dark background.
  bool onDark = false;
  /// The bar is logarithmic: a value's height is its log's share of the range's (min > 0).
  bool logScale = false;
  /// A key of named colors instead of a bar (the model colored by its sets): a box of each
  /// color beside its name, top to bottom.
  struct Swatch {
    QString name;
    glm::dvec3 rgb{0.0};
  };
  std::vector<Swatch> swatches;
};

/// The units of a quantity of a field whose units are `fieldUnits`: the field's for its
/// components, magnitudes, stresses and invariants of the first order; squared and cubed
/// for J2 and J3; "deg" for angles and the Lode angle; none for the triaxiality (a ratio).
QString quantityUnits(const Quantity& quantity, const QString& fieldUnits);

/// The words' color over a background: near-black, or near-white over a dark one.
QColor textColorOver(bool dark);
/// Whether a background color is dark enough for light words (luminance below one half).
bool isDarkBackground(const glm::dvec3& rgb);

/// Draws a vertical bar with ticks at "nice" values along the right edge of `area`.
void paintLegend(QPainter& painter, const QRect& area, const ColorMap& map, const LegendContent& content);

/// The widest the legend paintLegend draws in `area` can be, pixels from its right edge
/// (the bar and its tick labels; the title lines above it are right-aligned text).
int legendWidth(const QRect& area, const LegendNumbers& numbers = {}, double textScale = 1.0);
/// The same for this content: a key of named colors is as wide as its longest name.
int legendWidth(const QRect& area, const LegendContent& content);

/// Tick values for [min, max]: multiples of 1, 2 or 5 x 10^k, about `target` of them.
std::vector<double> niceTicks(double min, double max, int target = 6);
/// Tick values for a logarithmic [min, max] (0 < min < max): the powers of ten inside it,
/// with 2 and 5 times them while there are fewer than `target`, every k-th power when there
/// are many more; the ends when none falls inside.
std::vector<double> logTicks(double min, double max, int target = 6);

}  // namespace volpost::app

// Maps a scalar onto the 1D color-map texture. Values at or above NO_VALUE are missing
// results (NaN in the file) and get the no-value color.
const float NO_VALUE = 1.0e38;

// With `bands` > 0 the range is cut into that many bands of equal width, each drawn in the
// color of its middle (contour bands); 0 gives continuous colors.
vec3 colorForValueInBands(sampler1D colorMap, float value, float vmin, float vmax, vec3 noValueColor, int bands) {
  if (!(value < NO_VALUE)) return noValueColor;
  float t = vmax > vmin ? (value - vmin) / (vmax - vmin) : 0.5;
  t = clamp(t, 0.0, 1.0);
  if (bands > 0) t = (min(floor(t * float(bands)), float(bands - 1)) + 0.5) / float(bands);
  // Sample at texel centres so t = 0 and t = 1 hit the map's end colors exactly.
  float n = float(textureSize(colorMap, 0));
  return texture(colorMap, (t * (n - 1.0) + 0.5) / n).rgb;
}

// Values below vmin (above vmax) in their own color when useBelow (useAbove) is set,
// else in the map's end color.
vec3 colorForValueInRange(sampler1D colorMap, float value, float vmin, float vmax, vec3 noValueColor, int bands,
                          bool useBelow, vec3 belowColor, bool useAbove, vec3 aboveColor) {
  if (value < NO_VALUE && useBelow && value < vmin) return belowColor;
  if (value < NO_VALUE && useAbove && value > vmax) return aboveColor;
  return colorForValueInBands(colorMap, value, vmin, vmax, noValueColor, bands);
}

vec3 colorForValue(sampler1D colorMap, float value, float vmin, float vmax, vec3 noValueColor) {
  return colorForValueInBands(colorMap, value, vmin, vmax, noValueColor, 0);
}

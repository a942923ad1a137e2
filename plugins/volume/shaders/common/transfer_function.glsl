// The transfer function as control points in SSBOs (exact, any count): color + extinction
// per point, values sorted ascending.
layout(std430, binding = BINDING_TF_COLOR_TAU) readonly buffer TfColorTau { vec4 tfColorTau[]; };
layout(std430, binding = BINDING_TF_VALUES) readonly buffer TfValues { float tfValue[]; };
uniform int tfCount;
// Per control point: its pre-integration table coordinate (optics::TableWarp), the running
// integral of the extinction over the value from the first point (two floats: high, low
// part), and the value up to which the extinction stays zero from inside the piece that
// starts at the point (-inf where it does not); tfZeroBelow for values below the first.
layout(std430, binding = BINDING_TF_KNOTS) readonly buffer TfKnots { vec4 tfKnot[]; };
uniform float tfZeroBelow;

// Between two control points, weighted sum rather than mix(): mix may be a + w (b - a),
// which near w = 1 leaves b with the rounding of a (extinctions 1e5 and 0.01 next to each
// other gave 0.0078 for 0.01). Both terms are >= 0: each keeps its own relative accuracy.
vec4 tfLerp(vec4 a, vec4 b, float w) { return a * (1.0 - w) + b * w; }
float tfLerp(float a, float b, float w) { return a * (1.0 - w) + b * w; }

// Color (rgb) and extinction (a) at scalar s, clamped at the ends.
vec4 tfEval(float s) {
  if (tfCount == 0) return vec4(0.0);
  if (s <= tfValue[0]) return tfColorTau[0];
  if (s >= tfValue[tfCount - 1]) return tfColorTau[tfCount - 1];
  int lo = 0, hi = tfCount - 1;  // tfValue[lo] <= s < tfValue[hi]
  while (hi - lo > 1) {
    int mid = (lo + hi) / 2;
    if (tfValue[mid] <= s) lo = mid; else hi = mid;
  }
  float w = (s - tfValue[lo]) / (tfValue[hi] - tfValue[lo]);
  return tfLerp(tfColorTau[lo], tfColorTau[hi], w);
}

// The first control point with a value above s (tfCount if none).
int tfFirstAbove(float s) {
  int lo = 0, hi = tfCount;
  while (lo < hi) { int mid = (lo + hi) / 2; if (tfValue[mid] > s) hi = mid; else lo = mid + 1; }
  return lo;
}

// The first control point with a value at or above s (tfCount if none).
int tfFirstNotBelow(float s) {
  int lo = 0, hi = tfCount;
  while (lo < hi) { int mid = (lo + hi) / 2; if (tfValue[mid] >= s) hi = mid; else lo = mid + 1; }
  return lo;
}

// True when the extinction is zero for every value in [a, b] (a <= b): a piece there
// neither emits nor absorbs, and costs one search instead of its cuts and integrals.
bool tfTransparent(float a, float b) {
  if (tfCount == 0) return true;
  int above = tfFirstAbove(a);
  return b <= (above == 0 ? tfZeroBelow : tfKnot[above - 1].w);
}

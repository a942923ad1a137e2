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
  return mix(tfColorTau[lo], tfColorTau[hi], w);
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

// Color and extinction at s as a piece of a segment sees them: reaching s from lower values
// (fromBelow: where points share the value s, the first) or going on to higher ones (the
// last). Two points at one value are a step; each side integrates its own limit
// (optics::sampleSide).
vec4 tfEvalFrom(float s, bool fromBelow) {
  if (tfCount == 0) return vec4(0.0);
  int hi = fromBelow ? tfFirstNotBelow(s) : tfFirstAbove(s);
  if (hi == 0) return tfColorTau[0];
  if (hi == tfCount) return tfColorTau[tfCount - 1];
  float w = (s - tfValue[hi - 1]) / (tfValue[hi] - tfValue[hi - 1]);
  return mix(tfColorTau[hi - 1], tfColorTau[hi], w);
}

// The first control-point value met going from a toward b (strictly beyond a, strictly
// before b), or b itself if there is none: exact, by binary search.
float tfNextCut(float a, float b) {
  if (tfCount == 0 || a == b) return b;
  if (b > a) {
    int lo = 0, hi = tfCount;  // first index with tfValue > a
    while (lo < hi) { int mid = (lo + hi) / 2; if (tfValue[mid] > a) hi = mid; else lo = mid + 1; }
    return (lo < tfCount && tfValue[lo] < b) ? tfValue[lo] : b;
  }
  int lo = 0, hi = tfCount;  // first index with tfValue >= a; the one before is below a
  while (lo < hi) { int mid = (lo + hi) / 2; if (tfValue[mid] >= a) hi = mid; else lo = mid + 1; }
  return (lo > 0 && tfValue[lo - 1] > b) ? tfValue[lo - 1] : b;
}

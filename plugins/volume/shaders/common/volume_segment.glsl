// Shared by every volume shader of the plugin (the tet ray caster, cell projection, the
// grid ray marcher): the transfer-function tables, the integration of one ray piece over
// which the scalar is linear (exact linear segments, pre-integrated, sampled), clip planes,
// iso-surfaces, and the ray of a pixel. The includer sets rayOrigin/rayDir, defines
// isoGradient(t) (the scalar's gradient where the ray crosses an iso-surface, for its
// shading) and calls integrateValues(); the result accumulates front to back in
// accColor/accT.
// Binding points (BINDING_*, UNIT_*), limits (MAX_*) and INTEGRATION_MODE are #defines the
// plugin prepends (VolumeBindings.hpp, kMaxClipPlanes...): one source for C++ and GLSL.
#include "common/transfer_function.glsl"

uniform mat4 inverseViewProjection;  // NDC -> mesh-relative coordinates
uniform vec3 eye;                    // mesh-relative (perspective)
uniform bool orthographic;
uniform ivec2 imageSize_;
// INTEGRATION_MODE (0 linear segments with exact cuts, 1 pre-integrated, 2 sampling, 3
// linear segments cut where a 2D table says, 4 a 2D transfer function over the value and
// its gradient magnitude, grids only) is compiled in, one program per mode: as a
// run-time branch, some drivers (llvmpipe) run every mode's code for every segment (the
// ray caster took 37% longer on the fine post).
uniform float samplingStep;
uniform float terminationTransmittance;
uniform int clipCount;
uniform vec4 clipPlanes[MAX_CLIP_PLANES];  // keep dot(xyz, p) + w >= 0 (mesh-relative)
layout(binding = UNIT_PSI) uniform sampler2D psiTable;  // psi over gamma = t / (t + 1)
layout(binding = UNIT_THICK_PSI) uniform sampler1D thickPsiTable;  // (sqrt(pi)/2 erfcx, Dawson) x (1 + u) over u / (u + 1)
layout(binding = UNIT_ISO) uniform sampler2D isoTable;  // first and next control point crossed (range positions)
layout(binding = UNIT_PRE) uniform sampler3D preTable;  // (s_front, s_back, optical depth) -> mean color
uniform float sLo, sHi;              // range of the iso and pre-integration tables
uniform float preMaxDepth;           // segments thicker than this are integrated exactly
layout(binding = UNIT_SCENE_DEPTH) uniform sampler2D sceneDepth;  // opaque geometry's depth (window 0..1), bottom row first
uniform bool hasSceneDepth;
uniform int isoCount;
uniform float isoValue[MAX_ISO_SURFACES];
uniform vec4 isoColor[MAX_ISO_SURFACES];  // rgb, opacity

vec3 accColor = vec3(0.0);
float accT = 1.0;

// Shading of the emission by the gradient, the light at the eye (volpost/core/optics/
// Headlight.hpp): the color C becomes C (0.3 + 0.7 |cos|) + 0.3 |cos|^20. The includer sets
// the shading (multiplier, white added) at the two ends of each piece it integrates, where
// the value is shadeFromS and shadeToS; between them it is interpolated with the value
// (linearly along the piece). Off, colors are the transfer function's.
uniform bool shading;
vec2 shadeFront = vec2(1.0, 0.0), shadeBack = vec2(1.0, 0.0);
float shadeFromS = 0.0, shadeToS = 0.0;

vec4 lit(vec4 c, float s) {
  if (!shading) return c;
  float x = shadeToS != shadeFromS ? clamp((s - shadeFromS) / (shadeToS - shadeFromS), 0.0, 1.0) : 0.5;
  vec2 k = mix(shadeFront, shadeBack, x);
  return vec4(c.rgb * k.x + k.y, c.a);
}

vec2 headlight(vec3 gradient, vec3 direction) {
  float g = length(gradient);
  if (!(g > 0.0)) return vec2(1.0, 0.0);
  float c = abs(dot(gradient / g, direction));
  return vec2(0.3 + 0.7 * c, 0.3 * pow(c, 20.0));
}

void composite(vec3 color, float transmittance) {
  accColor += accT * color;
  accT *= transmittance;
}

// ---- segment integration ---------------------------------------------------------
float gammaUv(float t) {
  float n = float(textureSize(psiTable, 0).x);
  return ((t / (t + 1.0)) * (n - 1.0) + 0.5) / n;
}

// psi for thin pieces (optical depth <= 0.1) by its series: sum_k (-1)^k/k! int (a x + d x^2)^k,
// 6 terms leave < 0.1^6 / 720 ~ 1e-9. The table's interpolation error would otherwise
// add up over the many thin segments of a fine mesh.
float psiSeries(float a, float d) {
  float a2 = a * a, a3 = a2 * a, a4 = a3 * a, a5 = a4 * a, d2 = d * d, d3 = d2 * d, d4 = d3 * d, d5 = d4 * d;
  float k1 = a / 2.0 + d / 3.0;
  float k2 = a2 / 3.0 + a * d / 2.0 + d2 / 5.0;
  float k3 = a3 / 4.0 + 3.0 * a2 * d / 5.0 + a * d2 / 2.0 + d3 / 7.0;
  float k4 = a4 / 5.0 + 4.0 * a3 * d / 6.0 + 6.0 * a2 * d2 / 7.0 + 4.0 * a * d3 / 8.0 + d4 / 9.0;
  float k5 = a5 / 6.0 + 5.0 * a4 * d / 7.0 + 10.0 * a3 * d2 / 8.0 + 10.0 * a2 * d3 / 9.0 + 5.0 * a * d4 / 10.0 + d5 / 11.0;
  return 1.0 - k1 + k2 / 2.0 - k3 / 6.0 + k4 / 24.0 - k5 / 120.0;
}

// psi of thick pieces (optics::ThickPsiTable): F(t / 2r) / r, F tabulated over
// y = u / (u + 1) up to THICK_PSI_TABLE_END and interpolated here with float weights (a
// sampler's may have 8 bits), its asymptotic series beyond.
float thickF(bool frontThicker, float t, float r) {
  float u = t / (2.0 * r);
  if (u > THICK_PSI_TABLE_END) {
    float q = 2.0 * r * r / (t * t);
    return (1.0 + (frontThicker ? q : -q) + 3.0 * q * q) / t;
  }
  int n = textureSize(thickPsiTable, 0);
  float yEnd = THICK_PSI_TABLE_END / (THICK_PSI_TABLE_END + 1.0);
  float x = u / (1.0 + u) / yEnd * float(n - 1);
  int i = min(int(x), n - 2);
  float w = x - float(i);
  vec2 g = texelFetch(thickPsiTable, i, 0).rg * (1.0 - w) + texelFetch(thickPsiTable, i + 1, 0).rg * w;
  return (frontThicker ? g.g : g.r) / ((1.0 + u) * r);
}

// Pieces of optical depth (tf + tb) / 2 > THICK_PSI_MIN_DEPTH: a transparent front and an
// opaque back (or the reverse) is where the 2D table is far off (up to 0.02).
float psiThick(float tf, float tb) {
  float d = 0.5 * (tb - tf);
  if (d == 0.0) return (1.0 - exp(-tf)) / tf;
  bool frontThicker = d < 0.0;
  float r = sqrt(abs(d));
  return thickF(frontThicker, tf, r) - exp(-0.5 * (tf + tb)) * thickF(frontThicker, tb, r);
}

void linearPiece(vec4 front, vec4 back, float len) {  // rgb color, a extinction
  float tf = front.a * len, tb = back.a * len;
  float depth = 0.5 * (tf + tb);
  float zeta = exp(-depth);
  float psi = depth <= 0.1                 ? psiSeries(tf, 0.5 * (tb - tf))
              : depth > THICK_PSI_MIN_DEPTH ? psiThick(tf, tb)
                                            : textureLod(psiTable, vec2(gammaUv(tf), gammaUv(tb)), 0.0).r;
  psi = clamp(psi, zeta, 1.0);
  composite(back.rgb * (psi - zeta) + front.rgb * (1.0 - psi), zeta);
}

float rangePos(float s) { return (s - sLo) / (sHi - sLo); }
float rangeValue(float p) { return sLo + p * (sHi - sLo); }

#if INTEGRATION_MODE == 3
// Espinha 2005, 4.2: the iso-detection table says whether a segment crosses a control point
// at all (optics::IsoDetectionTable: its entry covers the two texels' whole cells, so "none"
// is never wrong); most segments cross none and are one exact piece without a search.
bool isoTableSaysNoCut(float sf, float sb) {
  int n = textureSize(isoTable, 0).x;
  ivec2 texel = clamp(ivec2(floor(clamp(vec2(rangePos(sf), rangePos(sb)), 0.0, 1.0) * float(n - 1) + 0.5)), 0, n - 1);
  return texelFetch(isoTable, texel, 0).r < 0.0;
}
#endif

void integrateLinear(float sf, float sb, float len) {
  // Constant (or varying below float resolution, where sb - sf may flush to zero and the
  // piece lengths below would divide by it): no division, no cut.
  if (abs(sb - sf) <= 1e-6 * max(abs(sf), abs(sb)) || sb - sf == 0.0) {
    vec4 c = lit(tfEval(0.5 * (sf + sb)), 0.5 * (sf + sb));
    float alpha = 1.0 - exp(-c.a * len);
    composite(c.rgb * alpha, 1.0 - alpha);
    return;
  }
#if INTEGRATION_MODE == 3
  if (isoTableSaysNoCut(sf, sb)) {
    linearPiece(lit(tfEval(sf), sf), lit(tfEval(sb), sb), len);
    return;
  }
#endif
  // The control points crossed, one after the other from the first beyond sf (one search):
  // a piece ends at a point with that point's own color and extinction, and where two
  // points share a value (a step) the next piece starts from the other one, so each side
  // of a step integrates its own limit (optics::sampleSide).
  bool rising = sb > sf;
  int k = rising ? tfFirstAbove(sf) : tfFirstNotBelow(sf) - 1;
  float s = sf;
  vec4 front = tfEval(sf);
  for (int n = 0; n <= tfCount; ++n) {
    bool cut = rising ? (k < tfCount && tfValue[k] < sb) : (k >= 0 && tfValue[k] > sb);
    float end = cut ? tfValue[k] : sb;
    vec4 back = cut ? tfColorTau[k] : tfEval(sb);
    linearPiece(lit(front, s), lit(back, end), len * ((end - s) / (sb - sf)));
    if (!cut || accT < terminationTransmittance) return;
    if (rising) {
      while (k + 1 < tfCount && tfValue[k + 1] == end) ++k;
    } else {
      while (k > 0 && tfValue[k - 1] == end) --k;
    }
    front = tfColorTau[k];
    k += rising ? 1 : -1;
    s = end;
  }
  // Not reached (at most tfCount cuts); were it, the rest in one piece.
  linearPiece(lit(front, s), lit(tfEval(sb), sb), len * ((sb - s) / (sb - sf)));
}

// ---- a 2D transfer function (value, gradient magnitude) ---------------------------
// The includer sets the gradient magnitudes at the ends of the piece it hands to
// integrateValues (gradientFront, gradientBack); between them the magnitude goes linearly
// along the ray, like the value. Color and extinction from the table at both ends of each
// part are integrated as linear along it (exactly, as linearPiece does): second order in
// the step, as the sampled 1D modes.
float gradientFront = 0.0, gradientBack = 0.0;
float pieceStart = 0.0, pieceEnd = 1.0;  // the parameters integrateValues was given
#if INTEGRATION_MODE == 4
layout(binding = UNIT_TF2D) uniform sampler2D tf2dTable;  // nodes: (emission rgb, extinction)
uniform float tf2dValueLow, tf2dValueHigh, tf2dGradientHigh;

// TransferFunction2D::evaluate: the table's bilinear interpolation, zero outside it.
vec4 tf2dEval(float s, float g) {
  vec2 x = vec2((s - tf2dValueLow) / (tf2dValueHigh - tf2dValueLow), g / tf2dGradientHigh);
  if (any(lessThan(x, vec2(0.0))) || any(greaterThan(x, vec2(1.0)))) return vec4(0.0);
  vec2 n = vec2(textureSize(tf2dTable, 0));
  vec4 e = textureLod(tf2dTable, (x * (n - 1.0) + 0.5) / n, 0.0);
  return e.a > 0.0 ? vec4(e.rgb / e.a, e.a) : vec4(0.0);
}

void integrate2D(float t0, float t1, float sf, float sb) {
  float span = pieceEnd - pieceStart;
  float g0 = span > 0.0 ? mix(gradientFront, gradientBack, (t0 - pieceStart) / span) : gradientFront;
  float g1 = span > 0.0 ? mix(gradientFront, gradientBack, (t1 - pieceStart) / span) : gradientBack;
  linearPiece(lit(tf2dEval(sf, g0), sf), lit(tf2dEval(sb, g1), sb), t1 - t0);
}
#endif

// ---- pre-integrated (optics::PreintegrationTable, optics::OpticalDepth) --------------
// The extinction at s, given the first control point above it.
float tfExtinctionAt(float s, int above) {
  if (above == 0) return tfColorTau[0].a;
  if (above == tfCount) return tfColorTau[tfCount - 1].a;
  float width = tfValue[above] - tfValue[above - 1];
  return width > 0.0 ? tfLerp(tfColorTau[above - 1].a, tfColorTau[above].a, (s - tfValue[above - 1]) / width)
                     : tfColorTau[above].a;
}

// The table coordinate of s: the warp is linear between control points (the range's ends
// at 0 and 1), so the coordinates at the two points around s give it exactly.
float preCoordinate(float s, int above) {
  s = clamp(s, sLo, sHi);
  float s0 = above == 0 ? sLo : clamp(tfValue[above - 1], sLo, sHi), u0 = above == 0 ? 0.0 : tfKnot[above - 1].x;
  float s1 = above == tfCount ? sHi : clamp(tfValue[above], sLo, sHi), u1 = above == tfCount ? 1.0 : tfKnot[above].x;
  return s1 > s0 ? mix(u0, u1, (s - s0) / (s1 - s0)) : u0;
}

// Opacity exactly from the optical depth (the mean extinction over [sf, sb], from the two
// partial pieces at the ends and the running integrals between); the mean color from the
// table where the piece is thin, the exact cut integration where it is thick.
void integratePreintegrated(float sf, float sb, float len) {
  if (tfCount == 0) return;
  float a = min(sf, sb), b = max(sf, sb);
  int above = tfFirstAbove(a), notBelow = tfFirstNotBelow(b);
  float tauA = tfExtinctionAt(a, above);
  float tauB = notBelow == tfCount ? tfColorTau[tfCount - 1].a : tfExtinctionAt(b, notBelow);
  float meanTau;
  if (above >= notBelow || !(b > a)) {
    meanTau = 0.5 * (tauA + tauB);  // one linear piece
  } else {
    int first = above, last = notBelow - 1;
    float span = b - a;
    float whole = ((tfKnot[last].y - tfKnot[first].y) + (tfKnot[last].z - tfKnot[first].z)) / span;
    meanTau = (tfValue[first] - a) / span * 0.5 * (tauA + tfColorTau[first].a) + whole +
              (b - tfValue[last]) / span * 0.5 * (tfColorTau[last].a + tauB);
  }
  float depth = meanTau * len;
  if (depth > preMaxDepth) { integrateLinear(sf, sb, len); return; }
  bool forward = sb >= sf;
  vec3 x = vec3(preCoordinate(sf, forward ? above : notBelow), preCoordinate(sb, forward ? notBelow : above),
                depth / preMaxDepth);
  vec3 size = vec3(textureSize(preTable, 0));
  vec3 mean = textureLod(preTable, (x * (size - 1.0) + 0.5) / size, 0.0).rgb;
  float alpha = 1.0 - exp(-depth);
  if (shading) {  // the table holds unlit light: the piece's mean shading on it
    vec2 k = mix(shadeFront, shadeBack, 0.5);
    mean = mean * k.x + k.y;
  }
  composite(mean * alpha, 1.0 - alpha);
}

// Midpoint rule on one lattice along the ray: the piece [t0, t1) is cut at every multiple
// of the step and each part gives one sample, at its middle, over its own length. The
// lattice is the same wherever a piece starts, so pieces integrated one by one (the tets
// along a ray, the fragments of cell projection, the pieces between iso-surfaces) take
// exactly the samples of one walk along the whole ray, and where the ray enters or leaves
// the mesh between two lattice points only the part inside counts.
void integrateSampling(float t0, float t1, float sf, float sb) {
  float h = samplingStep;
  for (float k = floor(t0 / h); accT >= terminationTransmittance; k += 1.0) {
    float a = max(t0, k * h), b = min(t1, (k + 1.0) * h);
    if (a >= t1) break;
    if (b <= a) continue;  // the division rounded down
    float w = (0.5 * (a + b) - t0) / max(t1 - t0, 1e-30);
    vec4 c = lit(tfEval(mix(sf, sb, w)), mix(sf, sb, w));
    float alpha = 1.0 - exp(-c.a * (b - a));
    composite(c.rgb * alpha, 1.0 - alpha);
  }
}

// ---- the ray ---------------------------------------------------------------------
vec3 rayOrigin, rayDir;

bool clipSegment(inout float t0, inout float t1) {
  for (int i = 0; i < clipCount; ++i) {
    float a = dot(clipPlanes[i].xyz, rayOrigin) + clipPlanes[i].w, b = dot(clipPlanes[i].xyz, rayDir);
    if (b == 0.0) { if (a < 0.0) return false; continue; }
    float t = -a / b;
    if (b > 0.0) t0 = max(t0, t); else t1 = min(t1, t);
  }
  return t0 < t1;
}

void integratePiece(float t0, float t1, float sf, float sb) {
  if (t1 <= t0) return;
#if INTEGRATION_MODE != 4
  if (tfTransparent(min(sf, sb), max(sf, sb))) return;  // no extinction: nothing emitted or absorbed
#endif
#if INTEGRATION_MODE == 0 || INTEGRATION_MODE == 3
  integrateLinear(sf, sb, t1 - t0);
#elif INTEGRATION_MODE == 1
  integratePreintegrated(sf, sb, t1 - t0);
#elif INTEGRATION_MODE == 4
  integrate2D(t0, t1, sf, sb);
#else
  integrateSampling(t0, t1, sf, sb);
#endif
}

// The scalar's gradient at parameter t of the ray (the includer's geometry knows it).
vec3 isoGradient(float t);

// A piece [t0, t1] of the ray over which the scalar goes linearly from sf to sb, cut at the
// iso-surfaces it crosses: volume pieces between crossings, each surface composited there,
// shaded by the gradient (0.3 + 0.7 |cos| headlight).
void integrateValues(float t0, float t1, float sf, float sb) {
  shadeFromS = sf;
  shadeToS = sb;
  pieceStart = t0;
  pieceEnd = t1;
  if (isoCount == 0 || sf == sb) { integratePiece(t0, t1, sf, sb); return; }
  // Iso-surfaces crossed in (sf, sb], in ray order (picked one by one: no local arrays,
  // which cost registers on every invocation), between volume pieces.
  float x0 = 0.0;
  float shade = -1.0;
  for (int h = 0; h < isoCount; ++h) {
    float best = 2.0;
    int which = -1;
    for (int i = 0; i < isoCount; ++i) {
      float v = isoValue[i];
      if ((sb > sf && v > sf && v <= sb) || (sb < sf && v < sf && v >= sb)) {
        float x = (v - sf) / (sb - sf);
        if (x > x0 && x < best) { best = x; which = i; }
      }
    }
    if (which < 0) break;
    if (shade < 0.0) {
      vec3 g = isoGradient(mix(t0, t1, best));
      shade = dot(g, g) > 0.0 ? 0.3 + 0.7 * abs(dot(normalize(g), rayDir)) : 1.0;
    }
    integratePiece(mix(t0, t1, x0), mix(t0, t1, best), mix(sf, sb, x0), isoValue[which]);
    vec4 c = isoColor[which];
    composite(c.rgb * shade * c.a, 1.0 - c.a);
    x0 = best;
  }
  integratePiece(mix(t0, t1, x0), t1, mix(sf, sb, x0), sb);
}

// ---- the ray of a pixel ------------------------------------------------------------
// The normalized image coordinates of pixel `pix`'s centre (row 0 at the top).
vec2 pixelNdc(ivec2 pix) {
  precise vec2 ndc = vec2(2.0 * (float(pix.x) + 0.5) / float(imageSize_.x) - 1.0,
                          1.0 - 2.0 * (float(pix.y) + 0.5) / float(imageSize_.y));
  return ndc;
}

// Sets rayOrigin and rayDir for the point `ndc` of the image (pixel `fromTop`, row 0 at
// the top) and returns the ray's parameters at the near plane and at the far plane, or at
// the opaque scene drawn before the volume where there is one.
// (precise: the entry maps' fragments and the ray caster's invocations must trace the very
// same ray for the same pixel.)
vec2 setupRay(vec2 ndc, ivec2 fromTop) {
  precise vec4 nearP = inverseViewProjection * vec4(ndc, -1.0, 1.0), farP = inverseViewProjection * vec4(ndc, 1.0, 1.0);
  precise vec3 nearPoint = nearP.xyz / nearP.w, farPoint = farP.xyz / farP.w;
  rayOrigin = orthographic ? nearPoint : eye;
  precise vec3 direction = normalize(farPoint - rayOrigin);
  rayDir = direction;
  float tNear = orthographic ? 0.0 : length(nearPoint - eye);
  float tFar = length(farPoint - rayOrigin);
  if (hasSceneDepth) {  // opaque geometry ends the ray where it is
    float depth = texelFetch(sceneDepth, ivec2(fromTop.x, imageSize_.y - 1 - fromTop.y), 0).r;
    if (depth < 1.0) {
      vec4 hit = inverseViewProjection * vec4(ndc, 2.0 * depth - 1.0, 1.0);
      tFar = min(tFar, dot(hit.xyz / hit.w - rayOrigin, rayDir));
    }
  }
  return vec2(tNear, tFar);
}

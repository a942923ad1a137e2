#version 450 core
// GPU ray casting through tetrahedra, one invocation per pixel: enter at a boundary face
// (found in a BVH over boundary faces, which also finds where a ray re-enters a
// non-convex mesh), walk tet to tet through face adjacency, leave each tet through the
// face with the smallest exit parameter, integrate each segment (three modes), composite
// front to back, stop early when nearly opaque.
layout(local_size_x = 8, local_size_y = 8) in;
layout(rgba32f, binding = 0) uniform writeonly image2D outImage;

layout(std430, binding = 0) readonly buffer Nodes { vec4 nodes[]; };      // xyz mesh-relative, w nodal value
layout(std430, binding = 1) readonly buffer Tets { uvec4 tets[]; };
layout(std430, binding = 2) readonly buffer Neighbors { ivec4 neighbors[]; };
layout(std430, binding = 3) readonly buffer CellValues { float cellValues[]; };
layout(std430, binding = 4) readonly buffer Bvh { vec4 bvh[]; };
layout(std430, binding = 5) readonly buffer BoundaryFaces { uint boundaryFaces[]; };

#include "common/transfer_function.glsl"

uniform mat4 inverseViewProjection;  // NDC -> mesh-relative coordinates
uniform vec3 eye;                    // mesh-relative (perspective)
uniform bool orthographic;
uniform ivec2 imageSize_;
uniform bool cellField;
uniform int mode;                    // 0 linear segments, 1 pre-integrated, 2 sampling
uniform bool exactCuts;              // linear segments: cut by binary search, not the iso texture
uniform float samplingStep;
uniform float terminationTransmittance;
uniform int clipCount;
uniform vec4 clipPlanes[6];          // keep dot(xyz, p) + w >= 0 (mesh-relative)
uniform sampler2D psiTable;          // psi over gamma = t / (t + 1)
uniform sampler2D isoTable;          // first and next control point crossed (range positions)
uniform sampler3D preTable;          // (s_front, s_back, length) -> premultiplied rgba
uniform float sLo, sHi;              // range of the iso and pre-integration tables
uniform float preMaxLength;
uniform int maxSteps;
uniform sampler2D sceneDepth;        // opaque geometry's depth (window 0..1), bottom row first
uniform bool hasSceneDepth;
uniform int isoCount;
uniform float isoValue[8];
uniform vec4 isoColor[8];           // rgb, opacity

const ivec3 FACE[4] = ivec3[4](ivec3(1, 2, 3), ivec3(0, 2, 3), ivec3(0, 1, 3), ivec3(0, 1, 2));

vec3 accColor = vec3(0.0);
float accT = 1.0;

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

void linearPiece(vec4 front, vec4 back, float len) {  // rgb color, a extinction
  float tf = front.a * len, tb = back.a * len;
  float zeta = exp(-0.5 * (tf + tb));
  float psi = 0.5 * (tf + tb) <= 0.1 ? psiSeries(tf, 0.5 * (tb - tf))
                                      : texture(psiTable, vec2(gammaUv(tf), gammaUv(tb))).r;
  psi = clamp(psi, zeta, 1.0);
  composite(back.rgb * (psi - zeta) + front.rgb * (1.0 - psi), zeta);
}

float rangePos(float s) { return (s - sLo) / (sHi - sLo); }
float rangeValue(float p) { return sLo + p * (sHi - sLo); }

void integrateLinear(float sf, float sb, float len) {
  if (sf == sb) {  // constant: no division, no cut
    vec4 c = tfEval(sf);
    float alpha = 1.0 - exp(-c.a * len);
    composite(c.rgb * alpha, 1.0 - alpha);
    return;
  }
  float n = float(textureSize(isoTable, 0).x);
  float s = sf;
  for (int k = 0; k <= tfCount + 1; ++k) {
    float end = sb;
    if (exactCuts) {
      end = tfNextCut(s, sb);
    } else {  // the seed's method: the iso-detection texture says where to cut
      vec2 uv = (clamp(vec2(rangePos(s), rangePos(sb)), 0.0, 1.0) * (n - 1.0) + 0.5) / n;
      float iso = texture(isoTable, uv).r;
      if (iso >= 0.0) {
        float v = rangeValue(iso);
        // The table is quantised: cut only where the point really lies ahead.
        if ((sb > s && v > s && v < sb) || (sb < s && v < s && v > sb)) end = v;
      }
    }
    float pieceLen = len * (end - s) / (sb - sf);
    linearPiece(tfEval(s), tfEval(end), pieceLen);
    if (end == sb || accT < terminationTransmittance) return;
    s = end;
  }
}

void integratePreintegrated(float sf, float sb, float len) {
  int pieces = max(1, int(ceil(len / preMaxLength)));
  vec3 size = vec3(textureSize(preTable, 0));
  for (int i = 0; i < pieces; ++i) {
    float a = mix(sf, sb, float(i) / float(pieces)), b = mix(sf, sb, float(i + 1) / float(pieces));
    vec3 x = clamp(vec3(rangePos(a), rangePos(b), len / float(pieces) / preMaxLength), 0.0, 1.0);
    vec4 v = texture(preTable, (x * (size - 1.0) + 0.5) / size);
    composite(v.rgb, 1.0 - v.a);
  }
}

float nextSample = 0.0;  // sampling mode: ray parameter of the next sample

void integrateSampling(float t0, float t1, float sf, float sb) {
  if (nextSample < t0) nextSample = t0 + 0.5 * samplingStep;
  for (; nextSample < t1 && accT >= terminationTransmittance; nextSample += samplingStep) {
    float w = (nextSample - t0) / max(t1 - t0, 1e-30);
    vec4 c = tfEval(mix(sf, sb, w));
    float alpha = 1.0 - exp(-c.a * samplingStep);
    composite(c.rgb * alpha, 1.0 - alpha);
  }
}

// ---- geometry --------------------------------------------------------------------
vec3 rayOrigin, rayDir;

// Outward normal and a point of face k of tet t.
void facePlane(uvec4 tv, int k, out vec3 n, out vec3 a) {
  vec3 p0 = nodes[tv[FACE[k].x]].xyz, p1 = nodes[tv[FACE[k].y]].xyz, p2 = nodes[tv[FACE[k].z]].xyz;
  n = cross(p1 - p0, p2 - p0);
  if (dot(n, nodes[tv[k]].xyz - p0) > 0.0) n = -n;
  a = p0;
}

// Nearest entry (front-facing boundary face) hit with parameter >= tMin, other than the
// face `excluded` (tet * 4 + face); -1 if none.
int findEntry(float tMin, uint excluded, out float tHit, out int faceOut) {
  int best = -1;
  tHit = 3.4e38;
  uint stack[64];
  int top = 0;
  stack[top++] = 0u;
  vec3 inv = 1.0 / rayDir;
  while (top > 0) {
    uint node = stack[--top];
    vec4 lo = bvh[2u * node], hi = bvh[2u * node + 1u];
    vec3 t0 = (lo.xyz - rayOrigin) * inv, t1 = (hi.xyz - rayOrigin) * inv;
    vec3 tn = min(t0, t1), tx = max(t0, t1);
    float enter = max(max(tn.x, tn.y), max(tn.z, tMin)), leave = min(min(tx.x, tx.y), min(tx.z, tHit));
    if (!(enter <= leave)) continue;  // NaN-safe: a NaN compares false
    uint first = floatBitsToUint(lo.w), count = floatBitsToUint(hi.w);
    if (count == 0u) {
      if (top < 62) { stack[top++] = first; stack[top++] = first + 1u; }
      continue;
    }
    for (uint i = first; i < first + count; ++i) {
      uint code = boundaryFaces[i];
      if (code == excluded) continue;  // the face the ray last entered through: no re-entry loop
      uint tet = code >> 2;
      int k = int(code & 3u);
      uvec4 tv = tets[tet];
      vec3 n, a;
      facePlane(tv, k, n, a);
      float den = dot(n, rayDir);
      if (den >= 0.0) continue;  // leaving through it, not entering
      float t = dot(n, a - rayOrigin) / den;
      if (t < tMin || t >= tHit) continue;
      // Inside the triangle, with a little slack so rays through shared edges are not lost.
      // (Barycentrics against the face's own winding: n may have been flipped outward.)
      vec3 p = rayOrigin + t * rayDir;
      vec3 p0 = nodes[tv[FACE[k].x]].xyz, p1 = nodes[tv[FACE[k].y]].xyz, p2 = nodes[tv[FACE[k].z]].xyz;
      vec3 w = cross(p1 - p0, p2 - p0);
      float area = dot(w, w);
      float u = dot(cross(p1 - p, p2 - p), w) / area, v = dot(cross(p2 - p, p0 - p), w) / area;
      float eps = 1e-5;
      if (u < -eps || v < -eps || u + v > 1.0 + eps) continue;
      best = int(tet);
      faceOut = k;
      tHit = t;
    }
  }
  return best;
}

float valueAt(uvec4 tv, uint tet, vec3 p) {
  if (cellField) return cellValues[tet];
  // Barycentric weights from the face planes: lambda_k = distance to face k / height.
  float s = 0.0;
  for (int k = 0; k < 4; ++k) {
    vec3 n, a;
    facePlane(tv, k, n, a);
    s += nodes[tv[k]].w * dot(n, a - p) / dot(n, a - nodes[tv[k]].xyz);
  }
  return s;
}

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
  if (mode == 0) integrateLinear(sf, sb, t1 - t0);
  else if (mode == 1) integratePreintegrated(sf, sb, t1 - t0);
  else integrateSampling(t0, t1, sf, sb);
}

vec3 gradientOf(uvec4 tv) {  // of the linear scalar: sum_k s_k grad(lambda_k)
  vec3 g = vec3(0.0);
  for (int k = 0; k < 4; ++k) {
    vec3 n, a;
    facePlane(tv, k, n, a);
    g -= nodes[tv[k]].w * n / dot(n, a - nodes[tv[k]].xyz);
  }
  return g;
}

void integrate(uvec4 tv, uint tet, float t0, float t1) {
  if (!clipSegment(t0, t1)) return;
  float sf = valueAt(tv, tet, rayOrigin + t0 * rayDir), sb = valueAt(tv, tet, rayOrigin + t1 * rayDir);
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
      vec3 g = cellField ? vec3(0.0) : gradientOf(tv);
      shade = dot(g, g) > 0.0 ? 0.3 + 0.7 * abs(dot(normalize(g), rayDir)) : 1.0;
    }
    integratePiece(mix(t0, t1, x0), mix(t0, t1, best), mix(sf, sb, x0), isoValue[which]);
    vec4 c = isoColor[which];
    composite(c.rgb * shade * c.a, 1.0 - c.a);
    x0 = best;
  }
  integratePiece(mix(t0, t1, x0), t1, mix(sf, sb, x0), sb);
}

void main() {
  ivec2 pix = ivec2(gl_GlobalInvocationID.xy);
  if (pix.x >= imageSize_.x || pix.y >= imageSize_.y) return;
  vec2 ndc = vec2(2.0 * (float(pix.x) + 0.5) / float(imageSize_.x) - 1.0,
                  1.0 - 2.0 * (float(pix.y) + 0.5) / float(imageSize_.y));
  vec4 nearP = inverseViewProjection * vec4(ndc, -1.0, 1.0), farP = inverseViewProjection * vec4(ndc, 1.0, 1.0);
  vec3 nearPoint = nearP.xyz / nearP.w, farPoint = farP.xyz / farP.w;
  rayOrigin = orthographic ? nearPoint : eye;
  rayDir = normalize(farPoint - rayOrigin);
  float t = orthographic ? 0.0 : length(nearPoint - eye);
  float tEnd = length(farPoint - rayOrigin);
  if (hasSceneDepth) {  // opaque geometry ends the ray where it is
    float depth = texelFetch(sceneDepth, ivec2(pix.x, imageSize_.y - 1 - pix.y), 0).r;
    if (depth < 1.0) {
      vec4 hit = inverseViewProjection * vec4(ndc, 2.0 * depth - 1.0, 1.0);
      tEnd = min(tEnd, dot(hit.xyz / hit.w - rayOrigin, rayDir));
    }
  }

  int steps = 0;
  uint lastEntry = 0xffffffffu;
  while (steps < maxSteps && accT >= terminationTransmittance) {
    float tIn;
    int face;
    int tet = findEntry(t, lastEntry, tIn, face);
    if (tet >= 0) lastEntry = uint(tet) * 4u + uint(face);
    if (tet < 0 || tIn > tEnd) break;
    // Walk until the ray leaves the mesh, then look for where it comes back.
    while (tet >= 0 && steps < maxSteps && accT >= terminationTransmittance) {
      ++steps;
      uvec4 tv = tets[tet];
      // Exit: the face the ray leaves through first, among those not behind the entry
      // point (rounding can put a face sharing the entry edge slightly behind it).
      float eps = 1e-5 * (abs(tIn) + length(nodes[tv.x].xyz - nodes[tv.y].xyz));
      float tOut = 3.4e38, tBehind = -3.4e38;
      int exitFace = -1, behindFace = -1;
      float tk[4];
      for (int k = 0; k < 4; ++k) {
        tk[k] = 3.4e38;
        if (k == face) continue;
        vec3 n, a;
        facePlane(tv, k, n, a);
        float den = dot(n, rayDir);
        if (den <= 0.0) continue;
        tk[k] = dot(n, a - rayOrigin) / den;
        if (tk[k] >= tIn - eps) {
          if (tk[k] < tOut) { tOut = tk[k]; exitFace = k; }  // ties: the lowest face index
        } else if (tk[k] > tBehind) {
          tBehind = tk[k];
          behindFace = k;
        }
      }
      // No segment through a tet is longer than its longest edge: a longer one means the
      // ray only grazes this tet (its true exit rounded to just behind the entry).
      vec3 q0 = nodes[tv.x].xyz, q1 = nodes[tv.y].xyz, q2 = nodes[tv.z].xyz, q3 = nodes[tv.w].xyz;
      float diameter = max(max(max(distance(q0, q1), distance(q0, q2)), max(distance(q0, q3), distance(q1, q2))),
                           max(distance(q1, q3), distance(q2, q3)));
      if (exitFace >= 0 && tOut - tIn > 1.001 * diameter + eps && behindFace >= 0) exitFace = -1;
      if (exitFace < 0) { exitFace = behindFace; tOut = tIn; }  // the ray only grazes this tet
      // A ray through an edge or vertex may tie a boundary face with an interior one: leaving
      // through the boundary there would skip the rest of the mesh, so take the interior one.
      if (exitFace >= 0 && neighbors[tet][exitFace] < 0) {
        for (int k = 0; k < 4; ++k)
          if (k != exitFace && tk[k] <= tOut + eps && tk[k] >= tIn - eps && neighbors[tet][k] >= 0) {
            exitFace = k;
            break;
          }
      }
      if (exitFace < 0) { t = tIn; break; }  // degenerate: search again from here
      tOut = max(tOut, tIn);  // a grazing exit (through the entry edge) has no length
      integrate(tv, uint(tet), tIn, min(tOut, tEnd));
      t = tOut;
      if (tOut >= tEnd) { tet = -1; steps = maxSteps; break; }
      int next = neighbors[tet][exitFace];
      if (next < 0) break;  // left the mesh
      // The face of `next` we came through is the one whose neighbour is `tet`.
      ivec4 nb = neighbors[next];
      face = nb.x == tet ? 0 : nb.y == tet ? 1 : nb.z == tet ? 2 : 3;
      tet = next;
      tIn = tOut;
    }
  }
  imageStore(outImage, pix, vec4(accColor, 1.0 - accT));
}

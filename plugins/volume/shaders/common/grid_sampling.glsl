// A regular grid's values as a 3D texture, sampled along the ray: trilinear interpolation
// in float from the 8 points around a continuous index, the trilinear field's gradient for
// iso-surface shading (isoGradient, which common/volume_segment.glsl asks for), and the
// part of a ray inside the grid's box. Shared by the ray marcher and the slicer; the
// includer sets rayIndexOrigin and rayIndexDir from rayOrigin and rayDir.
layout(binding = UNIT_GRID) uniform sampler3D gridValues;  // R32F, values in their frame
uniform mat4 worldToIndex;  // volume-relative position -> continuous grid index
uniform ivec3 gridSize;     // points per axis
uniform float marchStep;    // along the ray, model units

vec3 rayIndexOrigin, rayIndexDir;  // the ray in index space

// Trilinear interpolation in float from the 8 points around `index` (clamped to the grid).
float valueAtIndex(vec3 index) {
  vec3 top = vec3(gridSize - 1);
  vec3 x = clamp(index, vec3(0.0), top);
  vec3 cell = min(floor(x), max(top - 1.0, vec3(0.0)));
  vec3 w = x - cell;
  ivec3 c = ivec3(cell);
  ivec3 step1 = ivec3(greaterThan(gridSize, ivec3(1)));
  float v000 = texelFetch(gridValues, c, 0).r;
  float v100 = texelFetch(gridValues, c + ivec3(step1.x, 0, 0), 0).r;
  float v010 = texelFetch(gridValues, c + ivec3(0, step1.y, 0), 0).r;
  float v110 = texelFetch(gridValues, c + ivec3(step1.x, step1.y, 0), 0).r;
  float v001 = texelFetch(gridValues, c + ivec3(0, 0, step1.z), 0).r;
  float v101 = texelFetch(gridValues, c + ivec3(step1.x, 0, step1.z), 0).r;
  float v011 = texelFetch(gridValues, c + ivec3(0, step1.y, step1.z), 0).r;
  float v111 = texelFetch(gridValues, c + step1, 0).r;
  float a = mix(mix(v000, v100, w.x), mix(v010, v110, w.x), w.y);
  float b = mix(mix(v001, v101, w.x), mix(v011, v111, w.x), w.y);
  return mix(a, b, w.z);
}

float valueAlongRay(float t) { return valueAtIndex(rayIndexOrigin + t * rayIndexDir); }

// The trilinear field's gradient by central differences of half a grid step, in model units.
vec3 isoGradient(float t) {
  vec3 index = rayIndexOrigin + t * rayIndexDir;
  vec3 g = vec3(valueAtIndex(index + vec3(0.5, 0.0, 0.0)) - valueAtIndex(index - vec3(0.5, 0.0, 0.0)),
                valueAtIndex(index + vec3(0.0, 0.5, 0.0)) - valueAtIndex(index - vec3(0.0, 0.5, 0.0)),
                valueAtIndex(index + vec3(0.0, 0.0, 0.5)) - valueAtIndex(index - vec3(0.0, 0.0, 0.5)));
  return transpose(mat3(worldToIndex)) * g;  // ds/dworld = J^T ds/dindex
}

// The part of the ray inside the grid's box [0, size - 1]^3 (in index space): false if none.
bool insideGrid(inout float t0, inout float t1) {
  vec3 top = vec3(gridSize - 1);
  for (int a = 0; a < 3; ++a) {
    float o = rayIndexOrigin[a], d = rayIndexDir[a];
    if (d == 0.0) {
      if (o < 0.0 || o > top[a]) return false;
      continue;
    }
    float ta = (0.0 - o) / d, tb = (top[a] - o) / d;
    t0 = max(t0, min(ta, tb));
    t1 = min(t1, max(ta, tb));
  }
  return t0 < t1;
}


// A regular grid's values as a 3D texture, sampled along the ray: trilinear interpolation
// in float from the 8 points around a continuous index, the trilinear field's gradient for
// the shading of the volume and of iso-surfaces (isoGradient, which common/volume_segment.glsl
// asks for), and the part of a ray inside the grid's box. Shared by the ray marcher and the
// slicer; the includer sets rayIndexOrigin and rayIndexDir from rayOrigin and rayDir.
// A grid larger than the GPU memory budget is drawn brick by brick: the texture then
// holds the points brickFirst .. brickFirst + brickPoints - 1 (bricks share their border
// points), and a ray's part is the part inside the brick's box.
layout(binding = UNIT_GRID) uniform sampler3D gridValues;  // R32F, values in their frame
uniform mat4 worldToIndex;  // volume-relative position -> continuous grid index
uniform ivec3 gridSize;     // points per axis
uniform ivec3 brickFirst;   // the grid index of the texture's first point
uniform ivec3 brickPoints;  // the texture's points per axis
uniform vec2 texelToValue;  // value = x * texel + y: 8- and 16-bit integers stored as they are read
uniform float marchStep;    // along the ray, model units

vec3 rayIndexOrigin, rayIndexDir;  // the ray in index space

// The cell (its lowest corner's index) holding `index`, clamped to the grid.
vec3 cellOfIndex(vec3 index) {
  vec3 top = vec3(gridSize - 1);
  return min(floor(clamp(index, vec3(0.0), top)), max(top - 1.0, vec3(0.0)));
}

// Trilinear interpolation in float from the 8 points around `index` (clamped to the
// grid): the value (x) and its gradient in index space (yzw), exactly the cell's own.
vec4 trilinearInCell(vec3 index, vec3 cell);
vec4 trilinearAtIndex(vec3 index) { return trilinearInCell(index, cellOfIndex(index)); }

// The same with the polynomial of a given cell (on its faces, the side a piece lies on).
vec4 trilinearInCell(vec3 index, vec3 cell) {
  vec3 top = vec3(gridSize - 1);
  vec3 x = clamp(index, vec3(0.0), top);
  // The cell within the brick (the same cell inside it; its last cell on its far face).
  vec3 first = vec3(brickFirst);
  cell = clamp(cell, first, max(first + vec3(brickPoints) - 2.0, first));
  vec3 w = x - cell;
  ivec3 c = ivec3(cell) - brickFirst;
  ivec3 step1 = ivec3(greaterThan(brickPoints, ivec3(1)));
  float v000 = texelFetch(gridValues, c, 0).r;
  float v100 = texelFetch(gridValues, c + ivec3(step1.x, 0, 0), 0).r;
  float v010 = texelFetch(gridValues, c + ivec3(0, step1.y, 0), 0).r;
  float v110 = texelFetch(gridValues, c + ivec3(step1.x, step1.y, 0), 0).r;
  float v001 = texelFetch(gridValues, c + ivec3(0, 0, step1.z), 0).r;
  float v101 = texelFetch(gridValues, c + ivec3(step1.x, 0, step1.z), 0).r;
  float v011 = texelFetch(gridValues, c + ivec3(0, step1.y, step1.z), 0).r;
  float v111 = texelFetch(gridValues, c + step1, 0).r;
  float y0 = mix(v000, v100, w.x), y1 = mix(v010, v110, w.x), y2 = mix(v001, v101, w.x), y3 = mix(v011, v111, w.x);
  float a = mix(y0, y1, w.y), b = mix(y2, y3, w.y);
  float gx = mix(mix(v100 - v000, v110 - v010, w.y), mix(v101 - v001, v111 - v011, w.y), w.z);
  float gy = mix(y1 - y0, y3 - y2, w.z);
  // Interpolation is linear: the texels' map to values applies to the result.
  return vec4(texelToValue.x * mix(a, b, w.z) + texelToValue.y, texelToValue.x * vec3(gx, gy, b - a));
}

float valueAtIndex(vec3 index) { return trilinearAtIndex(index).x; }
vec4 sampleAlongRay(float t) { return trilinearAtIndex(rayIndexOrigin + t * rayIndexDir); }

// Where the ray next crosses a cell face after t (grid planes in index space), or 1e30.
float nextCellFace(float t) {
  vec3 p = rayIndexOrigin + t * rayIndexDir;
  float best = 1e30;
  for (int a = 0; a < 3; ++a) {
    float d = rayIndexDir[a];
    if (d == 0.0) continue;
    float plane = d > 0.0 ? floor(p[a]) + 1.0 : ceil(p[a]) - 1.0;
    float at = (plane - rayIndexOrigin[a]) / d;
    if (!(at > t)) at = (plane + sign(d) - rayIndexOrigin[a]) / d;  // p rounded onto the plane itself
    best = min(best, at);
  }
  return best;
}
float valueAlongRay(float t) { return sampleAlongRay(t).x; }

// An index-space gradient in model units: ds/dworld = J^T ds/dindex.
vec3 worldGradient(vec3 indexGradient) { return transpose(mat3(worldToIndex)) * indexGradient; }

// The shading at a sample (value and index gradient), lit or not.
vec2 shadeOf(vec4 sampled) { return shading ? headlight(worldGradient(sampled.yzw), rayDir) : vec2(1.0, 0.0); }

// The trilinear field's gradient where the ray crosses an iso-surface, in model units.
vec3 isoGradient(float t) { return worldGradient(sampleAlongRay(t).yzw); }

// The part of the ray inside the brick's box (the grid's, [0, size - 1]^3, unbricked), in
// index space: false if none.
bool insideGrid(inout float t0, inout float t1) {
  vec3 bottom = vec3(brickFirst), top = vec3(brickFirst + brickPoints - 1);
  for (int a = 0; a < 3; ++a) {
    float o = rayIndexOrigin[a], d = rayIndexDir[a];
    if (d == 0.0) {  // along a face: it belongs to the brick above it, never to two
      if (o < bottom[a] || o > top[a] || (o == top[a] && brickFirst[a] + brickPoints[a] < gridSize[a])) return false;
      continue;
    }
    float ta = (bottom[a] - o) / d, tb = (top[a] - o) / d;
    t0 = max(t0, min(ta, tb));
    t1 = min(t1, max(ta, tb));
  }
  return t0 < t1;
}


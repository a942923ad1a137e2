// Outlines of projected cells on the image (cell projection's tets, the entry maps'
// faces): the convex hull of the projected corners, grown so that every pixel whose ray may
// cross the cell gets a fragment (the fragment shader then decides exactly).
const float MARGIN = 0.25;  // pixels: far beyond the rasterizer's snapping (1/256 px)

float orient(vec2 a, vec2 b, vec2 c) { return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x); }

bool crosses(vec2 a, vec2 b, vec2 c, vec2 d) {  // segments ab and cd properly cross
  return orient(a, b, c) * orient(a, b, d) < 0.0 && orient(c, d, a) * orient(c, d, b) < 0.0;
}

bool inside(vec2 p, vec2 a, vec2 b, vec2 c) {
  float o = orient(a, b, c);
  return orient(a, b, p) * o >= 0.0 && orient(b, c, p) * o >= 0.0 && orient(c, a, p) * o >= 0.0;
}

// How far corner i's mitre must reach per unit of margin, as its inverse: the cosine between
// the mitre and the edges' outward normals (0 where the two edges fold back on each other).
float mitreCosine(vec2 hull[4], int count, int i) {
  vec2 prev = hull[(i + count - 1) % count], here = hull[i], next = hull[(i + 1) % count];
  vec2 e0 = normalize(here - prev), e1 = normalize(next - here);
  vec2 n0 = vec2(e0.y, -e0.x), n1 = vec2(e1.y, -e1.x);  // outward for counter-clockwise
  vec2 miter = n0 + n1;
  float len = length(miter);
  return len < 1e-6 ? 0.0 : dot(miter / len, n0);
}

// The hull of the projected vertices in counter-clockwise order: 3 or 4 corners; 0 when it
// is degenerate (collinear or coincident points), then the bounding box is drawn instead.
int projectedHull(vec2 q[4], out vec2 hull[4]) {
  int count = 0;
  for (int i = 0; i < 4 && count == 0; ++i) {
    vec2 a = q[(i + 1) % 4], b = q[(i + 2) % 4], c = q[(i + 3) % 4];
    if (inside(q[i], a, b, c) && orient(a, b, c) != 0.0) {
      hull[0] = a; hull[1] = b; hull[2] = c; hull[3] = c;
      count = 3;
    }
  }
  if (count == 0) {  // a quadrilateral: its diagonals are the pair of segments that cross
    if (crosses(q[0], q[2], q[1], q[3])) { hull[0] = q[0]; hull[1] = q[1]; hull[2] = q[2]; hull[3] = q[3]; count = 4; }
    else if (crosses(q[0], q[1], q[2], q[3])) { hull[0] = q[0]; hull[1] = q[2]; hull[2] = q[1]; hull[3] = q[3]; count = 4; }
    else if (crosses(q[0], q[3], q[1], q[2])) { hull[0] = q[0]; hull[1] = q[1]; hull[2] = q[3]; hull[3] = q[2]; count = 4; }
  }
  if (count > 0 && orient(hull[0], hull[1], hull[2]) < 0.0) {
    vec2 t = hull[1]; hull[1] = hull[count - 1]; hull[count - 1] = t;  // (0 1 2 [3]) -> (0 [3] 2 1)
  }
  // A mitre grows as 1 / sin(angle / 2): past 32 margins (8 px, corners under ~3.6
  // degrees) the outline is drawn as its box instead. (Capping the mitre there left the
  // long edges of a sliver, a face or tet seen edge-on, without their margin: a pixel just
  // inside the exact outline got no fragment; seen on the wheel, a ray at its silhouette
  // lost.)
  for (int i = 0; i < count; ++i)
    if (!(mitreCosine(hull, count, i) >= 1.0 / 32.0)) return 0;
  return count;
}

// Corner i of the hull moved out so that every edge moves out by MARGIN (mitred; the hull
// has no corner sharper than projectedHull allows).
vec2 grown(vec2 hull[4], int count, int i) {
  vec2 prev = hull[(i + count - 1) % count], here = hull[i], next = hull[(i + 1) % count];
  vec2 e0 = normalize(here - prev), e1 = normalize(next - here);
  vec2 n0 = vec2(e0.y, -e0.x), n1 = vec2(e1.y, -e1.x);
  vec2 miter = normalize(n0 + n1);
  return here + miter * (MARGIN / dot(miter, n0));
}


// The signs every decision about a ray and a face is made from (raycast.comp's walk and
// entry search, entry_faces.frag's entry maps): the ray's Plucker products with the edges.
// The ray's Plucker product with the edge p -> q (vertex ids), computed from the lower id to
// the higher whatever the direction asked (then negated), so two tets sharing a face see the
// same numbers and agree on every decision: no ray slips between them or is claimed by both.
// Within its float rounding bound of zero the product is taken in double, and an exact zero
// (a ray through a vertex, along an edge, in a face) is decided by a symbolic perturbation of
// the ray (its origin moved by (e, e^2, e^3), then its direction by (h, h^2, h^3)), the same
// for every edge: the signs are those of one ray in general position. Never returns 0.
float l1(vec3 v) { return abs(v.x) + abs(v.y) + abs(v.z); }
double firstNonZero(dvec3 v) { return v.x != 0.0lf ? v.x : v.y != 0.0lf ? v.y : v.z; }

float edgeProduct(uint p, uint q, vec3 pp, vec3 pq) {
  bool ascending = p < q;
  vec3 lo = ascending ? pp : pq, hi = ascending ? pq : pp;
  precise vec3 a = lo - rayOrigin;
  precise vec3 b = hi - rayOrigin;
  precise float c = dot(rayDir, cross(a, b));
  if (abs(c) <= 1e-6 * l1(a) * l1(b)) {
    dvec3 o = dvec3(rayOrigin), d = dvec3(rayDir);
    precise dvec3 da = dvec3(lo) - o;
    precise dvec3 db = dvec3(hi) - o;
    precise double v = dot(d, cross(da, db));
    if (v == 0.0lf) v = firstNonZero(cross(da - db, d));  // the origin's move
    if (v == 0.0lf) {  // the edge is parallel to the ray: the direction's move
      double lambda = dot(db - da, d) > 0.0lf ? 1.0lf : -1.0lf;
      v = lambda * firstNonZero(cross(da, d));
      if (v == 0.0lf) {  // on the ray's own line
        double g = d.z != 0.0lf ? sign(d.z) : d.y != 0.0lf ? -sign(d.y) : sign(d.x);
        v = -lambda * g;
      }
    }
    c = v > 0.0lf ? max(float(v), 1e-30) : min(float(v), -1e-30);
  }
  return ascending ? c : -c;
}

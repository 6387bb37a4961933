// NewProximityIntersection element tests (spec/interaction.md §2.5).
//
// The primitives below append outputs whose `value` is still the raw distance;
// each pair test then stamps the element indices and subtracts its effective
// contact distance from the outputs it appended (SOFA's two-stage scheme, kept
// for identical rounding). Rejections against alarm² are strict (`>=` rejects).
// Unlike MinProximity, coincident points are not guarded except in T–S: the
// normal is then 0/0 (NaN), as in SOFA.
#include "collision/intersect/new_proximity_tests.h"

#include <limits>

#include "collision/intersect/proximity_math.h"

namespace sinew::new_proximity {

using namespace intersect_detail;

namespace {

using Out = std::vector<DetectionOutput>;

// Points p (on element 1) and q (on element 2), raw distance, normal p→q.
void emit(Out& out, std::int64_t id, const Vec3& p, const Vec3& q, const Vec3& pq, double norm2_pq) {
  DetectionOutput& d = out.emplace_back();
  d.id = id;
  d.point1 = p;
  d.point2 = q;
  d.value = std::sqrt(norm2_pq);
  d.normal = pq / d.value;
}

// Same, for a primitive whose roles are swapped with respect to the pair:
// `q` lies on element 1 and `p` on element 2, so the normal is reversed.
void emit_swapped(Out& out, std::int64_t id, const Vec3& p, const Vec3& q, const Vec3& pq, double norm2_pq) {
  DetectionOutput& d = out.emplace_back();
  d.id = id;
  d.point1 = q;
  d.point2 = p;
  d.value = std::sqrt(norm2_pq);
  d.normal = -pq / d.value;
}

int point_point_raw(double dist2, const Vec3& p, const Vec3& q, std::int64_t id, Out& out) {
  const Vec3 pq = q - p;
  const double n2 = norm2(pq);
  if (n2 >= dist2) return 0;
  emit(out, id, p, q, pq, n2);
  return 1;
}

// Segment p1p2 against point q (closest point clamped to the segment).
int line_point_raw(double dist2, const Vec3& p1, const Vec3& p2, const Vec3& q, std::int64_t id, bool swap, Out& out) {
  const Vec3 AB = p2 - p1;
  const Vec3 AQ = q - p1;
  double alpha = dot(AQ, AB) / dot(AB, AB);
  if (alpha < 0.0)
    alpha = 0.0;
  else if (alpha > 1.0)
    alpha = 1.0;
  const Vec3 p = p1 + AB * alpha;
  const Vec3 pq = q - p;
  const double n2 = norm2(pq);
  if (n2 >= dist2) return 0;
  if (swap)
    emit_swapped(out, id, p, q, pq, n2);
  else
    emit(out, id, p, q, pq, n2);
  return 1;
}

// Segments p1p2 and q1q2, interior closest points only (midpoints when parallel).
int line_line_raw(double dist2, const Vec3& p1, const Vec3& p2, const Vec3& q1, const Vec3& q2, std::int64_t id,
                  Out& out) {
  const Vec3 AB = p2 - p1;
  const Vec3 CD = q2 - q1;
  const Vec3 AC = q1 - p1;
  const double a00 = dot(AB, AB);
  const double a11 = dot(CD, CD);
  const double a01 = -dot(CD, AB);
  const double b0 = dot(AB, AC);
  const double b1 = -dot(CD, AC);
  const double det = a00 * a11 - a01 * a01;
  double alpha = 0.5;
  double beta = 0.5;
  if (det < -0.000000000001 || det > 0.000000000001) {  // 1e-12, not MinProximity's 1e-15
    alpha = (b0 * a11 - b1 * a01) / det;
    beta = (b1 * a00 - b0 * a01) / det;
    if (alpha < 0.000001 || alpha > 0.999999 || beta < 0.000001 || beta > 0.999999) return 0;
  }
  const Vec3 p = p1 + AB * alpha;
  const Vec3 q = q1 + CD * beta;
  const Vec3 pq = q - p;
  const double n2 = norm2(pq);
  if (n2 >= dist2) return 0;
  emit(out, id, p, q, pq, n2);
  return 1;
}

// Triangle p1p2p3 against point q: the closest point of the whole triangle,
// but a corner or edge counts only if this triangle owns it (flags), so that
// a feature shared by several triangles yields one contact, not one per triangle.
int triangle_point_raw(double dist2, int flags, const Vec3& p1, const Vec3& p2, const Vec3& p3, const Vec3& q,
                       std::int64_t id, bool swap, Out& out) {
  const Vec3 AB = p2 - p1;
  const Vec3 AC = p3 - p1;
  const Vec3 AQ = q - p1;
  const double a00 = dot(AB, AB);
  const double a11 = dot(AC, AC);
  const double a01 = dot(AB, AC);
  const double b0 = dot(AQ, AB);
  const double b1 = dot(AQ, AC);
  const double det = a00 * a11 - a01 * a01;
  const double eps = std::numeric_limits<double>::epsilon();
  double alpha = (b0 * a11 - b1 * a01) / det;
  double beta = (b1 * a00 - b0 * a01) / det;
  if (alpha < eps || beta < eps || alpha + beta > 1 - eps) {
    const double pAB = b0 / a00;   // parameter of q's projection on AB
    const double pAC = b1 / a11;   // ... on AC
    if (pAB < eps && pAC < eps) {  // corner A
      if (!(flags & kFlagP1)) return 0;
      alpha = 0.0;
      beta = 0.0;
    } else if (pAB < 1 - eps && pAB >= eps && beta < eps) {  // edge AB
      if (!(flags & kFlagE12)) return 0;
      alpha = pAB;
      beta = 0.0;
    } else if (pAC < 1 - eps && pAC >= eps && alpha < eps) {  // edge AC
      if (!(flags & kFlagE31)) return 0;
      alpha = 0.0;
      beta = pAC;
    } else {
      // Parameter on BC: (BQ·BC)/|BC|² expanded with the products at hand.
      const double pBC = (b1 - b0 + a00 - a01) / (a00 + a11 - 2 * a01);
      if (pBC < eps) {  // corner B
        if (!(flags & kFlagP2)) return 0;
        alpha = 1.0;
        beta = 0.0;
      } else if (pBC > 1 - eps) {  // corner C
        if (!(flags & kFlagP3)) return 0;
        alpha = 0.0;
        beta = 1.0;
      } else {  // edge BC
        if (!(flags & kFlagE23)) return 0;
        alpha = 1.0 - pBC;
        beta = pBC;
      }
    }
  }
  const Vec3 p = p1 + AB * alpha + AC * beta;
  const Vec3 pq = q - p;
  const double n2 = norm2(pq);
  if (n2 >= dist2) return 0;
  if (swap)
    emit_swapped(out, id, p, q, pq, n2);
  else
    emit(out, id, p, q, pq, n2);
  return 1;
}

// Second stage of every pair test: element indices and value -= contact on the last n outputs.
int finish(Out& out, int n, const ElemInfo& i1, const ElemInfo& i2, double contact) {
  for (auto it = out.end() - n; it != out.end(); ++it) {
    it->elem1 = i1.index;
    it->elem2 = i2.index;
    it->value -= contact;
  }
  return n;
}

}  // namespace

int point_point(const Params& prm, const PointElem& e1, const PointElem& e2, Out& out) {
  const double alarm = prm.alarm + e1.info.cd + e2.info.cd;
  const int n = point_point_raw(alarm * alarm, e1.p, e2.p, larger_model_index(e1.info, e2.info), out);
  return finish(out, n, e1.info, e2.info, prm.contact + e1.info.cd + e2.info.cd);
}

int line_point(const Params& prm, const LineElem& e1, const PointElem& e2, Out& out) {
  const double alarm = prm.alarm + e1.info.cd + e2.info.cd;
  const int n = line_point_raw(alarm * alarm, e1.a, e1.b, e2.p, e2.info.index, false, out);
  return finish(out, n, e1.info, e2.info, prm.contact + e1.info.cd + e2.info.cd);
}

int line_line(const Params& prm, const LineElem& e1, const LineElem& e2, Out& out) {
  // Always tested: useLineLine only gates the edge–edge tests inside T–L and T–T.
  const double alarm = prm.alarm + e1.info.cd + e2.info.cd;
  const int n = line_line_raw(alarm * alarm, e1.a, e1.b, e2.a, e2.b, larger_model_index(e1.info, e2.info), out);
  return finish(out, n, e1.info, e2.info, prm.contact + e1.info.cd + e2.info.cd);
}

int triangle_point(const Params& prm, const TriangleElem& e1, const PointElem& e2, Out& out) {
  const double alarm = prm.alarm + e1.info.cd + e2.info.cd;
  const int n = triangle_point_raw(alarm * alarm, e1.flags, e1.a, e1.b, e1.c, e2.p, e2.info.index, false, out);
  return finish(out, n, e1.info, e2.info, prm.contact + e1.info.cd + e2.info.cd);
}

int triangle_line(const Params& prm, const TriangleElem& e1, const LineElem& e2, Out& out) {
  const double alarm = prm.alarm + e1.info.cd + e2.info.cd;
  const double dist2 = alarm * alarm;
  const std::int64_t id = e2.info.index;
  const int f1 = e1.flags;
  int n = 0;
  // The triangle's owned corners against the segment (roles swapped: the corner is on element 1).
  if (f1 & kFlagP1) n += line_point_raw(dist2, e2.a, e2.b, e1.a, id, true, out);
  if (f1 & kFlagP2) n += line_point_raw(dist2, e2.a, e2.b, e1.b, id, true, out);
  if (f1 & kFlagP3) n += line_point_raw(dist2, e2.a, e2.b, e1.c, id, true, out);
  // Both segment ends against the triangle (lines have no flags to consult).
  n += triangle_point_raw(dist2, f1, e1.a, e1.b, e1.c, e2.a, id, false, out);
  n += triangle_point_raw(dist2, f1, e1.a, e1.b, e1.c, e2.b, id, false, out);
  if (prm.use_line_line) {
    if (f1 & kFlagE12) n += line_line_raw(dist2, e1.a, e1.b, e2.a, e2.b, id, out);
    if (f1 & kFlagE23) n += line_line_raw(dist2, e1.b, e1.c, e2.a, e2.b, id, out);
    if (f1 & kFlagE31) n += line_line_raw(dist2, e1.c, e1.a, e2.a, e2.b, id, out);
  }
  return finish(out, n, e1.info, e2.info, prm.contact + e1.info.cd + e2.info.cd);
}

int triangle_triangle(const Params& prm, const TriangleElem& e1, const TriangleElem& e2, Out& out) {
  // SOFA refuses (with an error) element indices outside their model.
  if (e1.info.index >= e1.info.model_size || e2.info.index >= e2.info.model_size) return 0;
  // Adjacent triangles of one surface always touch: never a contact.
  if (e1.info.model == e2.info.model) {
    for (unsigned i : e1.v)
      for (unsigned j : e2.v)
        if (i == j) return 0;
  }
  const double alarm = prm.alarm + e1.info.cd + e2.info.cd;
  const double dist2 = alarm * alarm;
  const int f1 = e1.flags;
  const int f2 = e2.flags;
  // Ids: 3 per triangle of model 1 for its corners, then 12 per triangle of
  // model 2 (3 corners + 9 edge pairs), so every candidate of the pair is unique.
  const std::int64_t id1 = std::int64_t{e1.info.index} * 3;
  const std::int64_t id2 = static_cast<std::int64_t>(e1.info.model_size) * 3 + std::int64_t{e2.info.index} * 12;
  // SOFA also overwrites the stored normal of one triangle with minus the other's
  // (unless both models are bothSide). That side effect on the models is not
  // reproduced here: the tests below never read the normals, only later users of
  // the stored normals would see it (the caller owns that decision).
  int n = 0;
  // e1's corners against e2. Corner 0 is tested whatever e1's FLAG_P1
  // (source quirk, kept: it can add contacts SOFA also adds).
  n += triangle_point_raw(dist2, f2, e2.a, e2.b, e2.c, e1.a, id1 + 0, true, out);
  if (f1 & kFlagP2) n += triangle_point_raw(dist2, f2, e2.a, e2.b, e2.c, e1.b, id1 + 1, true, out);
  if (f1 & kFlagP3) n += triangle_point_raw(dist2, f2, e2.a, e2.b, e2.c, e1.c, id1 + 2, true, out);
  // e2's owned corners against e1.
  if (f2 & kFlagP1) n += triangle_point_raw(dist2, f1, e1.a, e1.b, e1.c, e2.a, id2 + 0, false, out);
  if (f2 & kFlagP2) n += triangle_point_raw(dist2, f1, e1.a, e1.b, e1.c, e2.b, id2 + 1, false, out);
  if (f2 & kFlagP3) n += triangle_point_raw(dist2, f1, e1.a, e1.b, e1.c, e2.c, id2 + 2, false, out);
  if (prm.use_line_line) {
    // Owned edges of e1 (12, 23, 31) against owned edges of e2 (12, 23, 31), ids id2+3 ... id2+11.
    const Vec3* p[3][2] = {{&e1.a, &e1.b}, {&e1.b, &e1.c}, {&e1.c, &e1.a}};
    const Vec3* q[3][2] = {{&e2.a, &e2.b}, {&e2.b, &e2.c}, {&e2.c, &e2.a}};
    const int edge_flag[3] = {kFlagE12, kFlagE23, kFlagE31};
    for (int i = 0; i < 3; ++i) {
      if (!(f1 & edge_flag[i])) continue;
      for (int j = 0; j < 3; ++j)
        if (f2 & edge_flag[j])
          n += line_line_raw(dist2, *p[i][0], *p[i][1], *q[j][0], *q[j][1], id2 + 3 + 3 * i + j, out);
    }
  }
  return finish(out, n, e1.info, e2.info, prm.contact + e1.info.cd + e2.info.cd);
}

int sphere_sphere(const Params& prm, const SphereElem& e1, const SphereElem& e2, Out& out) {
  const double alarm = prm.alarm + e1.info.cd + e2.info.cd + e1.r + e2.r;
  // Points are the centres here, even for rigid spheres.
  const int n = point_point_raw(alarm * alarm, e1.c, e2.c, larger_model_index(e1.info, e2.info), out);
  return finish(out, n, e1.info, e2.info, prm.contact + e1.info.cd + e2.info.cd + e1.r + e2.r);
}

int sphere_point(const Params& prm, const SphereElem& e1, const PointElem& e2, Out& out) {
  const double alarm = prm.alarm + e1.info.cd + e2.info.cd + e1.r;
  const int n = point_point_raw(alarm * alarm, e1.c, e2.p, larger_model_index(e1.info, e2.info), out);
  return finish(out, n, e1.info, e2.info, prm.contact + e1.info.cd + e2.info.cd + e1.r);
}

int line_sphere(const Params& prm, const LineElem& e1, const SphereElem& e2, Out& out) {
  const double alarm = prm.alarm + e1.info.cd + e2.info.cd + e2.r;
  const int n = line_point_raw(alarm * alarm, e1.a, e1.b, e2.c, e2.info.index, false, out);
  return finish(out, n, e1.info, e2.info, prm.contact + e1.info.cd + e2.info.cd + e2.r);
}

int triangle_sphere(const Params& prm, const TriangleElem& e1, const SphereElem& e2, Out& out) {
  // Its own variant of triangle–point: 1e-6 windows instead of machine epsilon,
  // a 1e-7 test on pAC for corner A, two edge-flag quirks, and edge branches
  // without the lower bounds pAB ≥ ε / pAC ≥ ε: when β < 1e-6 with pAB < 0 and
  // pAC ≥ 1e-7 (possible at an obtuse corner A), "edge AB" is taken at α = pAB,
  // a point outside the triangle. All kept: SOFA's SofaScene contacts use this.
  const int flags = e1.flags;
  const double alarm = prm.alarm + e1.info.cd + e2.info.cd + e2.r;
  const double dist2 = alarm * alarm;
  const Vec3 AB = e1.b - e1.a;
  const Vec3 AC = e1.c - e1.a;
  const Vec3 AQ = e2.c - e1.a;
  const double a00 = dot(AB, AB);
  const double a11 = dot(AC, AC);
  const double a01 = dot(AB, AC);
  const double b0 = dot(AQ, AB);
  const double b1 = dot(AQ, AC);
  const double det = a00 * a11 - a01 * a01;
  double alpha = (b0 * a11 - b1 * a01) / det;
  double beta = (b1 * a00 - b0 * a01) / det;
  if (alpha < 0.000001 || beta < 0.000001 || alpha + beta > 0.999999) {
    const double pAB = b0 / a00;
    const double pAC = b1 / a11;
    if (pAB < 0.000001 && pAC < 0.0000001) {  // corner A
      if (!(flags & kFlagP1)) return 0;
      alpha = 0.0;
      beta = 0.0;
    } else if (pAB < 0.999999 && beta < 0.000001) {  // edge AB (pAB may be < 0)
      if (!(flags & kFlagE12)) return 0;
      alpha = pAB;
      beta = 0.0;
    } else if (pAC < 0.999999 && alpha < 0.000001) {  // edge AC: SOFA checks E12 here (quirk)
      if (!(flags & kFlagE12)) return 0;
      alpha = 0.0;
      beta = pAC;
    } else {
      const double pBC = (b1 - b0 + a00 - a01) / (a00 + a11 - 2 * a01);
      if (pBC < 0.000001) {  // corner B
        if (!(flags & kFlagP2)) return 0;
        alpha = 1.0;
        beta = 0.0;
      } else if (pBC > 0.999999) {  // corner C
        if (!(flags & kFlagP3)) return 0;
        alpha = 0.0;
        beta = 1.0;
      } else {  // edge BC: SOFA checks E31 here (quirk)
        if (!(flags & kFlagE31)) return 0;
        alpha = 1.0 - pBC;
        beta = pBC;
      }
    }
  }
  const Vec3 p = e1.a + AB * alpha + AC * beta;
  const Vec3 pq = e2.c - p;
  const double n2 = norm2(pq);
  if (n2 >= dist2) return 0;
  DetectionOutput& d = append(out, e1.info, e2.info, e2.info.index);
  d.value = std::sqrt(n2);
  d.normal = d.value > 1e-15 ? Vec3(pq / d.value) : Vec3(1, 0, 0);
  d.value -= prm.contact + e1.info.cd + e2.info.cd + e2.r;
  d.point1 = p;
  d.point2 = e2.contact_point(d.normal);  // rigid: the sphere's near side
  return 1;
}

}  // namespace sinew::new_proximity

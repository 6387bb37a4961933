// MinProximityIntersection element tests (spec/interaction.md §2.4).
//
// Every test keeps SOFA's arithmetic: the same 2×2 normal equations, the same
// literal thresholds (1e-6, 0.999999, det 1e-15) and the same summation order
// of skins (SOFA's own "e1" is the point or sphere in the mixed pairs, so its
// skin is added first there). Rejections against alarm² are strict (`>=`
// rejects); S–S goes through DiscreteIntersection's inclusive test.
#include "collision/intersect/min_proximity_tests.h"

#include "collision/intersect/discrete_tests.h"
#include "collision/intersect/proximity_math.h"

namespace sinew::min_proximity {

using namespace intersect_detail;

namespace {

// Barycentric window of the interior-only triangle and segment tests: edges and
// corners are left to the L–P and P–P tests of the neighbouring elements.
constexpr double kLow = 0.000001;
constexpr double kHigh = 0.999999;

}  // namespace

int point_point(const Params& prm, const PointElem& e1, const PointElem& e2, std::vector<DetectionOutput>& out) {
  const double alarm = prm.alarm + e1.info.cd + e2.info.cd;
  const Vec3 PQ = e2.p - e1.p;
  if (norm2(PQ) >= alarm * alarm) return 0;
  DetectionOutput& d = append_along(out, e1.info, e2.info, larger_model_index(e1.info, e2.info), PQ,
                                    prm.contact + e1.info.cd + e2.info.cd);
  d.point1 = e1.p;
  d.point2 = e2.p;
  return 1;
}

int line_point(const Params& prm, const LineElem& e1, const PointElem& e2, std::vector<DetectionOutput>& out) {
  const double alarm = prm.alarm + e2.info.cd + e1.info.cd;
  const Vec3 AB = e1.b - e1.a;
  const Vec3 AP = e2.p - e1.a;
  const double alpha = dot(AP, AB) / dot(AB, AB);
  // Closest point of the segment (clamped; the cube-level test uses a window).
  Vec3 Q;
  if (alpha <= 0.0)
    Q = e1.a;
  else if (alpha >= 1.0)
    Q = e1.b;
  else
    Q = e1.a + AB * alpha;
  const Vec3 QP = e2.p - Q;
  if (norm2(QP) >= alarm * alarm) return 0;
  DetectionOutput& d = append_along(out, e1.info, e2.info, e2.info.index, QP, prm.contact + e2.info.cd + e1.info.cd);
  d.point1 = Q;
  d.point2 = e2.p;
  return 1;
}

int line_line(const Params& prm, const LineElem& e1, const LineElem& e2, std::vector<DetectionOutput>& out) {
  const double alarm = prm.alarm + e1.info.cd + e2.info.cd;
  const Vec3 AB = e1.b - e1.a;
  const Vec3 CD = e2.b - e2.a;
  const Vec3 AC = e2.a - e1.a;
  // Closest points P = A + α AB, Q = C + β CD: PQ ⟂ AB and PQ ⟂ CD.
  const double a00 = dot(AB, AB);
  const double a11 = dot(CD, CD);
  const double a01 = -dot(CD, AB);
  const double b0 = dot(AB, AC);
  const double b1 = -dot(CD, AC);
  const double det = a00 * a11 - a01 * a01;
  double alpha = 0.5;
  double beta = 0.5;
  if (det < -1.0e-15 || det > 1.0e-15) {
    alpha = (b0 * a11 - b1 * a01) / det;
    beta = (b1 * a00 - b0 * a01) / det;
    // Interior pairs only: a closest point at an end is a line–point case.
    if (alpha < kLow || alpha > kHigh || beta < kLow || beta > kHigh) return 0;
  }  // else (near-)parallel: the two midpoints
  const Vec3 P = e1.a + AB * alpha;
  const Vec3 Q = e2.a + CD * beta;
  const Vec3 PQ = Q - P;
  if (norm2(PQ) >= alarm * alarm) return 0;
  DetectionOutput& d = append_along(out, e1.info, e2.info, larger_model_index(e1.info, e2.info), PQ,
                                    prm.contact + e1.info.cd + e2.info.cd);
  d.point1 = P;
  d.point2 = Q;
  return 1;
}

int triangle_point(const Params& prm, const TriangleElem& e1, const PointElem& e2, std::vector<DetectionOutput>& out) {
  const double alarm = prm.alarm + e2.info.cd + e1.info.cd;
  const Vec3 AB = e1.b - e1.a;
  const Vec3 AC = e1.c - e1.a;
  const Vec3 AP = e2.p - e1.a;
  // Projection Q = A + α AB + β AC of P on the triangle's plane.
  const double a00 = dot(AB, AB);
  const double a11 = dot(AC, AC);
  const double a01 = dot(AB, AC);
  const double b0 = dot(AP, AB);
  const double b1 = dot(AP, AC);
  const double det = a00 * a11 - a01 * a01;
  const double alpha = (b0 * a11 - b1 * a01) / det;
  const double beta = (b1 * a00 - b0 * a01) / det;
  if (alpha < kLow || beta < kLow || alpha + beta > kHigh) return 0;  // interior only
  const Vec3 Q = e1.a + AB * alpha + AC * beta;
  const Vec3 QP = e2.p - Q;
  if (norm2(QP) >= alarm * alarm) return 0;
  DetectionOutput& d = append_along(out, e1.info, e2.info, e2.info.index, QP, prm.contact + e2.info.cd + e1.info.cd);
  d.point1 = Q;
  d.point2 = e2.p;
  // useSurfaceNormals: the stored triangle normal replaces the direction (value unchanged).
  if (prm.use_surface_normals) d.normal = e1.normal;
  return 1;
}

int triangle_sphere(const Params& prm, const TriangleElem& e1, const SphereElem& e2,
                    std::vector<DetectionOutput>& out) {
  const double alarm = prm.alarm + e2.r + e2.info.cd + e1.info.cd;
  // Same projection as triangle_point, written with edge vectors leaving from A
  // reversed as SOFA does (signs cancel exactly in every product).
  const Vec3 x13 = e1.a - e1.b;
  const Vec3 x23 = e1.a - e1.c;
  const Vec3 x03 = e1.a - e2.c;
  const double a00 = dot(x13, x13);
  const double a11 = dot(x23, x23);
  const double a01 = dot(x13, x23);
  const double b0 = dot(x13, x03);
  const double b1 = dot(x23, x03);
  const double det = a00 * a11 - a01 * a01;
  const double alpha = (b0 * a11 - b1 * a01) / det;
  const double beta = (b1 * a00 - b0 * a01) / det;
  if (alpha < kLow || beta < kLow || alpha + beta > kHigh) return 0;
  const Vec3 Q = e1.a - x13 * alpha - x23 * beta;
  const Vec3 QP = e2.c - Q;
  if (norm2(QP) >= alarm * alarm) return 0;
  DetectionOutput& d =
      append_along(out, e1.info, e2.info, e2.info.index, QP, prm.contact + e2.r + e2.info.cd + e1.info.cd);
  d.point1 = Q;
  d.point2 = e2.contact_point(d.normal);  // normal points into the sphere: its near side
  return 1;
}

int line_sphere(const Params& prm, const LineElem& e1, const SphereElem& e2, std::vector<DetectionOutput>& out) {
  const double alarm = prm.alarm + e2.r + e2.info.cd + e1.info.cd;
  const Vec3 x32 = e1.a - e1.b;
  const Vec3 x31 = e2.c - e1.b;
  // α is the centre's projection parameter measured from B towards A...
  const double alpha = dot(x32, x31) / dot(x32, x32);
  if (alpha < kLow || alpha > kHigh) return 0;
  // ...but SOFA applies it from A towards B: Q is the projection mirrored about
  // the midpoint. Kept on purpose (spec §2.4 "L–S quirk"; no regression scene
  // exercises it, and matching SOFA matters more than the geometry here).
  const Vec3 Q = e1.a - x32 * alpha;
  const Vec3 QP = e2.c - Q;
  if (norm2(QP) >= alarm * alarm) return 0;
  DetectionOutput& d =
      append_along(out, e1.info, e2.info, e2.info.index, QP, prm.contact + e2.r + e2.info.cd + e1.info.cd);
  d.point1 = Q;
  d.point2 = e2.contact_point(d.normal);
  return 1;
}

int sphere_point(const Params& prm, const SphereElem& e1, const PointElem& e2, std::vector<DetectionOutput>& out) {
  const double alarm = prm.alarm + e1.r + e1.info.cd + e2.info.cd;
  const Vec3 PQ = e2.p - e1.c;
  if (norm2(PQ) >= alarm * alarm) return 0;
  // id is the sphere's index whatever the model sizes (SOFA's choice here).
  DetectionOutput& d =
      append_along(out, e1.info, e2.info, e1.info.index, PQ, prm.contact + e1.r + e1.info.cd + e2.info.cd);
  d.point1 = e1.contact_point(-d.normal);  // sphere side facing the point
  d.point2 = e2.p;
  return 1;
}

int sphere_sphere(const Params& prm, const SphereElem& e1, const SphereElem& e2, std::vector<DetectionOutput>& out) {
  const double alarm = prm.alarm + e1.info.cd + e2.info.cd;
  const double contact = prm.contact + e1.info.cd + e2.info.cd;
  return discrete::sphere_sphere(e1, e2, alarm, contact, out);
}

}  // namespace sinew::min_proximity

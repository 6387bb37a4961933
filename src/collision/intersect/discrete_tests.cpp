// DiscreteIntersection element tests (spec/interaction.md §2.3).
#include "collision/intersect/discrete_tests.h"

#include <cmath>

#include "collision/intersect/proximity_math.h"

namespace sinew::discrete {

using namespace intersect_detail;

int sphere_sphere(const SphereElem& e1, const SphereElem& e2, double alarm, double contact,
                  std::vector<DetectionOutput>& out) {
  const double r = e1.r + e2.r;
  const double reach = alarm + r;
  const Vec3 d12 = e2.c - e1.c;
  const double dist2 = norm2(d12);
  // Inclusive bound (`>` rejects), unlike the proximity point tests' strict `<`.
  if (dist2 > reach * reach) return 0;
  DetectionOutput& d = append(out, e1.info, e2.info, larger_model_index(e1.info, e2.info));
  const double dist = std::sqrt(dist2);
  // No guard for coincident centres: SOFA divides by zero too (normal NaN).
  d.normal = d12 / dist;
  // Each sphere's point faces the other one (rigid: surface point; Vec3: centre).
  d.point1 = e1.contact_point(-d.normal);
  d.point2 = e2.contact_point(d.normal);
  d.value = dist - r - contact;
  return 1;
}

int sphere_sphere(const SphereElem& e1, const SphereElem& e2, std::vector<DetectionOutput>& out) {
  // DiscreteIntersection has no distances of its own and ignores the models' skins.
  return sphere_sphere(e1, e2, 0.0, 0.0, out);
}

}  // namespace sinew::discrete

// DiscreteIntersection (spec/interaction.md §2.3): exact intersection tests
// with no alarm distance (spheres against spheres).
#include "collision/intersect/discrete_tests.h"
#include "collision/intersection.h"
#include "collision/model/sphere_collision_model.h"
#include "core/registry.h"

namespace sinew {

namespace {

int sphere_sphere(const Intersection&, const CollisionModelBase& m1, unsigned i1, const CollisionModelBase& m2,
                  unsigned i2, std::vector<DetectionOutput>& out) {
  return discrete::sphere_sphere(static_cast<const SphereCollisionModel&>(m1).elem(i1),
                                 static_cast<const SphereCollisionModel&>(m2).elem(i2), out);
}

class DiscreteIntersection final : public Intersection {
 public:
  double alarm_distance() const override { return 0.0; }
  double contact_distance() const override { return 0.0; }
  double cube_margin(const CollisionModelBase&, const CollisionModelBase&) const override { return 0.0; }

  void init() override { add(Kind::sphere, Kind::sphere, &sphere_sphere); }
};

}  // namespace

void register_discrete_intersection(Registry& r) {
  ComponentInfo info;
  info.name = "DiscreteIntersection";
  info.category = "Collision/Detection";
  info.description = "exact intersection tests (spheres against spheres)";
  info.create = creator<DiscreteIntersection>();
  r.add(std::move(info));
}

}  // namespace sinew

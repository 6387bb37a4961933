// DiscreteIntersection (spec/interaction.md §2.3): exact intersection tests
// with no alarm distance (spheres against spheres, segments crossing
// triangles, points inside tetrahedra, oriented boxes against boxes and spheres).
#include "collision/intersect/discrete_tests.h"
#include "collision/intersect/element_test.h"
#include "collision/intersect/obb_tests.h"
#include "collision/intersection.h"
#include "collision/model/line_collision_model.h"
#include "collision/model/obb_collision_model.h"
#include "collision/model/point_collision_model.h"
#include "collision/model/sphere_collision_model.h"
#include "collision/model/tetrahedron_collision_model.h"
#include "collision/model/triangle_collision_model.h"
#include "core/registry.h"

namespace sinew {

namespace {

int sphere_sphere(const Intersection&, const CollisionModelBase& m1, unsigned i1, const CollisionModelBase& m2,
                  unsigned i2, std::vector<DetectionOutput>& out) {
  return discrete::sphere_sphere(static_cast<const SphereCollisionModel&>(m1).elem(i1),
                                 static_cast<const SphereCollisionModel&>(m2).elem(i2), out);
}

int triangle_line(const Intersection&, const CollisionModelBase& m1, unsigned i1, const CollisionModelBase& m2,
                  unsigned i2, std::vector<DetectionOutput>& out) {
  return discrete::triangle_line(static_cast<const TriangleCollisionModel&>(m1).elem(i1),
                                 static_cast<const LineCollisionModel&>(m2).elem(i2), out);
}

int tetrahedron_point(const Intersection&, const CollisionModelBase& m1, unsigned i1, const CollisionModelBase& m2,
                      unsigned i2, std::vector<DetectionOutput>& out) {
  return discrete::tetrahedron_point(static_cast<const TetrahedronCollisionModel&>(m1).elem(i1),
                                     static_cast<const PointCollisionModel&>(m2).elem(i2),
                                     m1.mstate() == m2.mstate(), out);
}

class DiscreteIntersection final : public Intersection {
 public:
  double alarm_distance() const override { return 0.0; }
  double contact_distance() const override { return 0.0; }
  double cube_margin(const CollisionModelBase&, const CollisionModelBase&) const override { return 0.0; }

  void init() override {
    add(Kind::sphere, Kind::sphere, &sphere_sphere);
    add(Kind::triangle, Kind::line, &triangle_line);
    add(Kind::tetrahedron, Kind::point, &tetrahedron_point);
    // SOFA's oriented-box plugin adds these to every intersection method derived from this one.
    add(Kind::obb, Kind::obb, &distance_test<ObbCollisionModel, ObbCollisionModel, obb::obb_obb>);
    add(Kind::sphere, Kind::obb, &distance_test<SphereCollisionModel, ObbCollisionModel, obb::sphere_obb>);
  }
};

}  // namespace

void register_discrete_intersection(Registry& r) {
  ComponentInfo info;
  info.name = "DiscreteIntersection";
  info.category = "Collision/Detection";
  info.description = "exact intersection tests: spheres, segments crossing triangles, points inside tetrahedra";
  info.create = creator<DiscreteIntersection>();
  r.add(std::move(info));
}

}  // namespace sinew

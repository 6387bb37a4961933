// MinProximityIntersection (spec/interaction.md §2.4): proximity tests that
// only report interior projections (triangle–point inside the triangle,
// line–line inside both segments), edges and corners being left to the
// line and point models.
#include "collision/intersect/element_test.h"
#include "collision/intersect/min_proximity_tests.h"
#include "collision/intersect/obb_tests.h"
#include "collision/model/line_collision_model.h"
#include "collision/model/obb_collision_model.h"
#include "collision/model/point_collision_model.h"
#include "collision/model/sphere_collision_model.h"
#include "collision/model/triangle_collision_model.h"
#include "collision/proximity_intersection.h"
#include "core/registry.h"

namespace sinew {

namespace {

using P = PointCollisionModel;
using L = LineCollisionModel;
using T = TriangleCollisionModel;
using S = SphereCollisionModel;
using B = ObbCollisionModel;

class MinProximityIntersection final : public ProximityIntersection {
 public:
  Field<bool> use_sphere_triangle{this, "useSphereTriangle", true, "test spheres against triangles, lines and points",
                                  "Collision"};
  Field<bool> use_point_point{this, "usePointPoint", true, "test points against points", "Collision"};
  Field<bool> use_surface_normals{this, "useSurfaceNormals", false, "use the triangle's normal as the contact normal",
                                  "Collision"};
  Field<bool> use_line_point{this, "useLinePoint", true, "test lines against points", "Collision"};
  Field<bool> use_line_line{this, "useLineLine", true, "test lines against lines", "Collision"};

  const min_proximity::Params& params() const { return params_; }

  void init() override {
    if (!check_distances()) return;
    using K = Kind;
    using M = MinProximityIntersection;
    add(K::sphere, K::sphere, &element_test<M, S, S, min_proximity::sphere_sphere>);
    if (use_point_point.value()) add(K::point, K::point, &element_test<M, P, P, min_proximity::point_point>);
    if (use_line_point.value()) add(K::line, K::point, &element_test<M, L, P, min_proximity::line_point>);
    if (use_line_line.value()) add(K::line, K::line, &element_test<M, L, L, min_proximity::line_line>);
    add(K::triangle, K::point, &element_test<M, T, P, min_proximity::triangle_point>);
    if (use_sphere_triangle.value()) {
      add(K::sphere, K::point, &element_test<M, S, P, min_proximity::sphere_point>);
      add(K::triangle, K::sphere, &element_test<M, T, S, min_proximity::triangle_sphere>);
      add(K::line, K::sphere, &element_test<M, L, S, min_proximity::line_sphere>);
    }
    ignore(K::triangle, K::line);
    ignore(K::triangle, K::triangle);
    // Oriented boxes: the pairs SOFA's plugin gives every method derived from DiscreteIntersection.
    add(K::obb, K::obb, &distance_test<B, B, obb::obb_obb>);
    add(K::sphere, K::obb, &distance_test<S, B, obb::sphere_obb>);
    begin_detection();
  }

  void begin_detection() override {
    params_.alarm = alarm.value();
    params_.contact = contact.value();
    params_.use_surface_normals = use_surface_normals.value();
  }

 private:
  min_proximity::Params params_;
};

}  // namespace

void register_min_proximity_intersection(Registry& r) {
  ComponentInfo info;
  info.name = "MinProximityIntersection";
  info.category = "Collision/Detection";
  info.description = "proximity tests between points, lines, triangles and spheres, interior projections only";
  info.create = creator<MinProximityIntersection>();
  r.add(std::move(info));
}

}  // namespace sinew

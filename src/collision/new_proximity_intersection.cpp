// NewProximityIntersection (spec/interaction.md §2.5): proximity tests that
// project onto the closest feature (vertex, edge or interior) of lines and
// triangles, each feature owned by one triangle (the triangle flags).
#include "collision/intersect/element_test.h"
#include "collision/intersect/new_proximity_tests.h"
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

class NewProximityIntersection final : public ProximityIntersection {
 public:
  Field<bool> use_line_line{this, "useLineLine", false, "test lines against lines (and triangle edges)", "Collision"};

  const new_proximity::Params& params() const { return params_; }

  void init() override {
    if (!check_distances()) return;
    using K = Kind;
    using M = NewProximityIntersection;
    add(K::sphere, K::sphere, &element_test<M, S, S, new_proximity::sphere_sphere>);
    add(K::point, K::point, &element_test<M, P, P, new_proximity::point_point>);
    add(K::line, K::point, &element_test<M, L, P, new_proximity::line_point>);
    add(K::line, K::line, &element_test<M, L, L, new_proximity::line_line>);
    add(K::triangle, K::point, &element_test<M, T, P, new_proximity::triangle_point>);
    add(K::triangle, K::line, &element_test<M, T, L, new_proximity::triangle_line>);
    add(K::triangle, K::triangle, &element_test<M, T, T, new_proximity::triangle_triangle>);
    add(K::sphere, K::point, &element_test<M, S, P, new_proximity::sphere_point>);
    add(K::line, K::sphere, &element_test<M, L, S, new_proximity::line_sphere>);
    add(K::triangle, K::sphere, &element_test<M, T, S, new_proximity::triangle_sphere>);
    // Oriented boxes (SOFA's plugin): the discrete method's box pairs, and triangle–box for this method only.
    add(K::obb, K::obb, &distance_test<B, B, obb::obb_obb>);
    add(K::sphere, K::obb, &distance_test<S, B, obb::sphere_obb>);
    add(K::triangle, K::obb, &distance_test<T, B, obb::triangle_obb>);
    begin_detection();
  }

  void begin_detection() override {
    params_.alarm = alarm.value();
    params_.contact = contact.value();
    params_.use_line_line = use_line_line.value();
  }

 private:
  new_proximity::Params params_;
};

}  // namespace

void register_new_proximity_intersection(Registry& r) {
  ComponentInfo info;
  info.name = "NewProximityIntersection";
  info.category = "Collision/Detection";
  info.description = "proximity tests between points, lines, triangles and spheres, closest features included";
  info.create = creator<NewProximityIntersection>();
  r.add(std::move(info));
}

}  // namespace sinew

// MinProximityIntersection (spec/interaction.md §2.4): proximity tests that
// only report interior projections (triangle–point inside the triangle,
// line–line inside both segments), edges and corners being left to the
// line and point models.
#include "collision/intersect/element_test.h"
#include "collision/intersect/min_proximity_tests.h"
#include "collision/model/line_collision_model.h"
#include "collision/model/point_collision_model.h"
#include "collision/model/sphere_collision_model.h"
#include "collision/model/triangle_collision_model.h"
#include "core/registry.h"

namespace sinew {

namespace {

using P = PointCollisionModel;
using L = LineCollisionModel;
using T = TriangleCollisionModel;
using S = SphereCollisionModel;

class MinProximityIntersection final : public Intersection {
 public:
  Field<double> alarm{this, "alarmDistance", 1.0, "distance below which pairs are reported", "Collision", "length"};
  Field<double> contact{this, "contactDistance", 0.5, "distance the response keeps between the objects",
                        "Collision", "length"};
  Field<bool> use_sphere_triangle{this, "useSphereTriangle", true, "test spheres against triangles, lines and points",
                                  "Collision"};
  Field<bool> use_point_point{this, "usePointPoint", true, "test points against points", "Collision"};
  Field<bool> use_surface_normals{this, "useSurfaceNormals", false,
                                  "use the triangle's normal as the contact normal", "Collision"};
  Field<bool> use_line_point{this, "useLinePoint", true, "test lines against points", "Collision"};
  Field<bool> use_line_line{this, "useLineLine", true, "test lines against lines", "Collision"};

  double alarm_distance() const override { return alarm.value(); }
  double contact_distance() const override { return contact.value(); }
  const min_proximity::Params& params() const { return params_; }

  void init() override {
    if (!(alarm.value() >= 0) || !(contact.value() >= 0)) {
      msg_error("alarmDistance and contactDistance must be >= 0");
      set_state(ComponentState::invalid);
      return;
    }
    using K = Kind;
    add(K::sphere, K::sphere, &element_test<MinProximityIntersection, S, S, min_proximity::sphere_sphere>);
    if (use_point_point.value()) add(K::point, K::point, &element_test<MinProximityIntersection, P, P, min_proximity::point_point>);
    if (use_line_point.value()) add(K::line, K::point, &element_test<MinProximityIntersection, L, P, min_proximity::line_point>);
    if (use_line_line.value()) add(K::line, K::line, &element_test<MinProximityIntersection, L, L, min_proximity::line_line>);
    add(K::triangle, K::point, &element_test<MinProximityIntersection, T, P, min_proximity::triangle_point>);
    if (use_sphere_triangle.value()) {
      add(K::sphere, K::point, &element_test<MinProximityIntersection, S, P, min_proximity::sphere_point>);
      add(K::triangle, K::sphere, &element_test<MinProximityIntersection, T, S, min_proximity::triangle_sphere>);
      add(K::line, K::sphere, &element_test<MinProximityIntersection, L, S, min_proximity::line_sphere>);
    }
    ignore(K::triangle, K::line);
    ignore(K::triangle, K::triangle);
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

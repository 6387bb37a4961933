// LocalMinDistance (spec/interaction.md §2.7): proximity tests whose contacts
// must also leave each element inside the cone its neighbourhood allows (a
// point's surrounding triangles and edges, an edge's two triangles, a
// triangle's front side), so that contacts found through a thin part of a
// surface are rejected.
#include "collision/intersect/element_test.h"
#include "collision/intersect/local_min_distance_tests.h"
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

namespace lmd = local_min_distance;
using P = PointCollisionModel;
using L = LineCollisionModel;
using T = TriangleCollisionModel;
using S = SphereCollisionModel;
using B = ObbCollisionModel;

class LocalMinDistance final : public ProximityIntersection {
 public:
  Field<bool> filter_intersection{this, "filterIntersection", true,
                                  "reject contacts leaving an element outside its neighbourhood's cone", "Collision"};
  Field<double> angle_cone{this, "angleCone", 0.0, "widening of the filtering cones", "Collision"};
  Field<double> cone_factor{this, "coneFactor", 0.5, "factor of the cone width taken from the mean normal",
                            "Collision"};
  Field<bool> use_lmd_filters{this, "useLMDFilters", false, "filters are applied by an external component",
                              "Collision"};

  const lmd::Params& params() const { return params_; }
  bool uses_neighbourhoods() const override { return true; }

  void init() override {
    if (!check_distances()) return;
    using K = Kind;
    add(K::sphere, K::sphere, &sphere_sphere);
    add(K::sphere, K::point, &sphere_point);
    add(K::point, K::point, &point_point);
    add(K::line, K::line, &line_line);
    add(K::line, K::point, &line_point);
    add(K::line, K::sphere, &line_sphere);
    add(K::triangle, K::point, &triangle_point);
    add(K::triangle, K::sphere, &triangle_sphere);
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
    params_.filter_intersection = filter_intersection.value();
    params_.angle_cone = angle_cone.value();
    params_.cone_factor = cone_factor.value();
    params_.use_lmd_filters = use_lmd_filters.value();
  }

 private:
  // Adapters: the elements and the neighbourhoods their filters read.
  static const lmd::Params& prm(const Intersection& in) { return static_cast<const LocalMinDistance&>(in).params(); }
  template <class M>
  static const M& as(const CollisionModelBase& m) {
    return static_cast<const M&>(m);
  }
  static int sphere_sphere(const Intersection& in, const CollisionModelBase& m1, unsigned i1,
                           const CollisionModelBase& m2, unsigned i2, std::vector<DetectionOutput>& out) {
    return lmd::sphere_sphere(prm(in), as<S>(m1).elem(i1), as<S>(m2).elem(i2), out);
  }
  static int sphere_point(const Intersection& in, const CollisionModelBase& m1, unsigned i1,
                          const CollisionModelBase& m2, unsigned i2, std::vector<DetectionOutput>& out) {
    return lmd::sphere_point(prm(in), as<S>(m1).elem(i1), as<P>(m2).elem(i2), as<P>(m2).lmd_neighbourhood(i2), out);
  }
  static int point_point(const Intersection& in, const CollisionModelBase& m1, unsigned i1,
                         const CollisionModelBase& m2, unsigned i2, std::vector<DetectionOutput>& out) {
    return lmd::point_point(prm(in), as<P>(m1).elem(i1), as<P>(m1).lmd_neighbourhood(i1), as<P>(m2).elem(i2),
                            as<P>(m2).lmd_neighbourhood(i2), out);
  }
  static int line_line(const Intersection& in, const CollisionModelBase& m1, unsigned i1, const CollisionModelBase& m2,
                       unsigned i2, std::vector<DetectionOutput>& out) {
    return lmd::line_line(prm(in), as<L>(m1).elem(i1), as<L>(m1).lmd_neighbourhood(i1), as<L>(m2).elem(i2),
                          as<L>(m2).lmd_neighbourhood(i2), out);
  }
  static int line_point(const Intersection& in, const CollisionModelBase& m1, unsigned i1, const CollisionModelBase& m2,
                        unsigned i2, std::vector<DetectionOutput>& out) {
    return lmd::line_point(prm(in), as<L>(m1).elem(i1), as<L>(m1).lmd_neighbourhood(i1), as<P>(m2).elem(i2),
                           as<P>(m2).lmd_neighbourhood(i2), out);
  }
  static int line_sphere(const Intersection& in, const CollisionModelBase& m1, unsigned i1,
                         const CollisionModelBase& m2, unsigned i2, std::vector<DetectionOutput>& out) {
    return lmd::line_sphere(prm(in), as<L>(m1).elem(i1), as<L>(m1).lmd_neighbourhood(i1), as<S>(m2).elem(i2), out);
  }
  static int triangle_point(const Intersection& in, const CollisionModelBase& m1, unsigned i1,
                            const CollisionModelBase& m2, unsigned i2, std::vector<DetectionOutput>& out) {
    return lmd::triangle_point(prm(in), as<T>(m1).elem(i1), as<T>(m1).both_side.value(), as<P>(m2).elem(i2),
                               as<P>(m2).lmd_neighbourhood(i2), out);
  }
  static int triangle_sphere(const Intersection& in, const CollisionModelBase& m1, unsigned i1,
                             const CollisionModelBase& m2, unsigned i2, std::vector<DetectionOutput>& out) {
    return lmd::triangle_sphere(prm(in), as<T>(m1).elem(i1), as<T>(m1).both_side.value(), as<S>(m2).elem(i2), out);
  }

  lmd::Params params_;
};

}  // namespace

void register_local_min_distance(Registry& r) {
  ComponentInfo info;
  info.name = "LocalMinDistance";
  info.category = "Collision/Detection";
  info.description = "proximity tests filtered by the cone of directions each element's neighbourhood allows";
  info.create = creator<LocalMinDistance>();
  r.add(std::move(info));
}

}  // namespace sinew

// CCDTightInclusionIntersection (spec/interaction.md §2.8): continuous
// vertex–face collision detection with Tight-Inclusion's root finder
// (third_party/tight_inclusion): a point and a triangle moving linearly from
// their positions to their end positions over the step touch (within the
// minimal separation) at a time of impact; the contact is then stated at the
// start positions with the triangle's normal at that time.
//
// End positions: FreeMotion mode reads the states' free positions, Inertia
// mode x + v·dt, None the positions themselves (a distance query). SOFA's
// element test always reads the free positions, which only a free-motion loop
// fills; Sinew uses the end positions its bounding trees were built with, the
// same thing under FreeMotionAnimationLoop and a meaningful one otherwise.
// Edge–edge CCD is not registered: SOFA's version mixes up the edges' end
// points, ignores the root finder's answer and appends a default output
// before its contact (spec §2.8), and no example uses it.
#include <tight_inclusion/ccd.hpp>

#include <Eigen/Geometry>

#include <limits>

#include "collision/model/point_collision_model.h"
#include "collision/model/triangle_collision_model.h"
#include "collision/proximity_intersection.h"
#include "core/registry.h"

namespace sinew {

namespace {

class CCDTightInclusionIntersection final : public ProximityIntersection {
 public:
  Field<std::string> continuous_collision_type{
      this, "continuousCollisionType", "None",
      "None (positions only), Inertia (x + v·dt) or FreeMotion (free positions): the end of the motion tested",
      "Collision"};
  Field<double> tolerance{this, "tolerance", 1e-10, "precision of the root finder", "Collision"};
  Field<int> max_iterations{this, "maxIterations", 1000, "iteration limit of the root finder", "Collision"};

  CollisionModelBase::Motion continuous_motion() const override { return motion_; }
  bool use_continuous() const override { return motion_ != CollisionModelBase::Motion::none; }

  void init() override {
    if (!check_distances()) return;
    const std::string& t = continuous_collision_type.value();
    if (t == "None" || t == "0") motion_ = CollisionModelBase::Motion::none;
    else if (t == "Inertia" || t == "1") motion_ = CollisionModelBase::Motion::inertia;
    else if (t == "FreeMotion" || t == "2") motion_ = CollisionModelBase::Motion::free_motion;
    else {
      msg_error("continuousCollisionType \"" + t + "\" is not one of None, Inertia, FreeMotion");
      set_state(ComponentState::invalid);
      return;
    }
    if (!(tolerance.value() > 0) || max_iterations.value() == 0) {
      msg_error("tolerance must be > 0 and maxIterations non-zero (-1: no limit)");
      set_state(ComponentState::invalid);
      return;
    }
    using K = Kind;
    add(K::triangle, K::point, &triangle_point);
    for (auto [a, b] : {std::pair{K::sphere, K::sphere}, {K::sphere, K::point}, {K::point, K::point},
                        {K::line, K::point}, {K::line, K::line}, {K::line, K::sphere}, {K::triangle, K::line},
                        {K::triangle, K::triangle}, {K::triangle, K::sphere}})
      ignore(a, b);
  }

 private:
  static int triangle_point(const Intersection& in, const CollisionModelBase& m1, unsigned i1,
                            const CollisionModelBase& m2, unsigned i2, std::vector<DetectionOutput>& out) {
    const auto& self = static_cast<const CCDTightInclusionIntersection&>(in);
    const TriangleElem t = static_cast<const TriangleCollisionModel&>(m1).elem(i1);
    const PointElem p = static_cast<const PointCollisionModel&>(m2).elem(i2);
    const auto end1 = m1.end_positions(), end2 = m2.end_positions();
    auto at_end = [](std::span<const Vec3> end, unsigned v, const Vec3& start) {
      return v < end.size() ? end[v] : start;
    };
    const Vec3 a1 = at_end(end1, t.v[0], t.a), b1 = at_end(end1, t.v[1], t.b), c1 = at_end(end1, t.v[2], t.c);
    const Vec3 p1 = at_end(end2, p.info.index, p.p);
    const double ms = self.contact.value() + t.info.cd + p.info.cd;
    double toi = std::numeric_limits<double>::infinity();
    double output_tolerance = 0;
    const bool hit = ticcd::vertexFaceCCD(p.p, t.a, t.b, t.c, p1, a1, b1, c1, ticcd::Array3(-1, -1, -1), ms, toi,
                                          self.tolerance.value(), 1.0, self.max_iterations.value(), output_tolerance);
    if (!hit) return 0;
    // Positions at the time of impact, the projection of the point on the triangle's plane there.
    const Vec3 at = (1 - toi) * t.a + a1 * toi, bt = (1 - toi) * t.b + b1 * toi, ct = (1 - toi) * t.c + c1 * toi;
    const Vec3 pt = (1 - toi) * p.p + p1 * toi;
    const Vec3 g = (at + bt + ct) / 3.0;
    const Vec3 n = (bt - at).cross(ct - at).normalized();
    const Vec3 proj = g + (pt - g) - n * (pt - g).dot(n);
    // Barycentric coordinates by signed areas (SOFA's geometry::Triangle), flat triangle → (−1, −1, −1).
    Vec3 bary(-1, -1, -1);
    const Vec3 N = (bt - at).cross(ct - at);
    const double nn = N.dot(N);
    const double eps = std::numeric_limits<double>::epsilon();
    if (nn >= eps * eps) {
      bary[0] = N.dot((ct - bt).cross(proj - bt)) / nn;
      bary[1] = N.dot((at - ct).cross(proj - ct)) / nn;
      bary[2] = 1 - bary[0] - bary[1];
      if (std::fabs(bary[2]) <= eps) bary[2] = 0;
    }
    DetectionOutput& d = out.emplace_back();
    d.elem1 = t.info.index;
    d.elem2 = p.info.index;
    d.id = t.info.model_size > p.info.model_size ? t.info.index : p.info.index;
    d.point1 = t.a * bary[0] + t.b * bary[1] + t.c * bary[2];
    d.point2 = p.p;
    d.normal = n;
    d.value = (d.point2 - d.point1).dot(d.normal) - ms;
    return 1;
  }

  CollisionModelBase::Motion motion_ = CollisionModelBase::Motion::none;
};

}  // namespace

void register_ccd_tight_inclusion_intersection(Registry& r) {
  ComponentInfo info;
  info.name = "CCDTightInclusionIntersection";
  info.category = "Collision/Detection";
  info.description = "continuous point–triangle collision detection (Tight-Inclusion root finder)";
  info.create = creator<CCDTightInclusionIntersection>();
  r.add(std::move(info));
}

}  // namespace sinew

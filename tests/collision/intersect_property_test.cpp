// Properties of every element test on random configurations: each output's
// value is |point2 − point1| minus the effective contact distance, its normal
// is unit and points from point1 to point2, its points lie on their elements,
// and where the method projects exactly (segments, triangles with every
// feature owned) the distance is the true minimum distance.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>

#include "collision/intersect/discrete_tests.h"
#include "collision/intersect/min_proximity_tests.h"
#include "collision/intersect/new_proximity_tests.h"
#include "elem_builders.h"

using namespace sinew;
using namespace sinew::test;

namespace {

constexpr int kTrials = 3000;
constexpr double kTol = 1e-10;

// Closest point of triangle abc to p (Ericson, Real-Time Collision Detection §5.1.5).
Vec3 closest_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + ab * (d1 / (d1 - d3));
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + ac * (d2 / (d2 - d6));
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
  const double denom = 1 / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

Vec3 closest_on_segment(const Vec3& p, const Vec3& a, const Vec3& b) {
  const double t = std::clamp((p - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
  return a + (b - a) * t;
}

double dist_to_triangle(const Vec3& p, const TriangleElem& t) {
  return (p - closest_on_triangle(p, t.a, t.b, t.c)).norm();
}
double dist_to_segment(const Vec3& p, const LineElem& l) { return (p - closest_on_segment(p, l.a, l.b)).norm(); }

// Segment–segment distance by dense sampling of one segment (an upper bound of the true one).
double sampled_segment_distance(const LineElem& l1, const LineElem& l2) {
  double best = 1e300;
  for (int i = 0; i <= 2000; ++i) {
    const Vec3 p = l1.a + (l1.b - l1.a) * (i / 2000.0);
    best = std::min(best, dist_to_segment(p, l2));
  }
  return best;
}

struct Rng {
  std::mt19937 gen{12345};
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(gen); }
  Vec3 vec(double h = 1.0) { return {uniform(-h, h), uniform(-h, h), uniform(-h, h)}; }
  ElemInfo inf() {
    return info(static_cast<unsigned>(uniform(0, 50)), static_cast<std::size_t>(uniform(50, 100)), uniform(0, 0.1));
  }
  int flags() { return static_cast<int>(uniform(0, 512)); }
};

// The checks shared by every output. `contact` is the effective contact distance.
void check_output(const DetectionOutput& d, double contact, const ElemInfo& i1, const ElemInfo& i2) {
  EXPECT_EQ(d.elem1, i1.index);
  EXPECT_EQ(d.elem2, i2.index);
  const Vec3 v = d.point2 - d.point1;
  EXPECT_NEAR(v.norm() - contact, d.value, kTol);
  EXPECT_NEAR(d.normal.norm(), 1.0, kTol);
  if (v.norm() > 1e-9) {
    EXPECT_TRUE(vec_near(d.normal, v.normalized(), 1e-8));
  }
}

}  // namespace

TEST(IntersectProperty, MinProximity) {
  Rng rng;
  min_proximity::Params prm;
  prm.alarm = 0.8;
  prm.contact = 0.3;
  int accepted = 0;
  for (int k = 0; k < kTrials; ++k) {
    std::vector<DetectionOutput> out;
    const auto i1 = rng.inf(), i2 = rng.inf();
    const double c = prm.contact + i1.cd + i2.cd;
    const auto p1 = point(rng.vec(), i1), p2 = point(rng.vec(), i2);
    if (min_proximity::point_point(prm, p1, p2, out)) {
      check_output(out.back(), c, i1, i2);
      EXPECT_NEAR((out.back().point2 - out.back().point1).norm(), (p2.p - p1.p).norm(), kTol);
    }
    const auto l1 = line(rng.vec(), rng.vec(), i1), l2 = line(rng.vec(), rng.vec(), i2);
    if (min_proximity::line_point(prm, l1, p2, out)) {
      check_output(out.back(), c, i1, i2);
      EXPECT_NEAR(out.back().value + c, dist_to_segment(p2.p, l1), kTol);
    }
    if (min_proximity::line_line(prm, l1, l2, out)) {
      check_output(out.back(), c, i1, i2);
      EXPECT_NEAR(dist_to_segment(out.back().point1, l1), 0.0, kTol);
      EXPECT_NEAR(dist_to_segment(out.back().point2, l2), 0.0, kTol);
      EXPECT_LE(out.back().value + c, sampled_segment_distance(l1, l2) + kTol);
    }
    const auto t1 = triangle(rng.vec(), rng.vec(), rng.vec(), 0, i1);
    if (min_proximity::triangle_point(prm, t1, p2, out)) {
      check_output(out.back(), c, i1, i2);
      EXPECT_NEAR(out.back().value + c, dist_to_triangle(p2.p, t1), kTol);
    }
    const auto s2 = sphere(rng.vec(), rng.uniform(0, 0.3), false, i2);
    if (min_proximity::triangle_sphere(prm, t1, s2, out)) {
      check_output(out.back(), c + s2.r, i1, i2);
      EXPECT_NEAR(out.back().value + c + s2.r, dist_to_triangle(s2.c, t1), kTol);
    }
    if (min_proximity::line_sphere(prm, l1, s2, out)) {
      check_output(out.back(), c + s2.r, i1, i2);  // mirrored point, but still point1 → centre
      EXPECT_NEAR(dist_to_segment(out.back().point1, l1), 0.0, kTol);
    }
    const auto s1 = sphere(rng.vec(), rng.uniform(0, 0.3), false, i1);
    if (min_proximity::sphere_point(prm, s1, p2, out)) check_output(out.back(), c + s1.r, i1, i2);
    if (min_proximity::sphere_sphere(prm, s1, s2, out)) check_output(out.back(), c + s1.r + s2.r, i1, i2);
    accepted += static_cast<int>(out.size());
  }
  EXPECT_GT(accepted, kTrials);  // the configurations do exercise the tests
}

TEST(IntersectProperty, RigidSpherePointsSitOnTheSurfaceAlongTheNormal) {
  Rng rng;
  min_proximity::Params mprm;
  new_proximity::Params nprm;
  for (int k = 0; k < kTrials; ++k) {
    std::vector<DetectionOutput> out;
    const auto s1 = sphere(rng.vec(), rng.uniform(0.05, 0.3), true, rng.inf());
    const auto s2 = sphere(rng.vec(), rng.uniform(0.05, 0.3), true, rng.inf());
    const auto t = triangle(rng.vec(), rng.vec(), rng.vec(), 511, rng.inf());
    if (discrete::sphere_sphere(s1, s2, out)) {
      const auto& d = out.back();
      EXPECT_TRUE(vec_near(d.point1, s1.c + d.normal * s1.r, kTol));
      EXPECT_TRUE(vec_near(d.point2, s2.c - d.normal * s2.r, kTol));
      EXPECT_NEAR(d.value, (s2.c - s1.c).norm() - s1.r - s2.r, kTol);
    }
    if (min_proximity::sphere_sphere(mprm, s1, s2, out)) {
      const auto& d = out.back();
      EXPECT_TRUE(vec_near(d.point1, s1.c + d.normal * s1.r, kTol));
      EXPECT_TRUE(vec_near(d.point2, s2.c - d.normal * s2.r, kTol));
    }
    if (min_proximity::triangle_sphere(mprm, t, s2, out)) {
      EXPECT_TRUE(vec_near(out.back().point2, s2.c - out.back().normal * s2.r, kTol));
    }
    if (new_proximity::triangle_sphere(nprm, t, s2, out)) {
      EXPECT_TRUE(vec_near(out.back().point2, s2.c - out.back().normal * s2.r, kTol));
    }
    if (new_proximity::sphere_sphere(nprm, s1, s2, out)) {  // centres here
      EXPECT_TRUE(vec_near(out.back().point1, s1.c, 0));
      EXPECT_TRUE(vec_near(out.back().point2, s2.c, 0));
    }
  }
}

TEST(IntersectProperty, NewProximity) {
  Rng rng;
  new_proximity::Params prm;
  prm.alarm = 0.8;
  prm.contact = 0.3;
  prm.use_line_line = true;
  constexpr int kAllFlags = kFlagPoints | kFlagEdges;
  int accepted = 0;
  for (int k = 0; k < kTrials; ++k) {
    std::vector<DetectionOutput> out;
    const auto i1 = rng.inf(), i2 = rng.inf();
    const double c = prm.contact + i1.cd + i2.cd;
    const auto p2 = point(rng.vec(), i2);
    if (new_proximity::point_point(prm, point(rng.vec(), i1), p2, out)) check_output(out.back(), c, i1, i2);
    const auto l1 = line(rng.vec(), rng.vec(), i1), l2 = line(rng.vec(), rng.vec(), i2);
    if (new_proximity::line_point(prm, l1, p2, out)) {
      check_output(out.back(), c, i1, i2);
      EXPECT_NEAR(out.back().value + c, dist_to_segment(p2.p, l1), kTol);
    }
    if (new_proximity::line_line(prm, l1, l2, out)) check_output(out.back(), c, i1, i2);
    // Every feature owned: the closest point of the whole triangle.
    const auto t1 = triangle(rng.vec(), rng.vec(), rng.vec(), kAllFlags, i1);
    if (new_proximity::triangle_point(prm, t1, p2, out)) {
      check_output(out.back(), c, i1, i2);
      EXPECT_NEAR(out.back().value + c, dist_to_triangle(p2.p, t1), 1e-9);
    } else {
      EXPECT_GE(dist_to_triangle(p2.p, t1), prm.alarm + i1.cd + i2.cd - 1e-9);
    }
    // Random flags: accepted outputs keep the geometric properties, and never beat the true distance.
    auto t1f = t1;
    t1f.flags = rng.flags();
    if (new_proximity::triangle_point(prm, t1f, p2, out)) {
      EXPECT_NEAR(out.back().value + c, dist_to_triangle(p2.p, t1), 1e-9);
    }
    const auto s2 = sphere(rng.vec(), rng.uniform(0, 0.3), false, i2);
    // T–S has its own branch order, which can pick a point of an edge's line
    // outside the triangle (see NewProximityTriangleSphere.ObtuseCornerPicksAPointOffTheTriangle):
    // only the plane and, for points on the triangle, the lower bound hold.
    if (new_proximity::triangle_sphere(prm, t1, s2, out)) {
      const auto& d = out.back();
      check_output(d, c + s2.r, i1, i2);
      EXPECT_NEAR((d.point1 - t1.a).dot(t1.normal), 0.0, 1e-9);
      if (dist_to_triangle(d.point1, t1) < 1e-9) {
        EXPECT_GE(d.value + c + s2.r, dist_to_triangle(s2.c, t1) - 1e-9);
      }
    }
    if (new_proximity::line_sphere(prm, l1, s2, out)) check_output(out.back(), c + s2.r, i1, i2);
    const auto s1 = sphere(rng.vec(), rng.uniform(0, 0.3), true, i1);
    if (new_proximity::sphere_point(prm, s1, p2, out)) check_output(out.back(), c + s1.r, i1, i2);
    if (new_proximity::sphere_sphere(prm, s1, s2, out)) check_output(out.back(), c + s1.r + s2.r, i1, i2);
    // T–L and T–T: every output has point1 on element 1 and point2 on element 2.
    {
      std::vector<DetectionOutput> tl;
      new_proximity::triangle_line(prm, t1f, l2, tl);
      for (const auto& d : tl) {
        check_output(d, c, i1, i2);
        EXPECT_EQ(d.id, i2.index);
        EXPECT_NEAR(dist_to_triangle(d.point1, t1), 0.0, 1e-9);
        EXPECT_NEAR(dist_to_segment(d.point2, l2), 0.0, 1e-9);
      }
      accepted += static_cast<int>(tl.size());
    }
    {
      auto j1 = i1, j2 = i2;
      j1.model = &rng;  // distinct models
      const auto ta = triangle(rng.vec(), rng.vec(), rng.vec(), rng.flags(), j1);
      const auto tb = triangle(rng.vec(), rng.vec(), rng.vec(), rng.flags(), j2);
      std::vector<DetectionOutput> tt;
      new_proximity::triangle_triangle(prm, ta, tb, tt);
      for (const auto& d : tt) {
        check_output(d, c, i1, i2);
        EXPECT_NEAR(dist_to_triangle(d.point1, ta), 0.0, 1e-9);
        EXPECT_NEAR(dist_to_triangle(d.point2, tb), 0.0, 1e-9);
        const std::int64_t base2 = static_cast<std::int64_t>(j1.model_size) * 3 + std::int64_t{j2.index} * 12;
        EXPECT_TRUE((d.id >= 3 * std::int64_t{j1.index} && d.id < 3 * std::int64_t{j1.index} + 3) ||
                    (d.id >= base2 && d.id < base2 + 12));
      }
      accepted += static_cast<int>(tt.size());
    }
    accepted += static_cast<int>(out.size());
  }
  EXPECT_GT(accepted, kTrials);
}

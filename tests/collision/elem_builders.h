// Small builders for collision elements and vector comparisons shared by the
// intersection element tests.
#pragma once

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <vector>

#include "collision/detection_output.h"
#include "collision/intersect/elements.h"

namespace sinew::test {

inline ElemInfo info(unsigned index, std::size_t model_size = 10, double cd = 0, const void* model = nullptr) {
  ElemInfo i;
  i.index = index;
  i.model_size = model_size;
  i.cd = cd;
  i.model = model;
  return i;
}

inline PointElem point(const Vec3& p, const ElemInfo& i = info(0)) { return PointElem{p, i}; }

inline LineElem line(const Vec3& a, const Vec3& b, const ElemInfo& i = info(0), std::array<unsigned, 2> v = {0, 1}) {
  LineElem l;
  l.a = a;
  l.b = b;
  l.v = v;
  l.info = i;
  return l;
}

inline TriangleElem triangle(const Vec3& a, const Vec3& b, const Vec3& c, int flags = 0, const ElemInfo& i = info(0),
                             std::array<unsigned, 3> v = {0, 1, 2}) {
  TriangleElem t;
  t.a = a;
  t.b = b;
  t.c = c;
  t.normal = (b - a).cross(c - a).normalized();
  t.v = v;
  t.flags = flags;
  t.info = i;
  return t;
}

inline SphereElem sphere(const Vec3& c, double r, bool rigid = false, const ElemInfo& i = info(0)) {
  SphereElem s;
  s.c = c;
  s.r = r;
  s.rigid = rigid;
  s.info = i;
  return s;
}

inline ::testing::AssertionResult vec_near(const Vec3& actual, const Vec3& expected, double tol = 1e-12) {
  if ((actual - expected).lpNorm<Eigen::Infinity>() <= tol) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "got (" << actual.transpose() << "), expected (" << expected.transpose()
                                       << ")";
}

// The output appended last, with its element indices, id, points, normal and value.
struct Expected {
  unsigned elem1, elem2;
  std::int64_t id;
  Vec3 point1, point2, normal;
  double value;
};

inline void expect_output(const DetectionOutput& d, const Expected& e, double tol = 1e-12) {
  EXPECT_EQ(d.elem1, e.elem1);
  EXPECT_EQ(d.elem2, e.elem2);
  EXPECT_EQ(d.id, e.id);
  EXPECT_TRUE(vec_near(d.point1, e.point1, tol)) << "point1";
  EXPECT_TRUE(vec_near(d.point2, e.point2, tol)) << "point2";
  EXPECT_TRUE(vec_near(d.normal, e.normal, tol)) << "normal";
  EXPECT_NEAR(d.value, e.value, tol);
}

}  // namespace sinew::test

// MinProximityIntersection element tests (spec/interaction.md §2.4) against
// hand-computed contacts. Default distances: alarm 1, contact 0.5.
#include <gtest/gtest.h>

#include <cmath>

#include "collision/intersect/min_proximity_tests.h"
#include "elem_builders.h"

using namespace sinew;
using namespace sinew::test;
namespace mp = sinew::min_proximity;

namespace {
const mp::Params kDefault{};
// Unit right triangle in z = 0, normal +z.
TriangleElem unit_triangle(const ElemInfo& i = info(3, 20), int flags = 0) {
  return triangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, flags, i);
}
}  // namespace

// ---------------------------------------------------------------- point–point

TEST(MinProximityPointPoint, InsideAlarmGivesDistanceNormalAndValue) {
  std::vector<DetectionOutput> out;
  ASSERT_EQ(mp::point_point(kDefault, point({1, 2, 3}, info(2, 5)), point({1.3, 2.4, 3}, info(1, 3)), out), 1);
  // |PQ| = 0.5 → value 0.5 − 0.5 = 0; id from model 1 (5 elements > 3).
  expect_output(out[0], {2, 1, 2, {1, 2, 3}, {1.3, 2.4, 3}, {0.6, 0.8, 0}, 0.0});
}

TEST(MinProximityPointPoint, AlarmBoundIsStrict) {
  std::vector<DetectionOutput> out;
  EXPECT_EQ(mp::point_point(kDefault, point({0, 0, 0}), point({1, 0, 0}), out), 0);  // |PQ|² = alarm²
  EXPECT_EQ(mp::point_point(kDefault, point({0, 0, 0}), point({0, 0, 1.0000001}), out), 0);
  EXPECT_EQ(mp::point_point(kDefault, point({0, 0, 0}), point({0, 0, 0.9999999}), out), 1);
  EXPECT_NEAR(out[0].value, 0.4999999, 1e-15);
}

TEST(MinProximityPointPoint, SkinsAddToAlarmAndContact) {
  std::vector<DetectionOutput> out;
  // alarm = 1 + 0.25 + 0.125 = 1.375, contact = 0.5 + 0.375 = 0.875.
  const auto p = point({0, 0, 0}, info(0, 1, 0.25));
  EXPECT_EQ(mp::point_point(kDefault, p, point({0, 1.25, 0}, info(0, 1, 0.125)), out), 1);
  EXPECT_DOUBLE_EQ(out[0].value, 1.25 - 0.875);
  EXPECT_EQ(mp::point_point(kDefault, p, point({0, 1.375, 0}, info(0, 1, 0.125)), out), 0);
}

TEST(MinProximityPointPoint, IdIsElementOfLargerModelAndElement2OnTies) {
  std::vector<DetectionOutput> out;
  mp::point_point(kDefault, point({0, 0, 0}, info(2, 3)), point({0.5, 0, 0}, info(1, 5)), out);
  mp::point_point(kDefault, point({0, 0, 0}, info(2, 4)), point({0.5, 0, 0}, info(1, 4)), out);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[0].id, 1);
  EXPECT_EQ(out[1].id, 1);
}

TEST(MinProximityPointPoint, CoincidentPointsGetXNormal) {
  std::vector<DetectionOutput> out;
  ASSERT_EQ(mp::point_point(kDefault, point({1, 1, 1}), point({1, 1, 1}), out), 1);
  EXPECT_TRUE(vec_near(out[0].normal, {1, 0, 0}));
  EXPECT_DOUBLE_EQ(out[0].value, -0.5);
}

// ----------------------------------------------------------------- line–point

TEST(MinProximityLinePoint, InteriorProjection) {
  std::vector<DetectionOutput> out;
  const auto l = line({0, 0, 0}, {2, 0, 0}, info(6, 9));
  ASSERT_EQ(mp::line_point(kDefault, l, point({0.5, 0.5, 0}, info(4, 2)), out), 1);
  // α = 0.25: Q = (0.5,0,0); elem (line, point); id = point index even from the smaller model.
  expect_output(out[0], {6, 4, 4, {0.5, 0, 0}, {0.5, 0.5, 0}, {0, 1, 0}, 0.0});
}

TEST(MinProximityLinePoint, ProjectionIsClampedToTheEnds) {
  std::vector<DetectionOutput> out;
  const auto l = line({0, 0, 0}, {2, 0, 0});
  ASSERT_EQ(mp::line_point(kDefault, l, point({-0.3, 0.4, 0}), out), 1);
  expect_output(out[0], {0, 0, 0, {0, 0, 0}, {-0.3, 0.4, 0}, {-0.6, 0.8, 0}, 0.0});
  ASSERT_EQ(mp::line_point(kDefault, l, point({2.3, 0, -0.4}), out), 1);
  expect_output(out[1], {0, 0, 0, {2, 0, 0}, {2.3, 0, -0.4}, {0.6, 0, -0.8}, 0.0});
}

TEST(MinProximityLinePoint, OutsideAlarmRejected) {
  std::vector<DetectionOutput> out;
  const auto l = line({0, 0, 0}, {2, 0, 0});
  EXPECT_EQ(mp::line_point(kDefault, l, point({1, 1, 0}), out), 0);
  EXPECT_EQ(mp::line_point(kDefault, l, point({-1, 0, 0}), out), 0);
  // Skins widen the alarm: 1 + 0.5 + 0 = 1.5.
  EXPECT_EQ(mp::line_point(kDefault, line({0, 0, 0}, {2, 0, 0}, info(0, 1, 0.5)), point({1, 1, 0}), out), 1);
  EXPECT_DOUBLE_EQ(out[0].value, 1.0 - 1.0);
}

// ------------------------------------------------------------------ line–line

TEST(MinProximityLineLine, CrossingSegments) {
  std::vector<DetectionOutput> out;
  const auto l1 = line({0, 0, 0}, {2, 0, 0}, info(1, 4));
  const auto l2 = line({1, -1, 0.5}, {1, 1, 0.5}, info(2, 7));
  ASSERT_EQ(mp::line_line(kDefault, l1, l2, out), 1);
  // α = β = 0.5; id from model 2 (7 > 4).
  expect_output(out[0], {1, 2, 2, {1, 0, 0}, {1, 0, 0.5}, {0, 0, 1}, 0.0});
}

TEST(MinProximityLineLine, ClosestPointsAtAnEndAreRejected) {
  std::vector<DetectionOutput> out;
  const auto l1 = line({0, 0, 0}, {2, 0, 0});
  // α = 1 (exactly at B): a line–point case.
  EXPECT_EQ(mp::line_line(kDefault, l1, line({2, -1, 0.5}, {2, 1, 0.5}), out), 0);
  // α = 1 − 1e-7 > 0.999999: rejected; α = 1 − 2e-6: accepted.
  EXPECT_EQ(mp::line_line(kDefault, l1, line({2 - 2e-7, -1, 0.5}, {2 - 2e-7, 1, 0.5}), out), 0);
  EXPECT_EQ(mp::line_line(kDefault, l1, line({2 - 4e-6, -1, 0.5}, {2 - 4e-6, 1, 0.5}), out), 1);
  // β outside [0,1]: the second segment stops short of the first line.
  EXPECT_EQ(mp::line_line(kDefault, l1, line({1, 0.1, 0.5}, {1, 1, 0.5}), out), 0);
}

TEST(MinProximityLineLine, ParallelSegmentsUseMidpoints) {
  std::vector<DetectionOutput> out;
  ASSERT_EQ(mp::line_line(kDefault, line({0, 0, 0}, {2, 0, 0}), line({0.5, 0.5, 0}, {2.5, 0.5, 0}), out), 1);
  // det = 0 → α = β = 0.5: P = (1,0,0), Q = (1.5,0.5,0) (not the 0.5 true distance).
  const double s = std::sqrt(0.5);
  expect_output(out[0], {0, 0, 0, {1, 0, 0}, {1.5, 0.5, 0}, {s, s, 0}, s - 0.5}, 1e-15);
}

TEST(MinProximityLineLine, OutsideAlarmRejectedAndSkinsAdd) {
  std::vector<DetectionOutput> out;
  const auto l1 = line({0, 0, 0}, {2, 0, 0});
  EXPECT_EQ(mp::line_line(kDefault, l1, line({1, -1, 1}, {1, 1, 1}), out), 0);
  ASSERT_EQ(mp::line_line(kDefault, l1, line({1, -1, 1}, {1, 1, 1}, info(0, 1, 0.125)), out), 1);
  EXPECT_DOUBLE_EQ(out[0].value, 1 - 0.625);
}

// -------------------------------------------------------------- triangle–point

TEST(MinProximityTrianglePoint, InteriorProjectionAboveAndBelow) {
  std::vector<DetectionOutput> out;
  const auto t = unit_triangle(info(3, 20));
  ASSERT_EQ(mp::triangle_point(kDefault, t, point({0.25, 0.25, 0.5}, info(8, 2)), out), 1);
  expect_output(out[0], {3, 8, 8, {0.25, 0.25, 0}, {0.25, 0.25, 0.5}, {0, 0, 1}, 0.0});
  ASSERT_EQ(mp::triangle_point(kDefault, t, point({0.5, 0.25, -0.75}, info(8, 2)), out), 1);
  expect_output(out[1], {3, 8, 8, {0.5, 0.25, 0}, {0.5, 0.25, -0.75}, {0, 0, -1}, 0.25});
}

TEST(MinProximityTrianglePoint, SurfaceNormalsReplaceTheDirectionOnly) {
  std::vector<DetectionOutput> out;
  mp::Params prm;
  prm.use_surface_normals = true;
  ASSERT_EQ(mp::triangle_point(prm, unit_triangle(), point({0.5, 0.25, -0.75}), out), 1);
  EXPECT_TRUE(vec_near(out[0].normal, {0, 0, 1}));  // stored normal, though the point is below
  EXPECT_DOUBLE_EQ(out[0].value, 0.25);
}

TEST(MinProximityTrianglePoint, OnlyTheInteriorWindowIsAccepted) {
  std::vector<DetectionOutput> out;
  const auto t = unit_triangle();
  // Projection exactly on edge AB (β = 0), near it (β = 5e-7 < 1e-6) or just inside (β = 2e-6).
  EXPECT_EQ(mp::triangle_point(kDefault, t, point({0.5, 0, 0.3}), out), 0);
  EXPECT_EQ(mp::triangle_point(kDefault, t, point({0.5, 5e-7, 0.3}), out), 0);
  EXPECT_EQ(mp::triangle_point(kDefault, t, point({0.5, 2e-6, 0.3}), out), 1);
  // Near edge AC (α).
  EXPECT_EQ(mp::triangle_point(kDefault, t, point({5e-7, 0.5, 0.3}), out), 0);
  EXPECT_EQ(mp::triangle_point(kDefault, t, point({2e-6, 0.5, 0.3}), out), 1);
  // Near edge BC: α+β = 0.9999992 > 0.999999 rejected, 0.9999988 accepted.
  EXPECT_EQ(mp::triangle_point(kDefault, t, point({0.4999996, 0.4999996, 0.3}), out), 0);
  EXPECT_EQ(mp::triangle_point(kDefault, t, point({0.4999994, 0.4999994, 0.3}), out), 1);
  // Outside the triangle (corner region): no contact here, even close.
  EXPECT_EQ(mp::triangle_point(kDefault, t, point({-0.1, -0.1, 0}), out), 0);
  EXPECT_EQ(out.size(), 3u);
}

TEST(MinProximityTrianglePoint, AlarmBoundAndSkins) {
  std::vector<DetectionOutput> out;
  EXPECT_EQ(mp::triangle_point(kDefault, unit_triangle(), point({0.25, 0.25, 1.0}), out), 0);
  EXPECT_EQ(mp::triangle_point(kDefault, unit_triangle(), point({0.25, 0.25, 0.999}), out), 1);
  // alarm 1 + 0.25 + 0.5 = 1.75, contact 0.5 + 0.75 = 1.25.
  ASSERT_EQ(
      mp::triangle_point(kDefault, unit_triangle(info(0, 1, 0.25)), point({0.25, 0.25, 1.5}, info(0, 1, 0.5)), out), 1);
  EXPECT_DOUBLE_EQ(out[1].value, 0.25);
  EXPECT_EQ(
      mp::triangle_point(kDefault, unit_triangle(info(0, 1, 0.25)), point({0.25, 0.25, 1.75}, info(0, 1, 0.5)), out),
      0);
}

// ------------------------------------------------------------- triangle–sphere

TEST(MinProximityTriangleSphere, Vec3SphereGivesCentre) {
  std::vector<DetectionOutput> out;
  const auto s = sphere({0.25, 0.25, 1.0}, 0.5, false, info(5, 2));
  ASSERT_EQ(mp::triangle_sphere(kDefault, unit_triangle(info(3, 20)), s, out), 1);
  // alarm 1.5, contact 1.0, distance 1: value 0; id = sphere index.
  expect_output(out[0], {3, 5, 5, {0.25, 0.25, 0}, {0.25, 0.25, 1.0}, {0, 0, 1}, 0.0});
}

TEST(MinProximityTriangleSphere, RigidSphereGivesItsNearSurfacePoint) {
  std::vector<DetectionOutput> out;
  const auto s = sphere({0.25, 0.25, 0.75}, 0.5, true, info(5, 2));
  ASSERT_EQ(mp::triangle_sphere(kDefault, unit_triangle(), s, out), 1);
  expect_output(out[0], {3, 5, 5, {0.25, 0.25, 0}, {0.25, 0.25, 0.25}, {0, 0, 1}, -0.25});
}

TEST(MinProximityTriangleSphere, RadiusAndSkinsWidenAlarm) {
  std::vector<DetectionOutput> out;
  EXPECT_EQ(mp::triangle_sphere(kDefault, unit_triangle(), sphere({0.25, 0.25, 1.5}, 0.5), out), 0);
  EXPECT_EQ(mp::triangle_sphere(kDefault, unit_triangle(), sphere({0.25, 0.25, 1.49}, 0.5), out), 1);
  // alarm 1 + 0.5 + 0.25 + 0.125 = 1.875; contact 1.375.
  ASSERT_EQ(mp::triangle_sphere(kDefault, unit_triangle(info(0, 1, 0.125)),
                                sphere({0.25, 0.25, 1.75}, 0.5, false, info(0, 1, 0.25)), out),
            1);
  EXPECT_DOUBLE_EQ(out[1].value, 0.375);
  // Interior window as for points.
  EXPECT_EQ(mp::triangle_sphere(kDefault, unit_triangle(), sphere({0.5, 5e-7, 0.3}, 0.1), out), 0);
}

// ----------------------------------------------------------------- line–sphere

TEST(MinProximityLineSphere, SymmetricCaseIsTheTrueProjection) {
  std::vector<DetectionOutput> out;
  const auto l = line({0, 0, 0}, {4, 0, 0}, info(1, 3));
  ASSERT_EQ(mp::line_sphere(kDefault, l, sphere({2, 0.5, 0}, 0.25, false, info(9, 1)), out), 1);
  // alarm 1.25, contact 0.75, distance 0.5; id = sphere index.
  expect_output(out[0], {1, 9, 9, {2, 0, 0}, {2, 0.5, 0}, {0, 1, 0}, -0.25});
}

TEST(MinProximityLineSphere, ParameterIsMirroredAboutTheMidpoint) {
  std::vector<DetectionOutput> out;
  const auto l = line({0, 0, 0}, {4, 0, 0});
  // True projection (1.8,0,0); α measured from B is 0.55, applied from A: Q = (2.2,0,0).
  ASSERT_EQ(mp::line_sphere(kDefault, l, sphere({1.8, 0.5, 0}, 0.25), out), 1);
  const double d = std::sqrt(0.41);
  expect_output(out[0], {0, 0, 0, {2.2, 0, 0}, {1.8, 0.5, 0}, Vec3(-0.4, 0.5, 0) / d, d - 0.75}, 1e-12);
  // A centre projecting near A ends up near B, out of alarm.
  EXPECT_EQ(mp::line_sphere(kDefault, l, sphere({0.5, 0.5, 0}, 0.25), out), 0);
}

TEST(MinProximityLineSphere, WindowRejectsEndsAndRigidPointIsOffset) {
  std::vector<DetectionOutput> out;
  const auto l = line({0, 0, 0}, {4, 0, 0});
  EXPECT_EQ(mp::line_sphere(kDefault, l, sphere({4.1, 0.1, 0}, 0.25), out), 0);   // beyond B
  EXPECT_EQ(mp::line_sphere(kDefault, l, sphere({-0.1, 0.1, 0}, 0.25), out), 0);  // beyond A
  ASSERT_EQ(mp::line_sphere(kDefault, l, sphere({2, 0, 0.75}, 0.25, true), out), 1);
  EXPECT_TRUE(vec_near(out[0].point2, {2, 0, 0.5}));
  EXPECT_DOUBLE_EQ(out[0].value, 0.0);
}

// ---------------------------------------------------------------- sphere–point

TEST(MinProximitySpherePoint, Vec3AndRigid) {
  std::vector<DetectionOutput> out;
  // alarm 1.5, contact 1.0, distance 1.2; id = sphere index even from the smaller model.
  ASSERT_EQ(mp::sphere_point(kDefault, sphere({0, 0, 0}, 0.5, false, info(2, 3)), point({0, 0, 1.2}, info(7, 9)), out),
            1);
  expect_output(out[0], {2, 7, 2, {0, 0, 0}, {0, 0, 1.2}, {0, 0, 1}, 0.2});
  ASSERT_EQ(mp::sphere_point(kDefault, sphere({0, 0, 0}, 0.5, true, info(2, 3)), point({0, 0, 1.2}, info(7, 9)), out),
            1);
  expect_output(out[1], {2, 7, 2, {0, 0, 0.5}, {0, 0, 1.2}, {0, 0, 1}, 0.2});
  EXPECT_EQ(mp::sphere_point(kDefault, sphere({0, 0, 0}, 0.5), point({0, 1.5, 0}), out), 0);
}

// --------------------------------------------------------------- sphere–sphere

TEST(MinProximitySphereSphere, InclusiveBoundWithSkinsAndRigidPoints) {
  std::vector<DetectionOutput> out;
  // alarm 1 + radii 1 = 2: exactly 2 accepted (DiscreteIntersection's `<=`).
  ASSERT_EQ(mp::sphere_sphere(kDefault, sphere({0, 0, 0}, 0.5, true, info(1, 2)),
                              sphere({0, 0, 2}, 0.5, true, info(0, 2)), out),
            1);
  expect_output(out[0], {1, 0, 0, {0, 0, 0.5}, {0, 0, 1.5}, {0, 0, 1}, 0.5});
  EXPECT_EQ(mp::sphere_sphere(kDefault, sphere({0, 0, 0}, 0.5), sphere({0, 0, 2.0000001}, 0.5), out), 0);
  // Skins 0.1 and 0.2: alarm 2.3, contact 0.8 (+ radii 1).
  ASSERT_EQ(mp::sphere_sphere(kDefault, sphere({0, 0, 0}, 0.5, false, info(0, 1, 0.1)),
                              sphere({2.2, 0, 0}, 0.5, false, info(0, 1, 0.2)), out),
            1);
  EXPECT_NEAR(out[1].value, 0.4, 1e-15);
  EXPECT_EQ(mp::sphere_sphere(kDefault, sphere({0, 0, 0}, 0.5, false, info(0, 1, 0.1)),
                              sphere({2.31, 0, 0}, 0.5, false, info(0, 1, 0.2)), out),
            0);
}

// DiscreteIntersection sphere–sphere (spec/interaction.md §2.3) against
// hand-computed contacts: inclusive bound, no skins, rigid contact points.
#include <gtest/gtest.h>

#include "collision/intersect/discrete_tests.h"
#include "elem_builders.h"

using namespace sinew;
using namespace sinew::test;

TEST(DiscreteSphereSphere, OverlappingVec3SpheresGiveCentresAndPenetration) {
  std::vector<DetectionOutput> out;
  const auto s1 = sphere({0, 0, 0}, 1.0, false, info(4, 10));
  const auto s2 = sphere({1.5, 0, 0}, 1.0, false, info(7, 3));
  ASSERT_EQ(discrete::sphere_sphere(s1, s2, out), 1);
  ASSERT_EQ(out.size(), 1u);
  // |c2−c1| = 1.5, r1+r2 = 2: penetration 0.5; id from the larger model (model 1).
  expect_output(out[0], {4, 7, 4, {0, 0, 0}, {1.5, 0, 0}, {1, 0, 0}, -0.5});
}

TEST(DiscreteSphereSphere, RigidSpheresGiveSurfacePointsFacingEachOther) {
  std::vector<DetectionOutput> out;
  const auto s1 = sphere({1, 1, 1}, 0.5, true, info(0, 2));
  const auto s2 = sphere({1, 1 + 0.6, 1 + 0.8}, 0.75, true, info(1, 5));  // distance 1
  ASSERT_EQ(discrete::sphere_sphere(s1, s2, out), 1);
  const Vec3 n(0, 0.6, 0.8);
  // point1 = c1 − (−n) r1, point2 = c2 − n r2; value = 1 − 1.25.
  expect_output(out[0], {0, 1, 1, Vec3(1, 1, 1) + 0.5 * n, Vec3(1, 1.6, 1.8) - 0.75 * n, n, -0.25}, 1e-12);
}

TEST(DiscreteSphereSphere, MixedVec3AndRigidOnlyTheRigidOneIsOffset) {
  std::vector<DetectionOutput> out;
  ASSERT_EQ(discrete::sphere_sphere(sphere({0, 0, 0}, 1.0, false), sphere({0, 0, 1}, 1.0, true), out), 1);
  EXPECT_TRUE(vec_near(out[0].point1, {0, 0, 0}));
  EXPECT_TRUE(vec_near(out[0].point2, {0, 0, 0}));  // (0,0,1) − (0,0,1)·1
  EXPECT_DOUBLE_EQ(out[0].value, -1.0);
}

TEST(DiscreteSphereSphere, TouchingSpheresAreAcceptedAndSeparatedOnesRejected) {
  std::vector<DetectionOutput> out;
  // Exactly touching (|d|² = (r1+r2)² = 4): the bound is inclusive.
  EXPECT_EQ(discrete::sphere_sphere(sphere({0, 0, 0}, 1.0), sphere({2, 0, 0}, 1.0), out), 1);
  EXPECT_DOUBLE_EQ(out.back().value, 0.0);
  EXPECT_EQ(discrete::sphere_sphere(sphere({0, 0, 0}, 1.0), sphere({2.000001, 0, 0}, 1.0), out), 0);
  EXPECT_EQ(out.size(), 1u);
}

TEST(DiscreteSphereSphere, ModelSkinsAreIgnored) {
  std::vector<DetectionOutput> out;
  // Discrete has alarm = contact = 0 and does not add the models' contactDistance.
  EXPECT_EQ(discrete::sphere_sphere(sphere({0, 0, 0}, 1.0, false, info(0, 1, 1.0)),
                                    sphere({2.5, 0, 0}, 1.0, false, info(0, 1, 1.0)), out),
            0);
  ASSERT_EQ(discrete::sphere_sphere(sphere({0, 0, 0}, 1.0, false, info(0, 1, 1.0)),
                                    sphere({1.9, 0, 0}, 1.0, false, info(0, 1, 1.0)), out),
            1);
  EXPECT_NEAR(out[0].value, -0.1, 1e-15);
}

TEST(DiscreteSphereSphere, IdOnEqualModelSizesIsSphere2Index) {
  std::vector<DetectionOutput> out;
  discrete::sphere_sphere(sphere({0, 0, 0}, 1, false, info(3, 6)), sphere({1, 0, 0}, 1, false, info(5, 6)), out);
  discrete::sphere_sphere(sphere({0, 0, 0}, 1, false, info(3, 6)), sphere({1, 0, 0}, 1, false, info(5, 7)), out);
  discrete::sphere_sphere(sphere({0, 0, 0}, 1, false, info(3, 8)), sphere({1, 0, 0}, 1, false, info(5, 7)), out);
  ASSERT_EQ(out.size(), 3u);
  EXPECT_EQ(out[0].id, 5);
  EXPECT_EQ(out[1].id, 5);
  EXPECT_EQ(out[2].id, 3);
}

TEST(DiscreteSphereSphere, ExplicitDistancesAddToTheRadii) {
  std::vector<DetectionOutput> out;
  // alarm 0.5: accepted up to r1+r2+0.5 = 2.5 (inclusive); value = |d| − (r1+r2) − contact.
  EXPECT_EQ(discrete::sphere_sphere(sphere({0, 0, 0}, 1), sphere({2.5, 0, 0}, 1), 0.5, 0.25, out), 1);
  EXPECT_DOUBLE_EQ(out.back().value, 0.25);
  EXPECT_EQ(discrete::sphere_sphere(sphere({0, 0, 0}, 1), sphere({2.5001, 0, 0}, 1), 0.5, 0.25, out), 0);
}

namespace sinew {
namespace {

using test::info;
using test::vec_near;

// Segment from (0.25, 0.25, 1) to (0.25, 0.25, −1) crosses the unit right
// triangle in the z = 0 plane at (0.25, 0.25, 0): both points there, the
// triangle's normal, value 0, id = the line's index.
TEST(DiscreteTriangleLine, SegmentCrossingTheTriangle) {
  const TriangleElem t = test::triangle(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), 0, info(2));
  const LineElem l = test::line(Vec3(0.25, 0.25, 1), Vec3(0.25, 0.25, -1), info(7));
  std::vector<DetectionOutput> out;
  ASSERT_EQ(discrete::triangle_line(t, l, out), 1);
  EXPECT_TRUE(vec_near(out[0].point1, Vec3(0.25, 0.25, 0)));
  EXPECT_TRUE(vec_near(out[0].point2, Vec3(0.25, 0.25, 0)));
  EXPECT_TRUE(vec_near(out[0].normal, Vec3(0, 0, 1)));
  EXPECT_EQ(out[0].value, 0.0);
  EXPECT_EQ(out[0].id, 7);
  EXPECT_EQ(out[0].elem1, 2u);
  EXPECT_EQ(out[0].elem2, 7u);
}

TEST(DiscreteTriangleLine, MissesOutsideTheTriangleTheSegmentOrWhenParallel) {
  const TriangleElem t = test::triangle(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0));
  std::vector<DetectionOutput> out;
  EXPECT_EQ(discrete::triangle_line(t, test::line(Vec3(0.6, 0.6, 1), Vec3(0.6, 0.6, -1)), out), 0);  // u+v > 1
  EXPECT_EQ(discrete::triangle_line(t, test::line(Vec3(0.2, 0.2, 2), Vec3(0.2, 0.2, 1)), out), 0);   // above
  EXPECT_EQ(discrete::triangle_line(t, test::line(Vec3(0.1, 0.1, 0), Vec3(0.3, 0.1, 0)), out), 0);  // in plane
  EXPECT_TRUE(out.empty());
}

TetrahedronElem unit_tetra() {
  TetrahedronElem t;
  t.p = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
  t.v = {0, 1, 2, 3};
  t.info = info(3);
  return t;
}

// Point (0.1, 0.1, 0.2) inside the unit tetrahedron with normal (0, 0, −1):
// it leaves along −n = +z and meets the face x + y + z = 1 after l = 0.6.
TEST(DiscreteTetrahedronPoint, PointInsideLeavesAlongItsNormal) {
  PointElem p = test::point(Vec3(0.1, 0.1, 0.2), info(9));
  p.n = Vec3(0, 0, -1);
  std::vector<DetectionOutput> out;
  ASSERT_EQ(discrete::tetrahedron_point(unit_tetra(), p, false, out), 1);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_TRUE(vec_near(out[0].point1, Vec3(0.1, 0.1, 0.8)));
  EXPECT_TRUE(vec_near(out[0].point2, Vec3(0.1, 0.1, 0.2)));
  EXPECT_TRUE(vec_near(out[0].normal, Vec3(0, 0, 1)));
  EXPECT_NEAR(out[0].value, -0.6, 1e-12);
  EXPECT_EQ(out[0].id, 9);
}

TEST(DiscreteTetrahedronPoint, OutsideWithoutNormalOrOwnVertexGiveNothing) {
  std::vector<DetectionOutput> out;
  PointElem outside = test::point(Vec3(0.6, 0.6, 0.6), info(1));
  outside.n = Vec3(0, 0, 1);
  EXPECT_EQ(discrete::tetrahedron_point(unit_tetra(), outside, false, out), 1);  // handled, nothing appended
  const PointElem no_normal = test::point(Vec3(0.1, 0.1, 0.1), info(1));
  EXPECT_EQ(discrete::tetrahedron_point(unit_tetra(), no_normal, false, out), 0);
  PointElem own_vertex = test::point(Vec3(0.1, 0.1, 0.1), info(2));  // index 2 is a vertex of the tetrahedron
  own_vertex.n = Vec3(0, 0, 1);
  EXPECT_EQ(discrete::tetrahedron_point(unit_tetra(), own_vertex, true, out), 0);
  EXPECT_TRUE(out.empty());
}

}  // namespace
}  // namespace sinew

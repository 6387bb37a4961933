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

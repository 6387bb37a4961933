// NewProximityIntersection element tests (spec/interaction.md §2.5) against
// hand-computed contacts: closest-feature projection with ownership flags,
// T–L / T–T orientation and ids, sphere variants. Default distances: alarm 1, contact 0.5.
#include <gtest/gtest.h>

#include <cmath>

#include "collision/intersect/min_proximity_tests.h"
#include "collision/intersect/new_proximity_tests.h"
#include "elem_builders.h"

using namespace sinew;
using namespace sinew::test;
namespace np = sinew::new_proximity;

namespace {
const np::Params kDefault{};
constexpr int kAll = kFlagPoints | kFlagEdges;
TriangleElem unit_triangle(int flags, const ElemInfo& i = info(3, 20)) {
  return triangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, flags, i);
}
}  // namespace

// ------------------------------------------------------------ point / line pairs

TEST(NewProximityPointPoint, InsideAlarmAndIds) {
  std::vector<DetectionOutput> out;
  ASSERT_EQ(np::point_point(kDefault, point({1, 2, 3}, info(2, 5)), point({1.3, 2.4, 3}, info(1, 3)), out), 1);
  expect_output(out[0], {2, 1, 2, {1, 2, 3}, {1.3, 2.4, 3}, {0.6, 0.8, 0}, 0.0});
  np::point_point(kDefault, point({0, 0, 0}, info(2, 4)), point({0.5, 0, 0}, info(1, 4)), out);  // tie → element 2
  EXPECT_EQ(out[1].id, 1);
  EXPECT_EQ(np::point_point(kDefault, point({0, 0, 0}), point({1, 0, 0}), out), 0);  // strict
  // Skins: alarm 1.375, contact 0.875.
  EXPECT_EQ(np::point_point(kDefault, point({0, 0, 0}, info(0, 1, 0.25)), point({0, 1.25, 0}, info(0, 1, 0.125)), out),
            1);
  EXPECT_DOUBLE_EQ(out[2].value, 0.375);
}

TEST(NewProximityPointPoint, CoincidentPointsAreNotGuarded) {
  std::vector<DetectionOutput> out;
  ASSERT_EQ(np::point_point(kDefault, point({1, 1, 1}), point({1, 1, 1}), out), 1);
  EXPECT_TRUE(std::isnan(out[0].normal[0]));  // 0/0, as in SOFA
  EXPECT_DOUBLE_EQ(out[0].value, -0.5);
}

TEST(NewProximityLinePoint, InteriorAndClampedEnds) {
  std::vector<DetectionOutput> out;
  const auto l = line({0, 0, 0}, {2, 0, 0}, info(6, 9));
  ASSERT_EQ(np::line_point(kDefault, l, point({0.5, 0.5, 0}, info(4, 2)), out), 1);
  expect_output(out[0], {6, 4, 4, {0.5, 0, 0}, {0.5, 0.5, 0}, {0, 1, 0}, 0.0});
  ASSERT_EQ(np::line_point(kDefault, l, point({-0.3, 0.4, 0}, info(4, 2)), out), 1);
  expect_output(out[1], {6, 4, 4, {0, 0, 0}, {-0.3, 0.4, 0}, {-0.6, 0.8, 0}, 0.0});
  EXPECT_EQ(np::line_point(kDefault, l, point({1, 1, 0}), out), 0);
  EXPECT_EQ(np::line_point(kDefault, l, point({3, 0, 0}), out), 0);
}

TEST(NewProximityLineLine, CrossingSegmentsAndWindow) {
  std::vector<DetectionOutput> out;
  const auto l1 = line({0, 0, 0}, {2, 0, 0}, info(1, 4));
  ASSERT_EQ(np::line_line(kDefault, l1, line({1, -1, 0.5}, {1, 1, 0.5}, info(2, 7)), out), 1);
  expect_output(out[0], {1, 2, 2, {1, 0, 0}, {1, 0, 0.5}, {0, 0, 1}, 0.0});
  EXPECT_EQ(np::line_line(kDefault, l1, line({2 - 2e-7, -1, 0.5}, {2 - 2e-7, 1, 0.5}), out), 0);
  EXPECT_EQ(np::line_line(kDefault, l1, line({2 - 4e-6, -1, 0.5}, {2 - 4e-6, 1, 0.5}), out), 1);
  // useLineLine does not gate the L–L pair itself.
  np::Params prm;
  prm.use_line_line = false;
  EXPECT_EQ(np::line_line(prm, l1, line({1, -1, 0.5}, {1, 1, 0.5}), out), 1);
}

TEST(NewProximityLineLine, NearlyParallelUsesMidpointsBelowDet1e12) {
  std::vector<DetectionOutput> out;
  // det ≈ 1e-14: MinProximity (threshold 1e-15) solves and finds the closest
  // points far outside the segments; NewProximity (1e-12) takes the midpoints.
  const auto l1 = line({0, 0, 0}, {1, 0, 0});
  const auto l2 = line({0, 0.5, 0}, {1, 0.5 + 1e-7, 0});
  EXPECT_EQ(min_proximity::line_line(min_proximity::Params{}, l1, l2, out), 0);
  ASSERT_EQ(np::line_line(kDefault, l1, l2, out), 1);
  EXPECT_TRUE(vec_near(out[0].point1, {0.5, 0, 0}));
  EXPECT_TRUE(vec_near(out[0].point2, {0.5, 0.5 + 0.5e-7, 0}, 1e-15));
  EXPECT_NEAR(out[0].value, 0.5e-7, 1e-15);
}

// --------------------------------------------------------------- triangle–point

TEST(NewProximityTrianglePoint, InteriorNeedsNoFlag) {
  std::vector<DetectionOutput> out;
  ASSERT_EQ(np::triangle_point(kDefault, unit_triangle(0), point({0.25, 0.25, 0.5}, info(8, 2)), out), 1);
  expect_output(out[0], {3, 8, 8, {0.25, 0.25, 0}, {0.25, 0.25, 0.5}, {0, 0, 1}, 0.0});
  // Machine-epsilon window, not 1e-6: β = 1e-9 is still interior here (MinProximity rejects it).
  EXPECT_EQ(np::triangle_point(kDefault, unit_triangle(0), point({0.5, 1e-9, 0.3}), out), 1);
  EXPECT_EQ(min_proximity::triangle_point(min_proximity::Params{}, unit_triangle(0), point({0.5, 1e-9, 0.3}), out), 0);
}

struct FeatureCase {
  const char* name;
  Vec3 q;        // point tested against the unit triangle
  int needed;    // flag owning the closest feature
  Vec3 closest;  // expected closest point
};

TEST(NewProximityTrianglePoint, ClosestFeatureNeedsItsFlag) {
  const FeatureCase cases[] = {
      {"corner A", {-0.3, -0.4, 0}, kFlagP1, {0, 0, 0}},
      {"edge AB", {0.5, -0.5, 0}, kFlagE12, {0.5, 0, 0}},
      {"edge AB on the edge", {0.5, 0, 0.3}, kFlagE12, {0.5, 0, 0}},
      {"edge AC", {-0.5, 0.5, 0}, kFlagE31, {0, 0.5, 0}},
      {"corner B", {1.3, -0.4, 0}, kFlagP2, {1, 0, 0}},
      {"corner C", {-0.4, 1.3, 0}, kFlagP3, {0, 1, 0}},
      {"edge BC", {0.75, 0.75, 0}, kFlagE23, {0.5, 0.5, 0}},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    std::vector<DetectionOutput> out;
    // Every other flag set: still rejected without the owning one.
    EXPECT_EQ(np::triangle_point(kDefault, unit_triangle(kAll & ~c.needed), point(c.q), out), 0);
    ASSERT_EQ(np::triangle_point(kDefault, unit_triangle(c.needed, info(3, 20)), point(c.q, info(8, 2)), out), 1);
    const Vec3 pq = c.q - c.closest;
    expect_output(out[0], {3, 8, 8, c.closest, c.q, pq.normalized(), pq.norm() - 0.5}, 1e-12);
  }
}

TEST(NewProximityTrianglePoint, AlarmBoundAndSkins) {
  std::vector<DetectionOutput> out;
  // Beyond corner B: distance 0.5 accepted, distance 1 rejected (strict).
  ASSERT_EQ(np::triangle_point(kDefault, unit_triangle(kAll), point({1.5, 0, 0}), out), 1);
  EXPECT_DOUBLE_EQ(out[0].value, 0.0);
  EXPECT_EQ(np::triangle_point(kDefault, unit_triangle(kAll), point({2, 0, 0}), out), 0);
  // Skin 0.25 on the triangle: alarm 1.25, contact 0.75.
  ASSERT_EQ(np::triangle_point(kDefault, unit_triangle(kAll, info(0, 1, 0.25)), point({2, 0, 0}), out), 1);
  EXPECT_DOUBLE_EQ(out[1].value, 0.25);
}

// ---------------------------------------------------------------- triangle–line

TEST(NewProximityTriangleLine, OwnedCornerIsSwappedTowardsTheLine) {
  std::vector<DetectionOutput> out;
  const Vec3 q1(0.25, 0.25, 0.5), q2(0.25, 0.25, 3);
  const auto l = line(q1, q2, info(5, 8));
  // Flags 0: only the segment end q1 against the triangle interior.
  ASSERT_EQ(np::triangle_line(kDefault, unit_triangle(0, info(3, 20)), l, out), 1);
  expect_output(out[0], {3, 5, 5, {0.25, 0.25, 0}, q1, {0, 0, 1}, 0.0});
  out.clear();
  // FLAG_P1: corner A against the segment first, oriented from the corner (element 1) to the line.
  ASSERT_EQ(np::triangle_line(kDefault, unit_triangle(kFlagP1, info(3, 20)), l, out), 2);
  const double d = std::sqrt(0.375);
  expect_output(out[0], {3, 5, 5, {0, 0, 0}, q1, q1 / d, d - 0.5}, 1e-12);
  expect_output(out[1], {3, 5, 5, {0.25, 0.25, 0}, q1, {0, 0, 1}, 0.0});
}

TEST(NewProximityTriangleLine, EdgeEdgeOnlyWithUseLineLine) {
  std::vector<DetectionOutput> out;
  // Segment crossing above edge AB; its ends are over edge AB's outside (too
  // far) and over edge BC's region (E23 not owned).
  const auto l = line({0.5, -1, 0.5}, {0.5, 1, 0.5}, info(5, 8));
  EXPECT_EQ(np::triangle_line(kDefault, unit_triangle(kFlagE12), l, out), 0);
  np::Params prm;
  prm.use_line_line = true;
  ASSERT_EQ(np::triangle_line(prm, unit_triangle(kFlagE12), l, out), 1);
  expect_output(out[0], {3, 5, 5, {0.5, 0, 0}, {0.5, 0, 0.5}, {0, 0, 1}, 0.0});
  // With E23 owned, the end q2 finds edge BC at (0.25,0.75,0), and edge BC
  // meets the segment's middle part 0.5 below (0.5,0.5,0.5): ends first, then edges.
  out.clear();
  ASSERT_EQ(np::triangle_line(prm, unit_triangle(kFlagE12 | kFlagE23), l, out), 3);
  EXPECT_TRUE(vec_near(out[0].point1, {0.25, 0.75, 0}));
  EXPECT_TRUE(vec_near(out[0].point2, {0.5, 1, 0.5}));
  EXPECT_TRUE(vec_near(out[1].point1, {0.5, 0, 0}));
  EXPECT_TRUE(vec_near(out[2].point1, {0.5, 0.5, 0}));
  EXPECT_TRUE(vec_near(out[2].point2, {0.5, 0.5, 0.5}));
}

// ------------------------------------------------------------ triangle–triangle

namespace {
int kModel1 = 1, kModel2 = 2;  // their addresses stand for two models
// e2: the unit triangle translated by (0.25, 0.25, 0.5).
TriangleElem raised(int flags, const ElemInfo& i, std::array<unsigned, 3> v = {10, 11, 12}) {
  return triangle({0.25, 0.25, 0.5}, {1.25, 0.25, 0.5}, {0.25, 1.25, 0.5}, flags, i, v);
}
}  // namespace

TEST(NewProximityTriangleTriangle, FirstCornerAlwaysTestedAndIdsPerCorner) {
  std::vector<DetectionOutput> out;
  const auto e1 = triangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 0, info(1, 4, 0, &kModel1));
  const auto e2 = raised(kFlagP1, info(2, 10, 0, &kModel2));
  ASSERT_EQ(np::triangle_triangle(kDefault, e1, e2, out), 2);
  const Vec3 q1(0.25, 0.25, 0.5);
  const double d = q1.norm();
  // e1's corner A (no FLAG_P1 on e1, tested anyway) against e2's corner q1: id 3·1 + 0.
  expect_output(out[0], {1, 2, 3, {0, 0, 0}, q1, q1 / d, d - 0.5}, 1e-12);
  // e2's owned corner q1 against e1's interior: id 3·4 + 12·2 + 0 = 36.
  expect_output(out[1], {1, 2, 36, {0.25, 0.25, 0}, q1, {0, 0, 1}, 0.0});
}

TEST(NewProximityTriangleTriangle, AllCornersWithFlags) {
  std::vector<DetectionOutput> out;
  const auto e1 = triangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, kFlagP2 | kFlagP3, info(1, 4, 0, &kModel1));
  const auto e2 = raised(kAll, info(2, 10, 0, &kModel2));
  ASSERT_EQ(np::triangle_triangle(kDefault, e1, e2, out), 6);
  const std::int64_t ids[] = {3, 4, 5, 36, 37, 38};
  for (int k = 0; k < 6; ++k) {
    EXPECT_EQ(out[k].id, ids[k]);
    EXPECT_EQ(out[k].elem1, 1u);
    EXPECT_EQ(out[k].elem2, 2u);
    // Every normal points from model 1 (z = 0) up to model 2 (z = 0.5).
    EXPECT_GT(out[k].normal.z(), 0.0);
  }
  // e1's B against e2: closest on e2's edge q1q2 at (1, 0.25, 0.5).
  EXPECT_TRUE(vec_near(out[1].point1, {1, 0, 0}));
  EXPECT_TRUE(vec_near(out[1].point2, {1, 0.25, 0.5}));
  EXPECT_NEAR(out[1].value, std::sqrt(0.3125) - 0.5, 1e-12);
  // e2's q2 against e1: corner B (FLAG_P2 of e1).
  EXPECT_TRUE(vec_near(out[4].point1, {1, 0, 0}));
  EXPECT_TRUE(vec_near(out[4].point2, {1.25, 0.25, 0.5}));
}

TEST(NewProximityTriangleTriangle, SameModelSharingAVertexIsSkipped) {
  std::vector<DetectionOutput> out;
  const auto e1 = triangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, kAll, info(1, 40, 0, &kModel1), {0, 1, 2});
  // Shares point index 2 with e1 in the same model: nothing, even within alarm.
  EXPECT_EQ(np::triangle_triangle(kDefault, e1, raised(kAll, info(2, 40, 0, &kModel1), {7, 2, 9}), out), 0);
  // Same model, no shared index: tested.
  EXPECT_GT(np::triangle_triangle(kDefault, e1, raised(kAll, info(2, 40, 0, &kModel1), {7, 8, 9}), out), 0);
  // Another model with the same point indices: tested.
  out.clear();
  EXPECT_GT(np::triangle_triangle(kDefault, e1, raised(kAll, info(2, 40, 0, &kModel2), {7, 2, 9}), out), 0);
}

TEST(NewProximityTriangleTriangle, IndexOutsideItsModelIsRefused) {
  std::vector<DetectionOutput> out;
  const auto e1 = triangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, kAll, info(4, 4, 0, &kModel1));
  EXPECT_EQ(np::triangle_triangle(kDefault, e1, raised(kAll, info(2, 10, 0, &kModel2)), out), 0);
}

TEST(NewProximityTriangleTriangle, EdgeEdgeIdsWithUseLineLine) {
  np::Params prm;
  prm.alarm = 0.6;
  prm.contact = 0.1;
  // e2's edge q1q2 crosses 0.5 above e1's edge; e2 rises away elsewhere.
  const auto e2 =
      triangle({0.5, -1, 0.5}, {0.5, 1, 0.5}, {0.5, 0, 5}, kFlagE12, info(2, 10, 0, &kModel2), {10, 11, 12});
  const std::int64_t id2 = 3 * 4 + 12 * 2;
  {
    std::vector<DetectionOutput> out;
    const auto e1 = triangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, kFlagE12, info(1, 4, 0, &kModel1));
    // Corner A is 0.707 from e2's edge q1q2 (> 0.6), nothing else is owned: no contact without edge–edge.
    EXPECT_EQ(np::triangle_triangle(prm, e1, e2, out), 0);
    prm.use_line_line = true;
    ASSERT_EQ(np::triangle_triangle(prm, e1, e2, out), 1);
    expect_output(out[0], {1, 2, id2 + 3, {0.5, 0, 0}, {0.5, 0, 0.5}, {0, 0, 1}, 0.4});  // E12 × E12
  }
  {
    std::vector<DetectionOutput> out;
    // Same edge as e1's E23 (vertices 1→2); corner 0 at (0,1,0) is 0.707 from e2.
    const auto e1 = triangle({0, 1, 0}, {0, 0, 0}, {1, 0, 0}, kFlagE23, info(1, 4, 0, &kModel1));
    ASSERT_EQ(np::triangle_triangle(prm, e1, e2, out), 1);
    EXPECT_EQ(out[0].id, id2 + 6);  // E23 × E12
    EXPECT_TRUE(vec_near(out[0].point1, {0.5, 0, 0}));
  }
}

// -------------------------------------------------------------------- spheres

TEST(NewProximitySphereSphere, CentresEvenForRigidAndStrictBound) {
  std::vector<DetectionOutput> out;
  ASSERT_EQ(np::sphere_sphere(kDefault, sphere({0, 0, 0}, 0.5, true, info(1, 2)),
                              sphere({0, 0, 1.5}, 0.5, true, info(0, 3)), out),
            1);
  // alarm 1 + radii = 2; value 1.5 − (0.5 + 1); id from model 2 (3 > 2).
  expect_output(out[0], {1, 0, 0, {0, 0, 0}, {0, 0, 1.5}, {0, 0, 1}, 0.0});
  EXPECT_EQ(np::sphere_sphere(kDefault, sphere({0, 0, 0}, 0.5), sphere({0, 0, 2}, 0.5), out), 0);
  // Skins 0.1 + 0.2: alarm 2.3, contact 1.8.
  ASSERT_EQ(np::sphere_sphere(kDefault, sphere({0, 0, 0}, 0.5, false, info(0, 1, 0.1)),
                              sphere({2.2, 0, 0}, 0.5, false, info(0, 1, 0.2)), out),
            1);
  EXPECT_NEAR(out[1].value, 0.4, 1e-15);
}

TEST(NewProximitySpherePoint, IdFromLargerModel) {
  std::vector<DetectionOutput> out;
  ASSERT_EQ(np::sphere_point(kDefault, sphere({0, 0, 0}, 0.5, true, info(2, 3)), point({0, 0, 1.2}, info(7, 9)), out),
            1);
  // Unlike MinProximity: id from the larger model, point1 the centre.
  expect_output(out[0], {2, 7, 7, {0, 0, 0}, {0, 0, 1.2}, {0, 0, 1}, 0.2});
  EXPECT_EQ(np::sphere_point(kDefault, sphere({0, 0, 0}, 0.5), point({0, 1.5, 0}), out), 0);
}

TEST(NewProximityLineSphere, ClampedProjectionToCentre) {
  std::vector<DetectionOutput> out;
  const auto l = line({0, 0, 0}, {2, 0, 0}, info(1, 30));
  ASSERT_EQ(np::line_sphere(kDefault, l, sphere({0.5, 0.5, 0}, 0.25, true, info(4, 2)), out), 1);
  expect_output(out[0], {1, 4, 4, {0.5, 0, 0}, {0.5, 0.5, 0}, {0, 1, 0}, -0.25});
  ASSERT_EQ(np::line_sphere(kDefault, l, sphere({2.6, 0, 0.8}, 0.25, false, info(4, 2)), out), 1);
  expect_output(out[1], {1, 4, 4, {2, 0, 0}, {2.6, 0, 0.8}, {0.6, 0, 0.8}, 0.25});
  EXPECT_EQ(np::line_sphere(kDefault, l, sphere({1, 1.25, 0}, 0.25), out), 0);
}

// ------------------------------------------------------------- triangle–sphere

TEST(NewProximityTriangleSphere, InteriorVec3AndRigid) {
  std::vector<DetectionOutput> out;
  ASSERT_EQ(np::triangle_sphere(kDefault, unit_triangle(0), sphere({0.25, 0.25, 1.0}, 0.5, false, info(5, 2)), out), 1);
  expect_output(out[0], {3, 5, 5, {0.25, 0.25, 0}, {0.25, 0.25, 1.0}, {0, 0, 1}, 0.0});
  ASSERT_EQ(np::triangle_sphere(kDefault, unit_triangle(0), sphere({0.25, 0.25, 0.75}, 0.5, true, info(5, 2)), out), 1);
  expect_output(out[1], {3, 5, 5, {0.25, 0.25, 0}, {0.25, 0.25, 0.25}, {0, 0, 1}, -0.25});
  EXPECT_EQ(np::triangle_sphere(kDefault, unit_triangle(0), sphere({0.25, 0.25, 1.5}, 0.5), out), 0);
}

TEST(NewProximityTriangleSphere, FlagQuirksOnEdgesACAndBC) {
  std::vector<DetectionOutput> out;
  // Closest on AC: SOFA tests FLAG_E12 there, not E31.
  EXPECT_EQ(np::triangle_sphere(kDefault, unit_triangle(kAll & ~kFlagE12), sphere({-0.5, 0.5, 0}, 0.1), out), 0);
  ASSERT_EQ(np::triangle_sphere(kDefault, unit_triangle(kFlagE12), sphere({-0.5, 0.5, 0}, 0.1), out), 1);
  EXPECT_TRUE(vec_near(out[0].point1, {0, 0.5, 0}));
  // Closest on BC: SOFA tests FLAG_E31 there, not E23.
  EXPECT_EQ(np::triangle_sphere(kDefault, unit_triangle(kAll & ~kFlagE31), sphere({0.75, 0.75, 0}, 0.1), out), 0);
  ASSERT_EQ(np::triangle_sphere(kDefault, unit_triangle(kFlagE31), sphere({0.75, 0.75, 0}, 0.1), out), 1);
  EXPECT_TRUE(vec_near(out[1].point1, {0.5, 0.5, 0}));
  // Corners and AB use their own flags.
  EXPECT_EQ(np::triangle_sphere(kDefault, unit_triangle(kAll & ~kFlagP1), sphere({-0.3, -0.4, 0}, 0.1), out), 0);
  EXPECT_EQ(np::triangle_sphere(kDefault, unit_triangle(kFlagP1), sphere({-0.3, -0.4, 0}, 0.1), out), 1);
  EXPECT_EQ(np::triangle_sphere(kDefault, unit_triangle(kAll & ~kFlagP2), sphere({1.3, -0.4, 0}, 0.1), out), 0);
  EXPECT_EQ(np::triangle_sphere(kDefault, unit_triangle(kFlagP2), sphere({1.3, -0.4, 0}, 0.1), out), 1);
  EXPECT_EQ(np::triangle_sphere(kDefault, unit_triangle(kAll & ~kFlagP3), sphere({-0.4, 1.3, 0}, 0.1), out), 0);
  EXPECT_EQ(np::triangle_sphere(kDefault, unit_triangle(kFlagP3), sphere({-0.4, 1.3, 0}, 0.1), out), 1);
  EXPECT_EQ(np::triangle_sphere(kDefault, unit_triangle(kAll & ~kFlagE12), sphere({0.5, -0.5, 0}, 0.1), out), 0);
  EXPECT_EQ(np::triangle_sphere(kDefault, unit_triangle(kFlagE12), sphere({0.5, -0.5, 0}, 0.1), out), 1);
}

TEST(NewProximityTriangleSphere, MicroWindowsAndOffTriangleEdgePoint) {
  std::vector<DetectionOutput> out;
  // β = 5e-7 < 1e-6 leaves the interior: edge AB (needs E12) at the same place.
  EXPECT_EQ(np::triangle_sphere(kDefault, unit_triangle(0), sphere({0.5, 5e-7, 0.3}, 0.1), out), 0);
  // Corner A needs pAC < 1e-7: with pAC = 5e-7 and pAB < 0 the AB branch is taken
  // without a lower bound on pAB, so the "closest point" lies off the triangle at α = pAB.
  ASSERT_EQ(np::triangle_sphere(kDefault, unit_triangle(kFlagE12), sphere({-0.5, 5e-7, 0.3}, 0.1), out), 1);
  EXPECT_TRUE(vec_near(out[0].point1, {-0.5, 0, 0}));
  EXPECT_NEAR(out[0].value, std::hypot(5e-7, 0.3) - 0.6, 1e-12);
}

TEST(NewProximityTriangleSphere, ObtuseCornerPicksAPointOffTheTriangle) {
  // Obtuse at A. The centre projects at α = −0.6, β = −0.1 with pAB = −0.5, pAC = 0.2:
  // the true closest feature is edge AC at (−0.2,0.2,0), which triangle–point
  // finds; T–S's branch order takes "edge AB" at α = pAB (no lower bound), i.e.
  // (−0.5,0,0), outside the triangle. SOFA does the same; kept.
  std::vector<DetectionOutput> out;
  const auto t = triangle({0, 0, 0}, {1, 0, 0}, {-1, 1, 0}, kAll, info(3, 20));
  const Vec3 c(-0.5, -0.1, 0.3);
  ASSERT_EQ(np::triangle_sphere(kDefault, t, sphere(c, 0.1, false, info(5, 2)), out), 1);
  const Vec3 pq(0, -0.1, 0.3);
  expect_output(out[0], {3, 5, 5, {-0.5, 0, 0}, c, pq.normalized(), pq.norm() - 0.6}, 1e-12);
  ASSERT_EQ(np::triangle_point(kDefault, t, point(c, info(5, 2)), out), 1);
  EXPECT_TRUE(vec_near(out[1].point1, {-0.2, 0.2, 0}, 1e-12));
}

TEST(NewProximityTriangleSphere, CoincidentCentreGetsXNormal) {
  std::vector<DetectionOutput> out;
  ASSERT_EQ(np::triangle_sphere(kDefault, unit_triangle(0), sphere({0.25, 0.25, 0}, 0.5, true), out), 1);
  EXPECT_TRUE(vec_near(out[0].normal, {1, 0, 0}));
  EXPECT_TRUE(vec_near(out[0].point2, {-0.25, 0.25, 0}));
  EXPECT_DOUBLE_EQ(out[0].value, -1.0);
}

// LocalMinDistance element tests and validity filters (spec/interaction.md
// §2.7) against hand-computed cases. Default distances: alarm 1, contact 0.5,
// angleCone 0, coneFactor 0.5.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "collision/intersect/local_min_distance_tests.h"
#include "elem_builders.h"

using namespace sinew;
using namespace sinew::test;
namespace lmd = sinew::local_min_distance;

namespace {
const lmd::Params kDefault{};
const lmd::PointNeighbourhood kFreePoint{};  // no line model above: never filtered
const lmd::LineNeighbourhood kFreeEdge{};    // boundary/free edge
TriangleElem unit_triangle(const ElemInfo& i = info(3, 20)) { return triangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 0, i); }
const double kS = std::sqrt(0.5);
}  // namespace

// ------------------------------------------------------------------ geometry

TEST(LocalMinDistanceTrianglePoint, InteriorAboveTheFrontFace) {
  std::vector<DetectionOutput> out;
  ASSERT_EQ(
      lmd::triangle_point(kDefault, unit_triangle(), false, point({0.25, 0.25, 0.5}, info(8, 2)), kFreePoint, out), 1);
  expect_output(out[0], {3, 8, 8, {0.25, 0.25, 0}, {0.25, 0.25, 0.5}, {0, 0, 1}, 0.0});
  // Interior window as MinProximity; alarm strict; skins add.
  EXPECT_EQ(lmd::triangle_point(kDefault, unit_triangle(), false, point({0.5, 5e-7, 0.3}), kFreePoint, out), 0);
  EXPECT_EQ(lmd::triangle_point(kDefault, unit_triangle(), false, point({0.25, 0.25, 1.0}), kFreePoint, out), 0);
  ASSERT_EQ(
      lmd::triangle_point(kDefault, unit_triangle(info(0, 1, 0.25)), false, point({0.25, 0.25, 1.0}), kFreePoint, out),
      1);
  EXPECT_DOUBLE_EQ(out[1].value, 0.25);
}

TEST(LocalMinDistanceTrianglePoint, BackFaceIsFilteredUnlessBothSideOrUnfiltered) {
  std::vector<DetectionOutput> out;
  const auto below = point({0.25, 0.25, -0.5});
  EXPECT_EQ(lmd::triangle_point(kDefault, unit_triangle(), false, below, kFreePoint, out), 0);
  EXPECT_EQ(lmd::triangle_point(kDefault, unit_triangle(), true, below, kFreePoint, out), 1);
  lmd::Params unfiltered;
  unfiltered.filter_intersection = false;
  EXPECT_EQ(lmd::triangle_point(unfiltered, unit_triangle(), false, below, kFreePoint, out), 1);
  lmd::Params external;
  external.use_lmd_filters = true;
  EXPECT_EQ(lmd::triangle_point(external, unit_triangle(), false, below, kFreePoint, out), 1);
  ASSERT_EQ(out.size(), 3u);
  EXPECT_TRUE(vec_near(out[0].normal, {0, 0, -1}));
}

TEST(LocalMinDistanceTrianglePoint, PointFilterUsesItsOwnSurfaceNormal) {
  std::vector<DetectionOutput> out;
  const auto p = point({0.25, 0.25, 0.5});
  // The point's surface faces up, away from the triangle below it: the contact
  // would pull it through its own surface.
  const Vec3 up[] = {Vec3(0, 0, 1)};
  const Vec3 down[] = {Vec3(0, 0, -1)};
  lmd::PointNeighbourhood nb;
  nb.line_model_above = true;
  nb.triangle_normals = up;
  EXPECT_EQ(lmd::triangle_point(kDefault, unit_triangle(), false, p, nb, out), 0);
  nb.both_side = true;
  EXPECT_EQ(lmd::triangle_point(kDefault, unit_triangle(), false, p, nb, out), 1);
  nb.both_side = false;
  nb.triangle_normals = down;
  EXPECT_EQ(lmd::triangle_point(kDefault, unit_triangle(), false, p, nb, out), 1);
  // Without a line model above the point model the filter does not apply.
  nb.triangle_normals = up;
  nb.line_model_above = false;
  EXPECT_EQ(lmd::triangle_point(kDefault, unit_triangle(), false, p, nb, out), 1);
}

TEST(LocalMinDistanceTriangleSphere, CentreAsPointAndRadiusInDistances) {
  std::vector<DetectionOutput> out;
  ASSERT_EQ(
      lmd::triangle_sphere(kDefault, unit_triangle(), false, sphere({0.25, 0.25, 1.0}, 0.5, false, info(5, 2)), out),
      1);
  expect_output(out[0], {3, 5, 5, {0.25, 0.25, 0}, {0.25, 0.25, 1.0}, {0, 0, 1}, 0.0});
  EXPECT_EQ(lmd::triangle_sphere(kDefault, unit_triangle(), false, sphere({0.25, 0.25, -1.0}, 0.5), out), 0);
  EXPECT_EQ(lmd::triangle_sphere(kDefault, unit_triangle(), true, sphere({0.25, 0.25, -1.0}, 0.5), out), 1);
  EXPECT_EQ(lmd::triangle_sphere(kDefault, unit_triangle(), false, sphere({0.25, 0.25, 1.5}, 0.5), out), 0);
}

TEST(LocalMinDistanceLinePoint, InteriorOnlyNoClamping) {
  std::vector<DetectionOutput> out;
  const auto l = line({0, 0, 0}, {2, 0, 0}, info(6, 9));
  ASSERT_EQ(lmd::line_point(kDefault, l, kFreeEdge, point({0.5, 0.5, 0}, info(4, 2)), kFreePoint, out), 1);
  expect_output(out[0], {6, 4, 4, {0.5, 0, 0}, {0.5, 0.5, 0}, {0, 1, 0}, 0.0});
  EXPECT_EQ(lmd::line_point(kDefault, l, kFreeEdge, point({-0.1, 0.5, 0}), kFreePoint, out), 0);  // before A
  EXPECT_EQ(lmd::line_point(kDefault, l, kFreeEdge, point({1, 1, 0}), kFreePoint, out), 0);       // alarm
  // Degenerate segment: |AB| < 1e-12 |AP|.
  EXPECT_EQ(lmd::line_point(kDefault, line({1, 0, 0}, {1, 0, 0}), kFreeEdge, point({1, 0.5, 0}), kFreePoint, out), 0);
}

TEST(LocalMinDistanceLineSphere, TrueProjectionAndCentre) {
  std::vector<DetectionOutput> out;
  // Unlike MinProximity, no mirrored parameter.
  ASSERT_EQ(lmd::line_sphere(kDefault, line({0, 0, 0}, {4, 0, 0}, info(1, 3)), kFreeEdge,
                             sphere({1, 0.5, 0}, 0.25, true, info(9, 1)), out),
            1);
  expect_output(out[0], {1, 9, 9, {1, 0, 0}, {1, 0.5, 0}, {0, 1, 0}, -0.25});
}

TEST(LocalMinDistanceLineLine, CrossingParallelAndWindow) {
  std::vector<DetectionOutput> out;
  const auto l1 = line({0, 0, 0}, {2, 0, 0}, info(1, 4));
  ASSERT_EQ(lmd::line_line(kDefault, l1, kFreeEdge, line({1, -1, 0.5}, {1, 1, 0.5}, info(2, 7)), kFreeEdge, out), 1);
  expect_output(out[0], {1, 2, 2, {1, 0, 0}, {1, 0, 0.5}, {0, 0, 1}, 0.0});
  // Window [1e-15, 1−1e-15]: α = 1 − 1e-7 is accepted here.
  EXPECT_EQ(lmd::line_line(kDefault, l1, kFreeEdge, line({2 - 2e-7, -1, 0.5}, {2 - 2e-7, 1, 0.5}), kFreeEdge, out), 1);
  EXPECT_EQ(lmd::line_line(kDefault, l1, kFreeEdge, line({2, -1, 0.5}, {2, 1, 0.5}), kFreeEdge, out), 0);
  // Parallel: midpoints, whose oblique direction the free-edge filter refuses.
  const auto l2 = line({0.5, 0.5, 0}, {2.5, 0.5, 0});
  EXPECT_EQ(lmd::line_line(kDefault, l1, kFreeEdge, l2, kFreeEdge, out), 0);
  lmd::Params unfiltered;
  unfiltered.filter_intersection = false;
  ASSERT_EQ(lmd::line_line(unfiltered, l1, kFreeEdge, l2, kFreeEdge, out), 1);
  EXPECT_TRUE(vec_near(out.back().point2, {1.5, 0.5, 0}));
  EXPECT_TRUE(vec_near(out.back().normal, {kS, kS, 0}, 1e-15));
}

TEST(LocalMinDistancePoints, PointPointSpherePointSphereSphere) {
  std::vector<DetectionOutput> out;
  ASSERT_EQ(lmd::point_point(kDefault, point({1, 2, 3}, info(2, 5)), kFreePoint, point({1.3, 2.4, 3}, info(1, 3)),
                             kFreePoint, out),
            1);
  expect_output(out[0], {2, 1, 2, {1, 2, 3}, {1.3, 2.4, 3}, {0.6, 0.8, 0}, 0.0});
  // Sphere–point: id from the larger model (the point's here), centre as point1.
  ASSERT_EQ(lmd::sphere_point(kDefault, sphere({0, 0, 0}, 0.5, false, info(2, 3)), point({0, 0, 1.2}, info(7, 9)),
                              kFreePoint, out),
            1);
  expect_output(out[1], {2, 7, 7, {0, 0, 0}, {0, 0, 1.2}, {0, 0, 1}, 0.2});
  // Its point filter reads QP (towards the sphere): a point facing away is refused.
  const Vec3 up[] = {Vec3(0, 0, 1)};
  lmd::PointNeighbourhood nb;
  nb.line_model_above = true;
  nb.triangle_normals = up;
  EXPECT_EQ(lmd::sphere_point(kDefault, sphere({0, 0, 0}, 0.5), point({0, 0, 1.2}), nb, out), 0);
  // Sphere–sphere: centres, radii in both distances, strict bound.
  ASSERT_EQ(lmd::sphere_sphere(kDefault, sphere({0, 0, 0}, 0.5, false, info(1, 2)),
                               sphere({0, 0, 1.5}, 0.5, false, info(0, 3)), out),
            1);
  expect_output(out[2], {1, 0, 0, {0, 0, 0}, {0, 0, 1.5}, {0, 0, 1}, 0.0});
  EXPECT_EQ(lmd::sphere_sphere(kDefault, sphere({0, 0, 0}, 0.5), sphere({0, 0, 2}, 0.5), out), 0);
}

// ------------------------------------------------------------------- filters

TEST(LocalMinDistanceFilters, PointEdgeConesAndAngleCone) {
  const auto p = point({0, 0, 0});
  const Vec3 down[] = {Vec3(0, 0, -1)};
  const Vec3 neighbours[] = {Vec3(1, 0, 0)};  // edge direction l = (−1,0,0)
  lmd::PointNeighbourhood nb;
  nb.line_model_above = true;
  nb.triangle_normals = down;
  nb.edge_neighbours = neighbours;
  // l·PQ = −0.1 < −cone·|PQ| with cone = max(0, n·l·0.5) + 0 = 0.
  EXPECT_FALSE(lmd::valid_point(kDefault, p, nb, {0.1, 0, -1}));
  EXPECT_TRUE(lmd::valid_point(kDefault, p, nb, {-0.1, 0, -1}));
  lmd::Params wide;
  wide.angle_cone = 0.2;  // cone 0.2: −0.1 ≥ −0.2·|PQ|
  EXPECT_TRUE(lmd::valid_point(wide, p, nb, {0.1, 0, -1}));
  // The normal test also widens with angleCone: n·PQ = −0.1 vs −0.2·|PQ|.
  EXPECT_FALSE(lmd::valid_point(kDefault, p, nb, {-1, 0, 0.1}));
  EXPECT_TRUE(lmd::valid_point(wide, p, nb, {-1, 0, 0.1}));
}

TEST(LocalMinDistanceFilters, WirePointUsesItsEdges) {
  // End of a wire arriving along +x: nMean = (1,0,0).
  const auto p = point({0, 0, 0});
  const Vec3 neighbours[] = {Vec3(-1, 0, 0)};
  lmd::PointNeighbourhood nb;
  nb.line_model_above = true;
  nb.edge_neighbours = neighbours;
  EXPECT_TRUE(lmd::valid_point(kDefault, p, nb, {1, 0.5, 0}));
  EXPECT_TRUE(lmd::valid_point(kDefault, p, nb, {0, 1, 0}));
  EXPECT_FALSE(lmd::valid_point(kDefault, p, nb, {-0.3, 1, 0}));
  EXPECT_FALSE(lmd::valid_point(kDefault, p, nb, {-1, 0, 0}));
  // Opposite triangle normals cancel: no normal test, and no edges: valid.
  const Vec3 opposite[] = {Vec3(0, 0, 1), Vec3(0, 0, -1)};
  lmd::PointNeighbourhood flat;
  flat.line_model_above = true;
  flat.triangle_normals = opposite;
  EXPECT_TRUE(lmd::valid_point(kDefault, p, flat, {0, 0, -1}));
}

TEST(LocalMinDistanceFilters, EdgeBetweenTwoTrianglesOfARoof) {
  // Ridge along x; left face (listing 0→1) slopes down to +y, right face to −y.
  const auto l = line({0, 0, 0}, {1, 0, 0}, info(0), {0, 1});
  const std::array<Vec3, 3> left = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.5, 1, -1)};
  const std::array<Vec3, 3> right = {Vec3(1, 0, 0), Vec3(0, 0, 0), Vec3(0.5, -1, -1)};
  const auto nb = lmd::two_triangles(l, {0, 1, 2}, left, right, false);
  EXPECT_TRUE(vec_near(nb.left_normal, {0, kS, kS}, 1e-15));
  EXPECT_TRUE(vec_near(nb.right_normal, {0, -kS, kS}, 1e-15));
  // The shell order does not matter: t0 not running 0→1 is the right one.
  const auto swapped = lmd::two_triangles(l, {1, 0, 3}, right, left, false);
  EXPECT_TRUE(vec_near(swapped.left_normal, nb.left_normal, 0));
  EXPECT_TRUE(vec_near(swapped.right_normal, nb.right_normal, 0));
  // nMean = (0,0,1); tangents t1 = (0,1,1)/√2, t2 = (0,−1,1)/√2; cones 0.5/√2.
  EXPECT_TRUE(lmd::valid_line(kDefault, l, nb, {0, 0, 1}));
  EXPECT_FALSE(lmd::valid_line(kDefault, l, nb, {0, 0, -1}));
  EXPECT_TRUE(lmd::valid_line(kDefault, l, nb, {0, -1, 1}));
  EXPECT_TRUE(lmd::valid_line(kDefault, l, nb, {0, -1, 0.5}));   // t1·PQ = −0.354 ≥ −0.395
  EXPECT_FALSE(lmd::valid_line(kDefault, l, nb, {0, -1, 0.2}));  // t1·PQ = −0.566 < −0.361
  EXPECT_FALSE(lmd::valid_line(kDefault, l, nb, {0, -1, 0}));    // n·PQ = 0 passes, the cone does not
  // bothSide skips the normal test only.
  auto both = nb;
  both.both_side = true;
  EXPECT_FALSE(lmd::valid_line(kDefault, l, both, {0, 0, -1}));
  lmd::Params unfiltered;
  unfiltered.filter_intersection = false;
  EXPECT_TRUE(lmd::valid_line(unfiltered, l, nb, {0, 0, -1}));
}

TEST(LocalMinDistanceFilters, FreeEdgeWantsPerpendicularDirections) {
  const auto l = line({0, 0, 0}, {1, 0, 0});
  EXPECT_TRUE(lmd::valid_line(kDefault, l, kFreeEdge, {0, 0.3, 0.4}));
  EXPECT_FALSE(lmd::valid_line(kDefault, l, kFreeEdge, {0.01, 0, 1}));  // |cos| ≈ 0.01 > 1e-4
  EXPECT_TRUE(lmd::valid_line(kDefault, l, kFreeEdge, {0.00005, 0, 1}));
  lmd::Params wide;
  wide.angle_cone = 0.02;
  EXPECT_TRUE(lmd::valid_line(wide, l, kFreeEdge, {0.01, 0, 1}));
}

TEST(LocalMinDistanceFilters, TriangleFrontSideOnly) {
  const auto t = unit_triangle();
  EXPECT_TRUE(lmd::valid_triangle(kDefault, t, false, {0, 0, 1}));
  EXPECT_TRUE(lmd::valid_triangle(kDefault, t, false, {1, 0, 0}));  // in-plane: n·PQ = 0
  EXPECT_FALSE(lmd::valid_triangle(kDefault, t, false, {0, 0, -1}));
  EXPECT_TRUE(lmd::valid_triangle(kDefault, t, true, {0, 0, -1}));
}

// ------------------------------------------------------------------ property

TEST(LocalMinDistanceProperty, ValueNormalAndPointsAgree) {
  std::mt19937 gen(777);
  std::uniform_real_distribution<double> u(-1, 1), cd(0, 0.1), rad(0, 0.3);
  const auto vec = [&] { return Vec3(u(gen), u(gen), u(gen)); };
  lmd::Params prm;
  prm.alarm = 0.8;
  prm.contact = 0.3;
  prm.filter_intersection = false;
  int accepted = 0;
  const auto check = [&](const std::vector<DetectionOutput>& out, int n, double contact) {
    if (!n) return;
    ++accepted;
    const auto& d = out.back();
    const Vec3 v = d.point2 - d.point1;
    EXPECT_NEAR(v.norm() - contact, d.value, 1e-10);
    EXPECT_NEAR(d.normal.norm(), 1.0, 1e-10);
    EXPECT_TRUE(vec_near(d.normal, v.normalized(), 1e-8));
  };
  for (int k = 0; k < 3000; ++k) {
    std::vector<DetectionOutput> out;
    const auto i1 = info(1, 5, cd(gen)), i2 = info(2, 6, cd(gen));
    const double c = prm.contact + i1.cd + i2.cd;
    const auto p2 = point(vec(), i2);
    const auto l1 = line(vec(), vec(), i1), l2 = line(vec(), vec(), i2);
    const auto t1 = triangle(vec(), vec(), vec(), 0, i1);
    const auto s1 = sphere(vec(), rad(gen), false, i1), s2 = sphere(vec(), rad(gen), false, i2);
    check(out, lmd::point_point(prm, point(vec(), i1), kFreePoint, p2, kFreePoint, out), c);
    check(out, lmd::line_point(prm, l1, kFreeEdge, p2, kFreePoint, out), c);
    check(out, lmd::line_line(prm, l1, kFreeEdge, l2, kFreeEdge, out), c);
    check(out, lmd::triangle_point(prm, t1, false, p2, kFreePoint, out), c);
    check(out, lmd::triangle_sphere(prm, t1, false, s2, out), c + s2.r);
    check(out, lmd::line_sphere(prm, l1, kFreeEdge, s2, out), c + s2.r);
    check(out, lmd::sphere_point(prm, s1, p2, kFreePoint, out), c + s1.r);
    check(out, lmd::sphere_sphere(prm, s1, s2, out), c + s1.r + s2.r);
  }
  EXPECT_GT(accepted, 3000);
}

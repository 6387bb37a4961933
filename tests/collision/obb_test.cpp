// Oriented boxes (OBBCollisionModel and its element tests, SOFA's
// CollisionOBBCapsule plugin): contacts worked out by hand for face, edge and
// corner configurations, SOFA's quirks pinned, the model's Data, and boxes
// resting on a floor and on each other under Lagrangian friction contacts.
#include <gtest/gtest.h>

#include <cmath>

#include "badinput_helpers.h"
#include "collision/intersect/obb_tests.h"
#include "collision/model/obb_collision_model.h"
#include "elem_builders.h"
#include "math/quat.h"
#include "test_scene.h"

namespace sinew {
namespace {

using test::expect_output;
using test::info;
using test::vec_near;

ObbElem box(const Vec3& c, const Vec3& ext, const Quat& q = {}, const ElemInfo& i = info(0)) {
  ObbElem b;
  b.c = c;
  b.axis = {quat_rotate(q, Vec3(1, 0, 0)), quat_rotate(q, Vec3(0, 1, 0)), quat_rotate(q, Vec3(0, 0, 1))};
  b.ext = ext;
  b.v = Vec3::Zero();
  b.info = i;
  return b;
}

const Vec3 kUnit(1, 1, 1);

// ---------------------------------------------------------------- box–box

// Two aligned boxes 0.5 apart along x: face against face; the contact points
// are the middles of the facing faces' overlap.
TEST(ObbObb, FacingFacesSeparated) {
  std::vector<DetectionOutput> out;
  ASSERT_EQ(obb::obb_obb(1.0, 0.25, box({0, 0, 0}, kUnit, {}, info(3, 5)), box({2.5, 0, 0}, kUnit, {}, info(4, 5)), out),
            1);
  // Equal model sizes: the id is box 2's index (SOFA's strict `>`).
  expect_output(out[0], {3, 4, 4, {1, 0, 0}, {1.5, 0, 0}, {1, 0, 0}, 0.25});
  // The overlap of unequal faces: box 2 (half-extent 0.5) shifted by 0.75 in y: faces overlap on y ∈ [0.25, 1].
  // The clip keeps a margin of |n·p|·1e-6 outside each cutting plane (Geometric Tools'
  // tolerance; here n = (0, 1, 0), p on y = 0.25): the cut corners sit at y = 0.25 − 2.5e-7.
  ASSERT_EQ(obb::obb_obb(1.0, 0.0, box({0, 0, 0}, kUnit), box({2.0, 0.75, 0}, Vec3(0.5, 0.5, 0.5)), out), 1);
  const double y = (2 * (0.25 - 0.25e-6) + 2 * 1.0) / 4;
  expect_output(out[1], {0, 0, 0, {1, y, 0}, {1.5, y, 0}, {1, 0, 0}, 0.5});
  // Box 2 on the left of box 1: the normal still runs from box 1 to box 2.
  ASSERT_EQ(obb::obb_obb(1.0, 0.0, box({0, 0, 0}, kUnit), box({0, -2.5, 0}, kUnit), out), 1);
  expect_output(out[2], {0, 0, 0, {0, -1, 0}, {0, -1.5, 0}, {0, -1, 0}, 0.5});
  // At or beyond the alarm distance on one axis: nothing.
  EXPECT_EQ(obb::obb_obb(0.5, 0.0, box({0, 0, 0}, kUnit), box({2.5, 0, 0}, kUnit), out), 0);
  EXPECT_EQ(out.size(), 3u);
}

// Overlapping boxes: the axis of least overlap, value −depth − contact.
TEST(ObbObb, PenetrationDepthAlongTheAxisOfLeastOverlap) {
  std::vector<DetectionOutput> out;
  ASSERT_EQ(obb::obb_obb(0.2, 0.1, box({0, 0, 0}, kUnit), box({1.8, 0.5, 0}, kUnit), out), 1);
  // Faces overlap on y ∈ [−0.5, 1]; the cut at y = −0.5 keeps the margin |2·(−0.5)|·1e-6 / 2 (n = (0, 2, 0)).
  const double y = (2 * (-0.5 - 0.5e-6) + 2 * 1.0) / 4;
  expect_output(out[0], {0, 0, 0, {1, y, 0}, {0.8, y, 0}, {1, 0, 0}, -0.3});
}

// Box 2 turned 45° about z: its edge (along z) faces box 1's +x face. The
// edge, moved onto the face, is clipped to it; the contact is its middle.
TEST(ObbObb, EdgeAgainstFace) {
  std::vector<DetectionOutput> out;
  const Quat q = quat_from_axis_angle(Vec3(0, 0, 1), M_PI / 4);
  ASSERT_EQ(obb::obb_obb(1.0, 0.0, box({0, 0, 0}, kUnit), box({3, 0, 0}, kUnit, q), out), 1);
  const double gap = 3 - std::sqrt(2.0) - 1;
  expect_output(out[0], {0, 0, 0, {1, 0, 0}, {1 + gap, 0, 0}, {1, 0, 0}, gap}, 1e-12);
  // Edge against edge: box 1 turned 45° about y, box 2 about z, crossing edges 0.3 apart along x.
  const Quat qy = quat_from_axis_angle(Vec3(0, 1, 0), M_PI / 4);
  ASSERT_EQ(obb::obb_obb(1.0, 0.0, box({0, 0, 0}, kUnit, qy), box({2 * std::sqrt(2.0) + 0.3, 0, 0}, kUnit, q), out),
            1);
  expect_output(out[1], {0, 0, 0, {std::sqrt(2.0), 0, 0}, {std::sqrt(2.0) + 0.3, 0, 0}, {1, 0, 0}, 0.3}, 1e-12);
}

// A corner of a box in general orientation against a face: the corner is the
// point on box 2, its projection on the face the point on box 1.
TEST(ObbObb, CornerAgainstFace) {
  const Quat q = quat_normalized({0.3, -0.2, 0.5, 0.8});
  ObbElem b2 = box({0, 0, 0}, Vec3(0.5, 0.7, 0.9), q);
  const auto vs = obb_vertices(b2);
  Vec3 low = vs[0];
  for (const Vec3& v : vs)
    if (v[0] < low[0]) low = v;
  // Place box 2 so its lowest-x corner is 0.4 from box 1's +x face, in front of it.
  const Vec3 shift = Vec3(1.4, 0.1, -0.2) - low;
  b2.c += shift;
  std::vector<DetectionOutput> out;
  ASSERT_EQ(obb::obb_obb(1.0, 0.05, box({0, 0, 0}, kUnit), b2, out), 1);
  expect_output(out[0], {0, 0, 0, {1, 0.1, -0.2}, {1.4, 0.1, -0.2}, {1, 0, 0}, 0.35}, 1e-12);
}

// ------------------------------------------------------------ triangle–box

TriangleElem floor_triangle(int flags = kFlagPoints | kFlagEdges, const ElemInfo& i = info(7, 2)) {
  return test::triangle({-10, 0, -10}, {0, 0, 10}, {10, 0, -10}, flags, i);
}

TEST(TriangleObb, BoxAboveTheTriangleFace) {
  std::vector<DetectionOutput> out;
  const TriangleElem t = floor_triangle();
  ASSERT_NEAR(t.normal[1], 1.0, 1e-15);
  ASSERT_EQ(obb::triangle_obb(1.0, 0.1, t, box({0, 1.3, 0}, kUnit, {}, info(2, 9)), out), 1);
  // Face on face: the clipped face's middle; the id is the triangle's index.
  expect_output(out[0], {7, 2, 7, {0, 0, 0}, {0, 0.3, 0}, {0, 1, 0}, 0.2});
  EXPECT_EQ(obb::triangle_obb(0.3, 0.1, t, box({0, 1.3, 0}, kUnit), out), 0);
}

// Kept from SOFA: the triangle–box query never flags a collision, so an
// overlap of 0.2 is reported at +0.2 − contact.
TEST(TriangleObb, OverlapIsReportedAsAPositiveDistance) {
  std::vector<DetectionOutput> out;
  ASSERT_EQ(obb::triangle_obb(1.0, 0.1, floor_triangle(), box({0, 0.8, 0}, kUnit), out), 1);
  expect_output(out[0], {7, 0, 7, {0, 0, 0}, {0, -0.2, 0}, {0, 1, 0}, 0.1});
}

// The triangle's apex is its closest feature; the contact is dropped when the
// triangle does not own that vertex (a neighbour reports it).
TEST(TriangleObb, ApexContactNeedsTheVertexFlag) {
  std::vector<DetectionOutput> out;
  const auto tri = [](int flags) { return test::triangle({0, 0, 0}, {1, -1, 0}, {-1, -1, 0.5}, flags); };
  ASSERT_EQ(obb::triangle_obb(1.0, 0.0, tri(kFlagPoints | kFlagEdges), box({0, 1.5, 0}, kUnit), out), 1);
  expect_output(out[0], {0, 0, 0, {0, 0, 0}, {0, 0.5, 0}, {0, 1, 0}, 0.5});
  EXPECT_EQ(obb::triangle_obb(1.0, 0.0, tri(kFlagP2 | kFlagP3 | kFlagEdges), box({0, 1.5, 0}, kUnit), out), 0);
}

// ------------------------------------------------------------ sphere–box

TEST(SphereObb, OutsideAndInside) {
  std::vector<DetectionOutput> out;
  // Outside: along the segment to the clamped centre; a Vec3d sphere's point is its centre.
  ASSERT_EQ(obb::sphere_obb(2.0, 0.1, test::sphere({3, 0, 0}, 0.5, false, info(4)), box({0, 0, 0}, kUnit), out), 1);
  expect_output(out[0], {4, 0, 4, {3, 0, 0}, {1, 0, 0}, {-1, 0, 0}, 1.4});
  // A rigid sphere's point is on its surface.
  ASSERT_EQ(obb::sphere_obb(2.0, 0.1, test::sphere({3, 0, 0}, 0.5, true, info(4)), box({0, 0, 0}, kUnit), out), 1);
  EXPECT_TRUE(vec_near(out[1].point1, {2.5, 0, 0}));
  EXPECT_EQ(obb::sphere_obb(1.4, 0.1, test::sphere({3, 0, 0}, 0.5), box({0, 0, 0}, kUnit), out), 0);
  // Inside: the axis of largest relative coordinate (x), towards the box centre.
  ASSERT_EQ(obb::sphere_obb(0.1, 0.1, test::sphere({0.5, 0.2, 0}, 0.3, true), box({0, 0, 0}, kUnit), out), 1);
  expect_output(out[2], {0, 0, 0, {0.2, 0.2, 0}, {1, 0.2, 0}, {-1, 0, 0}, -0.9});
}

// ---------------------------------------------------------------- the model

TEST(ObbCollisionModel, ExtentsArePaddedWithTheDefaultAndBoundTheBoxes) {
  scene::LoadedScene s = test::load(R"(<Node name="root">
    <MechanicalObject template="Rigid3d" position="0 0 0 0 0 0.3826834323650898 0.9238795325112867  5 0 0 0 0 0 1"/>
    <OBBCollisionModel name="boxes" extents="1 2 3" defaultExtent="0.5" contactDistance="0.1"/>
  </Node>)");
  ASSERT_TRUE(s.root);
  auto* m = test::get<ObbCollisionModel>(*s.root, "boxes");
  ASSERT_EQ(m->extents.get().size(), 2u);
  EXPECT_TRUE(vec_near(m->extents.get()[1], Vec3(0.5, 0.5, 0.5)));
  m->compute_bounding_tree(0);
  ASSERT_EQ(m->size(), 2u);
  // Box 0 turned 45° about z: its xy footprint is (1 + 2)/√2 wide either side; z ±3; plus the skin.
  const double r = 3 / std::sqrt(2.0) + 0.1;
  const CubeTree::Leaf* leaf = nullptr;
  for (const auto& l : m->tree().leaves())
    if (l.elem == 0) leaf = &l;
  ASSERT_TRUE(leaf);
  const Aabb& b0 = leaf->box;
  EXPECT_TRUE(vec_near(b0.min, Vec3(-r, -r, -3.1), 1e-12));
  EXPECT_TRUE(vec_near(b0.max, Vec3(r, r, 3.1), 1e-12));
  EXPECT_TRUE(vec_near(m->elem(0).axis[0], Vec3(std::sqrt(0.5), std::sqrt(0.5), 0), 1e-15));
}

// Extents follow the state and the writes made to them while the scene runs.
TEST(ObbCollisionModel, ExtentsAreCheckedAgainWhenTheyOrTheStateChange) {
  scene::LoadedScene s = test::load(R"(<Node name="root">
    <MechanicalObject name="x" template="Rigid3d" position="0 0 0 0 0 0 1"/>
    <OBBCollisionModel name="boxes" defaultExtent="0.25" moving="0"/>
  </Node>)");
  ASSERT_TRUE(s.root);
  auto* m = test::get<ObbCollisionModel>(*s.root, "boxes");
  auto* x = test::get<MechanicalState>(*s.root, "x");
  m->compute_bounding_tree(0);
  x->resize(3);
  m->compute_bounding_tree(0);
  ASSERT_EQ(m->size(), 3u);
  EXPECT_TRUE(vec_near(m->extents.get()[2], Vec3(0.25, 0.25, 0.25)));
  // A new extent on an obstacle (moving=0) rebuilds its boxes all the same.
  m->extents.set({Vec3(2, 2, 2), Vec3(1, 1, 1), Vec3(1, 1, 1)});
  m->compute_bounding_tree(0);
  double lo = 0;
  for (const auto& l : m->tree().leaves())
    if (l.elem == 0) lo = l.box.min[0];
  EXPECT_DOUBLE_EQ(lo, -2.0);
  m->extents.set({Vec3(1, -1, 1)});
  m->compute_bounding_tree(0);
  EXPECT_EQ(m->state(), ComponentState::invalid);
  EXPECT_TRUE(test::any_contains(test::messages(s.root->diagnostics(), Severity::error), "extents of box 0"));
}

TEST(ObbCollisionModel, BadInputIsRefused) {
  test::TempDir dir;
  const char* head = R"(<Node name="root" dt="0.01"><CollisionPipeline/><BruteForceBroadPhase/><BVHNarrowPhase/>
    <NewProximityIntersection/><CollisionResponse/>)";
  test::Outcome o = test::run_xml(dir, std::string(head) + R"(<Node name="a"><MechanicalObject position="0 0 0"/>
    <OBBCollisionModel name="boxes"/></Node></Node>)");
  EXPECT_TRUE(test::any_contains_all(o.errors, {"boxes", "needs a Rigid3d"})) << o.all();
  o = test::run_xml(dir, std::string(head) + R"(<Node name="a"><MechanicalObject template="Rigid3d" position="0 0 0 0 0 0 1"/>
    <OBBCollisionModel name="boxes" extents="1 0 1"/></Node></Node>)");
  EXPECT_TRUE(test::any_contains_all(o.errors, {"boxes", "extents of box 0", "> 0"})) << o.all();
  o = test::run_xml(dir, std::string(head) + R"(<Node name="a"><MechanicalObject template="Rigid3d" position="0 0 0 0 0 0 1"/>
    <OBBCollisionModel name="boxes" defaultExtent="-1"/></Node></Node>)");
  EXPECT_TRUE(test::any_contains_all(o.errors, {"boxes", "defaultExtent"})) << o.all();
}

// Box–box and sphere–box pairs come with every intersection method (SOFA's plugin
// registers them with DiscreteIntersection, the base of the proximity methods);
// triangle–box with NewProximityIntersection only.
TEST(ObbCollisionModel, PairsEachIntersectionMethodTests) {
  for (const std::string method : {"DiscreteIntersection", "MinProximityIntersection", "LocalMinDistance",
                                   "NewProximityIntersection"}) {
    const std::string xml = R"(<Node name="root" dt="0.01" gravity="0 0 0">
      <CollisionPipeline/><BruteForceBroadPhase/><BVHNarrowPhase/><)" +
                            method + R"(/><CollisionResponse response="PenalityContactForceField"/>
      <Node name="a"><EulerImplicitSolver/><CGLinearSolver iterations="10" tolerance="1e-9" threshold="1e-9"/>
        <MechanicalObject template="Rigid3d" position="0 0 0 0 0 0 1"/><UniformMass totalMass="1"/>
        <OBBCollisionModel name="box"/></Node>
      <Node name="b"><MechanicalObject template="Rigid3d" position="1.8 0 0 0 0 0 1"/>
        <OBBCollisionModel name="other" simulated="0" moving="0"/></Node>
      <Node name="c"><MechanicalObject position="0 1.5 0"/>
        <SphereCollisionModel name="ball" radius="0.6" simulated="0" moving="0"/></Node>
      <Node name="d"><MechanicalObject position="-3 -3 0.9  3 -3 0.9  0 3 0.9"/><MeshTopology triangles="0 1 2"/>
        <TriangleCollisionModel name="plate" simulated="0" moving="0"/></Node>
    </Node>)";
    scene::LoadedScene s = test::load(xml);
    ASSERT_TRUE(s.root) << method;
    animate(*s.root);
    auto* box = test::get<ObbCollisionModel>(*s.root->find_child_named("a"), "box");
    const bool with_triangles = method == "NewProximityIntersection";
    EXPECT_EQ(box->number_of_contacts.value(), with_triangles ? 3 : 2) << method;
  }
}

// A box falls on a floor of two triangles, a thinner box on it. Unilateral
// contacts keep each pair at the contact distance (0.09): the first box rests
// at 1 + 0.09, the second at 1.09 + 1 + 1 + 0.09 (the LCP tolerance, 1e-3 on
// impulses, lets them rock by a few thousandths).
TEST(ObbCollisionModel, BoxesRestOnTheFloorAndOnEachOther) {
  const std::string xml = R"(<Node name="root" dt="0.01" gravity="0 -9.81 0">
    <FreeMotionAnimationLoop/><CollisionPipeline/><BruteForceBroadPhase/><BVHNarrowPhase/>
    <NewProximityIntersection alarmDistance="0.2" contactDistance="0.09"/>
    <CollisionResponse response="FrictionContactConstraint"/>
    <LCPConstraintSolver maxIt="1000" tolerance="0.001" build_lcp="false"/>
    <Node name="cubes">
      <EulerImplicitSolver rayleighStiffness="0.1" rayleighMass="0.1"/>
      <CGLinearSolver iterations="25" tolerance="1e-5" threshold="1e-5"/>
      <Node name="A"><MechanicalObject name="x" template="Rigid3" translation="0 1.5 0"/><UniformMass totalMass="10"/>
        <UncoupledConstraintCorrection useOdeSolverIntegrationFactors="0"/><OBBCollisionModel/></Node>
      <Node name="B"><MechanicalObject name="x" template="Rigid3" translation="0.3 4 0.2"/><UniformMass totalMass="10"/>
        <UncoupledConstraintCorrection useOdeSolverIntegrationFactors="0"/><OBBCollisionModel extents="0.5 1 0.5"/></Node>
    </Node>
    <Node name="floor">
      <MeshTopology position="-10 0 -10  10 0 -10  10 0 10  -10 0 10" triangles="0 2 1  0 3 2"/>
      <MechanicalObject/><TriangleCollisionModel moving="0" simulated="0"/>
    </Node>
  </Node>)";
  scene::LoadedScene s = test::load(xml);
  ASSERT_TRUE(s.root);
  Node* cubes = s.root->find_child_named("cubes");
  auto* a = test::get<MechanicalState>(*cubes->find_child_named("A"), "x");
  auto* b = test::get<MechanicalState>(*cubes->find_child_named("B"), "x");
  for (int i = 0; i < 300; ++i) {
    animate(*s.root);
    if (i < 150) continue;
    EXPECT_NEAR(a->read(kPosition)[1], 1.09, 0.01) << "step " << i;
    EXPECT_NEAR(b->read(kPosition)[1], 3.18, 0.02) << "step " << i;
  }
}

// SOFA's benchmark of 72 boxes dropped on a tilted floor: after 3 s no box
// corner is below the floor by more than the solver's slack, every state is
// finite, and the boxes touch the floor or each other.
TEST(ObbCollisionModel, SofaBenchmarkCubesStayAboveTheFloor) {
  std::vector<std::vector<double>> frames;
  const test::Outcome o =
      test::run_sofa_example("Benchmark/Performance/benchmark_cubes.scn", 300, [&](runner::Session& s) {
        Node* grid = s.root().find_child_named("grid0");
        for (const auto& c : grid->children()) frames.push_back(c->mechanical_state->read(kPosition));
      });
  if (!o.loaded) GTEST_SKIP() << "SOFA data not found at " << SINEW_DATA_DIR << " (set SINEW_DATA_DIR)";
  ASSERT_TRUE(o.init_ok) << o.all();
  EXPECT_EQ(o.steps, 300);
  EXPECT_TRUE(o.finite);
  EXPECT_TRUE(o.errors.empty() && o.warnings.empty()) << o.all();
  ASSERT_EQ(frames.size(), 72u);
  // floor.obj's top face, y = −1.32967, turned 10° about x: the plane n·p = −1.32967.
  const double a = 10 * M_PI / 180;
  const Vec3 n(0, std::cos(a), std::sin(a));
  int resting = 0;
  for (const auto& f : frames) {
    const ObbElem e = box({f[0], f[1], f[2]}, kUnit, Quat::from(&f[3]));
    double lowest = 1e9;
    for (const Vec3& v : obb_vertices(e)) lowest = std::min(lowest, n.dot(v) + 1.32967);
    EXPECT_GT(lowest, -0.05) << "a corner below the floor";
    if (lowest < 0.2) ++resting;
  }
  EXPECT_GT(resting, 10);
}

}  // namespace
}  // namespace sinew

// The collision pipeline end to end: the bounding-volume traversal finds
// exactly the pairs a brute-force loop finds, penalty contacts are the
// gradient of their energy, a body comes to rest on an obstacle at the
// distance the penalty law predicts, and bad elements are skipped with a message.
#include <gtest/gtest.h>

#include <random>
#include <set>
#include <sstream>

#include "badinput_helpers.h"
#include "elem_builders.h"
#include "collision/intersect/min_proximity_tests.h"
#include "collision/intersect/new_proximity_tests.h"
#include "collision/model/point_collision_model.h"
#include "collision/model/triangle_collision_model.h"
#include "collision/narrow_phase.h"
#include "collision/response/penalty_contact.h"
#include "state/mechanical_object.h"
#include "test_scene.h"

namespace sinew {
namespace {

std::string points_text(std::mt19937& rng, int n, double lo, double hi) {
  std::uniform_real_distribution<double> u(lo, hi);
  std::ostringstream s;
  s.precision(17);
  for (int i = 0; i < 3 * n; ++i) s << u(rng) << ' ';
  return s.str();
}

// Two clouds of points, one simulated, one obstacle: every pair the BVH
// reports is a pair the brute-force loop reports, and the other way round,
// whatever the depth of the trees.
TEST(CollisionPipeline, BvhFindsExactlyTheBruteForcePairs) {
  std::mt19937 rng(7);
  for (int depth : {0, 1, 3, 6, 10}) {
    const std::string a = points_text(rng, 300, 0, 4), b = points_text(rng, 200, 1, 5);
    const std::string xml = R"(<Node name="root" dt="0.01">
      <CollisionPipeline depth=")" +
                            std::to_string(depth) + R"("/><BruteForceBroadPhase/><BVHNarrowPhase name="narrow"/>
      <MinProximityIntersection alarmDistance="0.3" contactDistance="0.1"/>
      <CollisionResponse response="PenalityContactForceField"/>
      <Node name="A"><MechanicalObject name="x" position=")" +
                            a + R"("/><PointCollisionModel name="pa" contactDistance="0.05"/></Node>
      <Node name="B"><MechanicalObject name="x" position=")" +
                            b + R"("/><PointCollisionModel name="pb" simulated="0" moving="0"/></Node>
    </Node>)";
    scene::LoadedScene s = test::load(xml);
    ASSERT_TRUE(s.root);
    s.root->collision_pipeline->collide(0.01);
    auto* narrow = test::get<BVHNarrowPhase>(*s.root, "narrow");
    ASSERT_NE(narrow, nullptr);
    std::set<std::pair<unsigned, unsigned>> found;
    const CollisionModelBase* m1 = nullptr;
    for (const PairOutputs& p : narrow->outputs())
      for (const DetectionOutput& o : p.outputs) {
        m1 = p.models.first;
        found.insert({o.elem1, o.elem2});
      }
    ASSERT_NE(m1, nullptr);
    auto* pa = test::get<PointCollisionModel>(*s.root->find_child_named("A"), "pa");
    auto* pb = test::get<PointCollisionModel>(*s.root->find_child_named("B"), "pb");
    const PointCollisionModel* first = m1 == pa ? pa : pb;
    const PointCollisionModel* second = first == pa ? pb : pa;
    min_proximity::Params prm{0.3, 0.1, false};
    std::set<std::pair<unsigned, unsigned>> brute;
    std::vector<DetectionOutput> out;
    for (unsigned i = 0; i < first->size(); ++i)
      for (unsigned j = 0; j < second->size(); ++j) {
        out.clear();
        if (min_proximity::point_point(prm, first->elem(i), second->elem(j), out)) brute.insert({i, j});
      }
    EXPECT_GT(brute.size(), 10u);
    EXPECT_EQ(found, brute) << "depth " << depth;
  }
}

// f = −∂E/∂x and df = K·dx, checked against central differences.
TEST(CollisionPipeline, PenaltyForceIsTheGradientOfItsEnergy) {
  MechanicalObject s1(StateType::vec3), s2(StateType::vec3);
  s1.resize(2);
  s2.resize(2);
  std::vector<double> x1 = {0, 0, 0, 1, 0.1, 0}, x2 = {0.05, 0.15, 0, 1.1, 0.05, 0.02};
  s1.write(kPosition) = x1;
  s2.write(kPosition) = x2;
  PenaltyContactForceField ff(s1, s2, false, false);
  const Vec3 n1 = Vec3(0, 1, 0), n2 = Vec3(0.1, 1, 0.2).normalized();
  ff.clear(2);
  ff.add_contact({0, 0, n1, 0.2, 500.0});
  ff.add_contact({1, 1, n2, 0.2, 300.0});
  auto energy = [&] {
    MechParams p;
    s1.write(kForce).assign(6, 0.0);
    s2.write(kForce).assign(6, 0.0);
    ff.add_force(p);
    return *ff.potential_energy();
  };
  energy();
  const std::vector<double> f1 = s1.read(kForce), f2 = s2.read(kForce);
  const double h = 1e-6;
  for (int side = 0; side < 2; ++side)
    for (int k = 0; k < 6; ++k) {
      MechanicalObject& s = side == 0 ? s1 : s2;
      std::vector<double> x = s.read(kPosition);
      s.write(kPosition)[k] = x[k] + h;
      const double ep = energy();
      s.write(kPosition)[k] = x[k] - h;
      const double em = energy();
      s.write(kPosition) = x;
      const double f = side == 0 ? f1[k] : f2[k];
      EXPECT_NEAR(f, -(ep - em) / (2 * h), 1e-5) << "side " << side << " scalar " << k;
    }
  // Stiffness: df for dx on both sides equals the change of force.
  energy();
  std::vector<double> dx1 = {0.3, -0.2, 0.1, 0.0, 0.5, -0.4}, dx2 = {-0.1, 0.2, 0.4, 0.3, -0.3, 0.1};
  s1.write(kDx) = dx1;
  s2.write(kDx) = dx2;
  s1.write(kDforce).assign(6, 0.0);
  s2.write(kDforce).assign(6, 0.0);
  MechParams p;
  ff.add_dforce(p, 1.0);
  const std::vector<double> df1 = s1.read(kDforce), df2 = s2.read(kDforce);
  for (double sign : {1.0, -1.0}) {
    for (int k = 0; k < 6; ++k) {
      s1.write(kPosition)[k] = x1[k] + sign * h * dx1[k];
      s2.write(kPosition)[k] = x2[k] + sign * h * dx2[k];
    }
    energy();
    static std::vector<double> fp1, fp2;
    if (sign > 0) {
      fp1 = s1.read(kForce);
      fp2 = s2.read(kForce);
    } else {
      for (int k = 0; k < 6; ++k) {
        EXPECT_NEAR(df1[k], (fp1[k] - s1.read(kForce)[k]) / (2 * h), 1e-4);
        EXPECT_NEAR(df2[k], (fp2[k] - s2.read(kForce)[k]) / (2 * h), 1e-4);
      }
    }
  }
}

// A point falls on a fixed floor: at rest, the penalty force ks·pen balances
// its weight, so it rests at contactDistance − m·g/ks above the floor with
// ks = contactStiffness² / contactDistance = 10·10/0.2 = 500.
TEST(CollisionPipeline, PointRestsOnTheFloorWherePenaltyBalancesWeight) {
  const std::string xml = R"(<Node name="root" dt="0.01" gravity="0 -9.81 0">
    <CollisionPipeline/><BruteForceBroadPhase/><BVHNarrowPhase/>
    <MinProximityIntersection alarmDistance="0.5" contactDistance="0.2"/>
    <CollisionResponse response="PenalityContactForceField"/>
    <Node name="ball">
      <EulerImplicitSolver rayleighMass="0.5"/><CGLinearSolver iterations="50" tolerance="1e-12" threshold="1e-14"/>
      <MechanicalObject name="x" position="0.5 0.6 0.2"/><UniformMass totalMass="1"/>
      <PointCollisionModel/>
    </Node>
    <Node name="floor">
      <MechanicalObject position="-1 0 -1  2 0 -1  2 0 2  -1 0 2"/>
      <MeshTopology triangles="0 2 1  0 3 2"/>
      <TriangleCollisionModel simulated="0" moving="0"/>
    </Node>
  </Node>)";
  scene::LoadedScene s = test::load(xml);
  ASSERT_TRUE(s.root);
  for (int i = 0; i < 600; ++i) animate(*s.root);
  auto* x = test::get<MechanicalState>(*s.root->find_child_named("ball"), "x");
  const double y = x->read(kPosition)[1];
  EXPECT_NEAR(y, 0.2 - 9.81 / 500.0, 1e-4);
  // The contact lives in the ball's node (obstacle–body contacts are solved implicitly there).
  EXPECT_EQ(s.root->find_child_named("ball")->interaction_force_fields.size(), 1u);
}

// Bad elements (zero radius, non-finite position) are skipped with a message
// naming the model and the element; the rest of the scene runs.
TEST(CollisionPipeline, BadElementsAreSkippedWithAMessage) {
  test::TempDir dir;
  const std::string xml = R"(<Node name="root" dt="0.01">
    <CollisionPipeline/><BruteForceBroadPhase/><BVHNarrowPhase/><DiscreteIntersection/>
    <CollisionResponse response="PenalityContactForceField"/>
    <Node name="a"><EulerImplicitSolver/><CGLinearSolver iterations="10" tolerance="1e-9" threshold="1e-9"/>
      <MechanicalObject position="0 0 0  3 0 0"/><UniformMass totalMass="1"/>
      <SphereCollisionModel name="balls" listRadius="0 1"/></Node>
    <Node name="b"><MechanicalObject position="0.5 0 0  3.5 0 0"/>
      <SphereCollisionModel name="obstacle" radius="1" simulated="0" moving="0"/></Node>
  </Node>)";
  const test::Outcome o = test::run_xml(dir, xml, 5);
  EXPECT_TRUE(o.init_ok) << o.all();
  EXPECT_EQ(o.steps, 5);
  EXPECT_TRUE(o.finite);
  EXPECT_TRUE(test::any_contains_all(o.warnings, {"balls", "sphere 0", "radius"})) << o.all();
}

TEST(CollisionPipeline, EmptyModelIsReported) {
  test::TempDir dir;
  const std::string xml = R"(<Node name="root" dt="0.01">
    <CollisionPipeline/><BruteForceBroadPhase/><BVHNarrowPhase/><MinProximityIntersection/>
    <CollisionResponse response="PenalityContactForceField"/>
    <Node name="a"><MechanicalObject position="0 0 0  1 0 0  0 1 0"/><MeshTopology edges="0 1"/>
      <TriangleCollisionModel name="skin"/><PointCollisionModel/></Node>
  </Node>)";
  const test::Outcome o = test::run_xml(dir, xml, 3);
  EXPECT_EQ(o.steps, 3);
  EXPECT_TRUE(test::any_contains_all(o.warnings, {"skin", "no triangles", "collides with nothing"})) << o.all();
}

TEST(CollisionPipeline, MissingPhaseIsAnError) {
  test::TempDir dir;
  const std::string xml = R"(<Node name="root" dt="0.01">
    <CollisionPipeline/><BVHNarrowPhase/><DiscreteIntersection/>
    <CollisionResponse response="PenalityContactForceField"/>
    <Node name="b"><MechanicalObject position="0 0 0"/><SphereCollisionModel radius="1"/></Node>
  </Node>)";
  const test::Outcome o = test::run_xml(dir, xml, 1);
  EXPECT_TRUE(test::any_contains_all(o.errors, {"CollisionPipeline", "broad phase"})) << o.all();
}

}  // namespace
}  // namespace sinew

namespace sinew {
namespace {

std::string floor_and_point_scene(const char* method, double y) {
  return std::string(R"(<Node name="root" dt="0.01" gravity="0 -9.81 0">
    <CollisionPipeline/><BruteForceBroadPhase/><BVHNarrowPhase name="narrow"/>
    <)") +
         method + R"( alarmDistance="0.5" contactDistance="0.2"/>
    <CollisionResponse response="PenalityContactForceField"/>
    <Node name="ball">
      <EulerImplicitSolver rayleighMass="0.5"/><CGLinearSolver iterations="50" tolerance="1e-12" threshold="1e-14"/>
      <MechanicalObject name="x" position="0.5 )" +
         std::to_string(y) + R"( 0.2"/><UniformMass totalMass="1"/>
      <PointCollisionModel/>
    </Node>
    <Node name="floor">
      <MechanicalObject position="-1 0 -1  2 0 -1  2 0 2  -1 0 2"/>
      <MeshTopology triangles="0 2 1  0 3 2"/>
      <TriangleCollisionModel simulated="0" moving="0"/>
    </Node>
  </Node>)";
}

std::size_t outputs_after_one_detection(const std::string& xml) {
  scene::LoadedScene s = test::load(xml);
  if (!s.root) return 0;
  s.root->collision_pipeline->collide(0.01);
  std::size_t n = 0;
  for (const PairOutputs& p : test::get<BVHNarrowPhase>(*s.root, "narrow")->outputs()) n += p.outputs.size();
  return n;
}

// LocalMinDistance keeps the contacts a triangle's front side allows: a point
// 0.1 in front of the floor is reported, 0.1 behind it is not (MinProximity
// reports both).
TEST(CollisionPipeline, LocalMinDistanceRejectsContactsBehindATriangle) {
  EXPECT_EQ(outputs_after_one_detection(floor_and_point_scene("LocalMinDistance", 0.1)), 1u);
  EXPECT_EQ(outputs_after_one_detection(floor_and_point_scene("LocalMinDistance", -0.1)), 0u);
  EXPECT_EQ(outputs_after_one_detection(floor_and_point_scene("MinProximityIntersection", -0.1)), 1u);
}

// Same rest height as with MinProximity: the penalty law does not depend on the method.
TEST(CollisionPipeline, PointRestsOnTheFloorWithLocalMinDistance) {
  scene::LoadedScene s = test::load(floor_and_point_scene("LocalMinDistance", 0.6));
  ASSERT_TRUE(s.root);
  for (int i = 0; i < 600; ++i) animate(*s.root);
  auto* x = test::get<MechanicalState>(*s.root->find_child_named("ball"), "x");
  EXPECT_NEAR(x->read(kPosition)[1], 0.2 - 9.81 / 500.0, 1e-4);
}

// A collision model takes the state of the nearest ancestor when its node has none (SOFA's context lookup).
TEST(CollisionPipeline, ModelUsesTheStateOfAnAncestor) {
  const std::string xml = R"(<Node name="root" dt="0.01">
    <CollisionPipeline/><BruteForceBroadPhase/><BVHNarrowPhase/><MinProximityIntersection/>
    <CollisionResponse response="PenalityContactForceField"/>
    <Node name="body"><MechanicalObject name="x" position="0 0 0  1 0 0"/>
      <Node name="surface"><PointCollisionModel name="points"/></Node></Node>
  </Node>)";
  scene::LoadedScene s = test::load(xml);
  ASSERT_TRUE(s.root);
  Node* surface = s.root->find_child_named("body")->find_child_named("surface");
  auto* points = test::get<PointCollisionModel>(*surface, "points");
  ASSERT_NE(points, nullptr);
  EXPECT_EQ(points->mstate(), test::get<MechanicalState>(*s.root->find_child_named("body"), "x"));
}

}  // namespace
}  // namespace sinew

namespace sinew {
namespace {

// DiscreteIntersection between a tetrahedron (simulated, contact points mapped
// barycentrically into it) and an obstacle point inside it. The point (normal
// n = +y from its triangle, computeNormals) is expelled along −n, through the
// face met that way, so the tetrahedron is pushed along +n.
TEST(CollisionPipeline, TetrahedronIsPushedOffAPointInsideIt) {
  const std::string xml = R"(<Node name="root" dt="0.01" gravity="0 0 0">
    <CollisionPipeline/><BruteForceBroadPhase/><BVHNarrowPhase name="narrow"/><DiscreteIntersection/>
    <CollisionResponse response="PenalityContactForceField"/>
    <Node name="tet">
      <EulerImplicitSolver/><CGLinearSolver iterations="50" tolerance="1e-12" threshold="1e-14"/>
      <MechanicalObject name="x" position="0 0 0  1 0 0  0 1 0  0 0 1"/>
      <MeshTopology tetrahedra="0 1 2 3"/>
      <UniformMass totalMass="1"/>
      <TetrahedronCollisionModel name="tets"/>
    </Node>
    <Node name="obstacle">
      <MechanicalObject position="0.1 0.1 0.2  5 0 0  5 0 1"/>
      <MeshTopology triangles="0 2 1"/>
      <PointCollisionModel computeNormals="1" simulated="0" moving="0"/>
    </Node>
  </Node>)";
  scene::LoadedScene s = test::load(xml);
  ASSERT_TRUE(s.root);
  animate(*s.root);
  std::size_t n = 0;
  for (const PairOutputs& p : test::get<BVHNarrowPhase>(*s.root, "narrow")->outputs()) n += p.outputs.size();
  EXPECT_EQ(n, 1u);
  Node* tet = s.root->find_child_named("tet");
  EXPECT_EQ(tet->interaction_force_fields.size(), 1u);  // in the body's node
  EXPECT_EQ(tet->children().size(), 1u);                // the mapped contact points
  for (int i = 0; i < 5; ++i) animate(*s.root);
  const auto& x = test::get<MechanicalState>(*tet, "x")->read(kPosition);
  EXPECT_GT(x[1], 0.0);  // vertex 0 (and the whole tetrahedron) moved along +y
  EXPECT_GT(x[1], 20 * std::fabs(x[0]));  // along the point's normal, (0.1, 4.9, 0) unnormalised
  EXPECT_EQ(x[2], 0.0);
}

}  // namespace
}  // namespace sinew

namespace sinew {
namespace {

// RuleBasedContactManager: the first rule matching a pair (by model name,
// group id or *) chooses the response; "nullptr" means no contact; $var$ is
// replaced by the variable's value; "default" alone is no rule at all.
std::size_t contacts_with_rules(const std::string& manager) {
  const std::string xml = R"(<Node name="root" dt="0.01" gravity="0 -9.81 0">
    <CollisionPipeline/><BruteForceBroadPhase/><BVHNarrowPhase/>
    <MinProximityIntersection alarmDistance="0.5" contactDistance="0.2"/>
    )" + manager + R"(
    <Node name="ball">
      <EulerImplicitSolver/><CGLinearSolver iterations="20" tolerance="1e-12" threshold="1e-14"/>
      <MechanicalObject position="0.5 0.1 0.2"/><UniformMass totalMass="1"/>
      <PointCollisionModel name="ballPoints" group="1"/>
    </Node>
    <Node name="floor">
      <MechanicalObject position="-1 0 -1  2 0 -1  2 0 2  -1 0 2"/>
      <MeshTopology triangles="0 2 1  0 3 2"/>
      <TriangleCollisionModel name="floorTriangles" group="2" simulated="0" moving="0"/>
    </Node>
  </Node>)";
  scene::LoadedScene s = test::load(xml);
  if (!s.root) return 99;
  animate(*s.root);
  return s.root->find_child_named("ball")->interaction_force_fields.size();
}

TEST(CollisionPipeline, RuleBasedContactManagerChoosesTheResponseByRule) {
  const char* base = R"(<RuleBasedContactManager response="PenalityContactForceField" )";
  EXPECT_EQ(contacts_with_rules(std::string(base) + R"(rules="default"/>)"), 1u);
  EXPECT_EQ(contacts_with_rules(std::string(base) + R"(rules="1 2 nullptr"/>)"), 0u);
  EXPECT_EQ(contacts_with_rules(std::string(base) + R"(rules="floorTriangles * nullptr"/>)"), 0u);
  EXPECT_EQ(contacts_with_rules(std::string(base) + R"(rules="3 * nullptr"/>)"), 1u);
  EXPECT_EQ(contacts_with_rules(
                R"(<RuleBasedContactManager response="nullptr" variables="kind" kind="PenalityContactForceField")"
                R"( rules="ballPoints floorTriangles $kind$"/>)"),
            1u);
}

}  // namespace
}  // namespace sinew

namespace sinew {
namespace {

// CCDTightInclusionIntersection: a point 0.5 above a floor moving at 100/s
// downwards crosses it within the step (dt 0.01): with Inertia the root finder
// sees it; the contact is stated at the start positions (value 0.5 − ms, the
// floor's normal, the point's projection on the floor); the proximity method
// (alarm 0.3) and CCD with no motion (None) see nothing at that distance.
std::vector<DetectionOutput> ccd_outputs(const std::string& method) {
  const std::string xml = R"(<Node name="root" dt="0.01" gravity="0 0 0">
    <CollisionPipeline/><BruteForceBroadPhase/><BVHNarrowPhase name="narrow"/>
    )" + method + R"(
    <CollisionResponse response="PenalityContactForceField"/>
    <Node name="ball">
      <EulerImplicitSolver/><CGLinearSolver iterations="20" tolerance="1e-12" threshold="1e-14"/>
      <MechanicalObject position="0.5 0.5 0.2" velocity="0 -100 0"/><UniformMass totalMass="1"/>
      <PointCollisionModel/>
    </Node>
    <Node name="floor">
      <MechanicalObject position="-1 0 -1  2 0 -1  2 0 2  -1 0 2"/>
      <MeshTopology triangles="0 2 1  0 3 2"/>
      <TriangleCollisionModel simulated="0" moving="0"/>
    </Node>
  </Node>)";
  scene::LoadedScene s = test::load(xml);
  std::vector<DetectionOutput> all;
  if (!s.root) return all;
  s.root->collision_pipeline->collide(0.01);
  for (const PairOutputs& p : test::get<BVHNarrowPhase>(*s.root, "narrow")->outputs())
    all.insert(all.end(), p.outputs.begin(), p.outputs.end());
  return all;
}

TEST(CollisionPipeline, ContinuousDetectionSeesAPointCrossingATriangleWithinTheStep) {
  const auto hit = ccd_outputs(
      R"(<CCDTightInclusionIntersection continuousCollisionType="Inertia" alarmDistance="0" contactDistance="0.001"/>)");
  ASSERT_EQ(hit.size(), 1u);
  EXPECT_TRUE(test::vec_near(hit[0].normal, Vec3(0, 1, 0), 1e-12));
  EXPECT_TRUE(test::vec_near(hit[0].point1, Vec3(0.5, 0, 0.2), 1e-9));
  EXPECT_TRUE(test::vec_near(hit[0].point2, Vec3(0.5, 0.5, 0.2), 1e-12));
  EXPECT_NEAR(hit[0].value, 0.5 - 0.001, 1e-9);
  EXPECT_TRUE(ccd_outputs(R"(<CCDTightInclusionIntersection continuousCollisionType="None" contactDistance="0.001"/>)")
                  .empty());
  EXPECT_TRUE(ccd_outputs(R"(<MinProximityIntersection alarmDistance="0.3" contactDistance="0.2"/>)").empty());
}

TEST(CollisionPipeline, ContinuousDetectionRefusesAnUnknownType) {
  test::TempDir dir;
  const test::Outcome o = test::run_xml(dir, R"(<Node name="root">
    <CCDTightInclusionIntersection continuousCollisionType="Sometimes"/></Node>)", 1);
  EXPECT_TRUE(test::any_contains_all(o.errors, {"continuousCollisionType", "Sometimes"})) << o.all();
}

}  // namespace
}  // namespace sinew

namespace sinew {
namespace {

// ParallelBVHNarrowPhase: one task per model pair, outputs identical (values
// and order) to the sequential narrow phase, for each intersection method.
TEST(CollisionPipeline, ParallelNarrowPhaseGivesTheSequentialOutputs) {
  std::mt19937 rng(11);
  std::string bodies;
  for (int b = 0; b < 6; ++b)
    bodies += "<Node name=\"b" + std::to_string(b) + R"("><MechanicalObject position=")" + points_text(rng, 40, 0, 2) +
              R"("/><PointCollisionModel/><SphereCollisionModel radius="0.05"/></Node>)";
  auto outputs = [&](const char* narrow, const char* method) {
    const std::string xml = std::string(R"(<Node name="root" dt="0.01">
      <CollisionPipeline depth="4"/><BruteForceBroadPhase/><)") + narrow + R"( name="narrow"/>
      <)" + method + R"( alarmDistance="0.2" contactDistance="0.05"/>
      <CollisionResponse response="PenalityContactForceField"/>)" + bodies + "</Node>";
    scene::LoadedScene s = test::load(xml);
    std::vector<DetectionOutput> all;
    if (!s.root) return all;
    s.root->collision_pipeline->collide(0.01);
    for (const PairOutputs& p : test::get<BVHNarrowPhase>(*s.root, "narrow")->outputs())
      all.insert(all.end(), p.outputs.begin(), p.outputs.end());
    return all;
  };
  for (const char* method : {"MinProximityIntersection", "NewProximityIntersection", "LocalMinDistance"}) {
    const auto seq = outputs("BVHNarrowPhase", method), par = outputs("ParallelBVHNarrowPhase", method);
    ASSERT_GT(seq.size(), 50u) << method;
    ASSERT_EQ(seq.size(), par.size()) << method;
    for (std::size_t i = 0; i < seq.size(); ++i) {
      EXPECT_EQ(seq[i].elem1, par[i].elem1);
      EXPECT_EQ(seq[i].elem2, par[i].elem2);
      EXPECT_EQ(seq[i].id, par[i].id);
      EXPECT_EQ(seq[i].value, par[i].value);
      EXPECT_EQ(seq[i].normal, par[i].normal);
    }
  }
}

}  // namespace
}  // namespace sinew

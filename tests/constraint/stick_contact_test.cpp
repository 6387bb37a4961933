// StickContactConstraint: a falling point glued to a static triangle where
// it came within the alarm distance, and kept glued (keepAlive) after the
// detection stops reporting the pair.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/parse.h"
#include "core/simulation.h"
#include "test_scene.h"

namespace sinew {
namespace {

// `params`: the responseParams of the contact manager.
std::string falling_points(const std::string& params) {
  return R"(<Node name="root" dt="0.01" gravity="0 -9.81 0">
    <FreeMotionAnimationLoop/>
    <BlockGaussSeidelConstraintSolver tolerance="1e-10" maxIterations="100"/>
    <CollisionPipeline/>
    <BruteForceBroadPhase/>
    <BVHNarrowPhase/>
    <MinProximityIntersection alarmDistance="0.2" contactDistance="0.05"/>
    <CollisionResponse response="StickContactConstraint" responseParams=")" +
         params + R"("/>
    <Node name="ground">
      <MechanicalObject name="g" position="-5 0 -5  5 0 -5  0 0 5"/>
      <MeshTopology triangles="0 2 1"/>
      <TriangleCollisionModel simulated="0" moving="0"/>
    </Node>
    <Node name="ball">
      <EulerImplicitSolver/>
      <CGLinearSolver iterations="25" tolerance="1e-12" threshold="1e-12"/>
      <MechanicalObject name="b" position="0 0.5 0  1 0.5 0"/>
      <UniformMass totalMass="1"/>
      <UncoupledConstraintCorrection defaultCompliance="1"/>
      <PointCollisionModel name="points"/>
    </Node>
  </Node>)";
}

struct StickRun {
  double y_glued = 0;    // height where the points stopped
  double y_final = 0;    // height at the end
  int stick_pairs = -1;  // pairs of the stick constraint at the end (-1: none attached)
};

// 40 steps falling and glued, then the points leave the detection (inactive
// model) and 40 more steps run.
StickRun run(const std::string& params) {
  auto s = test::load(falling_points(params));
  Node* ball = s.root->find_child_named("ball");
  auto* b = test::get<MechanicalState>(*ball, "b");
  StickRun r;
  for (int i = 0; i < 40; ++i) animate(*s.root);
  r.y_glued = b->read(kPosition)[1];
  test::get<Component>(*ball, "points")->find_field("active")->read("0");
  for (int i = 0; i < 40; ++i) animate(*s.root);
  r.y_final = b->read(kPosition)[1];
  std::vector<LagrangianConstraint*> all;
  s.root->collect_down(all);
  for (LagrangianConstraint* c : all)
    if (c->class_name() == "BilateralLagrangianConstraint")
      r.stick_pairs = static_cast<int>(parse::tokens(c->find_field("first_point")->text()).size());
  return r;
}

TEST(StickContactConstraint, GluesThePointsWhereTheyCameWithinTheAlarmDistance) {
  const StickRun r = run("");
  // Detected below 0.2 (alarm distance), then held there: no fall, no bounce.
  EXPECT_LT(r.y_glued, 0.2);
  EXPECT_GT(r.y_glued, 0.1);
  // keepAlive (default): still glued once the detection no longer reports the pair.
  EXPECT_NEAR(r.y_final, r.y_glued, 1e-9);
  EXPECT_EQ(r.stick_pairs, 2);  // one pair per point
}

TEST(StickContactConstraint, WithoutKeepAliveTheGlueGoesWithTheContact) {
  const StickRun r = run("keepAlive=0");
  EXPECT_LT(r.y_glued, 0.2);
  EXPECT_GT(r.y_glued, 0.1);
  EXPECT_LT(r.y_final, r.y_glued - 0.5);  // fell once the pair left the detection
  EXPECT_EQ(r.stick_pairs, -1);
}

}  // namespace
}  // namespace sinew

// StickContactForceField response (SOFA's BarycentricStickContact): a
// VectorSpringForceField between the contact points, at rest at their offset
// of the detection, stiffness and damping the sums of the models'; with
// keepAlive the springs outlive the collision and pull the bodies back.
#include <gtest/gtest.h>

#include <algorithm>

#include "badinput_helpers.h"
#include "collision/contact_manager.h"
#include "collision/response/contact.h"
#include "forcefield/spring/vector_spring_force_field.h"
#include "state/mechanical_object.h"
#include "test_scene.h"

namespace sinew {
namespace stick_contact_ff_test {

// A point leaving a fixed point at 2 units/s, within the alarm distance at the start.
std::string scene(const std::string& params) {
  return R"(<Node name="root" dt="0.01" gravity="0 0 0"><DefaultAnimationLoop/>
      <CollisionPipeline/><BruteForceBroadPhase/><BVHNarrowPhase/>
      <MinProximityIntersection alarmDistance="1" contactDistance="0.5"/>
      <CollisionResponse name="response" response="StickContactForceField" responseParams=")" +
         params + R"("/>
      <Node name="body"><EulerImplicitSolver rayleighStiffness="0" rayleighMass="0"/>
        <CGLinearSolver iterations="100" tolerance="1e-14" threshold="1e-16"/>
        <MechanicalObject name="x" position="0 0.6 0" velocity="0 2 0"/><UniformMass totalMass="1"/>
        <PointCollisionModel name="p" contactStiffness="7" contactFriction="0.5"/></Node>
      <Node name="floor"><MechanicalObject position="0 0 0"/>
        <PointCollisionModel name="q" simulated="0" moving="0" contactStiffness="3" contactFriction="0.25"/></Node>
    </Node>)";
}

TEST(StickContactForceField, SpringAtTheDetectedOffsetWithSummedStiffnessAndDamping) {
  auto s = test::load(scene(""));
  ASSERT_TRUE(s.root);
  animate(*s.root);
  auto* response = test::get<CollisionResponse>(*s.root, "response");
  ASSERT_NE(response, nullptr);
  ASSERT_EQ(response->contacts().size(), 1u);
  auto* ff = dynamic_cast<VectorSpringForceField*>(response->contacts()[0]->response());
  ASSERT_NE(ff, nullptr);
  ASSERT_EQ(ff->spring_list().size(), 1u);
  const auto& spring = ff->spring_list()[0];
  EXPECT_EQ(spring.ks, 10.0);   // 7 + 3
  EXPECT_EQ(spring.kd, 0.75);   // 0.5 + 0.25
  EXPECT_EQ(spring.rest[0], 0.0);
  // Point on model 2 − point on model 1 at detection (the pair is (floor, body) or (body, floor)).
  const bool body_first = response->contacts()[0]->model1().name.value() == "p";
  EXPECT_DOUBLE_EQ(spring.rest[1], body_first ? -0.6 : 0.6);
  EXPECT_EQ(ff->stiffness.value(), 10.0);
}

// Kept alive, the spring frozen at the last detection pulls the point back
// once it leaves the alarm distance; without keepAlive it flies on.
TEST(StickContactForceField, KeepAliveHoldsTheBodiesTogetherAfterSeparation) {
  for (bool keep : {true, false}) {
    auto s = test::load(scene(keep ? "" : "keepAlive=0"));
    ASSERT_TRUE(s.root);
    auto* x = test::get<MechanicalObject>(*s.root->find_child_named("body"), "x");
    auto* response = test::get<CollisionResponse>(*s.root, "response");
    ASSERT_TRUE(x && response);
    double top = 0;
    for (int i = 0; i < 300; ++i) {
      animate(*s.root);
      top = std::max(top, x->read(kPosition)[1]);
    }
    if (keep) {
      EXPECT_LT(top, 1.6) << "the spring of the last detection holds the point near the alarm distance";
      EXPECT_EQ(response->contacts().size(), 1u);
    } else {
      EXPECT_GT(x->read(kPosition)[1], 3.0) << "free flight once out of the alarm distance";
      EXPECT_TRUE(response->contacts().empty());
    }
  }
}

TEST(StickContactForceField, UnknownResponseParameterIsReported) {
  test::TempDir dir;
  const test::Outcome o = test::run_xml(dir, scene("sticky=1"), 3);
  EXPECT_TRUE(test::any_contains(o.warnings, "StickContactForceField has no parameter 'sticky'")) << o.all();
}

}  // namespace stick_contact_ff_test
}  // namespace sinew

// MultiStepAnimationLoop: collisionSteps × integrationSteps substeps per step,
// and SOFA's clock, which advances by integrationSteps substeps only.
#include <gtest/gtest.h>

#include "core/simulation.h"
#include "state/mechanical_object.h"
#include "test_scene.h"

namespace sinew {
namespace {

TEST(MultiStepAnimationLoop, RunsEverySubstepAndKeepsSofasClock) {
  scene::LoadedScene s = test::load(R"(<Node name="root" dt="0.6" gravity="0 -10 0">
    <MultiStepAnimationLoop collisionSteps="2" integrationSteps="3"/>
    <Node name="body">
      <EulerImplicitSolver rayleighMass="0" rayleighStiffness="0"/>
      <CGLinearSolver iterations="10" tolerance="1e-16" threshold="1e-16"/>
      <MechanicalObject name="p" position="0 0 0"/>
      <UniformMass totalMass="1"/>
    </Node>
  </Node>)");
  ASSERT_TRUE(s.root);
  animate(*s.root);
  auto* p = test::get<MechanicalObject>(*s.root->find_child_named("body"), "p");
  // Six substeps of 0.1 s of implicit Euler under gravity: v = −6, x = −0.1·(1+2+…+6).
  EXPECT_NEAR(p->read(kVelocity)[1], -6.0, 1e-12);
  EXPECT_NEAR(p->read(kPosition)[1], -2.1, 1e-12);
  EXPECT_NEAR(s.root->time.value(), 0.3, 1e-15);
}

}  // namespace
}  // namespace sinew

// Interaction force fields applied explicitly (outside any solver's subtree)
// write into externalForce, which is empty between steps: the stage sizes it
// first. SOFA's Tutorials/Topologies/TopologyTriangle2EdgeTopologicalMapping.scn
// (its solver macro renamed into a child node, so its springs are explicit)
// wrote past the vector (found by the whole-scene fuzzer under ASan).
#include <gtest/gtest.h>

#include "badinput_helpers.h"
#include "state/mechanical_object.h"
#include "test_scene.h"

namespace sinew {
namespace interaction_external_force_test {

TEST(InteractionForces, ExplicitSpringsSizeExternalForceFirst) {
  auto s = test::load(R"(<Node name="root" dt="0.01" gravity="0 0 0"><DefaultAnimationLoop/>
      <Node name="solved"><EulerImplicitSolver/><CGLinearSolver iterations="10" tolerance="1e-9" threshold="1e-12"/>
        <MechanicalObject position="5 5 5"/><UniformMass totalMass="1"/></Node>
      <Node name="free"><MechanicalObject name="x" position="0 0 0  2 0 0"/>
        <SpringForceField name="s" spring="0 1 10 0 1"/></Node>
    </Node>)");
  ASSERT_TRUE(s.root);
  auto* x = test::get<MechanicalObject>(*s.root->find_child_named("free"), "x");
  ASSERT_NE(x, nullptr);
  auto* spring = test::get<ForceField>(*s.root->find_child_named("free"), "s");
  ASSERT_NE(spring, nullptr);
  animate(*s.root);
  EXPECT_TRUE(x->read(kExternalForce).empty());  // emptied at the end of the step
  animate(*s.root);  // without the sizing: a write through the empty vector's null data
  // Stretched by 1 with ks = 10: the spring was evaluated (½·ks·1²)...
  ASSERT_TRUE(spring->potential_energy().has_value());
  EXPECT_DOUBLE_EQ(*spring->potential_energy(), 5.0);
  // ... into externalForce, emptied again at the end of the step.
  EXPECT_TRUE(x->read(kExternalForce).empty());
}

TEST(InteractionForces, SofaTriangle2EdgeTutorialRuns) {
  const test::Outcome o = test::run_sofa_example("Tutorials/Topologies/TopologyTriangle2EdgeTopologicalMapping.scn", 5);
  if (!o.loaded) GTEST_SKIP() << "SOFA data absent";
  ASSERT_TRUE(o.init_ok) << o.all();
  EXPECT_EQ(o.steps, 5);
  EXPECT_TRUE(o.finite);
}

}  // namespace interaction_external_force_test
}  // namespace sinew

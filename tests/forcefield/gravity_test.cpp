// Gravity sets the gravity of its node and the subtree below; the rest of the
// scene keeps the root's.
#include <gtest/gtest.h>

#include "core/simulation.h"
#include "test_scene.h"

namespace sinew {
namespace {

TEST(Gravity, SetsTheGravityOfItsSubtree) {
  const std::string xml = R"(<Node name="root" dt="0.1" gravity="0 -10 0">
    <Node name="up">
      <Gravity gravity="0 10 0"/>
      <EulerExplicitSolver symplectic="1"/>
      <MechanicalObject name="x" position="0 0 0"/><UniformMass totalMass="2"/>
    </Node>
    <Node name="down">
      <EulerExplicitSolver symplectic="1"/>
      <MechanicalObject name="x" position="0 0 0"/><UniformMass totalMass="2"/>
    </Node>
  </Node>)";
  scene::LoadedScene s = test::load(xml);
  ASSERT_TRUE(s.root);
  animate(*s.root);
  // Symplectic Euler: v = g·dt, x = v·dt.
  EXPECT_DOUBLE_EQ(test::get<MechanicalState>(*s.root->find_child_named("up"), "x")->read(kVelocity)[1], 1.0);
  EXPECT_DOUBLE_EQ(test::get<MechanicalState>(*s.root->find_child_named("down"), "x")->read(kVelocity)[1], -1.0);
  EXPECT_DOUBLE_EQ(s.root->find_child_named("up")->gravity.value()[1], 10.0);
}

}  // namespace
}  // namespace sinew

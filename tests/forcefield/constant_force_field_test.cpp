// ConstantForceField: indices default to the topology's points and are checked against the
// state once the graph is initialised (a mapped state is sized by its mapping's init).
#include <gtest/gtest.h>

#include "forcefield/load/constant_force_field.h"
#include "test_scene.h"

namespace sinew {
namespace constant_force_test {

// SOFA's MatrixLinearSystem.scn pattern: the force field comes before the IdentityMapping that
// sizes its Rigid3d state (one default frame until then); the indices come from the parent's grid.
std::string frames(const std::string& cff) {
  return R"(<Node name="root" dt="0.02" gravity="0 -10 0"><DefaultAnimationLoop/>
    <EulerImplicitSolver rayleighStiffness="0" rayleighMass="0"/>
    <CGLinearSolver iterations="25" tolerance="1e-12" threshold="1e-12"/>
    <RegularGridTopology name="grid" nx="1" ny="1" nz="20" xmin="5" xmax="5" ymin="-1.5" ymax="1.5" zmin="0" zmax="19"/>
    <MechanicalObject template="Rigid3d" name="DOFs" position="@grid.position"/>
    <UniformMass totalMass="1"/>
    <FixedProjectiveConstraint indices="0"/>
    <Node name="intermediate">
      <MechanicalObject template="Rigid3d" name="DOFs"/>
      )" + cff + R"(
      <IdentityMapping input="@../DOFs" output="@DOFs"/>
    </Node></Node>)";
}

TEST(ConstantForceField, MappedStateSizedAfterItsInitTakesTheForceOnEveryFrame) {
  scene::LoadedScene s = test::load(frames(R"(<ConstantForceField name="cff" forces="0 0 0.0005 0 0 0"/>)"));
  Node* child = s.root->find_child_named("intermediate");
  ASSERT_NE(child, nullptr);
  auto* cff = test::get<ConstantForceField>(*child, "cff");
  ASSERT_NE(cff, nullptr);
  EXPECT_EQ(cff->state(), ComponentState::valid);
  EXPECT_EQ(cff->applied().size(), 20u * 6u);  // one force per frame of the parent grid
  animate(*s.root);
  auto* dofs = test::get<MechanicalState>(*s.root, "DOFs");
  const std::vector<double>& v = dofs->read(kVelocity);
  ASSERT_EQ(v.size(), 120u);
  // Frame 19 (mass 1/20): v = dt·(f/m + g), exact with a mass-only system.
  EXPECT_NEAR(v[19 * 6 + 2], 0.02 * 0.0005 * 20, 1e-15);
  EXPECT_NEAR(v[19 * 6 + 1], -0.2, 1e-14);
  EXPECT_EQ(v[2], 0.0);  // frame 0 is fixed
}

TEST(ConstantForceField, IndexBeyondTheInitialisedStateIsAnError) {
  auto s = test::build(frames(R"(<ConstantForceField name="cff" indices="3 25" forces="0 0 1 0 0 0"/>)"));
  init_root(*s.root);
  EXPECT_TRUE(test::any_contains(test::messages(s.root->diagnostics(), Severity::error),
                                 "index 1 (25) exceeds the state size 20"));
}

}  // namespace constant_force_test
}  // namespace sinew

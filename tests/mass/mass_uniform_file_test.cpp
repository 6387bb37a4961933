// UniformMass reads a Rigid3d mass file (.rigid, SOFA's loadRigidMass): the
// vertex mass and the inertia tensor (scaled by the mass in the mass matrix).
#include <gtest/gtest.h>

#include "core/matrix_sink.h"
#include "core/mechanical_ops.h"
#include "core/simulation.h"
#include "mass/uniform_mass.h"
#include "badinput_helpers.h"
#include "test_scene.h"

namespace sinew {
namespace {

TEST(UniformMass, ReadsARigidMassFile) {
  test::TempDir dir;
  dir.write("tool.rigid",
            "Xsp 3.0\nvertexMass 2.5\nvolm 0.1\n# a comment line\n"
            "inrt 1 0 0  0 2 0  0 0 3\ncntr 0 0 0\n");
  const std::string scene = dir.write("scene.scn", R"(<Node name="root">
    <MechanicalObject template="Rigid3d" position="0 0 0 0 0 0 1"/>
    <UniformMass name="mass" filename="tool.rigid"/>
  </Node>)");
  const test::Outcome o = test::run_scene_file(scene, 0);
  EXPECT_TRUE(o.init_ok) << o.all();

  scene::LoadedScene s = test::load(R"(<Node name="root">
    <MechanicalObject template="Rigid3d" position="0 0 0 0 0 0 1"/>
    <UniformMass name="mass" filename=")" + dir.dir() + R"(/tool.rigid"/></Node>)");
  ASSERT_TRUE(s.root);
  auto* m = test::get<UniformMass>(*s.root, "mass");
  ASSERT_NE(m, nullptr);
  EXPECT_DOUBLE_EQ(m->total(), 2.5);
  MatrixSink M;
  ASSERT_TRUE(m->build_mass(M));
  std::vector<double> diag(6, 0.0);
  for (const auto& e : M.entries())
    if (e.row == e.col) diag[e.row] = e.value;
  EXPECT_EQ(diag, (std::vector<double>{2.5, 2.5, 2.5, 2.5, 5.0, 7.5}));  // m, m, m, m·I00, m·I11, m·I22
}

TEST(UniformMass, UnreadableMassFileIsAnError) {
  test::TempDir dir;
  dir.write("bad.rigid", "Xsp 3.0\ninrt 1 0 0 0 x\n");
  const test::Outcome o = test::run_scene_file(dir.write("scene.scn", R"(<Node name="root">
    <MechanicalObject template="Rigid3d" position="0 0 0 0 0 0 1"/>
    <UniformMass filename="bad.rigid"/></Node>)"), 1);
  EXPECT_TRUE(test::any_contains_all(o.errors, {"bad.rigid", "inrt"})) << o.all();
}

}  // namespace
}  // namespace sinew

namespace sinew {
namespace {

// Rigid2d: vertexMass is "mass volume inertia"; the rotation's mass is inertia·mass.
TEST(UniformMass, Rigid2dUsesTheScalarInertia) {
  scene::LoadedScene s = test::load(R"(<Node name="root" gravity="0 -10 0">
    <MechanicalObject name="x" template="Rigid2" position="0 0 0  1 2 0.5"/>
    <UniformMass name="mass" vertexMass="2 1 0.5"/>
  </Node>)");
  ASSERT_TRUE(s.root);
  auto* m = test::get<UniformMass>(*s.root, "mass");
  ASSERT_EQ(m->state(), ComponentState::valid);
  MechanicalState& st = *s.root->mechanical_state;
  const int dx = MechanicalOps::alloc_vec(), res = MechanicalOps::alloc_vec();
  st.write(dx) = {1, 1, 1, 1, 1, 1};
  st.write(res).assign(6, 0.0);
  m->add_mdx(MechParams{}, res, dx, 1.0);
  EXPECT_DOUBLE_EQ(st.read(res)[0], 2.0);
  EXPECT_DOUBLE_EQ(st.read(res)[2], 1.0);  // 0.5 · 2
  st.write(kForce).assign(6, 0.0);
  m->add_force(MechParams{});
  EXPECT_DOUBLE_EQ(st.read(kForce)[4], -20.0);  // gravity on the centre only
  EXPECT_DOUBLE_EQ(st.read(kForce)[5], 0.0);
}

}  // namespace
}  // namespace sinew

// MatrixProjectionMethod: the assembled system projects a mapped block as Jᵀ·K·J whether or
// not one is given; areJacobiansConstant keeps the Jacobians of the first assembly.
#include <gtest/gtest.h>

#include "solver/system/matrix_projection_method.h"
#include "test_scene.h"

namespace sinew {
namespace projection_method_test {

// A rigid frame hanging by two mapped points held by rest-shape springs, under gravity and a
// torque, solved with an assembled system (the springs' K is on the mapped state).
std::string frame(const std::string& mapping, const std::string& projection) {
  return R"(<Node name="root" gravity="0 -9.81 0" dt="0.01"><DefaultAnimationLoop/>
    <EulerImplicitSolver rayleighStiffness="0" rayleighMass="0"/>
    <SparseLDLSolver template="CompressedRowSparseMatrixd"/>
    <Node name="body">
      <MechanicalObject template="Rigid3d" name="frame" position="0 0 0 0 0 0 1"/>
      <UniformMass vertexMass="1 1 [0.1 0 0,0 0.1 0,0 0 0.1]"/>
      <ConstantForceField forces="0 0 0 0.5 1 2"/>
      <Node name="pts">
        <MechanicalObject name="p" position="1 0 0  0 1 0"/>
        <RestShapeSpringsForceField stiffness="500"/>
        )" + mapping + R"(
      </Node>
    </Node>)" + projection + "</Node>";
}

std::vector<double> run(const std::string& xml, int steps) {
  scene::LoadedScene s = test::load(xml);
  for (int i = 0; i < steps; ++i) animate(*s.root);
  return s.root->find_child_named("body")->get_mechanical_state()->read(kPosition);
}

const char* kRigid = R"(<RigidMapping input="@../frame" output="@p"/>)";
const char* kPair = R"(<MatrixProjectionMethod name="mpm" mechanicalStates="@body/pts/p @body/pts/p" areJacobiansConstant="%"/>)";

std::string pair(bool constant) {
  std::string p = kPair;
  p.replace(p.find('%'), 1, constant ? "true" : "false");
  return p;
}

TEST(MatrixProjectionMethod, DefaultProjectionIsTheAssemblersOwn) {
  // Without areJacobiansConstant the component changes nothing: bit for bit.
  EXPECT_EQ(run(frame(kRigid, pair(false)), 30), run(frame(kRigid, ""), 30));
}

TEST(MatrixProjectionMethod, ConstantJacobiansAreThoseOfTheFirstAssembly) {
  // The first step assembles with the current Jacobians either way.
  EXPECT_EQ(run(frame(kRigid, pair(true)), 1), run(frame(kRigid, ""), 1));
  // Then the frame has turned and the RigidMapping's J changed: the kept one gives another
  // tangent, so another implicit step (SOFA's behaviour when the flag is set wrongly).
  const auto frozen = run(frame(kRigid, pair(true)), 30);
  const auto fresh = run(frame(kRigid, ""), 30);
  double diff = 0;
  for (std::size_t i = 0; i < frozen.size(); ++i) diff = std::max(diff, std::abs(frozen[i] - fresh[i]));
  EXPECT_GT(diff, 1e-9);
  EXPECT_LT(diff, 1e-1);  // the same motion, not a blow-up
}

TEST(MatrixProjectionMethod, APairNeedsTwoStates) {
  auto s = test::build(frame(kRigid, R"(<MatrixProjectionMethod name="mpm" mechanicalStates="@body/pts/p"/>)"));
  init_root(*s.root);
  EXPECT_TRUE(test::any_contains(test::messages(s.root->diagnostics(), Severity::error), "names 1 state(s)"));
}

}  // namespace projection_method_test
}  // namespace sinew

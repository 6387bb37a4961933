// Built constraint solvers agree on well-posed bilateral problems (where the
// block laws are plain linear solves).
#include <gtest/gtest.h>

#include <string>

#include "core/simulation.h"
#include "state/mechanical_object.h"
#include "test_scene.h"

namespace sinew {
namespace {

// A chain of three points hanging from an anchor by bilateral constraints,
// each point also pulled sideways by its own rest vector.
std::string chain(const std::string& solver) {
  return R"(<Node name="root" dt="0.01" gravity="0 -9.81 0">
    <FreeMotionAnimationLoop/>)" +
         solver + R"(
    <Node name="anchor"><MechanicalObject name="a" position="0 0 0"/></Node>
    <Node name="body">
      <EulerImplicitSolver/><CGLinearSolver iterations="25" tolerance="1e-14" threshold="1e-14"/>
      <MechanicalObject name="p" position="0 -1 0  0 -2 0  0 -3 0"/>
      <UniformMass vertexMass="1"/>
      <UncoupledConstraintCorrection compliance="1"/>
    </Node>
    <BilateralLagrangianConstraint object1="@anchor/a" object2="@body/p" first_point="0" second_point="0" rest_vector="0.1 -1 0"/>
    <BilateralLagrangianConstraint object1="@body/p" object2="@body/p" first_point="0 1" second_point="1 2" rest_vector="0 -1 0.2  0 -1 0"/>
  </Node>)";
}

std::vector<double> run(const std::string& solver, int steps) {
  scene::LoadedScene s = test::load(chain(solver));
  if (!s.root) return {};
  for (int i = 0; i < steps; ++i) animate(*s.root);
  return test::get<MechanicalObject>(*s.root->find_child_named("body"), "p")->read(kPosition);
}

TEST(BuiltConstraintSolvers, ConjugateResidualMatchesBlockGaussSeidelOnBilateralChains) {
  const auto bgs = run(R"(<BlockGaussSeidelConstraintSolver tolerance="1e-14" maxIterations="10000"/>)", 30);
  const auto pcr = run(R"(<PreconditionedConjugateResidual tolerance="1e-14" maxIterations="100"/>)", 30);
  ASSERT_EQ(bgs.size(), 9u);
  ASSERT_EQ(pcr.size(), 9u);
  for (std::size_t k = 0; k < bgs.size(); ++k) EXPECT_NEAR(pcr[k], bgs[k], 1e-9) << k;
  // The constraints hold: x2 − x1 = rest at the end of each step.
  EXPECT_NEAR(bgs[3] - bgs[0], 0.0, 1e-9);
  EXPECT_NEAR(bgs[4] - bgs[1], -1.0, 1e-9);
  EXPECT_NEAR(bgs[5] - bgs[2], 0.2, 1e-9);
}

}  // namespace
}  // namespace sinew

// The constraint models make no heap allocation once warm: their three calls
// of a step (rows, violation, blocks) on the states' reused Jacobians.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#define SINEW_ALLOC_COUNTER_DECLARE_ONLY  // the counter is defined in constraint_allocation_test.cpp
#include "alloc_counter.h"
#include "constraint/solver/resolution.h"
#include "core/constraint_problem.h"
#include "core/simulation.h"
#include "test_scene.h"

namespace sinew {
namespace {

const char* kScene = R"(<Node name="root" dt="0.01" gravity="0 -9.81 0">
  <FreeMotionAnimationLoop/>
  <BlockGaussSeidelConstraintSolver tolerance="1e-10" maxIterations="50"/>
  <Node name="points">
    <EulerImplicitSolver/>
    <CGLinearSolver iterations="20" tolerance="1e-12" threshold="1e-12"/>
    <MechanicalObject name="p" position="0 0 0  1 0 0  2 0 0  3 0 0"/>
    <UniformMass totalMass="1"/>
    <UncoupledConstraintCorrection defaultCompliance="1"/>
    <FixedLagrangianConstraint indices="0"/>
    <Node name="lengths">
      <MechanicalObject name="ext" template="Vec1d"/>
      <MeshTopology name="edges" edges="0 1  1 2"/>
      <DistanceMapping topology="@edges"/>
      <UniformLagrangianConstraint template="Vec1d" iterative="false"/>
      <StopperLagrangianConstraint index="1" min="-0.1" max="0.1"/>
      <FixedLagrangianConstraint template="Vec1d" indices="0"/>
    </Node>
  </Node>
  <Node name="frames">
    <EulerImplicitSolver/>
    <CGLinearSolver iterations="20" tolerance="1e-12" threshold="1e-12"/>
    <MechanicalObject name="f" template="Rigid3d" position="0 -1 0 0 0 0 1  1 -1 0 0 0 0 1"/>
    <UniformMass totalMass="1"/>
    <UncoupledConstraintCorrection/>
    <FixedLagrangianConstraint indices="0"/>
  </Node>
  <BilateralLagrangianConstraint template="Rigid3d" object1="@frames/f" object2="@frames/f"
      first_point="0" second_point="1" keepOrientationDifference="true"/>
  <SlidingLagrangianConstraint object1="@points/p" object2="@points/p" sliding_point="3" axis_1="1" axis_2="2"/>
</Node>)";

TEST(ConstraintModelsAllocation, WarmCallsDoNotAllocate) {
  if (!SINEW_COUNT_ALLOCATIONS) GTEST_SKIP() << "allocations are not counted in sanitizer builds";
  auto s = test::load(kScene);
  ASSERT_EQ(test::messages(s.root->diagnostics(), Severity::error).size(), 0u);
  for (int i = 0; i < 3; ++i) animate(*s.root);  // warm: every model has run its step

  std::vector<LagrangianConstraint*> constraints;
  s.root->collect_down(constraints);
  std::vector<MechanicalState*> states;
  s.root->collect_down(states);
  ASSERT_EQ(constraints.size(), 7u);
  std::vector<double> dfree(64, 0.0);
  std::vector<ConstraintBlock> blocks;
  blocks.reserve(64);
  ConstraintParams p;
  p.dt = 0.01;
  // Allocations inside the models' calls only: clearing and compressing the
  // Jacobians is the framework's (ConstraintMatrix::compress sorts unsorted
  // entries with std::stable_sort, which takes a temporary buffer).
  long in_models = 0;
  auto counted = [&](auto&& call) {
    const long before = test::g_allocations.load();
    call();
    in_models += test::g_allocations.load() - before;
  };
  auto one_pass = [&] {
    for (MechanicalState* st : states) st->constraint_jacobian().clear(st->info().deriv_width);
    int row = 0;
    counted([&] {
      for (LagrangianConstraint* c : constraints) c->build_constraint_matrix(p, row);
    });
    for (MechanicalState* st : states) st->constraint_jacobian().compress();
    blocks.clear();
    counted([&] {
      for (LagrangianConstraint* c : constraints) c->constraint_violation(p, dfree);
      for (LagrangianConstraint* c : constraints) c->constraint_resolutions(p, blocks);
    });
    return row;
  };
  const int rows = one_pass();
  EXPECT_GT(rows, 20);
  ASSERT_LE(rows, 64);
  in_models = 0;
  for (int i = 0; i < 5; ++i) one_pass();
  EXPECT_EQ(in_models, 0);
}

}  // namespace
}  // namespace sinew

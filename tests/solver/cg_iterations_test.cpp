// CG with absurd iteration counts: warned after init; a user interruption
// stops the CG loop and the step finishes.
#include <gtest/gtest.h>

#include <chrono>
#include <string>

#include "badinput_helpers.h"
#include "core/interrupt.h"

using namespace sinew;
using namespace sinew::test;

namespace {

class CGIterations : public ::testing::Test {
 protected:
  TempDir dir;
  void TearDown() override { clear_interrupt(); }
};

}  // namespace

TEST_F(CGIterations, CGWithFarTooManyIterationsIsWarned) {
  const Outcome o = run_xml(dir, R"(<Node name="root" dt="0.01">
  <DefaultAnimationLoop/>
  <EulerImplicitSolver/>
  <CGLinearSolver name="cg" iterations="2000000000" tolerance="1e-9" threshold="1e-12"/>
  <MechanicalObject name="dofs" position="0 0 0 1 0 0 2 0 0"/>
  <UniformMass totalMass="1"/>
</Node>)", 1);
  EXPECT_TRUE(any_contains_all(o.warnings, {"'cg' (CGLinearSolver)", "iterations = 2000000000",
                                            "far more than the system size (9 unknowns)"}))
      << o.all();
}

TEST_F(CGIterations, InterruptStopsTheCGLoopAndTheStepFinishes) {
  request_interrupt();  // as Ctrl-C in `sinew run`
  const auto t0 = std::chrono::steady_clock::now();
  const Outcome o = run_xml(dir, R"(<Node name="root" dt="0.01">
  <DefaultAnimationLoop/>
  <EulerImplicitSolver/>
  <CGLinearSolver name="cg" iterations="2000000000" tolerance="0" threshold="0"/>
  <MechanicalObject name="dofs" position="0 0 0 1 0 0 2 0 0"/>
  <UniformMass totalMass="1"/>
  <RestShapeSpringsForceField stiffness="100"/>
</Node>)", 1);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 30.0);
  EXPECT_EQ(o.steps, 1) << o.all();
  EXPECT_TRUE(any_contains_all(o.warnings, {"'cg' (CGLinearSolver)", "interrupted after 0 CG iterations"})) << o.all();
}

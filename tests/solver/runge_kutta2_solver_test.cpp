// RungeKutta2Solver: SOFA's midpoint method.
#include <gtest/gtest.h>

#include <cmath>

#include "oscillator.h"

namespace sinew {
namespace {

TEST(RungeKutta2Solver, FirstStepByHand) {
  // h = 0.1, x0 = 1, v0 = 0, a = −x: a0 = −1; X = 1, V = −0.05; a1 = −1;
  // x1 = x0 + h·V = 0.995, v1 = v0 + h·a1 = −0.1.
  test::Oscillator o("<RungeKutta2Solver/>", 0.1);
  o.step();
  EXPECT_DOUBLE_EQ(o.x(), 0.995);
  EXPECT_DOUBLE_EQ(o.v(), -0.1);
  // Second step: a0 = −0.995, X = 0.995 − 0.005 = 0.99, V = −0.1 − 0.04975 = −0.14975, a1 = −0.99.
  o.step();
  EXPECT_NEAR(o.x(), 0.995 - 0.014975, 1e-15);
  EXPECT_NEAR(o.v(), -0.1 - 0.099, 1e-15);
}

TEST(RungeKutta2Solver, SecondOrderConvergence) {
  const double e1 = test::oscillator_error("<RungeKutta2Solver/>", 0.01);
  const double e2 = test::oscillator_error("<RungeKutta2Solver/>", 0.005);
  EXPECT_LT(e1, 1e-4);
  EXPECT_NEAR(e1 / e2, 4.0, 0.2);  // 2^order
}

TEST(RungeKutta2Solver, FreeFallIsExact) {
  // Constant acceleration: the midpoint rule is exact, x = x0 + g t²/2.
  auto s = test::load(
      "<Node dt=\"0.1\" gravity=\"0 -10 0\"><DefaultAnimationLoop/><RungeKutta2Solver/>"
      "<MechanicalObject name=\"dofs\" position=\"1 2 3\"/><UniformMass totalMass=\"2\"/></Node>");
  for (int i = 0; i < 10; ++i) animate(*s.root);
  auto* mo = test::get<MechanicalObject>(*s.root, "dofs");
  EXPECT_NEAR(mo->read(kPosition)[1], 2.0 - 5.0, 1e-12);
  EXPECT_NEAR(mo->read(kVelocity)[1], -10.0, 1e-12);
}

}  // namespace
}  // namespace sinew

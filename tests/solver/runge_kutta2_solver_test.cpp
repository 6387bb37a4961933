// RungeKutta2Solver: SOFA's midpoint method.
#include <gtest/gtest.h>

#include <cmath>

#include "core/mechanical_ops.h"
#include "oscillator.h"
#include "state/mechanical_object.h"

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

namespace sinew {
namespace rk_rigid_test {

// Solvers' position temporaries of a rigid state are coordinates: 7 scalars
// per DoF and the identity rotation (a Rigid3d midpoint once overflowed a
// 6-scalar derivative vector: found by the whole-scene fuzzer on SOFA's
// rungekutta2_heterogeneousobjects.scn).
TEST(MechanicalObjectVectors, CoordinateTemporariesOfARigidStateHaveSevenScalarsPerDof) {
  auto s = test::load(
      "<Node dt=\"0.1\"><MechanicalObject name=\"dofs\" template=\"Rigid3d\" position=\"1 2 3 0 0 0 1  4 5 6 0 0 0 1\"/>"
      "</Node>");
  auto* mo = test::get<MechanicalObject>(*s.root, "dofs");
  ASSERT_NE(mo, nullptr);
  const auto& x = mo->read(MechanicalOps::alloc_coord_vec());
  ASSERT_EQ(x.size(), 14u);
  EXPECT_EQ(x[6], 1.0);
  EXPECT_EQ(x[13], 1.0);
  EXPECT_EQ(x[0], 0.0);
  EXPECT_EQ(mo->read(MechanicalOps::alloc_vec()).size(), 12u);
}

// A spinning rigid body in free fall: both Runge-Kutta methods are exact for
// a constant acceleration and a constant angular velocity (no torque).
TEST(RungeKuttaSolvers, RigidFreeFallAndSpinAreExact) {
  for (const char* solver : {"RungeKutta2Solver", "RungeKutta4Solver"}) {
    auto s = test::load(std::string("<Node dt=\"0.1\" gravity=\"0 -10 0\"><DefaultAnimationLoop/><") + solver +
                        "/><MechanicalObject name=\"dofs\" template=\"Rigid3d\" position=\"1 2 3 0 0 0 1\" "
                        "velocity=\"0 0 0 0 0 1\"/><UniformMass template=\"Rigid3d\" totalMass=\"2\"/></Node>");
    auto* mo = test::get<MechanicalObject>(*s.root, "dofs");
    ASSERT_NE(mo, nullptr) << solver;
    for (int i = 0; i < 10; ++i) animate(*s.root);
    const auto& x = mo->read(kPosition);
    ASSERT_EQ(x.size(), 7u);
    EXPECT_NEAR(x[1], 2.0 - 5.0, 1e-12) << solver;
    EXPECT_NEAR(x[5], std::sin(0.5), 1e-12) << solver;  // 1 rad about z
    EXPECT_NEAR(x[6], std::cos(0.5), 1e-12) << solver;
    EXPECT_NEAR(mo->read(kVelocity)[1], -10.0, 1e-12) << solver;
  }
}

}  // namespace rk_rigid_test
}  // namespace sinew

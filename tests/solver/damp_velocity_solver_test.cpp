// DampVelocitySolver: velocity decay and threshold, alone and after another solver.
#include <gtest/gtest.h>

#include <cmath>

#include "state/mechanical_object.h"
#include "test_scene.h"

namespace sinew {
namespace {

using test::get;

std::string two_particles(const std::string& solvers, const std::string& gravity = "0 0 0") {
  return "<Node dt=\"0.1\" gravity=\"" + gravity + "\"><DefaultAnimationLoop/>" + solvers +
         "<MechanicalObject name=\"dofs\" position=\"0 0 0  1 0 0\" velocity=\"1 2 2  0.003 0.004 0\"/>"
         "<UniformMass totalMass=\"2\"/></Node>";
}

TEST(DampVelocitySolver, DefaultRateScalesTheVelocities) {
  auto s = test::load(two_particles("<DampVelocitySolver/>"));
  auto* mo = get<MechanicalObject>(*s.root, "dofs");
  animate(*s.root);
  const double f = std::exp(-0.99 * 0.1);
  const auto& v = mo->read(kVelocity);
  EXPECT_DOUBLE_EQ(v[0], 1.0 * f);
  EXPECT_DOUBLE_EQ(v[2], 2.0 * f);
  EXPECT_DOUBLE_EQ(v[3], 0.003 * f);
  // Positions are not integrated by this solver.
  EXPECT_DOUBLE_EQ(mo->read(kPosition)[0], 0.0);
}

TEST(DampVelocitySolver, ThresholdZeroesSlowDofsByNorm) {
  // |v1|·e^{−0.09} ≈ 0.00457 < 0.005: zeroed; |v0| = 3·e^{−0.09} stays. Per DOF, by norm.
  auto s = test::load(two_particles("<DampVelocitySolver rate=\"0.9\" threshold=\"0.005\"/>"));
  auto* mo = get<MechanicalObject>(*s.root, "dofs");
  animate(*s.root);
  const double f = std::exp(-0.9 * 0.1);
  const auto& v = mo->read(kVelocity);
  EXPECT_DOUBLE_EQ(v[1], 2.0 * f);
  EXPECT_EQ(v[3], 0.0);
  EXPECT_EQ(v[4], 0.0);
  // Just above the threshold: kept.
  auto s2 = test::load(two_particles("<DampVelocitySolver rate=\"0.9\" threshold=\"0.0045\"/>"));
  animate(*s2.root);
  EXPECT_DOUBLE_EQ(get<MechanicalObject>(*s2.root, "dofs")->read(kVelocity)[4], 0.004 * f);
}

TEST(DampVelocitySolver, RunsAfterTheIntegratorOfItsNode) {
  // Symplectic Euler under gravity then damping: v1 = (v0 + h·g)·e^{−rate·h}; x moved with the undamped v.
  auto s = test::load(two_particles("<EulerExplicitSolver/><DampVelocitySolver rate=\"0.5\"/>", "0 -10 0"));
  auto* mo = get<MechanicalObject>(*s.root, "dofs");
  animate(*s.root);
  EXPECT_DOUBLE_EQ(mo->read(kVelocity)[1], (2.0 - 1.0) * std::exp(-0.05));
  EXPECT_DOUBLE_EQ(mo->read(kPosition)[1], 0.1 * (2.0 - 1.0));
}

}  // namespace
}  // namespace sinew

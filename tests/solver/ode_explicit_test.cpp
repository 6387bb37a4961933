// Explicit and static ODE solvers and the point/line/plane/partial
// projective constraints, on scenes whose motion is known analytically.
#include <gtest/gtest.h>

#include <cmath>

#include "state/mechanical_object.h"
#include "test_scene.h"

namespace sinew {
namespace {

using test::get;

// One particle of mass 2 at (1, 2, 3), gravity (0, -10, 0), dt 0.1.
std::string particle(const std::string& solver, const std::string& extra = "") {
  return "<Node dt=\"0.1\" gravity=\"0 -10 0\"><DefaultAnimationLoop/>" + solver +
         "<MechanicalObject name=\"dofs\" position=\"1 2 3\"/><UniformMass totalMass=\"2\"/>" + extra + "</Node>";
}

Vec3 pos(Node& root) { return as_vec3(get<MechanicalObject>(root, "dofs")->write(kPosition))[0]; }
Vec3 vel(Node& root) { return as_vec3(get<MechanicalObject>(root, "dofs")->write(kVelocity))[0]; }

TEST(EulerExplicitSolver, SymplecticUsesTheNewVelocity) {
  auto s = test::load(particle("<EulerExplicitSolver/>"));
  animate(*s.root);
  EXPECT_DOUBLE_EQ(vel(*s.root).y(), -1.0);        // v = g·h
  EXPECT_DOUBLE_EQ(pos(*s.root).y(), 2.0 - 0.1);   // x = x0 + h·v_new
  animate(*s.root);
  EXPECT_DOUBLE_EQ(vel(*s.root).y(), -2.0);
  EXPECT_DOUBLE_EQ(pos(*s.root).y(), 2.0 - 0.1 - 0.2);
}

TEST(EulerExplicitSolver, NonSymplecticUsesTheOldVelocity) {
  auto s = test::load(particle("<EulerExplicitSolver symplectic=\"false\"/>"));
  animate(*s.root);
  EXPECT_DOUBLE_EQ(vel(*s.root).y(), -1.0);
  EXPECT_DOUBLE_EQ(pos(*s.root).y(), 2.0);  // moved with v = 0
  animate(*s.root);
  EXPECT_DOUBLE_EQ(pos(*s.root).y(), 2.0 - 0.1);
}

TEST(RungeKutta4Solver, FreeFallIsExact) {
  // RK4 integrates a constant acceleration exactly: x = x0 + g t²/2.
  auto s = test::load(particle("<RungeKutta4Solver/>"));
  for (int i = 0; i < 10; ++i) animate(*s.root);
  EXPECT_NEAR(pos(*s.root).y(), 2.0 - 0.5 * 10 * 1.0, 1e-12);
  EXPECT_NEAR(vel(*s.root).y(), -10.0, 1e-12);
  EXPECT_DOUBLE_EQ(pos(*s.root).x(), 1.0);
}

TEST(RungeKutta4Solver, HarmonicOscillatorFourthOrder) {
  // m = 1, k = 1 spring to the rest position, no gravity: x(t) = cos t.
  const std::string xml =
      "<Node dt=\"0.01\" gravity=\"0 0 0\"><DefaultAnimationLoop/><RungeKutta4Solver/>"
      "<MechanicalObject name=\"dofs\" position=\"0 0 0\" rest_position=\"0 0 0\"/>"
      "<UniformMass totalMass=\"1\"/><RestShapeSpringsForceField stiffness=\"1\"/></Node>";
  auto s = test::load(xml);
  auto* mo = get<MechanicalObject>(*s.root, "dofs");
  mo->write(kPosition)[0] = 1.0;  // start displaced by 1 along x
  for (int i = 0; i < 100; ++i) animate(*s.root);
  EXPECT_NEAR(pos(*s.root).x(), std::cos(1.0), 1e-9);   // global error O(h⁴)
  EXPECT_NEAR(vel(*s.root).x(), -std::sin(1.0), 1e-9);
}

TEST(StaticSolver, LinearSpringEquilibriumInOneNewtonStep) {
  // k = 50, m·g = 2·(-10): equilibrium at y0 + m g / k = 2 - 0.4.
  const std::string xml =
      "<Node dt=\"0.1\" gravity=\"0 -10 0\"><DefaultAnimationLoop/><StaticSolver/>"
      "<CGLinearSolver iterations=\"50\" tolerance=\"1e-12\" threshold=\"1e-20\"/>"
      "<MechanicalObject name=\"dofs\" position=\"1 2 3\"/><UniformMass totalMass=\"2\"/>"
      "<RestShapeSpringsForceField stiffness=\"50\"/></Node>";
  auto s = test::load(xml);
  animate(*s.root);
  EXPECT_NEAR(pos(*s.root).y(), 1.6, 1e-10);
  EXPECT_DOUBLE_EQ(vel(*s.root).y(), 0.0);  // velocities untouched
}

const char* kImplicit =
    "<EulerImplicitSolver/><CGLinearSolver iterations=\"25\" tolerance=\"1e-12\" threshold=\"1e-20\"/>";

TEST(PointProjectiveConstraint, KeepsTheParticleOnThePoint) {
  auto s = test::load(particle(kImplicit, "<PointProjectiveConstraint point=\"4 5 6\" indices=\"0\"/>"));
  // Projected at init: the particle jumps onto the point and stays there.
  EXPECT_EQ(pos(*s.root), Vec3(4, 5, 6));
  for (int i = 0; i < 3; ++i) animate(*s.root);
  EXPECT_EQ(pos(*s.root), Vec3(4, 5, 6));
  EXPECT_EQ(vel(*s.root), Vec3::Zero());
}

TEST(LineProjectiveConstraint, SlidesAlongTheLine) {
  // Line through the origin along (1, -1, 0): gravity's component along it is g/√2.
  auto s = test::load(particle(kImplicit, "<LineProjectiveConstraint origin=\"0 0 0\" direction=\"1 -1 0\"/>"));
  const Vec3 p0 = pos(*s.root);
  EXPECT_NEAR(p0.x() + p0.y(), 0.0, 1e-12);  // projected onto the line at init
  EXPECT_NEAR(p0.z(), 0.0, 1e-12);
  animate(*s.root);
  const Vec3 v = vel(*s.root);
  EXPECT_NEAR(v.x(), 0.5, 1e-12);  // h·g projected: (0.5, -0.5, 0)
  EXPECT_NEAR(v.y(), -0.5, 1e-12);
  EXPECT_NEAR(v.z(), 0.0, 1e-12);
}

TEST(PlaneProjectiveConstraint, CannotFallThroughAHorizontalPlane) {
  auto s = test::load(particle(kImplicit, "<PlaneProjectiveConstraint origin=\"0 2 0\" normal=\"0 3 0\"/>"));
  for (int i = 0; i < 3; ++i) animate(*s.root);
  EXPECT_DOUBLE_EQ(pos(*s.root).y(), 2.0);
  EXPECT_DOUBLE_EQ(vel(*s.root).y(), 0.0);
}

TEST(PartialFixedProjectiveConstraint, FixesOnlyTheChosenDirections) {
  auto s = test::load(particle(kImplicit, "<PartialFixedProjectiveConstraint indices=\"0\" fixedDirections=\"0 1 0\"/>"));
  animate(*s.root);
  EXPECT_DOUBLE_EQ(pos(*s.root).y(), 2.0);
  auto s2 = test::load(particle(kImplicit, "<PartialFixedProjectiveConstraint indices=\"0\" fixedDirections=\"1 0 1\"/>"));
  animate(*s2.root);
  EXPECT_NEAR(vel(*s2.root).y(), -1.0, 1e-12);
}

TEST(ProjectiveConstraints, OutOfRangeIndexIsAnError) {
  auto s = test::build(particle(kImplicit, "<PointProjectiveConstraint indices=\"7\"/>"));
  init_root(*s.root);
  EXPECT_TRUE(test::any_contains(test::messages(s.root->diagnostics(), Severity::error), "index 7"));
}

}  // namespace
}  // namespace sinew

// FreeMotionAnimationLoop with friction contact and bilateral constraints,
// checked against mechanics: Coulomb friction on an inclined plane, a stack
// of boxes at rest, and contradictory constraints reported without blowing up.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

#include "core/simulation.h"
#include "state/mechanical_object.h"
#include "badinput_helpers.h"
#include "test_scene.h"

namespace sinew {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A point of mass 1 on a plane tilted by `deg` about z, Coulomb friction mu.
std::string incline_scene(double deg, double mu) {
  const double c = std::cos(deg * kPi / 180), s = std::sin(deg * kPi / 180);
  std::ostringstream x;
  x.precision(17);
  // Plane corners: (±10 along the slope, ±10 along z); the point starts at the contact distance above the origin.
  for (double u : {-10.0, 10.0})
    for (double w : {-10.0, 10.0}) x << u * c << ' ' << u * s << ' ' << w << ' ';
  const double d = 0.01;
  std::ostringstream p;
  p.precision(17);
  p << -s * d << ' ' << c * d << " 0.3";  // off the plane's diagonal (MinProximity keeps interior projections only)
  return R"(<Node name="root" dt="0.01" gravity="0 -9.81 0">
    <FreeMotionAnimationLoop/>
    <BlockGaussSeidelConstraintSolver tolerance="1e-12" maxIterations="1000"/>
    <CollisionPipeline/><BruteForceBroadPhase/><BVHNarrowPhase/>
    <MinProximityIntersection alarmDistance="0.1" contactDistance="0.01"/>
    <CollisionResponse response="FrictionContactConstraint" responseParams="mu=)" +
         std::to_string(mu) + R"("/>
    <Node name="plane">
      <MechanicalObject position=")" +
         x.str() + R"("/>
      <MeshTopology triangles="0 1 3  0 3 2"/>
      <TriangleCollisionModel simulated="0" moving="0"/>
    </Node>
    <Node name="block">
      <EulerImplicitSolver/>
      <CGLinearSolver iterations="25" tolerance="1e-12" threshold="1e-12"/>
      <MechanicalObject name="x" position=")" +
         p.str() + R"("/>
      <UniformMass totalMass="1"/>
      <PointCollisionModel/>
      <UncoupledConstraintCorrection compliance="1"/>
    </Node>
  </Node>)";
}

Vec3 velocity(MechanicalState& s) { return as_vec3(s.read(kVelocity))[0]; }

// Above the friction angle the block slides with a = g (sin θ − μ cos θ) along the slope.
TEST(FreeMotionPhysics, BlockSlidesDownAnInclineWithCoulombAcceleration) {
  const double deg = 30, mu = 0.3, g = 9.81;
  scene::LoadedScene s = test::load(incline_scene(deg, mu));
  ASSERT_TRUE(s.root);
  auto* x = test::get<MechanicalObject>(*s.root->find_child_named("block"), "x");
  ASSERT_NE(x, nullptr);
  for (int i = 0; i < 50; ++i) animate(*s.root);
  const Vec3 v1 = velocity(*x);
  for (int i = 0; i < 50; ++i) animate(*s.root);
  const Vec3 v2 = velocity(*x);
  const double expected = g * (std::sin(deg * kPi / 180) - mu * std::cos(deg * kPi / 180));
  const double a = (v2.norm() - v1.norm()) / 0.5;
  EXPECT_NEAR(a, expected, 0.01 * expected);
  // Along the slope, downwards.
  const Vec3 down(-std::cos(deg * kPi / 180), -std::sin(deg * kPi / 180), 0);
  EXPECT_GT(v2.normalized().dot(down), 0.9999);
}

// Below the friction angle (tan 30° = 0.577 < μ) it stays where it is.
TEST(FreeMotionPhysics, BlockSticksOnAnInclineBelowTheFrictionAngle) {
  scene::LoadedScene s = test::load(incline_scene(30, 0.7));
  ASSERT_TRUE(s.root);
  auto* x = test::get<MechanicalObject>(*s.root->find_child_named("block"), "x");
  for (int i = 0; i < 20; ++i) animate(*s.root);
  const Vec3 p20 = as_vec3(x->read(kPosition))[0];
  for (int i = 0; i < 200; ++i) animate(*s.root);
  const Vec3 p220 = as_vec3(x->read(kPosition))[0];
  EXPECT_LT((p220 - p20).norm(), 1e-9);
  EXPECT_LT(velocity(*x).norm(), 1e-9);
}

// Five rigid boxes, each smaller than the one below, stacked on a floor:
// once settled they stay put (no creep beyond 1e-4 of the box size over 800 steps).
TEST(FreeMotionPhysics, StackOfFiveBoxesComesToRestWithoutDrift) {
  const char* tris = "0 2 1 0 3 2 4 5 6 4 6 7 0 1 5 0 5 4 1 2 6 1 6 5 2 3 7 2 7 6 3 0 4 3 4 7";
  std::ostringstream xml;
  xml << R"(<Node name="root" dt="0.01" gravity="0 -9.81 0">
    <FreeMotionAnimationLoop/>
    <BlockGaussSeidelConstraintSolver tolerance="1e-8" maxIterations="500"/>
    <CollisionPipeline/><BruteForceBroadPhase/><BVHNarrowPhase/>
    <MinProximityIntersection alarmDistance="0.02" contactDistance="0.005"/>
    <CollisionResponse response="FrictionContactConstraint" responseParams="mu=0.6"/>
    <Node name="floor">
      <MechanicalObject position="-5 0 -5  5 0 -5  5 0 5  -5 0 5"/>
      <MeshTopology triangles="0 2 1  0 3 2"/>
      <TriangleCollisionModel simulated="0" moving="0"/><LineCollisionModel simulated="0" moving="0"/>
    </Node>)";
  double y = 0.005;
  for (int i = 0; i < 5; ++i) {
    const double h = 0.5 - 0.05 * i;
    y += h;
    xml << "<Node name=\"box" << i << R"("><EulerImplicitSolver/>
      <CGLinearSolver iterations="25" tolerance="1e-12" threshold="1e-12"/>
      <MechanicalObject name="x" template="Rigid3" position="0 )"
        << y << R"( 0 0 0 0 1"/><UniformMass totalMass="1"/><UncoupledConstraintCorrection/>
      <Node name="surf"><MechanicalObject position=")";
    for (int k = 0; k < 8; ++k)
      xml << ((k == 1 || k == 2 || k == 5 || k == 6) ? h : -h) << ' ' << (k < 4 ? -h : h) << ' '
          << ((k == 2 || k == 3 || k == 6 || k == 7) ? h : -h) << ' ';
    xml << "\"/><MeshTopology triangles=\"" << tris << R"("/>
      <TriangleCollisionModel/><LineCollisionModel/><PointCollisionModel/><RigidMapping/></Node></Node>)";
    y += h + 0.005;
  }
  xml << "</Node>";
  scene::LoadedScene s = test::load(xml.str());
  ASSERT_TRUE(s.root);
  std::vector<MechanicalObject*> boxes;
  for (int i = 0; i < 5; ++i) boxes.push_back(test::get<MechanicalObject>(*s.root->find_child_named("box" + std::to_string(i)), "x"));
  for (int i = 0; i < 200; ++i) animate(*s.root);
  std::vector<std::vector<double>> settled;
  for (auto* b : boxes) settled.push_back(b->read(kPosition));
  for (int i = 0; i < 800; ++i) animate(*s.root);
  double expected_y = 0.005;
  for (int i = 0; i < 5; ++i) {
    const std::vector<double>& x = boxes[i]->read(kPosition);
    const double h = 0.5 - 0.05 * i;
    expected_y += h;
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(x[c], settled[i][c], 1e-4) << "box " << i << " coordinate " << c;
    EXPECT_NEAR(x[1], expected_y, 1e-6) << "box " << i << " rests at the contact distance";
    EXPECT_NEAR(std::abs(x[6]), 1.0, 1e-8) << "box " << i << " stays upright";
    expected_y += h + 0.005;
  }
}

// One point held by two bilateral constraints to two different anchors: the
// problem has no solution. The solver says so (iterations, residual) and the
// state stays finite.
TEST(FreeMotionPhysics, ContradictoryBilateralConstraintsReportNonConvergenceAndStayFinite) {
  scene::LoadedScene s = test::load(R"(<Node name="root" dt="0.01" gravity="0 -9.81 0">
    <FreeMotionAnimationLoop/>
    <BlockGaussSeidelConstraintSolver name="solver" tolerance="1e-10" maxIterations="50"/>
    <Node name="anchors"><MechanicalObject name="a" position="0 0 0  1 0 0"/></Node>
    <Node name="body">
      <EulerImplicitSolver/><CGLinearSolver iterations="25" tolerance="1e-12" threshold="1e-12"/>
      <MechanicalObject name="p" position="0.5 0 0"/>
      <UniformMass totalMass="1"/>
      <UncoupledConstraintCorrection compliance="1"/>
    </Node>
    <BilateralLagrangianConstraint object1="@anchors/a" object2="@body/p" first_point="0" second_point="0"/>
    <BilateralLagrangianConstraint object1="@anchors/a" object2="@body/p" first_point="1" second_point="0"/>
  </Node>)");
  ASSERT_TRUE(s.root);
  for (int i = 0; i < 100; ++i) animate(*s.root);
  auto* p = test::get<MechanicalObject>(*s.root->find_child_named("body"), "p");
  for (double v : p->read(kPosition)) EXPECT_TRUE(std::isfinite(v));
  for (double v : p->read(kVelocity)) EXPECT_TRUE(std::isfinite(v));
  const auto warnings = test::messages(s.root->diagnostics(), Severity::warning);
  EXPECT_TRUE(test::any_contains(warnings, "no convergence after 51 iterations")) << ::testing::PrintToString(warnings);
  EXPECT_TRUE(test::any_contains(warnings, "residual "));
}

// One point tied to three coincident anchors: consistent, but each axis has
// three identical rows, so plain projected Jacobi doubles its error every
// iteration (iteration matrix eigenvalue −2) until the forces overflow. The
// solver says why and what to do, applies nothing, and the state stays
// finite. With useSpectralCorrection the violation is scaled by
// ρ = 0.9·2/|λ|² (SOFA squares the eigenvalue): with compliance 100 (W =
// compliance·dt per entry) each axis' 3×3 block of W is all ones (λ = 3,
// ρ = 0.2, iteration eigenvalue 1 − 3ρ = 0.4) and the same problem converges.
std::string three_anchor_scene(const std::string& solver) {
  return R"(<Node name="root" dt="0.01" gravity="0 -9.81 0">
    <FreeMotionAnimationLoop/>)" + solver + R"(
    <Node name="anchors"><MechanicalObject name="a" position="0 0 0  0 0 0  0 0 0"/></Node>
    <Node name="body">
      <EulerImplicitSolver/><CGLinearSolver iterations="25" tolerance="1e-12" threshold="1e-12"/>
      <MechanicalObject name="p" position="0 0 0"/>
      <UniformMass totalMass="1"/>
      <UncoupledConstraintCorrection compliance="100"/>
    </Node>
    <BilateralLagrangianConstraint object1="@anchors/a" object2="@body/p" first_point="0" second_point="0"/>
    <BilateralLagrangianConstraint object1="@anchors/a" object2="@body/p" first_point="1" second_point="0"/>
    <BilateralLagrangianConstraint object1="@anchors/a" object2="@body/p" first_point="2" second_point="0"/>
  </Node>)";
}

TEST(FreeMotionPhysics, DivergingJacobiIsReportedWithItsRemedyAndAppliesNothing) {
  scene::LoadedScene s =
      test::load(three_anchor_scene(R"(<ImprovedJacobiConstraintSolver tolerance="1e-10" maxIterations="2000"/>)"));
  ASSERT_TRUE(s.root);
  animate(*s.root);
  const auto errors = test::messages(s.root->diagnostics(), Severity::error);
  EXPECT_TRUE(test::any_contains_all(errors, {"not finite after 2001 iterations", "useSpectralCorrection"}))
      << ::testing::PrintToString(errors);
  // Nothing applied: the point moved as in free fall for one step.
  auto* p = test::get<MechanicalObject>(*s.root->find_child_named("body"), "p");
  EXPECT_NEAR(p->read(kVelocity)[1], -9.81 * 0.01, 1e-12);
  for (double v : p->read(kPosition)) EXPECT_TRUE(std::isfinite(v));

  scene::LoadedScene c = test::load(three_anchor_scene(
      R"(<ImprovedJacobiConstraintSolver tolerance="1e-10" maxIterations="2000" useSpectralCorrection="1"/>)"));
  ASSERT_TRUE(c.root);
  for (int i = 0; i < 10; ++i) animate(*c.root);
  EXPECT_FALSE(c.root->diagnostics().has_errors())
      << ::testing::PrintToString(test::messages(c.root->diagnostics(), Severity::error));
  auto* q = test::get<MechanicalObject>(*c.root->find_child_named("body"), "p");
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(q->read(kPosition)[k], 0.0, 1e-9) << k;
}

// A point pinned (FixedProjectiveConstraint) inside a closed box it is too
// close to: every contact row is projected away, nothing can satisfy the
// contacts. The rows are reported and left without force; the state stays finite.
TEST(FreeMotionPhysics, PinnedPointInsideAClosedBoxIsReportedAndStaysFinite) {
  scene::LoadedScene s = test::load(R"(<Node name="root" dt="0.01" gravity="0 -9.81 0">
    <FreeMotionAnimationLoop/>
    <BlockGaussSeidelConstraintSolver tolerance="1e-10" maxIterations="100"/>
    <CollisionPipeline/><BruteForceBroadPhase/><BVHNarrowPhase/>
    <MinProximityIntersection alarmDistance="1" contactDistance="0.6"/>
    <CollisionResponse response="FrictionContactConstraint"/>
    <Node name="box">
      <MechanicalObject position="-0.5 -0.5 -0.5  0.5 -0.5 -0.5  0.5 -0.5 0.5  -0.5 -0.5 0.5  -0.5 0.5 -0.5  0.5 0.5 -0.5  0.5 0.5 0.5  -0.5 0.5 0.5"/>
      <MeshTopology triangles="0 2 1 0 3 2 4 5 6 4 6 7 0 1 5 0 5 4 1 2 6 1 6 5 2 3 7 2 7 6 3 0 4 3 4 7"/>
      <TriangleCollisionModel simulated="0" moving="0"/>
    </Node>
    <Node name="body">
      <EulerImplicitSolver/><CGLinearSolver iterations="25" tolerance="1e-12" threshold="1e-12"/>
      <MechanicalObject name="p" position="0.1 0.05 0.02"/>
      <UniformMass totalMass="1"/>
      <FixedProjectiveConstraint indices="0"/>
      <PointCollisionModel/>
      <UncoupledConstraintCorrection compliance="1"/>
    </Node>
  </Node>)");
  ASSERT_TRUE(s.root);
  for (int i = 0; i < 20; ++i) animate(*s.root);
  auto* p = test::get<MechanicalObject>(*s.root->find_child_named("body"), "p");
  const std::vector<double>& x = p->read(kPosition);
  EXPECT_DOUBLE_EQ(x[0], 0.1);
  EXPECT_DOUBLE_EQ(x[1], 0.05);
  EXPECT_DOUBLE_EQ(x[2], 0.02);
  for (double v : p->read(kVelocity)) EXPECT_EQ(v, 0.0);
  const auto warnings = test::messages(s.root->diagnostics(), Severity::warning);
  EXPECT_TRUE(test::any_contains(warnings, "have no compliance")) << ::testing::PrintToString(warnings);
}

// A Rigid3d sphere (frame turned 90° about x, so the contact point must be
// mapped through the frame) sliding along a floor with Coulomb friction.
// SOFA puts a rigid sphere's contact point on its surface (c − n·r) and its
// rigid contact mapper adds the radius to the contact distance as well, so the
// sphere is held at 2r + contactDistance: starting at r + 0.01 it is pushed up
// by r in one step, and the large normal impulse lets friction stop the contact
// point's slip at once: then v = 5/7 v0 and ω = −v / r (solid sphere,
// I = 2/5 m r²), which checks the lever arm of the mapped contact point.
TEST(FreeMotionPhysics, RigidSphereContactActsAtItsSurfaceThroughItsFrame) {
  const double r = 0.2, d = 0.01, v0 = 1.0, dt = 0.002;
  const std::string xml = R"(<Node name="root" dt="0.002" gravity="0 -9.81 0">
    <FreeMotionAnimationLoop/>
    <BlockGaussSeidelConstraintSolver tolerance="1e-12" maxIterations="1000"/>
    <CollisionPipeline/><BruteForceBroadPhase/><BVHNarrowPhase/>
    <MinProximityIntersection alarmDistance="0.05" contactDistance="0.01"/>
    <CollisionResponse response="FrictionContactConstraint" responseParams="mu=0.5"/>
    <Node name="floor">
      <MechanicalObject position="-10 0 -10  10 0 -10  -10 0 10  10 0 10"/>
      <MeshTopology triangles="0 2 3  0 3 1"/>
      <TriangleCollisionModel simulated="0" moving="0"/>
    </Node>
    <Node name="ball">
      <EulerImplicitSolver/>
      <CGLinearSolver iterations="25" tolerance="1e-12" threshold="1e-12"/>
      <MechanicalObject name="x" template="Rigid3d" position="0.3 0.21 0.4  0.70710678118654752 0 0 0.70710678118654752"
                        velocity="1 0 0 0 0 0"/>
      <UniformMass vertexMass="1 1  0.016 0 0  0 0.016 0  0 0 0.016"/>
      <SphereCollisionModel radius="0.2"/>
      <UncoupledConstraintCorrection/>
    </Node>
  </Node>)";
  scene::LoadedScene s = test::load(xml);
  ASSERT_TRUE(s.root);
  auto* x = test::get<MechanicalObject>(*s.root->find_child_named("ball"), "x");
  ASSERT_NE(x, nullptr);
  animate(*s.root);
  const std::vector<double>& v = x->read(kVelocity);
  const std::vector<double>& p = x->read(kPosition);
  EXPECT_NEAR(p[1], 2 * r + d, 1e-9);
  EXPECT_NEAR(v[1], r / dt, 1e-6);
  EXPECT_NEAR(v[0], 5.0 / 7.0 * v0, 1e-9);
  EXPECT_NEAR(v[5], -v[0] / r, 1e-9);
  for (int k : {2, 3, 4}) EXPECT_NEAR(v[k], 0.0, 1e-9) << k;
  EXPECT_NEAR(p[2], 0.4, 1e-12);
}

}  // namespace
}  // namespace sinew

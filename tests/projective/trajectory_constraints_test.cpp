// ParabolicProjectiveConstraint and HermiteSplineProjectiveConstraint: the
// points they impose at the ends and inside the motion (closed forms), SOFA's
// velocity rules, the DoFs left free outside [BeginTime, EndTime], the rigid
// orientation kept, bad input, and SOFA's example scenes.
#include <gtest/gtest.h>

#include <cmath>

#include "badinput_helpers.h"
#include "core/mechanical_ops.h"
#include "core/node.h"
#include "test_scene.h"
#include "test_paths.h"

using namespace sinew;

namespace {

void project_at(Node& root, double t) {
  root.time.set(t);
  MechanicalOps ops(root);
  ops.project_position(kPosition, t);
  ops.project_velocity(kVelocity, t);
}

const char* kParabola = R"(<Node gravity="0 0 0" dt="0.1"><DefaultAnimationLoop/>
    <MechanicalObject name="dofs" position="9 9 9  0 0 0"/>
    <ParabolicProjectiveConstraint indices="1" P1="1 0 0" P2="3 2 0" P3="5 0 0" BeginTime="1" EndTime="3"/></Node>)";

TEST(ParabolicConstraint, PassesThroughItsThreePoints) {
  // P1P3 along x (length 4), P2 above its middle: y(X) = −2/(4·2 − 4)·X² + 4·2/4·X = −X²/2 + 2X.
  auto s = test::load(kParabola);
  auto* mo = test::get<MechanicalState>(*s.root, "dofs");
  project_at(*s.root, 1.0);
  EXPECT_NEAR(mo->read(kPosition)[3], 1.0, 1e-14);
  EXPECT_NEAR(mo->read(kPosition)[4], 0.0, 1e-14);
  project_at(*s.root, 2.0);  // relative time ½: X = 2, the apex (3, 2, 0)
  EXPECT_NEAR(mo->read(kPosition)[3], 3.0, 1e-14);
  EXPECT_NEAR(mo->read(kPosition)[4], 2.0, 1e-14);
  // Velocity: (x(t + dt) − x(t))/dt: X moves by 0.2, y by (−2.2²/2 + 4.4) − 2 = −0.02.
  EXPECT_NEAR(mo->read(kVelocity)[3], 2.0, 1e-12);
  EXPECT_NEAR(mo->read(kVelocity)[4], -0.2, 1e-12);
  project_at(*s.root, 3.0);
  EXPECT_NEAR(mo->read(kPosition)[3], 5.0, 1e-14);
  EXPECT_NEAR(mo->read(kPosition)[4], 0.0, 1e-14);
  EXPECT_EQ(mo->read(kPosition)[0], 9.0);  // not listed
  // After EndTime the point is free again: nothing is imposed.
  mo->write(kPosition)[3] = 42;
  project_at(*s.root, 3.5);
  EXPECT_EQ(mo->read(kPosition)[3], 42.0);
}

TEST(ParabolicConstraint, ResponsesZeroedOnlyDuringTheMotion) {
  auto s = test::load(kParabola);
  auto* mo = test::get<MechanicalState>(*s.root, "dofs");
  const int dx = MechanicalOps::alloc_vec();
  for (const auto& [t, expect] : std::vector<std::pair<double, double>>{{0.5, 1.0}, {1.5, 0.0}}) {
    s.root->time.set(t);
    mo->write(dx).assign(6, 1.0);
    MechanicalOps(*s.root).project_response(dx);
    EXPECT_EQ(mo->read(dx)[4], expect) << t;
    EXPECT_EQ(mo->read(dx)[1], 1.0);
  }
}

TEST(ParabolicConstraint, Rigid3KeepsTheOrientation) {
  auto s = test::load(R"(<Node gravity="0 0 0" dt="0.1"><DefaultAnimationLoop/>
    <MechanicalObject name="dofs" template="Rigid3" position="0 0 0 0 0 0.6 0.8"/>
    <ParabolicProjectiveConstraint template="Rigid3" indices="0" P1="1 0 0" P2="3 2 0" P3="5 0 0" BeginTime="0" EndTime="2"/></Node>)");
  auto* mo = test::get<MechanicalState>(*s.root, "dofs");
  project_at(*s.root, 1.0);
  const auto& x = mo->read(kPosition);
  EXPECT_NEAR(x[0], 3.0, 1e-14);
  EXPECT_NEAR(x[1], 2.0, 1e-14);
  EXPECT_EQ(x[5], 0.6);
  EXPECT_EQ(x[6], 0.8);
}

TEST(ParabolicConstraint, DegenerateParabolasAreRefused) {
  for (const auto& [pts, msg] : std::vector<std::pair<std::string, std::string>>{
           {"P1='0 0 0' P2='0 0 0' P3='1 0 0'", "three distinct points"},
           {"P1='0 0 0' P2='1 0 0' P3='2 0 0'", "aligned"}}) {
    auto s = test::build("<Node><DefaultAnimationLoop/><MechanicalObject position='0 0 0'/>"
                         "<ParabolicProjectiveConstraint name='c' indices='0' BeginTime='0' EndTime='1' " + pts + "/></Node>");
    ASSERT_TRUE(s.root);
    init_root(*s.root);
    EXPECT_TRUE(test::any_contains(test::messages(s.root->diagnostics(), Severity::error), msg)) << pts;
  }
}

TEST(HermiteSplineConstraint, StartsAndEndsAtItsControlPoints) {
  // SX0 = (1, 0), SX1 = (0, 2): s(u) = 0·h10(u) + h01(u) + 2·h11(u).
  auto s = test::load(R"(<Node gravity="0 0 0" dt="0.01"><DefaultAnimationLoop/>
    <MechanicalObject name="dofs" position="0 0 0"/>
    <HermiteSplineProjectiveConstraint indices="0" BeginTime="0" EndTime="5" X0="0 0 0" dX0="0 10 0"
        X1="5 0 0" dX1="0 5 0" SX0="1 0" SX1="0 2"/></Node>)");
  auto* mo = test::get<MechanicalState>(*s.root, "dofs");
  project_at(*s.root, 0.0);
  EXPECT_NEAR(mo->read(kPosition)[0], 0.0, 1e-15);
  EXPECT_NEAR(mo->read(kVelocity)[1], 10.0, 1e-15);  // dh10/ds(0) = 1: dX0
  project_at(*s.root, 5.0);
  EXPECT_NEAR(mo->read(kPosition)[0], 5.0, 1e-14);
  EXPECT_NEAR(mo->read(kVelocity)[1], 5.0, 1e-14);  // dh11/ds(1) = 1: dX1
  // u = ½: s = ½ + 2·(1/8 − 1/4) = 1/4; position X0·h00 + dX0·h10 + X1·h01 + dX1·h11 at s = ¼.
  project_at(*s.root, 2.5);
  const double q = 0.25, h10 = q * q * q - 2 * q * q + q, h01 = -2 * q * q * q + 3 * q * q, h11 = q * q * q - q * q;
  EXPECT_NEAR(mo->read(kPosition)[0], 5 * h01, 1e-14);
  EXPECT_NEAR(mo->read(kPosition)[1], 10 * h10 + 5 * h11, 1e-14);
}

class TrajectoryExample : public ::testing::TestWithParam<const char*> {};

TEST_P(TrajectoryExample, Runs100Steps) {
  const test::Outcome o = test::run_sofa_example(GetParam(), 100);
  if (!o.loaded) GTEST_SKIP() << "SOFA data not found at " << SINEW_DATA_DIR;
  ASSERT_TRUE(o.init_ok) << o.all();
  EXPECT_EQ(o.steps, 100) << o.all();
  EXPECT_TRUE(o.errors.empty()) << o.all();
  EXPECT_TRUE(o.finite);
}

INSTANTIATE_TEST_SUITE_P(Sofa, TrajectoryExample,
                         ::testing::Values("Component/Constraint/Projective/ParabolicProjectiveConstraint.scn",
                                           "Component/Constraint/Projective/HermiteSplineProjectiveConstraint.scn"),
                         [](const auto& info) {
                           return std::string(info.param).find("Parabolic") != std::string::npos ? "Parabolic"
                                                                                                   : "HermiteSpline";
                         });

}  // namespace

// OscillatorProjectiveConstraint: positions and velocities on the sinusoid at the node's
// time (closed forms), the Rigid3d sum (centre and exponential of the angular amplitude),
// zeroed responses, bad input, and SOFA's two example scenes.
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

TEST(OscillatorConstraint, Vec3FollowsTheSinusoid) {
  auto s = test::load(R"(<Node gravity="0 0 0"><DefaultAnimationLoop/>
    <MechanicalObject name="dofs" position="9 9 9  0 0 0"/>
    <OscillatorProjectiveConstraint oscillators="1  1 2 3  0.5 0 -1  2 0.3"/></Node>)");
  auto* mo = test::get<MechanicalState>(*s.root, "dofs");
  project_at(*s.root, 0.7);
  const auto& x = mo->read(kPosition);
  const auto& v = mo->read(kVelocity);
  const double sn = std::sin(2 * 0.7 + 0.3), cs = std::cos(2 * 0.7 + 0.3);
  EXPECT_DOUBLE_EQ(x[3], 1 + 0.5 * sn);
  EXPECT_DOUBLE_EQ(x[4], 2.0);
  EXPECT_DOUBLE_EQ(x[5], 3 - sn);
  EXPECT_DOUBLE_EQ(v[3], 0.5 * 2 * cs);
  EXPECT_DOUBLE_EQ(v[5], -2 * cs);
  EXPECT_EQ(x[0], 9.0);  // DoF 0 is free
  // Responses of the oscillating DoF are zeroed.
  const int dx = MechanicalOps::alloc_vec();
  mo->write(dx).assign(6, 1.0);
  MechanicalOps(*s.root).project_response(dx);
  EXPECT_EQ(mo->read(dx), (std::vector<double>{1, 1, 1, 0, 0, 0}));
}

TEST(OscillatorConstraint, Rigid3TurnsTheOrientation) {
  // Angular amplitude (0, 0, π/2) at sin = 1: a quarter turn about z from the identity.
  const double w = 1.0, phase = M_PI / 2;
  auto s = test::load(R"(<Node gravity="0 0 0"><DefaultAnimationLoop/>
    <MechanicalObject name="dofs" template="Rigid3" position="0 0 0 0 0 0 1"/>
    <OscillatorProjectiveConstraint template="Rigid3" oscillators="0  1 2 3 0 0 0 1  0 0 1 0 0 1.5707963267948966  1 1.5707963267948966"/></Node>)");
  auto* mo = test::get<MechanicalState>(*s.root, "dofs");
  project_at(*s.root, 0.0);
  const auto& x = mo->read(kPosition);
  EXPECT_DOUBLE_EQ(x[0], 1.0);
  EXPECT_DOUBLE_EQ(x[1], 2.0);
  EXPECT_DOUBLE_EQ(x[2], 4.0);
  EXPECT_NEAR(x[5], std::sin(M_PI / 4), 1e-15);
  EXPECT_NEAR(x[6], std::cos(M_PI / 4), 1e-15);
  EXPECT_NEAR(mo->read(kVelocity)[5], M_PI / 2 * w * std::cos(phase), 1e-15);
}

TEST(OscillatorConstraint, BadInputIsReported) {
  for (const auto& [osc, msg] : std::vector<std::pair<std::string, std::string>>{
           {"0 1 2 3 0 0 0 1", "each oscillator takes 9"}, {"4  0 0 0  1 0 0  1 0", "names DoF 4"}}) {
    auto s = test::build(R"(<Node><DefaultAnimationLoop/><MechanicalObject position="0 0 0"/>
      <OscillatorProjectiveConstraint name="c" oscillators=")" + osc + "\"/></Node>");
    ASSERT_TRUE(s.root);
    init_root(*s.root);
    EXPECT_TRUE(test::any_contains(test::messages(s.root->diagnostics(), Severity::error), msg)) << osc;
    EXPECT_EQ(test::get<Component>(*s.root, "c")->state(), ComponentState::invalid);
  }
}

class OscillatorExample : public ::testing::TestWithParam<const char*> {};

TEST_P(OscillatorExample, Runs) {
  const test::Outcome o = test::run_sofa_example(GetParam(), 20);
  if (!o.loaded) GTEST_SKIP() << "SOFA data not found at " << SINEW_DATA_DIR << " (set SINEW_DATA_DIR)";
  ASSERT_TRUE(o.init_ok) << o.all();
  EXPECT_EQ(o.steps, 20);
  EXPECT_TRUE(o.errors.empty()) << o.all();
  EXPECT_TRUE(o.finite);
}

INSTANTIATE_TEST_SUITE_P(Scenes, OscillatorExample,
                         ::testing::Values("Component/Constraint/Projective/OscillatorProjectiveConstraint.scn",
                                           "Component/Constraint/Projective/OscillatorProjectiveConstraint_rigid.scn"));

}  // namespace

// SutureSpringForceField: vertices the needle's front passes near are pierced;
// when its back comes near one, a thread (tension-only spring, rest length =
// distance at creation) links them; the thread pulls the vertex only once
// stretched; bad input is an error naming the field.
#include <gtest/gtest.h>

#include <cmath>

#include "core/roles.h"
#include "forcefield/spring/suture_spring_force_field.h"
#include "test_scene.h"

using namespace sinew;

namespace {

// A body of three free vertices (no solver: the test moves things by hand) and a
// needle state with its front and back points.
const char* kScene = R"(<Node name="root" dt="0.01" gravity="0 0 0">
  <Node name="body">
    <MechanicalObject name="x" position="0 0 0  4 0 0  8 0 0"/>
    <SutureSpringForceField name="ss" needle="@../needle/p" captureDistance="1" stiffness="20"/>
  </Node>
  <Node name="needle"><MechanicalObject name="p" position="0 5 0  -3 5 0"/></Node>
</Node>)";

void set_needle(MechanicalState& n, const Vec3& front, const Vec3& back) {
  n.write(kPosition) = {front[0], front[1], front[2], back[0], back[1], back[2]};
}

void end_step(Node& root) {
  Event e{Event::Kind::animate_end, 0.01};
  propagate_event(root, e);
}

Vec3 force_on(SutureSpringForceField& ss, MechanicalState& body, int vertex) {
  std::vector<double>& f = body.write(kForce);
  std::fill(f.begin(), f.end(), 0.0);
  MechParams p;
  ss.add_force(p);
  return Vec3(f[3 * vertex], f[3 * vertex + 1], f[3 * vertex + 2]);
}

}  // namespace

TEST(SutureSpringForceField, BackPointLinksTheVerticesTheFrontPierced) {
  auto sc = test::load(kScene);
  ASSERT_TRUE(sc.root);
  Node& body = *sc.root->find_child_named("body");
  auto* ss = test::get<SutureSpringForceField>(body, "ss");
  MechanicalState& x = *body.get_mechanical_state();
  MechanicalState& n = *sc.root->find_child_named("needle")->get_mechanical_state();
  ASSERT_TRUE(ss);
  ASSERT_EQ(ss->state(), ComponentState::valid);

  // The back point near vertex 1 before the front went there: nothing (not pierced).
  set_needle(n, Vec3(20, 0, 0), Vec3(4, 0.5, 0));
  end_step(*sc.root);
  EXPECT_TRUE(ss->spring_list().empty());
  EXPECT_EQ(ss->pierced_count.value(), 0);

  // The front passes within 1 of vertex 1 (0.6 away): pierced.
  set_needle(n, Vec3(4, 0.6, 0), Vec3(1, 0.6, 0));
  end_step(*sc.root);
  EXPECT_EQ(ss->pierced_count.value(), 1);
  EXPECT_TRUE(ss->spring_list().empty());

  // The back follows through: a thread of rest length 0.8 (its distance then).
  set_needle(n, Vec3(7, 0.8, 0), Vec3(4, 0.8, 0));
  end_step(*sc.root);
  ASSERT_EQ(ss->spring_list().size(), 1u);
  EXPECT_EQ(ss->spring_list()[0].vertex, 1u);
  EXPECT_NEAR(ss->spring_list()[0].rest, 0.8, 1e-12);
  EXPECT_EQ(ss->springs.value(), (std::vector<double>{1, 0.8}));
  // The front at 7, 0.8 is 1.28 from vertex 2: not pierced. One thread per vertex.
  EXPECT_EQ(ss->pierced_count.value(), 1);
  end_step(*sc.root);
  EXPECT_EQ(ss->spring_list().size(), 1u);

  // Slack (back 0.5 from the vertex, rest 0.8): no force, no energy.
  set_needle(n, Vec3(7, 0.5, 0), Vec3(4, 0.5, 0));
  EXPECT_EQ(force_on(*ss, x, 1), Vec3::Zero());
  EXPECT_EQ(ss->potential_energy().value_or(-1), 0.0);
  // Stretched to 2.8 along y: pulls the vertex towards the back point with 20·(2.8 − 0.8) = 40.
  set_needle(n, Vec3(7, 2.8, 0), Vec3(4, 2.8, 0));
  const Vec3 f = force_on(*ss, x, 1);
  EXPECT_NEAR(f[0], 0.0, 1e-12);
  EXPECT_NEAR(f[1], 40.0, 1e-12);
  EXPECT_NEAR(ss->potential_energy().value_or(-1), 0.5 * 20 * 4, 1e-12);
  EXPECT_EQ(force_on(*ss, x, 0), Vec3::Zero());
}

TEST(SutureSpringForceField, BadInputIsAnErrorNamingTheField) {
  auto sc = test::build(R"(<Node name="root"><Node name="body"><MechanicalObject position="0 0 0  1 0 0"/>
    <SutureSpringForceField name="a" needle="@../needle/p" backIndex="2"/>
    <SutureSpringForceField name="b" needle="@../needle/p" springs="0 1 5"/>
    <SutureSpringForceField name="c"/></Node>
    <Node name="needle"><MechanicalObject name="p" position="0 0 0  1 0 0"/></Node></Node>)");
  ASSERT_TRUE(sc.root);
  init_root(*sc.root);
  const auto errors = test::messages(sc.root->diagnostics(), Severity::error);
  EXPECT_TRUE(test::any_contains(errors, "backIndex = 2")) << ::testing::PrintToString(errors);
  EXPECT_TRUE(test::any_contains(errors, "springs: pairs")) << ::testing::PrintToString(errors);
  EXPECT_TRUE(test::any_contains(errors, "needle: no state linked")) << ::testing::PrintToString(errors);
  animate(*sc.root);  // invalid components stay quiet
}

// LinearMovementProjectiveConstraint: positions, velocities and responses at
// times between key times (hand-computed), relative and absolute movements,
// Rigid3 orientations by slerp between the keys' Euler angles, the inactive
// constraint outside [first key, last key), whole steps under matrix-free and
// assembled solvers, and bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "core/mechanical_ops.h"
#include "core/node.h"
#include "core/simulation.h"
#include "projective/linear_movement_projective_constraint.h"
#include "test_scene.h"

using namespace sinew;
using sinew::test::any_contains;
using sinew::test::get;
using sinew::test::load;
using sinew::test::messages;

namespace {

std::string vec3_scene(const std::string& constraint) {
  return R"(<Node name="root" dt="0.1" gravity="0 0 0">
    <DefaultAnimationLoop/>
    <MechanicalObject name="dofs" position="0 0 0  1 1 1  5 5 5"/>
    )" + constraint + R"(
  </Node>)";
}

const char* kVec3 = R"(<LinearMovementProjectiveConstraint name="lm" indices="1 2" keyTimes="0 1 3"
                          movements="0 0 0  2 0 0  2 4 0"/>)";

// Projects position, velocity and a response filled with 7s at time t.
struct Projected {
  std::vector<double> x, v, dx;
};
Projected project_at(Node& root, MechanicalState& s, double t) {
  root.time.set(t);
  s.write(kVelocity).assign(s.size() * 3, -1.0);
  s.write(kForce).assign(s.size() * 3, 7.0);
  MechanicalOps ops(root);
  ops.project_position(kPosition, t);
  ops.project_velocity(kVelocity, t);
  ops.project_response(kForce);
  return {s.read(kPosition), s.read(kVelocity), s.read(kForce)};
}

void expect_vec3(const std::vector<double>& v, std::size_t i, double a, double b, double c) {
  EXPECT_NEAR(v[3 * i + 0], a, 1e-14) << "dof " << i;
  EXPECT_NEAR(v[3 * i + 1], b, 1e-14) << "dof " << i;
  EXPECT_NEAR(v[3 * i + 2], c, 1e-14) << "dof " << i;
}

}  // namespace

TEST(LinearMovementConstraint, InterpolatesRelativeMovementsBetweenKeys) {
  auto s = load(vec3_scene(kVec3));
  ASSERT_TRUE(s.root);
  auto* lm = get<LinearMovementProjectiveConstraint>(*s.root, "lm");
  ASSERT_NE(lm, nullptr);
  MechanicalState& st = *s.root->mechanical_state;

  // t = 0.5: between keys 0 and 1, s = 0.5, m = (1, 0, 0); slope (2, 0, 0).
  Projected p = project_at(*s.root, st, 0.5);
  EXPECT_TRUE(lm->active());
  expect_vec3(p.x, 0, 0, 0, 0);  // not constrained
  expect_vec3(p.x, 1, 2, 1, 1);
  expect_vec3(p.x, 2, 6, 5, 5);
  expect_vec3(p.v, 0, -1, -1, -1);
  expect_vec3(p.v, 1, 2, 0, 0);
  expect_vec3(p.dx, 0, 7, 7, 7);
  expect_vec3(p.dx, 1, 0, 0, 0);
  expect_vec3(p.dx, 2, 0, 0, 0);

  // t = 2: between keys 1 and 3, s = 0.5, m = (2, 2, 0), from the first positions; slope (0, 2, 0).
  p = project_at(*s.root, st, 2.0);
  expect_vec3(p.x, 1, 3, 3, 1);
  expect_vec3(p.x, 2, 7, 7, 5);
  expect_vec3(p.v, 1, 0, 2, 0);

  // t = 2.5: s = 0.75, m = (2, 3, 0).
  p = project_at(*s.root, st, 2.5);
  expect_vec3(p.x, 1, 3, 4, 1);
}

TEST(LinearMovementConstraint, DoesNothingBeforeTheFirstKeyAndFromTheLastKeyOn) {
  auto s = load(vec3_scene(R"(<LinearMovementProjectiveConstraint name="lm" indices="1" keyTimes="1 2"
                                 movements="0 0 0  1 0 0"/>)"));
  auto* lm = get<LinearMovementProjectiveConstraint>(*s.root, "lm");
  MechanicalState& st = *s.root->mechanical_state;
  // Before the first key: untouched (the first projection still records x0).
  Projected p = project_at(*s.root, st, 0.5);
  EXPECT_FALSE(lm->active());
  expect_vec3(p.x, 1, 1, 1, 1);
  expect_vec3(p.v, 1, -1, -1, -1);
  expect_vec3(p.dx, 1, 7, 7, 7);
  // At the first key: active, m = 0.
  p = project_at(*s.root, st, 1.0);
  EXPECT_TRUE(lm->active());
  expect_vec3(p.v, 1, 1, 0, 0);
  // At the last key and after: inactive, the DoF is free again.
  st.write(kPosition)[3] = 42.0;
  for (double t : {2.0, 3.0}) {
    p = project_at(*s.root, st, t);
    EXPECT_FALSE(lm->active()) << t;
    expect_vec3(p.x, 1, 42, 1, 1);
    expect_vec3(p.v, 1, -1, -1, -1);
    expect_vec3(p.dx, 1, 7, 7, 7);
  }
}

TEST(LinearMovementConstraint, AbsoluteMovementsAreThePositions) {
  auto s = load(vec3_scene(R"(<LinearMovementProjectiveConstraint name="lm" indices="1 2" keyTimes="0 1 3"
                                 movements="0 0 0  2 0 0  2 4 0" relativeMovements="false"/>)"));
  MechanicalState& st = *s.root->mechanical_state;
  Projected p = project_at(*s.root, st, 2.0);
  expect_vec3(p.x, 1, 2, 2, 0);
  expect_vec3(p.x, 2, 2, 2, 0);
  expect_vec3(p.x, 0, 0, 0, 0);
}

TEST(LinearMovementConstraint, DefaultsAndOldName) {
  // indices default to [0]; the default single key at time 0 never acts.
  auto s = load(vec3_scene(R"(<LinearMovementConstraint name="lm"/>)"));
  auto* lm = get<LinearMovementProjectiveConstraint>(*s.root, "lm");
  ASSERT_NE(lm, nullptr);
  EXPECT_EQ(lm->indices.get(), std::vector<unsigned>{0});
  EXPECT_EQ(lm->key_times.get(), std::vector<double>{0.0});
  EXPECT_TRUE(lm->relative_movements.get());
  EXPECT_FALSE(lm->show_movement.get());
  Projected p = project_at(*s.root, *s.root->mechanical_state, 0.0);
  EXPECT_FALSE(lm->active());
  expect_vec3(p.dx, 0, 7, 7, 7);
}

TEST(LinearMovementConstraint, Vec1) {
  auto s = load(R"(<Node name="root" dt="0.1">
    <MechanicalObject template="Vec1" name="dofs" position="10 20"/>
    <LinearMovementProjectiveConstraint name="lm" template="Vec1" indices="1" keyTimes="0 0.5" movements="0 1"/>
  </Node>)");
  ASSERT_NE(get<LinearMovementProjectiveConstraint>(*s.root, "lm"), nullptr);
  MechanicalState& st = *s.root->mechanical_state;
  s.root->time.set(0.2);
  MechanicalOps ops(*s.root);
  ops.project_position(kPosition, 0.2);
  ops.project_velocity(kVelocity, 0.2);
  EXPECT_NEAR(st.read(kPosition)[1], 20.4, 1e-14);
  EXPECT_EQ(st.read(kPosition)[0], 10.0);
  EXPECT_NEAR(st.read(kVelocity)[1], 2.0, 1e-14);
}

TEST(LinearMovementConstraint, Rigid3SlerpsBetweenTheKeysEulerAngles) {
  const double half_pi = std::numbers::pi / 2;
  // DoF 0 starts unrotated, DoF 1 rotated by π/2 about x; key 2 turns by π/2 about z and moves (2, 0, 0).
  const std::string c = std::to_string(std::cos(std::numbers::pi / 4)), sq = std::to_string(std::sin(std::numbers::pi / 4));
  auto s = load(R"(<Node name="root" dt="0.1">
    <MechanicalObject template="Rigid3" name="dofs" position="0 0 0 0 0 0 1   1 2 3 )" + sq + " 0 0 " + c + R"("/>
    <LinearMovementProjectiveConstraint name="lm" template="Rigid3" indices="0 1" keyTimes="0 2"
       movements="0 0 0 0 0 0   2 0 0 0 0 )" + std::to_string(half_pi) + R"("/>
  </Node>)");
  auto* lm = get<LinearMovementProjectiveConstraint>(*s.root, "lm");
  ASSERT_NE(lm, nullptr);
  MechanicalState& st = *s.root->mechanical_state;
  const std::vector<double> start = st.read(kPosition);
  s.root->time.set(1.0);
  MechanicalOps ops(*s.root);
  ops.project_position(kPosition, 1.0);
  ops.project_velocity(kVelocity, 1.0);
  const auto& x = st.read(kPosition);
  const auto& v = st.read(kVelocity);
  // s = 0.5: the slerp of identity and a π/2 turn about z is a π/4 turn about z.
  const double qz = std::sin(std::numbers::pi / 8), qw = std::cos(std::numbers::pi / 8);
  const double tol = 1e-6;  // the angle π/2 is written with 6 decimals
  EXPECT_NEAR(x[0], 1, 1e-14);
  EXPECT_NEAR(x[1], 0, 1e-14);
  EXPECT_NEAR(x[2], 0, 1e-14);
  EXPECT_NEAR(x[3], 0, tol);
  EXPECT_NEAR(x[4], 0, tol);
  EXPECT_NEAR(x[5], qz, tol);
  EXPECT_NEAR(x[6], qw, tol);
  // DoF 1: centre (2, 2, 3); orientation q0·q with q0 = (a, 0, 0, a), q = (0, 0, qz, qw), a = √½:
  // (a·qw, −a·qz, a·qz, a·qw).
  const double a = start[10];
  EXPECT_NEAR(x[7], 2, 1e-14);
  EXPECT_NEAR(x[8], 2, 1e-14);
  EXPECT_NEAR(x[9], 3, 1e-14);
  EXPECT_NEAR(x[10], a * qw, tol);
  EXPECT_NEAR(x[11], -a * qz, tol);
  EXPECT_NEAR(x[12], a * qz, tol);
  EXPECT_NEAR(x[13], a * qw, tol);
  // Velocity: (m_next − m_prev)/(t_next − t_prev) = (1, 0, 0, 0, 0, π/4).
  for (int d = 0; d < 2; ++d) {
    EXPECT_NEAR(v[6 * d + 0], 1.0, 1e-14);
    EXPECT_NEAR(v[6 * d + 1], 0.0, 1e-14);
    EXPECT_NEAR(v[6 * d + 5], half_pi / 2, 1e-6);
  }
  // Absolute movements: the orientation is the slerp itself.
  auto s2 = load(R"(<Node name="root" dt="0.1">
    <MechanicalObject template="Rigid3" position="1 2 3 )" + sq + " 0 0 " + c + R"("/>
    <LinearMovementProjectiveConstraint template="Rigid3" indices="0" keyTimes="0 2" relativeMovements="0"
       movements="0 0 0 0 0 0   2 0 0 0 0 )" + std::to_string(half_pi) + R"("/>
  </Node>)");
  s2.root->time.set(1.0);
  MechanicalOps ops2(*s2.root);
  ops2.project_position(kPosition, 1.0);
  const auto& x2 = s2.root->mechanical_state->read(kPosition);
  EXPECT_NEAR(x2[0], 1, 1e-14);
  EXPECT_NEAR(x2[1], 0, 1e-14);
  EXPECT_NEAR(x2[5], qz, tol);
  EXPECT_NEAR(x2[6], qw, tol);
}

namespace {

// A lone driven point (0) and a point hung to it by a spring, no gravity.
std::string stepping_scene(const std::string& solver) {
  return R"(<Node name="root" dt="0.1" gravity="0 0 0">
    <DefaultAnimationLoop/>
    <EulerImplicitSolver rayleighStiffness="0" rayleighMass="0"/>
    )" + solver + R"(
    <MechanicalObject name="dofs" position="0 0 0  0 -1 0"/>
    <UniformMass totalMass="2"/>
    <SpringForceField spring="0 1 100 0 1"/>
    <LinearMovementProjectiveConstraint name="lm" indices="0" keyTimes="0 1" movements="0 0 0  1 0 0"/>
  </Node>)";
}

}  // namespace

TEST(LinearMovementConstraint, WholeStepsFollowTheMovementWithOneStepOfLag) {
  // The end-of-step projection reads the context time before it advances:
  // after step k the driven point is at m((k−1)·dt).
  for (const char* solver : {R"(<CGLinearSolver iterations="100" tolerance="1e-16" threshold="1e-20"/>)",
                             R"(<SparseLDLSolver/>)"}) {
    auto s = load(stepping_scene(solver));
    ASSERT_TRUE(s.root);
    MechanicalState& st = *s.root->mechanical_state;
    for (int k = 1; k <= 10; ++k) {
      animate(*s.root);
      const auto& x = st.read(kPosition);
      EXPECT_NEAR(x[0], 0.1 * (k - 1), 1e-12) << solver << " step " << k;
      EXPECT_NEAR(x[1], 0.0, 1e-12);
      EXPECT_NEAR(st.read(kVelocity)[0], 1.0, 1e-12);
    }
    // The hanging point was dragged along x.
    EXPECT_GT(st.read(kPosition)[3], 0.1);
  }
}

TEST(LinearMovementConstraint, AfterTheLastKeyTheDoFIsFreeUnderMatrixFreeSolvers) {
  // A lone point, no force: once the constraint stops (t0 ≥ 1), the point keeps its last velocity.
  auto s = load(R"(<Node name="root" dt="0.1" gravity="0 0 0">
    <DefaultAnimationLoop/>
    <EulerImplicitSolver/>
    <CGLinearSolver iterations="100" tolerance="1e-16" threshold="1e-20"/>
    <MechanicalObject position="0 0 0"/>
    <UniformMass totalMass="1"/>
    <LinearMovementProjectiveConstraint indices="0" keyTimes="0 1" movements="0 0 0  1 0 0"/>
  </Node>)");
  MechanicalState& st = *s.root->mechanical_state;
  for (int k = 1; k <= 15; ++k) animate(*s.root);
  EXPECT_NEAR(st.read(kPosition)[0], 1.4, 1e-12);
  EXPECT_NEAR(st.read(kVelocity)[0], 1.0, 1e-12);
}

TEST(LinearMovementConstraint, AssembledRowsAreDirichletForEveryIndex) {
  auto s = load(vec3_scene(R"(<LinearMovementProjectiveConstraint name="lm" indices="2 0" keyTimes="0 1"
                                 movements="0 0 0  1 0 0"/>)"));
  auto* lm = get<LinearMovementProjectiveConstraint>(*s.root, "lm");
  std::vector<std::size_t> rows;
  ASSERT_TRUE(lm->dirichlet_indices(rows));
  EXPECT_EQ(rows, (std::vector<std::size_t>{6, 7, 8, 0, 1, 2}));
}

TEST(LinearMovementConstraint, BadInputIsReported) {
  // Too few movements for the key times.
  auto s = sinew::test::build(vec3_scene(R"(<LinearMovementProjectiveConstraint name="lm" keyTimes="0 1"
                                                movements="0 0 0  1 0"/>)"));
  init_root(*s.root);
  auto* lm = get<LinearMovementProjectiveConstraint>(*s.root, "lm");
  EXPECT_EQ(lm->state(), ComponentState::invalid);
  EXPECT_TRUE(any_contains(messages(s.root->diagnostics(), Severity::error), "one 3-component movement per key"));
  // An index past the end is skipped with a warning; the others still move.
  auto s2 = sinew::test::build(vec3_scene(R"(<LinearMovementProjectiveConstraint name="lm" indices="9 1"
                                                 keyTimes="0 1" movements="0 0 0  1 0 0"/>)"));
  init_root(*s2.root);
  EXPECT_TRUE(any_contains(messages(s2.root->diagnostics(), Severity::warning), "index 9 is out of range"));
  Projected p = project_at(*s2.root, *s2.root->mechanical_state, 0.5);
  expect_vec3(p.x, 1, 1.5, 1, 1);
  // Keys out of order: a warning.
  auto s3 = sinew::test::build(vec3_scene(R"(<LinearMovementProjectiveConstraint keyTimes="1 0"
                                                 movements="0 0 0  1 0 0"/>)"));
  init_root(*s3.root);
  EXPECT_TRUE(any_contains(messages(s3.root->diagnostics(), Severity::warning), "not in ascending order"));
}

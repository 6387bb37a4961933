// Block laws and the corrections, on problems small enough to solve by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "constraint/solver/resolution.h"
#include "core/constraint_problem.h"
#include "state/mechanical_object.h"
#include "test_scene.h"

namespace sinew {
namespace {

ConstraintProblem problem(int n, std::initializer_list<double> w, std::initializer_list<double> dfree) {
  ConstraintProblem p;
  p.clear(n);
  std::copy(w.begin(), w.end(), p.W.begin());
  std::copy(dfree.begin(), dfree.end(), p.dfree.begin());
  return p;
}

// d = dfree + W·f for the block's rows, then the block law.
void solve_block(ConstraintBlock& b, ConstraintProblem& p) {
  resolution_init(b, p, p.f.data());
  for (int l = 0; l < b.rows; ++l) {
    double s = p.dfree[b.first + l];
    for (int k = 0; k < p.n; ++k) s += p.w(b.first + l, k) * p.f[k];
    p.d[b.first + l] = s;
  }
  resolution_solve(b, p, p.d.data(), p.f.data());
}

TEST(ConstraintBlocks, UnilateralPushesOnlyWhenPenetrating) {
  ConstraintProblem p = problem(1, {0.5}, {-0.2});
  ConstraintBlock b;
  b.kind = ConstraintBlock::Kind::unilateral;
  solve_block(b, p);
  EXPECT_DOUBLE_EQ(p.f[0], 0.4);  // W f + dfree = 0
  p = problem(1, {0.5}, {0.2});
  p.f[0] = 1.0;
  solve_block(b, p);
  EXPECT_DOUBLE_EQ(p.f[0], 0.0);  // separating: no pull
}

TEST(ConstraintBlocks, Bilateral3SolvesTheBlockExactlyAndWarmStarts) {
  // W = [[2,1,0],[1,3,0],[0,0,4]], dfree = (1, 2, -4): f = -W⁻¹ dfree = (-0.2, -0.6, 1).
  ConstraintProblem p = problem(3, {2, 1, 0, 1, 3, 0, 0, 0, 4}, {1, 2, -4});
  double warm[3] = {5, 5, 5};
  ConstraintBlock b;
  b.kind = ConstraintBlock::Kind::bilateral3;
  b.rows = 3;
  b.warm = warm;
  solve_block(b, p);  // starts from the warm forces, one exact block solve
  EXPECT_NEAR(p.f[0], -0.2, 1e-14);
  EXPECT_NEAR(p.f[1], -0.6, 1e-14);
  EXPECT_NEAR(p.f[2], 1.0, 1e-14);
  resolution_store(b, p.f.data());
  EXPECT_NEAR(warm[1], -0.6, 1e-14);
}

TEST(ConstraintBlocks, FrictionStaysInTheCoulombCone) {
  // Isotropic unit compliance; pushed in by 1 and sliding by 3 along t: fn = 1,
  // the tangential force that would stop the slide (3) is cut to mu·fn = 0.5.
  ConstraintProblem p = problem(3, {1, 0, 0, 0, 1, 0, 0, 0, 1}, {-1, 3, 0});
  bool active = false;
  ConstraintBlock b;
  b.kind = ConstraintBlock::Kind::unilateral_friction;
  b.rows = 3;
  b.mu = 0.5;
  b.active = &active;
  solve_block(b, p);
  EXPECT_DOUBLE_EQ(p.f[0], 1.0);
  EXPECT_DOUBLE_EQ(p.f[1], -0.5);
  EXPECT_DOUBLE_EQ(p.f[2], 0.0);
  resolution_store(b, p.f.data());
  EXPECT_TRUE(active);
  // Sticking: a slide of 0.2 is stopped entirely (0.2 < mu·fn).
  p = problem(3, {1, 0, 0, 0, 1, 0, 0, 0, 1}, {-1, 0.2, 0});
  solve_block(b, p);
  EXPECT_DOUBLE_EQ(p.f[1], -0.2);
}

// SOFA's augmented Lagrangian law (AugmentedLagrangianResolutionWithFriction):
// steps of −ε·d whatever W, the tangential step kept inside the cone, else
// replaced by μ·ε·d_n along the slip.
TEST(ConstraintBlocks, AugmentedLagrangianStepsByEpsilon) {
  ConstraintProblem p = problem(3, {4, 0, 0, 0, 4, 0, 0, 0, 4}, {-0.1, 0.02, 0});
  bool active = false;
  ConstraintBlock b;
  b.kind = ConstraintBlock::Kind::augmented_friction;
  b.rows = 3;
  b.mu = 0.5;
  b.epsilon = 10;
  b.active = &active;
  solve_block(b, p);
  // fn = 0 − (−0.1)·10 = 1; ft = −0.02·10 = −0.2, inside the cone (0.2 < 0.5·1).
  EXPECT_DOUBLE_EQ(p.f[0], 1.0);
  EXPECT_DOUBLE_EQ(p.f[1], -0.2);
  EXPECT_DOUBLE_EQ(p.f[2], 0.0);
  resolution_store(b, p.f.data());
  EXPECT_TRUE(active);
  // Sliding by 0.3: ft = −3 is outside the cone (3 > 0.5·fn), so SOFA steps f_t by
  // −μ·d_n·ε·d_t/|d_t| from its value before (0) instead: with d_n = −0.1 that is +0.5
  // (along the slip: SOFA's formula, kept as it is).
  p = problem(3, {4, 0, 0, 0, 4, 0, 0, 0, 4}, {-0.1, 0.3, 0});
  solve_block(b, p);
  EXPECT_DOUBLE_EQ(p.f[0], 1.0);
  EXPECT_DOUBLE_EQ(p.f[1], -(0.5 * -0.1 * 10 * 0.3 / 0.3));  // f_t −= μ·d_n·ε·d_t/|d_t|, from f_t = 0
  EXPECT_DOUBLE_EQ(p.f[2], 0.0);
  // Separating: every force back to 0.
  p = problem(3, {4, 0, 0, 0, 4, 0, 0, 0, 4}, {0.1, 0.3, 0});
  p.f[0] = 0.5;
  p.f[1] = 0.2;
  solve_block(b, p);
  EXPECT_EQ(p.f[0], 0.0);
  EXPECT_EQ(p.f[1], 0.0);
}

// A point of mass 2 resting on a fixed point through a bilateral constraint:
// one step of FreeMotionAnimationLoop with UncoupledConstraintCorrection puts
// it back exactly (W = dt/m, dx = C·Jᵀλ, x = xf + dt·dx, v = vf + dx).
TEST(ConstraintCorrections, UncoupledCorrectionCancelsTheFreeMotionOfAHeldPoint) {
  scene::LoadedScene s = test::load(R"(<Node name="root" dt="0.1" gravity="0 -10 0">
    <FreeMotionAnimationLoop/>
    <BlockGaussSeidelConstraintSolver tolerance="1e-14" maxIterations="100"/>
    <Node name="anchor"><MechanicalObject name="a" position="0 0 0"/></Node>
    <Node name="body">
      <EulerImplicitSolver rayleighMass="0" rayleighStiffness="0"/>
      <CGLinearSolver iterations="10" tolerance="1e-16" threshold="1e-16"/>
      <MechanicalObject name="p" position="0 0 0"/>
      <UniformMass totalMass="2"/>
      <UncoupledConstraintCorrection compliance="0.5"/>
    </Node>
    <BilateralLagrangianConstraint object1="@anchor/a" object2="@body/p" first_point="0" second_point="0"/>
  </Node>)");
  ASSERT_TRUE(s.root);
  animate(*s.root);
  auto* p = test::get<MechanicalObject>(*s.root->find_child_named("body"), "p");
  // Free motion: v = -1, x = -0.1; the constraint force undoes both.
  EXPECT_NEAR(p->read(kPosition)[1], 0.0, 1e-15);
  EXPECT_NEAR(p->read(kVelocity)[1], 0.0, 1e-15);
  EXPECT_NEAR(p->read(kFreePosition)[1], -0.1, 1e-15);
  EXPECT_NEAR(p->read(kFreeVelocity)[1], -1.0, 1e-15);
}

// Rigid compliance from the UniformMass: 1/m for translations and the inverse
// of inertia·mass for rotations, so a push at the centre only translates.
TEST(ConstraintCorrections, UncoupledRigidComplianceComesFromTheMass) {
  scene::LoadedScene s = test::load(R"(<Node name="root" dt="0.01">
    <Node name="body">
      <EulerImplicitSolver/><CGLinearSolver iterations="10" tolerance="1e-16" threshold="1e-16"/>
      <MechanicalObject name="r" template="Rigid3" position="0 0 0 0 0 0 1"/>
      <UniformMass vertexMass="4 1 2 0 0 0 2 0 0 0 2"/>
      <UncoupledConstraintCorrection name="cc"/>
    </Node>
  </Node>)");
  ASSERT_TRUE(s.root);
  Component* cc = s.root->find_child_named("body")->find_object_named("cc");
  const std::vector<double> c = dynamic_cast<Field<std::vector<double>>*>(cc->find_field("compliance"))->value();
  ASSERT_EQ(c.size(), 7u);
  EXPECT_DOUBLE_EQ(c[0], 0.25);   // 1/m
  EXPECT_DOUBLE_EQ(c[1], 0.125);  // 1/(I·m) = 1/(2·4)
  EXPECT_DOUBLE_EQ(c[2], 0.0);
  EXPECT_DOUBLE_EQ(c[4], 0.125);
  EXPECT_DOUBLE_EQ(c[6], 0.125);
}

}  // namespace
}  // namespace sinew

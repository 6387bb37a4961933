// Lagrangian constraint models, GenericConstraintCorrection and the mouse
// settings: Jacobian rows and violations on small hand-computed cases, the
// new resolution laws, a rigid pendulum held by a bilateral constraint, and
// GenericConstraintCorrection against LinearSolverConstraintCorrection.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "constraint/solver/resolution.h"
#include "core/constraint_problem.h"
#include "core/simulation.h"
#include "math/quat.h"
#include "test_scene.h"

namespace sinew {
namespace {

// ---------------------------------------------------------------- helpers

template <class T>
T* named(Node& root, std::string_view name) {
  std::vector<Component*> all;
  root.collect_down(all);
  for (Component* c : all)
    if (c->name.value() == name) return dynamic_cast<T*>(c);
  return nullptr;
}

// One entry of a compressed Jacobian: row id, DOF and its values.
struct Entry {
  int row, dof;
  std::vector<double> v;
};
std::vector<Entry> entries(MechanicalState& s) {
  ConstraintMatrix& J = s.constraint_jacobian();
  J.compress();
  std::vector<Entry> out;
  for (const ConstraintMatrix::Row& r : J.rows())
    for (int e = r.begin; e < r.end; ++e)
      out.push_back({r.id, J.entries()[e].dof, std::vector<double>(J.value(e), J.value(e) + J.width())});
  return out;
}
void expect_entry(const Entry& e, int row, int dof, std::vector<double> v) {
  EXPECT_EQ(e.row, row);
  EXPECT_EQ(e.dof, dof);
  ASSERT_EQ(e.v.size(), v.size());
  for (std::size_t k = 0; k < v.size(); ++k) EXPECT_NEAR(e.v[k], v[k], 1e-15) << "row " << row << " component " << k;
}

// Runs the three calls of a constraint step on `c` with rows numbered from
// `first`; returns the violation vector (size first + rows).
struct Built {
  int rows = 0;
  std::vector<double> dfree;
  std::vector<ConstraintBlock> blocks;
};
Built build(LagrangianConstraint& c, const std::vector<MechanicalState*>& states, int first,
            ConstraintOrder order = ConstraintOrder::pos_and_vel, double dt = 0.1) {
  for (MechanicalState* s : states) s->constraint_jacobian().clear(s->info().deriv_width);
  ConstraintParams p;
  p.order = order;
  p.dt = dt;
  int row = first;
  c.build_constraint_matrix(p, row);
  Built b;
  b.rows = row - first;
  b.dfree.assign(row, 0.0);
  c.constraint_violation(p, b.dfree);
  c.constraint_resolutions(p, b.blocks);
  return b;
}

void set_vec(MechanicalState& s, int id, std::vector<double> v) { s.write(id) = std::move(v); }

Quat quat_z(double a) { return {0, 0, std::sin(a / 2), std::cos(a / 2)}; }
Quat quat_x(double a) { return {std::sin(a / 2), 0, 0, std::cos(a / 2)}; }

// ---------------------------------------------------------------- FixedLagrangianConstraint

TEST(FixedLagrangianConstraint, Vec3RowsAreUnitVectorsAndViolationIsFreeMinusRest) {
  auto s = test::load(R"(<Node name="root">
    <MechanicalObject name="dofs" position="0 0 0  1 0 0  2 0 0"/>
    <FixedLagrangianConstraint name="c" indices="0 2"/>
  </Node>)");
  auto* dofs = named<MechanicalState>(*s.root, "dofs");
  auto* c = named<LagrangianConstraint>(*s.root, "c");
  ASSERT_TRUE(dofs && c);
  set_vec(*dofs, kFreePosition, {0.1, 0.2, 0.3, 1, 0, 0, 2.5, -1, 0});
  const Built b = build(*c, {dofs}, 4);
  EXPECT_EQ(b.rows, 6);
  EXPECT_EQ(c->constraint_index.value(), 4u);
  const auto e = entries(*dofs);
  ASSERT_EQ(e.size(), 6u);
  expect_entry(e[0], 4, 0, {1, 0, 0});
  expect_entry(e[1], 5, 0, {0, 1, 0});
  expect_entry(e[2], 6, 0, {0, 0, 1});
  expect_entry(e[3], 7, 2, {1, 0, 0});
  expect_entry(e[5], 9, 2, {0, 0, 1});
  const std::vector<double> want = {0, 0, 0, 0, 0.1, 0.2, 0.3, 0.5, -1, 0};
  for (std::size_t i = 0; i < want.size(); ++i) EXPECT_NEAR(b.dfree[i], want[i], 1e-15) << i;
  // One warm-started 3-row block per DOF.
  ASSERT_EQ(b.blocks.size(), 2u);
  EXPECT_EQ(b.blocks[0].kind, ConstraintBlock::Kind::bilateral3);
  EXPECT_EQ(b.blocks[0].first, 4);
  EXPECT_EQ(b.blocks[1].first, 7);
  EXPECT_NE(b.blocks[0].warm, nullptr);
}

TEST(FixedLagrangianConstraint, Rigid3ViolationIsCentreOffsetAndEulerAngles) {
  auto s = test::load(R"(<Node name="root">
    <MechanicalObject name="frame" template="Rigid3d" position="1 2 3 0 0 0 1"/>
    <FixedLagrangianConstraint name="c" indices="0"/>
  </Node>)");
  auto* frame = named<MechanicalState>(*s.root, "frame");
  auto* c = named<LagrangianConstraint>(*s.root, "c");
  ASSERT_TRUE(frame && c);
  const Quat q = quat_z(0.3);
  set_vec(*frame, kFreePosition, {1.5, 2, 3, q.x, q.y, q.z, q.w});
  const Built b = build(*c, {frame}, 0);
  ASSERT_EQ(b.rows, 6);
  const auto e = entries(*frame);
  ASSERT_EQ(e.size(), 6u);
  expect_entry(e[0], 0, 0, {1, 0, 0, 0, 0, 0});
  expect_entry(e[3], 3, 0, {0, 0, 0, 1, 0, 0});
  expect_entry(e[5], 5, 0, {0, 0, 0, 0, 0, 1});
  const std::vector<double> want = {0.5, 0, 0, 0, 0, 0.3};
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(b.dfree[i], want[i], 1e-14) << i;
  // Translation and rotation: two warm-started 3-row blocks.
  ASSERT_EQ(b.blocks.size(), 2u);
  EXPECT_EQ(b.blocks[1].first, 3);
  EXPECT_EQ(b.blocks[1].kind, ConstraintBlock::Kind::bilateral3);
  EXPECT_EQ(b.blocks[1].warm, b.blocks[0].warm + 3);
}

TEST(FixedLagrangianConstraint, Vec1FixAllUsesExactBlocks) {
  auto s = test::load(R"(<Node name="root">
    <MechanicalObject name="v" template="Vec1d" position="1 2"/>
    <FixedLagrangianConstraint name="c" template="Vec1d" fixAll="true"/>
  </Node>)");
  auto* v = named<MechanicalState>(*s.root, "v");
  auto* c = named<LagrangianConstraint>(*s.root, "c");
  ASSERT_TRUE(v && c);
  set_vec(*v, kFreePosition, {1.25, 1.5});
  const Built b = build(*c, {v}, 0);
  ASSERT_EQ(b.rows, 2);
  EXPECT_NEAR(b.dfree[0], 0.25, 1e-15);
  EXPECT_NEAR(b.dfree[1], -0.5, 1e-15);
  ASSERT_EQ(b.blocks.size(), 2u);
  EXPECT_EQ(b.blocks[0].kind, ConstraintBlock::Kind::bilateral_n);
  EXPECT_EQ(b.blocks[0].rows, 1);
  EXPECT_NE(b.blocks[0].factor, nullptr);
}

TEST(FixedLagrangianConstraint, IndexOutOfRangeIsAnErrorNotACrash) {
  auto s = test::build(R"(<Node name="root" dt="0.01">
    <FreeMotionAnimationLoop/>
    <BlockGaussSeidelConstraintSolver/>
    <EulerImplicitSolver/>
    <CGLinearSolver iterations="10"/>
    <MechanicalObject name="dofs" position="0 0 0"/>
    <UniformMass totalMass="1"/>
    <UncoupledConstraintCorrection/>
    <FixedLagrangianConstraint name="c" indices="0 5"/>
  </Node>)");
  init_root(*s.root);
  const auto errors = test::messages(s.root->diagnostics(), Severity::error);
  EXPECT_TRUE(test::any_contains(errors, "index 5")) << ::testing::PrintToString(errors);
  auto* c = named<LagrangianConstraint>(*s.root, "c");
  EXPECT_EQ(c->state(), ComponentState::invalid);
  for (int i = 0; i < 3; ++i) animate(*s.root);  // the step skips it
}

// ---------------------------------------------------------------- UniformLagrangianConstraint

TEST(UniformLagrangianConstraint, OneRowPerValueWithPositionAndVelocityViolations) {
  auto s = test::load(R"(<Node name="root">
    <MechanicalObject name="v" template="Vec1d" position="0.1 -0.2 0.3"/>
    <UniformLagrangianConstraint name="zero" template="Vec1d"/>
    <UniformLagrangianConstraint name="rest" template="Vec1d" constrainToRestPos="true" iterative="false"/>
  </Node>)");
  auto* v = named<MechanicalState>(*s.root, "v");
  auto* zero = named<LagrangianConstraint>(*s.root, "zero");
  auto* rest = named<LagrangianConstraint>(*s.root, "rest");
  ASSERT_TRUE(v && zero && rest);
  set_vec(*v, kFreePosition, {0.5, 0, -1});
  set_vec(*v, kFreeVelocity, {1, 2, 3});

  Built b = build(*zero, {v}, 1);
  ASSERT_EQ(b.rows, 3);
  const auto e = entries(*v);
  ASSERT_EQ(e.size(), 3u);
  expect_entry(e[2], 3, 2, {1});
  EXPECT_NEAR(b.dfree[1], 0.5, 1e-15);
  EXPECT_NEAR(b.dfree[3], -1, 1e-15);
  ASSERT_EQ(b.blocks.size(), 3u);  // iterative: one bilateral row each
  EXPECT_EQ(b.blocks[2].kind, ConstraintBlock::Kind::bilateral);
  EXPECT_EQ(b.blocks[2].first, 3);

  b = build(*rest, {v}, 0);
  EXPECT_NEAR(b.dfree[0], 0.4, 1e-15);
  EXPECT_NEAR(b.dfree[1], 0.2, 1e-15);
  EXPECT_NEAR(b.dfree[2], -1.3, 1e-15);
  ASSERT_EQ(b.blocks.size(), 1u);  // not iterative: one exact block
  EXPECT_EQ(b.blocks[0].kind, ConstraintBlock::Kind::bilateral_n);
  EXPECT_EQ(b.blocks[0].rows, 3);

  // Velocity order: v_free + x/dt (x the current position), dt = 0.1.
  b = build(*zero, {v}, 0, ConstraintOrder::vel, 0.1);
  EXPECT_NEAR(b.dfree[0], 2, 1e-14);
  EXPECT_NEAR(b.dfree[1], 0, 1e-14);
  EXPECT_NEAR(b.dfree[2], 6, 1e-14);
}

// ---------------------------------------------------------------- StopperLagrangianConstraint

TEST(StopperLagrangianConstraint, RowOnOneValueAndFreeValuePushedBackOnItsBound) {
  auto s = test::load(R"(<Node name="root">
    <MechanicalObject name="v" template="Vec1d" position="0 0.8"/>
    <StopperLagrangianConstraint name="c" index="1" min="-1" max="0.5"/>
  </Node>)");
  auto* v = named<MechanicalState>(*s.root, "v");
  auto* c = named<LagrangianConstraint>(*s.root, "c");
  ASSERT_TRUE(v && c);
  set_vec(*v, kFreePosition, {0, 0.8});
  const Built b = build(*c, {v}, 0);
  ASSERT_EQ(b.rows, 1);
  const auto e = entries(*v);
  ASSERT_EQ(e.size(), 1u);
  expect_entry(e[0], 0, 1, {1});
  EXPECT_NEAR(b.dfree[0], 0.8, 1e-15);
  ASSERT_EQ(b.blocks.size(), 1u);
  EXPECT_EQ(b.blocks[0].kind, ConstraintBlock::Kind::stopper);

  // W = 2: the free value 0.8 passes max 0.5, so f = (0.5 − 0.8)/2 and d lands on 0.5.
  ConstraintProblem P;
  P.clear(1);
  P.w(0, 0) = 2;
  P.dfree[0] = 0.8;
  ConstraintBlock blk = b.blocks[0];
  P.f[0] = 7;  // the law starts from zero force
  ASSERT_TRUE(resolution_init(blk, P, P.f.data()));
  EXPECT_EQ(P.f[0], 0.0);
  for (int it = 0; it < 2; ++it) {
    P.d[0] = P.dfree[0] + P.w(0, 0) * P.f[0];
    resolution_solve(blk, P, P.d.data(), P.f.data());
    EXPECT_NEAR(P.f[0], -0.15, 1e-15);
  }
  // Inside the range: no force.
  P.dfree[0] = 0.2;
  P.d[0] = P.dfree[0] + P.w(0, 0) * P.f[0];
  resolution_solve(blk, P, P.d.data(), P.f.data());
  EXPECT_EQ(P.f[0], 0.0);
}

// ---------------------------------------------------------------- resolution: bilateral_n

TEST(Resolution, ExactBlockSolvesItsRowsInOneProjection) {
  ConstraintProblem P;
  P.clear(2);
  P.w(0, 0) = 2, P.w(0, 1) = 1, P.w(1, 0) = 1, P.w(1, 1) = 3;
  P.dfree = {1, 2};
  BlockFactor factor;
  ConstraintBlock b;
  b.kind = ConstraintBlock::Kind::bilateral_n;
  b.rows = 2;
  b.factor = &factor;
  ASSERT_TRUE(resolution_init(b, P, P.f.data()));
  P.d = P.dfree;
  resolution_solve(b, P, P.d.data(), P.f.data());
  // f = −W⁻¹·d = −(1/5)·[[3, −1], [−1, 2]]·(1, 2) = (−0.2, −0.6)
  EXPECT_NEAR(P.f[0], -0.2, 1e-15);
  EXPECT_NEAR(P.f[1], -0.6, 1e-15);
}

// ---------------------------------------------------------------- SlidingLagrangianConstraint

const char* kSliding = R"(<Node name="root">
  <Node name="p"><MechanicalObject name="P" position="0.5 1 0"/></Node>
  <Node name="ab"><MechanicalObject name="AB" position="0 0 0  2 0 0"/></Node>
  <SlidingLagrangianConstraint name="c" object1="@p/P" object2="@ab/AB" sliding_point="0" axis_1="0" axis_2="1"/>
</Node>)";

TEST(SlidingLagrangianConstraint, RowsAlongProjectionNormalAndBothAxisStops) {
  auto s = test::load(kSliding);
  auto* P = named<MechanicalState>(*s.root, "P");
  auto* AB = named<MechanicalState>(*s.root, "AB");
  auto* c = named<LagrangianConstraint>(*s.root, "c");
  ASSERT_TRUE(P && AB && c);
  set_vec(*P, kFreePosition, {0.5, 1, 0});
  set_vec(*AB, kFreePosition, {0, 0, 0, 2, 0, 0});
  const Built b = build(*c, {P, AB}, 0);
  ASSERT_EQ(b.rows, 4);
  // Axis (1,0,0), P projects at x = 0.5: b = 0.25; dirProj (0,1,0), dirOrtho = dirProj × axis = (0,0,−1).
  const auto e1 = entries(*P);
  ASSERT_EQ(e1.size(), 4u);
  expect_entry(e1[0], 0, 0, {0, 1, 0});
  expect_entry(e1[1], 1, 0, {0, 0, -1});
  expect_entry(e1[2], 2, 0, {1, 0, 0});
  expect_entry(e1[3], 3, 0, {-1, 0, 0});
  const auto e2 = entries(*AB);
  ASSERT_EQ(e2.size(), 6u);
  expect_entry(e2[0], 0, 0, {0, -0.75, 0});
  expect_entry(e2[1], 0, 1, {0, -0.25, 0});
  expect_entry(e2[2], 1, 0, {0, 0, 0.75});
  expect_entry(e2[3], 1, 1, {0, 0, 0.25});
  expect_entry(e2[4], 2, 0, {-1, 0, 0});
  expect_entry(e2[5], 3, 1, {1, 0, 0});
  EXPECT_NEAR(b.dfree[0], 1, 1e-15);
  EXPECT_NEAR(b.dfree[1], 0, 1e-15);
  EXPECT_NEAR(b.dfree[2], 0.5, 1e-15);
  EXPECT_NEAR(b.dfree[3], 1.5, 1e-15);
  ASSERT_EQ(b.blocks.size(), 4u);
  EXPECT_EQ(b.blocks[1].kind, ConstraintBlock::Kind::bilateral);
  EXPECT_EQ(b.blocks[2].kind, ConstraintBlock::Kind::unilateral);
  EXPECT_EQ(b.blocks[3].kind, ConstraintBlock::Kind::unilateral);

  // force = Σ direction·λ once the blocks are stored: λ = (1, 2, 3, 4).
  const double f[4] = {1, 2, 3, 4};
  for (ConstraintBlock blk : b.blocks) resolution_store(blk, f);
  const Vec3 force = dynamic_cast<Field<Vec3>*>(c->find_field("force"))->value();
  EXPECT_NEAR(force[0], -1, 1e-15);
  EXPECT_NEAR(force[1], 1, 1e-15);
  EXPECT_NEAR(force[2], -2, 1e-15);
}

TEST(SlidingLagrangianConstraint, CoincidentAxisEndsTieThePointToThem) {
  auto s = test::load(R"(<Node name="root">
    <Node name="p"><MechanicalObject name="P" position="0.5 1 0"/></Node>
    <Node name="ab"><MechanicalObject name="AB" position="1 1 1  1 1 1"/></Node>
    <SlidingLagrangianConstraint name="c" object1="@p/P" object2="@ab/AB" axis_1="0" axis_2="1"/>
  </Node>)");
  auto* P = named<MechanicalState>(*s.root, "P");
  auto* AB = named<MechanicalState>(*s.root, "AB");
  auto* c = named<LagrangianConstraint>(*s.root, "c");
  set_vec(*P, kFreePosition, {0.5, 1, 0});
  set_vec(*AB, kFreePosition, {1, 1, 1, 1, 1, 1});
  const Built b = build(*c, {P, AB}, 0);
  ASSERT_EQ(b.rows, 3);
  const auto e2 = entries(*AB);
  ASSERT_EQ(e2.size(), 3u);
  expect_entry(e2[1], 1, 0, {0, -1, 0});
  EXPECT_NEAR(b.dfree[0], -0.5, 1e-15);
  EXPECT_NEAR(b.dfree[2], -1, 1e-15);
  ASSERT_EQ(b.blocks.size(), 3u);
  for (const ConstraintBlock& blk : b.blocks) EXPECT_EQ(blk.kind, ConstraintBlock::Kind::bilateral);
}

// ---------------------------------------------------------------- BilateralLagrangianConstraint Rigid3d

TEST(BilateralLagrangianConstraint, Rigid3RowsAndViolationInFrameOne) {
  // Frame 1 turned 90° about x; frame 2 = frame 1 turned 0.2 about its own z:
  // the rotation vector from 1 to 2 in world axes is 0.2 along R_x(90°)·z = −y.
  const Quat q1 = quat_x(M_PI / 2);
  const Quat q2 = quat_mul(q1, quat_z(0.2));
  auto text = [](const Quat& q) {
    return std::to_string(q.x) + " " + std::to_string(q.y) + " " + std::to_string(q.z) + " " + std::to_string(q.w);
  };
  auto s = test::load(R"(<Node name="root">
    <Node name="a"><MechanicalObject name="f1" template="Rigid3d" position="0 0 0 )" + text(q1) + R"("/></Node>
    <Node name="b"><MechanicalObject name="f2" template="Rigid3d" position="1 2 3 )" + text(q2) + R"("/></Node>
    <BilateralLagrangianConstraint name="c" template="Rigid3d" object1="@a/f1" object2="@b/f2"
        first_point="0" second_point="0" rest_vector="0.5 0 0 0 0 0"/>
  </Node>)");
  auto* f1 = named<MechanicalState>(*s.root, "f1");
  auto* f2 = named<MechanicalState>(*s.root, "f2");
  auto* c = named<LagrangianConstraint>(*s.root, "c");
  ASSERT_TRUE(f1 && f2 && c);
  set_vec(*f1, kFreePosition, f1->read(kPosition));
  set_vec(*f2, kFreePosition, f2->read(kPosition));
  const Built b = build(*c, {f1, f2}, 2);
  ASSERT_EQ(b.rows, 6);
  const auto e1 = entries(*f1), e2 = entries(*f2);
  ASSERT_EQ(e1.size(), 6u);
  ASSERT_EQ(e2.size(), 6u);
  expect_entry(e1[0], 2, 0, {-1, 0, 0, 0, 0, 0});
  expect_entry(e1[4], 6, 0, {0, 0, 0, 0, -1, 0});
  expect_entry(e2[5], 7, 0, {0, 0, 0, 0, 0, 1});
  const std::vector<double> want = {0.5, 2, 3, 0, -0.2, 0};
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(b.dfree[2 + i], want[i], 1e-6) << i;  // quaternions printed to 6 digits
  // Two 3-row blocks per pair, from zero force, no load (SOFA's Rigid3d variant).
  ASSERT_EQ(b.blocks.size(), 2u);
  EXPECT_EQ(b.blocks[0].first, 2);
  EXPECT_EQ(b.blocks[1].first, 5);
  EXPECT_EQ(b.blocks[0].warm, nullptr);
  EXPECT_EQ(b.blocks[1].load, 1.0);
}

TEST(BilateralLagrangianConstraint, Rigid3KeepOrientationDifferenceHoldsTheInitialOffset) {
  auto s = test::load(R"(<Node name="root">
    <Node name="a"><MechanicalObject name="f1" template="Rigid3d" position="0 0 0 0.2 0.1 0 0.9746794"/></Node>
    <Node name="b"><MechanicalObject name="f2" template="Rigid3d" position="1 2 3 0 0.3 0.4 0.8660254"/></Node>
    <BilateralLagrangianConstraint name="c" template="Rigid3d" object1="@a/f1" object2="@b/f2"
        first_point="0" second_point="0" keepOrientationDifference="true" rest_vector="1 1 1 1 1 1"/>
  </Node>)");
  const auto warnings = test::messages(s.root->diagnostics(), Severity::warning);
  EXPECT_TRUE(test::any_contains(warnings, "rest_vector is ignored"));
  auto* f1 = named<MechanicalState>(*s.root, "f1");
  auto* f2 = named<MechanicalState>(*s.root, "f2");
  auto* c = named<LagrangianConstraint>(*s.root, "c");
  set_vec(*f1, kFreePosition, f1->read(kPosition));
  set_vec(*f2, kFreePosition, f2->read(kPosition));
  Built b = build(*c, {f1, f2}, 0);
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(b.dfree[i], 0, 1e-7) << i;
  // Moving frame 2 by (0.1, 0, 0) shows as that centre violation only.
  std::vector<double> x2 = f2->read(kPosition);
  x2[0] += 0.1;
  set_vec(*f2, kFreePosition, x2);
  b = build(*c, {f1, f2}, 0);
  EXPECT_NEAR(b.dfree[0], 0.1, 1e-12);
  for (int i = 1; i < 6; ++i) EXPECT_NEAR(b.dfree[i], 0, 1e-7) << i;
}

TEST(BilateralLagrangianConstraint, Rigid3TemplateOnPointsIsAnError) {
  auto s = test::build(R"(<Node name="root">
    <MechanicalObject name="p" position="0 0 0  1 0 0"/>
    <BilateralLagrangianConstraint name="c" template="Rigid3d" first_point="0" second_point="1"/>
  </Node>)");
  init_root(*s.root);
  const auto errors = test::messages(s.root->diagnostics(), Severity::error);
  EXPECT_TRUE(test::any_contains(errors, "Rigid3d")) << ::testing::PrintToString(errors);
  EXPECT_EQ(named<LagrangianConstraint>(*s.root, "c")->state(), ComponentState::invalid);
}

// ---------------------------------------------------------------- pendulum

// A rigid body hung from a fixed point by a bilateral constraint on the point
// of the body at distance 1 from its centre (mapped by RigidMapping): the
// body swings, its centre stays at distance 1 from the anchor. The position
// correction is linear in the rotation, so the length error of a step is of
// order (ω·dt)² (3e-7 at the bottom of this swing), and does not accumulate.
TEST(BilateralPendulum, RigidBodyKeepsItsLengthOver1000Steps) {
  auto s = test::load(R"(<Node name="root" dt="0.001" gravity="0 -9.81 0">
    <FreeMotionAnimationLoop/>
    <BlockGaussSeidelConstraintSolver tolerance="1e-12" maxIterations="100"/>
    <Node name="anchor"><MechanicalObject name="a" position="0 0 0"/></Node>
    <Node name="body">
      <EulerImplicitSolver rayleighStiffness="0" rayleighMass="0"/>
      <CGLinearSolver iterations="50" tolerance="1e-20" threshold="1e-30"/>
      <MechanicalObject name="frame" template="Rigid3d" position="0.28 -0.96 0 0 0 0.6 0.8"/>
      <UniformMass totalMass="1"/>
      <UncoupledConstraintCorrection/>
      <Node name="pin">
        <MechanicalObject name="p" position="0 0 0"/>
        <RigidMapping globalToLocalCoords="true"/>
      </Node>
    </Node>
    <BilateralLagrangianConstraint object1="@anchor/a" object2="@body/pin/p" first_point="0" second_point="0"/>
  </Node>)");
  auto* frame = named<MechanicalState>(*s.root, "frame");
  auto* pin = named<MechanicalState>(*s.root, "p");
  ASSERT_TRUE(frame && pin);
  double max_error = 0, max_pin = 0, min_x = 1;
  for (int i = 0; i < 1000; ++i) {
    animate(*s.root);
    const std::vector<double>& x = frame->read(kPosition);
    const double len = std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
    max_error = std::max(max_error, std::abs(len - 1.0));
    const std::vector<double>& p = pin->read(kPosition);
    max_pin = std::max(max_pin, std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]));
    min_x = std::min(min_x, x[0]);
  }
  EXPECT_LT(max_error, 1e-6);
  EXPECT_LT(max_pin, 1e-6);
  EXPECT_LT(min_x, -0.1);  // it swung through the bottom to the other side
}

// A chain of particles whose edge lengths (DistanceMapping) are held by a
// UniformLagrangianConstraint, solved at the velocity level and corrected by
// GenericConstraintCorrection (SOFA's InextensiblePendulum, smaller).
std::string chain(bool iterative) {
  return std::string(R"(<Node name="root" dt="0.01" gravity="0 -10 0">
    <FreeMotionAnimationLoop solveVelocityConstraintFirst="true"/>
    <BlockGaussSeidelConstraintSolver tolerance="1e-12" maxIterations="1000"/>
    <EulerImplicitSolver/>
    <EigenSimplicialLLT template="CompressedRowSparseMatrixMat3x3d"/>
    <GenericConstraintCorrection/>
    <EdgeSetTopologyContainer name="topology" position="0 0 0  0.25 0 0  0.5 0 0  0.75 0 0  1 0 0"
        edges="0 1  1 2  2 3  3 4"/>
    <MechanicalObject name="dofs"/>
    <FixedProjectiveConstraint indices="0"/>
    <DiagonalMass totalMass="1e-3"/>
    <Node name="lengths">
      <MechanicalObject name="ext" template="Vec1d"/>
      <DistanceMapping topology="@../topology"/>
      <UniformLagrangianConstraint template="Vec1d" iterative=")") +
         (iterative ? "true" : "false") + R"("/>
    </Node>
  </Node>)";
}

TEST(UniformLagrangianConstraint, ChainKeepsItsLengthsWithGenericConstraintCorrection) {
  // The chain swings down from horizontal and whips up the other side within 1 s.
  std::vector<double> end[2];
  for (bool iterative : {false, true}) {
    auto s = test::load(chain(iterative));
    auto* ext = named<MechanicalState>(*s.root, "ext");
    auto* dofs = named<MechanicalState>(*s.root, "dofs");
    ASSERT_TRUE(ext && dofs);
    double worst = 0, lowest = 0;
    for (int i = 0; i < 100; ++i) {
      animate(*s.root);
      for (double e : ext->read(kPosition)) worst = std::max(worst, std::abs(e));
      lowest = std::min(lowest, dofs->read(kPosition)[13]);
    }
    end[iterative] = dofs->read(kPosition);
    EXPECT_LT(lowest, -0.95) << "iterative " << iterative;
    // Velocity-level constraints let a length drift by about (v·dt)²/(2·l) in a
    // step: 5e-3 of the 0.25 edges when the free end whips through the bottom.
    EXPECT_LT(worst, 6e-3) << "iterative " << iterative;
  }
  // Row by row (Gauss-Seidel to 1e-12) or the whole block at once (LDLT): the same motion.
  for (std::size_t k = 0; k < end[0].size(); ++k) EXPECT_NEAR(end[0][k], end[1][k], 1e-10) << k;
}

// ---------------------------------------------------------------- GenericConstraintCorrection

// Two identical spring bodies held by FixedLagrangianConstraint, one corrected
// by LinearSolverConstraintCorrection, the other by GenericConstraintCorrection.
std::string two_bodies(const std::string& generic_attrs = "") {
  auto body = [](const std::string& name, const std::string& correction) {
    return "<Node name='" + name + R"('>
      <EulerImplicitSolver rayleighStiffness="0.1" rayleighMass="0.1"/>
      <SparseLDLSolver name="ls" template="CompressedRowSparseMatrixMat3x3d"/>
      <MechanicalObject name="dofs" position="0 0 0  1 0 0  1 1 0  0 1 0"/>
      <UniformMass totalMass="1"/>
      <MeshTopology edges="0 1  1 2  2 3  3 0  0 2"/>
      <MeshSpringForceField stiffness="100" damping="0.5"/>
      <FixedLagrangianConstraint indices="0 3"/>
      )" + correction + "</Node>";
  };
  return R"(<Node name="root" dt="0.01" gravity="0 -9.81 0">
    <FreeMotionAnimationLoop/>
    <BlockGaussSeidelConstraintSolver tolerance="1e-12" maxIterations="500"/>)" +
         body("A", R"(<LinearSolverConstraintCorrection name="cc" linearSolver="@ls"/>)") +
         body("B", "<GenericConstraintCorrection name='cc' " + generic_attrs + "/>") + "</Node>";
}

// W of the last step's Jacobian from one correction.
ConstraintProblem compliance_of(ConstraintCorrection& cc, int n, double dt) {
  ConstraintParams p;
  p.dt = dt;
  ConstraintProblem P;
  P.clear(n);
  cc.add_compliance(p, P);
  return P;
}

TEST(GenericConstraintCorrection, ComplianceAndMotionEqualLinearSolverConstraintCorrection) {
  auto s = test::load(two_bodies());
  Node* a = s.root->find_child_named("A");
  Node* b = s.root->find_child_named("B");
  ASSERT_TRUE(a && b);
  auto* cca = test::get<ConstraintCorrection>(*a, "cc");
  auto* ccb = test::get<ConstraintCorrection>(*b, "cc");
  ASSERT_TRUE(cca && ccb);
  EXPECT_EQ(ccb->class_name(), "GenericConstraintCorrection");
  for (int i = 0; i < 20; ++i) animate(*s.root);
  // Rows 0-5 are body A's, 6-11 body B's (its Jacobian is still on the states).
  const ConstraintProblem wa = compliance_of(*cca, 12, 0.01), wb = compliance_of(*ccb, 12, 0.01);
  double largest = 0;
  for (int r = 0; r < 6; ++r)
    for (int c = 0; c < 6; ++c) {
      largest = std::max(largest, std::abs(wa.w(r, c)));
      EXPECT_NEAR(wb.w(6 + r, 6 + c), wa.w(r, c), 1e-15) << r << ", " << c;
      EXPECT_EQ(wb.w(r, c), 0.0);  // B's correction sees only B's rows
    }
  EXPECT_GT(largest, 1e-4);
  const std::vector<double>& xa = test::get<MechanicalState>(*a, "dofs")->read(kPosition);
  const std::vector<double>& xb = test::get<MechanicalState>(*b, "dofs")->read(kPosition);
  ASSERT_EQ(xa.size(), xb.size());
  for (std::size_t k = 0; k < xa.size(); ++k) EXPECT_NEAR(xa[k], xb[k], 1e-14) << k;
  EXPECT_NEAR(xa[0], 0.0, 1e-9);  // fixed point 0 held
  EXPECT_LT(xa[4], -1e-3);        // point 1 fell
}

TEST(GenericConstraintCorrection, ComplianceFactorAndRegularizationScaleW) {
  auto s = test::load(two_bodies("complianceFactor='2' regularizationTerm='0.5'"));
  animate(*s.root);  // one step: both systems were assembled at the same (initial) state
  auto* cca = test::get<ConstraintCorrection>(*s.root->find_child_named("A"), "cc");
  auto* ccb = test::get<ConstraintCorrection>(*s.root->find_child_named("B"), "cc");
  const ConstraintProblem wa = compliance_of(*cca, 12, 0.01), wb = compliance_of(*ccb, 12, 0.01);
  for (int r = 0; r < 6; ++r)
    for (int c = 0; c < 6; ++c)
      EXPECT_NEAR(wb.w(6 + r, 6 + c), 2 * wa.w(r, c) + (r == c ? 0.5 : 0.0), 1e-14) << r << ", " << c;
}

TEST(GenericConstraintCorrection, WithoutAnAssembledSolverIsAnError) {
  auto s = test::build(R"(<Node name="root">
    <EulerImplicitSolver/>
    <CGLinearSolver iterations="10"/>
    <MechanicalObject position="0 0 0"/>
    <GenericConstraintCorrection name="cc"/>
  </Node>)");
  init_root(*s.root);
  const auto errors = test::messages(s.root->diagnostics(), Severity::error);
  EXPECT_TRUE(test::any_contains(errors, "does not assemble its matrix")) << ::testing::PrintToString(errors);
  EXPECT_EQ(named<ConstraintCorrection>(*s.root, "cc")->state(), ComponentState::invalid);

  auto s2 = test::build(R"(<Node name="root"><MechanicalObject position="0 0 0"/><GenericConstraintCorrection/></Node>)");
  init_root(*s2.root);
  EXPECT_TRUE(test::any_contains(test::messages(s2.root->diagnostics(), Severity::error), "no linear solver"));
}

// ---------------------------------------------------------------- mouse settings

TEST(MouseButtonSettings, LoadWithTheirDataAndDoNothing) {
  auto s = test::load(R"(<Node name="root">
    <ConstraintAttachButtonSetting name="cab" button="Right"/>
    <AttachBodyButtonSetting name="ab" stiffness="5" arrowSize="0.2" showFactorSize="2"/>
  </Node>)");
  Component* ab = named<Component>(*s.root, "ab");
  ASSERT_NE(ab, nullptr);
  EXPECT_EQ(ab->find_field("stiffness")->text(), "5");
  EXPECT_EQ(ab->find_field("button")->text(), "Left");
  EXPECT_EQ(named<Component>(*s.root, "cab")->find_field("button")->text(), "Right");
  animate(*s.root);

  auto bad = test::build(R"(<Node name="root"><ConstraintAttachButtonSetting button="Thumb"/></Node>)");
  init_root(*bad.root);
  EXPECT_TRUE(test::any_contains(test::messages(bad.root->diagnostics(), Severity::warning), "Thumb"));
}

}  // namespace
}  // namespace sinew

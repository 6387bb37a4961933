// The Lagrangian solvers inside FreeMotionAnimationLoop scenes, against
// hand-computed steps: a point held to an anchor by a bilateral constraint
// (one step corrects it exactly; UnbuiltGaussSeidel with
// UncoupledConstraintCorrection only by dt of it, SOFA's quirk), points
// resting on planes through LCPConstraintSolver (built and unbuilt, both
// corrections), its warm start by persistent contact id, and the messages
// of non-convergence and inconsistent settings.
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "constraint/solver/generic_constraint_solver.h"
#include "constraint/solver/lcp_constraint_solver.h"
#include "constraint_test_helpers.h"
#include "core/node.h"
#include "core/simulation.h"
#include "test_scene.h"

namespace sinew {
namespace {

// ---------------------------------------------------------------- bilateral

// A point of unit mass at (0.1, 0, 0), no gravity, held to a fixed anchor at
// the origin. Free motion: x_f = x. With compliance c and implicit Euler
// (position factor dt, velocity factor 1):
//  built:   W = c·dt, λ = −0.1/(c·dt), dx = c·λ  →  x = x_f + dt·dx = 0, v = dx = −0.1/dt
//  unbuilt: W = c (no factor), λ = −0.1/c        →  x = 0.1 − dt·0.1,   v = −0.1
std::string anchored_point(const std::string& solver, const std::string& correction) {
  return R"(<Node name="root" dt="0.01" gravity="0 0 0">
    <FreeMotionAnimationLoop/>
    )" + solver + R"(
    <Node name="anchor"><MechanicalObject name="x" position="0 0 0"/></Node>
    <Node name="body">
      <EulerImplicitSolver rayleighMass="0" rayleighStiffness="0"/>
      <SparseLDLSolver/>
      <MechanicalObject name="x" position="0.1 0 0"/>
      <UniformMass totalMass="1"/>
      )" + correction + R"(
    </Node>
    <BilateralLagrangianConstraint object1="@anchor/x" object2="@body/x" first_point="0" second_point="0"/>
  </Node>)";
}

Vec3 point(Node& root, const char* node, int vec) {
  auto* st = root.find_child_named(node)->get_mechanical_state();
  return as_vec3(st->read(vec))[0];
}

const char* kUncoupled = R"(<UncoupledConstraintCorrection defaultCompliance="2"/>)";
const char* kLinear = R"(<LinearSolverConstraintCorrection/>)";

TEST(BilateralStep, BuiltSolversCorrectExactly) {
  for (const char* solver : {R"(<BlockGaussSeidelConstraintSolver tolerance="1e-12"/>)",
                             R"(<NNCGConstraintSolver tolerance="1e-12"/>)",
                             R"(<ImprovedJacobiConstraintSolver tolerance="1e-12"/>)"}) {
    for (const char* cc : {kUncoupled, kLinear}) {
      scene::LoadedScene s = test::load(anchored_point(solver, cc));
      ASSERT_TRUE(s.root);
      animate(*s.root);
      EXPECT_NEAR(point(*s.root, "body", kPosition).x(), 0.0, 1e-12) << solver << cc;
      EXPECT_NEAR(point(*s.root, "body", kVelocity).x(), -10.0, 1e-9) << solver << cc;
    }
  }
}

// SOFA's quirk: the unbuilt compliance of UncoupledConstraintCorrection lacks
// the dt its correction applies, so one step only moves dt of the way.
TEST(BilateralStep, UnbuiltGaussSeidelUncoupledQuirk) {
  scene::LoadedScene s =
      test::load(anchored_point(R"(<UnbuiltGaussSeidelConstraintSolver tolerance="1e-12"/>)", kUncoupled));
  ASSERT_TRUE(s.root);
  animate(*s.root);
  EXPECT_NEAR(point(*s.root, "body", kPosition).x(), 0.1 - 0.01 * 0.1, 1e-14);
  EXPECT_NEAR(point(*s.root, "body", kVelocity).x(), -0.1, 1e-12);
}

// LinearSolverConstraintCorrection's block compliance has the factor: the
// unbuilt solver matches the built ones.
TEST(BilateralStep, UnbuiltGaussSeidelLinearSolverCorrectionIsExact) {
  scene::LoadedScene s =
      test::load(anchored_point(R"(<UnbuiltGaussSeidelConstraintSolver tolerance="1e-12"/>)", kLinear));
  ASSERT_TRUE(s.root);
  animate(*s.root);
  EXPECT_NEAR(point(*s.root, "body", kPosition).x(), 0.0, 1e-12);
  EXPECT_NEAR(point(*s.root, "body", kVelocity).x(), -10.0, 1e-9);
}

// wire_optimization reorders the rows of a body by the smallest DoF they
// touch (unbuilt solvers): the pair declared first acts on point 1 and is
// solved second. The answer is the built one (exact compliance).
TEST(BilateralStep, WireOptimizationKeepsTheAnswer) {
  auto scene = [](const char* solver) {
    return std::string(R"(<Node name="root" dt="0.01" gravity="0 -10 0">
      <FreeMotionAnimationLoop/>)") + solver + R"(
      <Node name="anchor"><MechanicalObject name="x" position="0 0 0  1 0 0"/></Node>
      <Node name="body">
        <EulerImplicitSolver rayleighMass="0" rayleighStiffness="0"/>
        <SparseLDLSolver/>
        <MechanicalObject name="x" position="0.1 0 0  1.2 0 0"/>
        <UniformMass totalMass="2"/>
        <MeshSpringForceField stiffness="100" damping="0"/>
        <MeshTopology edges="0 1"/>
        <LinearSolverConstraintCorrection wire_optimization="1"/>
      </Node>
      <BilateralLagrangianConstraint object1="@anchor/x" object2="@body/x" first_point="1" second_point="1"/>
      <BilateralLagrangianConstraint object1="@anchor/x" object2="@body/x" first_point="0" second_point="0"/>
    </Node>)";
  };
  scene::LoadedScene built = test::load(scene(R"(<BlockGaussSeidelConstraintSolver tolerance="1e-14"/>)"));
  scene::LoadedScene unbuilt =
      test::load(scene(R"(<UnbuiltGaussSeidelConstraintSolver tolerance="1e-14" maxIterations="10000"/>)"));
  ASSERT_TRUE(built.root && unbuilt.root);
  for (int step = 0; step < 3; ++step) {
    animate(*built.root);
    animate(*unbuilt.root);
  }
  auto* a = built.root->find_child_named("body")->get_mechanical_state();
  auto* b = unbuilt.root->find_child_named("body")->get_mechanical_state();
  for (std::size_t k = 0; k < a->read(kPosition).size(); ++k)
    EXPECT_NEAR(a->read(kPosition)[k], b->read(kPosition)[k], 1e-10) << k;
  EXPECT_NEAR(as_vec3(a->read(kPosition))[0].x(), 0.0, 1e-10);
  EXPECT_NEAR(as_vec3(a->read(kPosition))[1].x(), 1.0, 1e-10);
  EXPECT_TRUE(test::messages(unbuilt.root->diagnostics(), Severity::error).empty());
}

// A chain anchor – p0 – p1: the two pairs couple through p0, so one sweep
// cannot converge; the solver says so once, with iterations, error and size.
TEST(BilateralStep, NonConvergenceWarning) {
  for (const char* solver : {R"(<BlockGaussSeidelConstraintSolver name="s" tolerance="1e-12" maxIterations="1"/>)",
                             R"(<UnbuiltGaussSeidelConstraintSolver name="s" tolerance="1e-12" maxIterations="1"/>)"}) {
    scene::LoadedScene s = test::load(std::string(R"(<Node name="root" dt="0.01" gravity="0 0 0">
      <FreeMotionAnimationLoop/>)") + solver + R"(
      <Node name="anchor"><MechanicalObject name="x" position="0 0 0"/></Node>
      <Node name="body">
        <EulerImplicitSolver/>
        <SparseLDLSolver/>
        <MechanicalObject name="x" position="0.1 0 0  0.3 0 0"/>
        <UniformMass totalMass="2"/>
        <UncoupledConstraintCorrection defaultCompliance="1"/>
      </Node>
      <BilateralLagrangianConstraint object1="@anchor/x" object2="@body/x" first_point="0" second_point="0"/>
      <BilateralLagrangianConstraint object1="@body/x" object2="@body/x" first_point="0" second_point="1"
                                     rest_vector="0.1 0 0"/>
    </Node>)");
    ASSERT_TRUE(s.root);
    animate(*s.root);
    animate(*s.root);
    auto* gs = test::get<GenericConstraintSolver>(*s.root, "s");
    ASSERT_NE(gs, nullptr);
    EXPECT_EQ(gs->current_iterations.value(), 2);
    EXPECT_GT(gs->current_error.value(), 6e-12);
    EXPECT_EQ(gs->current_num_constraints.value(), 6);
    const auto warnings = test::messages(s.root->diagnostics(), Severity::warning);
    int count = 0;
    for (const std::string& w : warnings)
      if (w.find("no convergence after 2 iterations") != std::string::npos && w.find("(6 rows)") != std::string::npos)
        ++count;
    EXPECT_EQ(count, 1) << solver;  // warned once, not every step
  }
}

// ---------------------------------------------------------------- LCP

// Two points of mass 1 at z = 0 falling (g = −10, dt = 0.01) onto planes
// z ≥ 0: free motion v_f = −0.1, z_f = −0.001. With compliances c_k (no ODE
// factors) the LCP puts them back on the plane: λ_k = 0.001/c_k, z = 0,
// v = v_f + λ_k·c_k/dt = 0; LinearSolverConstraintCorrection: W = dt/m,
// same positions and velocities.
std::string points_on_plane(const std::string& lcp, const std::string& correction) {
  return R"(<Node name="root" dt="0.01" gravity="0 0 -10">
    <FreeMotionAnimationLoop/>
    )" + lcp + R"(
    <Node name="body">
      <EulerImplicitSolver rayleighMass="0" rayleighStiffness="0"/>
      <SparseLDLSolver/>
      <MechanicalObject name="x" position="0 0 0  1 0 0"/>
      <UniformMass totalMass="2"/>
      )" + correction + R"(
    </Node>
  </Node>)";
}

const char* kUncoupledTwo = R"(<UncoupledConstraintCorrection compliance="0.5 0.25" useOdeSolverIntegrationFactors="0"/>)";

test::PlaneContacts* add_contacts(Node& root, bool friction) {
  Node* body = root.find_child_named("body");
  auto c = std::make_unique<test::PlaneContacts>();
  c->name.set("contacts");
  c->state = body->get_mechanical_state();
  c->friction = friction;
  c->contacts.resize(2);
  c->contacts[0].dof = 0;
  c->contacts[0].id = 11;
  c->contacts[1].dof = 1;
  c->contacts[1].id = 22;
  return static_cast<test::PlaneContacts*>(body->add_object(std::move(c)));
}

TEST(LcpStep, PointsStayOnTheirPlanes) {
  const char* variants[] = {
      R"(<LCPConstraintSolver name="lcp" tolerance="1e-12" build_lcp="1" mu="0"/>)",
      R"(<LCPConstraintSolver name="lcp" tolerance="1e-12" build_lcp="0" mu="0"/>)",
      R"(<LCPConstraintSolver name="lcp" tolerance="1e-12" build_lcp="1" mu="0.5"/>)",
      R"(<LCPConstraintSolver name="lcp" tolerance="1e-12" build_lcp="0" mu="0.5"/>)",
  };
  for (const char* lcp : variants) {
    const bool friction = std::string(lcp).find("mu=\"0.5\"") != std::string::npos;
    for (const char* cc : {kUncoupledTwo, kLinear}) {
      scene::LoadedScene s = test::load(points_on_plane(lcp, cc));
      ASSERT_TRUE(s.root);
      add_contacts(*s.root, friction);
      for (int step = 0; step < 3; ++step) {
        animate(*s.root);
        auto* st = s.root->find_child_named("body")->get_mechanical_state();
        const auto x = as_vec3(st->read(kPosition));
        const auto v = as_vec3(st->read(kVelocity));
        for (int k = 0; k < 2; ++k) {
          EXPECT_NEAR(x[k].z(), 0.0, 1e-12) << lcp << cc << " step " << step;
          EXPECT_NEAR(v[k].z(), 0.0, 1e-9) << lcp << cc << " step " << step;
        }
      }
      auto* solver = test::get<LCPConstraintSolver>(*s.root, "lcp");
      ASSERT_NE(solver, nullptr);
      EXPECT_TRUE(solver->last_result().converged);
      if (std::string(cc) == kUncoupledTwo) {
        // λ = 0.001/c; the force went through externalForce (Jᵀλ).
        const int rows = friction ? 3 : 1;
        EXPECT_NEAR(solver->problem().f[0], 0.001 / 0.5, 1e-12);
        EXPECT_NEAR(solver->problem().f[rows], 0.001 / 0.25, 1e-12);
      }
    }
  }
}

// The warm start follows persistent ids: nothing the first two steps (a new
// contact set gives negated ids once), then last step's forces of the same
// id, wherever its rows moved; a new id starts from zero.
TEST(LcpStep, WarmStartByPersistentId) {
  scene::LoadedScene s = test::load(points_on_plane(
      R"(<LCPConstraintSolver name="lcp" tolerance="1e-12" build_lcp="1" mu="0.5" initial_guess="1"/>)", kUncoupledTwo));
  ASSERT_TRUE(s.root);
  test::PlaneContacts* c = add_contacts(*s.root, true);
  auto* solver = test::get<LCPConstraintSolver>(*s.root, "lcp");
  ASSERT_NE(solver, nullptr);
  const std::vector<double> zero(6, 0.0);
  animate(*s.root);
  EXPECT_EQ(solver->initial_forces(), zero);
  animate(*s.root);
  EXPECT_EQ(solver->initial_forces(), zero);
  std::vector<double> before = solver->problem().f;
  ASSERT_GT(before[0], 0.0);
  ASSERT_GT(before[3], before[0]);  // the stiffer point pushes harder
  animate(*s.root);
  EXPECT_EQ(solver->initial_forces(), before);
  EXPECT_EQ(solver->last_result().iterations, 1);  // started at the answer

  // Swap the contacts: rows move, ids follow.
  before = solver->problem().f;
  std::swap(c->contacts[0], c->contacts[1]);
  animate(*s.root);
  std::vector<double> swapped = {before[3], before[4], before[5], before[0], before[1], before[2]};
  EXPECT_EQ(solver->initial_forces(), swapped);

  // A contact with a new id joins: zero start for it only.
  before = solver->problem().f;
  test::PlaneContacts::Contact extra = c->contacts[0];
  extra.id = 33;
  c->contacts.push_back(extra);
  animate(*s.root);
  const std::vector<double>& guess = solver->initial_forces();
  ASSERT_EQ(guess.size(), 9u);
  for (int r = 0; r < 6; ++r) EXPECT_EQ(guess[r], before[r]) << r;
  for (int r = 6; r < 9; ++r) EXPECT_EQ(guess[r], 0.0) << r;

  // initial_guess off: always from zero.
  solver->initial_guess.set(false);
  animate(*s.root);
  EXPECT_EQ(solver->initial_forces(), std::vector<double>(9, 0.0));
}

// The solver's mu picks the 3-row algorithm; frictionless contacts (1 row)
// cannot be solved by it: one clear error, no force.
TEST(LcpStep, FrictionSolverWithFrictionlessContacts) {
  scene::LoadedScene s = test::load(
      points_on_plane(R"(<LCPConstraintSolver name="lcp" mu="0.5"/>)", kUncoupledTwo));
  ASSERT_TRUE(s.root);
  add_contacts(*s.root, false);
  animate(*s.root);
  const auto errors = test::messages(s.root->diagnostics(), Severity::error);
  EXPECT_TRUE(test::any_contains(errors, "nothing is solved")) << ::testing::PrintToString(errors);
  auto* st = s.root->find_child_named("body")->get_mechanical_state();
  EXPECT_NEAR(as_vec3(st->read(kPosition))[0].z(), -0.001, 1e-12);  // fell through
}

// Legacy attributes of older SOFA versions load without a message.
TEST(LcpStep, LegacyAttributesAccepted) {
  Diagnostics d;
  scene::LoadedScene s = test::build(
      points_on_plane(R"(<LCPConstraintSolver multi_grid="false" multi_grid_levels="2" merge_method="0"
                          merge_spatial_step="2" merge_local_levels="2" displayTime="0" group="0"/>)",
                      kUncoupledTwo),
      &d);
  ASSERT_TRUE(s.root);
  EXPECT_TRUE(test::messages(s.root->diagnostics(), Severity::warning).empty());
  EXPECT_TRUE(test::messages(s.root->diagnostics(), Severity::error).empty());
}

}  // namespace
}  // namespace sinew

// EulerImplicitSolver (spec/solvers.md §1.1) and CGLinearSolver (§3.1) on small analytic scenes.
#include "solver/linear/cg_linear_solver.h"
#include "solver/ode/euler_implicit_solver.h"

#include <gtest/gtest.h>

#include "runner/session.h"
#include "state/mechanical_object.h"
#include "test_scene.h"

using namespace sinew;
using sinew::test::any_contains;
using sinew::test::get;
using sinew::test::load;
using sinew::test::messages;

namespace {

// A single particle at (1, 2, 3) with mass m under gravity g, dt = h.
std::string particle(double h, const std::string& solver_attrs = "",
                     const std::string& cg_attrs = R"(iterations="25" tolerance="1e-9" threshold="1e-20")",
                     const std::string& extra = "") {
  return R"(<Node dt=")" + std::to_string(h) + R"(" gravity="0 -9.81 0">
    <DefaultAnimationLoop/>
    <EulerImplicitSolver name="ode" )" +
         solver_attrs + R"(/>
    <CGLinearSolver name="cg" )" +
         cg_attrs + R"(/>
    <MechanicalObject name="dofs" position="1 2 3"/>
    <UniformMass name="mass" vertexMass="2"/>
    )" + extra +
         R"(
  </Node>)";
}

const std::vector<double>& x_of(scene::LoadedScene& s) {
  return get<MechanicalObject>(*s.root, "dofs")->position.get().data;
}
const std::vector<double>& v_of(scene::LoadedScene& s) {
  return get<MechanicalObject>(*s.root, "dofs")->velocity.get().data;
}
CGLinearSolver& cg_of(scene::LoadedScene& s) { return *get<CGLinearSolver>(*s.root, "cg"); }

// A 2×2×2 hexahedral block (FEM) fixed at z = 0, pulled by gravity along x: CG needs several iterations.
std::string fem_block(const std::string& cg_attrs) {
  return R"(<Node dt="0.01" gravity="9.81 0 0">
    <EulerImplicitSolver name="ode"/>
    <CGLinearSolver name="cg" )" +
         cg_attrs + R"(/>
    <RegularGridTopology n="3 3 3" min="0 0 0" max="1 1 1"/>
    <MechanicalObject name="dofs"/>
    <UniformMass totalMass="1"/>
    <HexahedronFEMForceField youngModulus="1000" poissonRatio="0.3"/>
    <BoxROI name="roi" box="-0.1 -0.1 -0.1 1.1 1.1 0.1"/>
    <FixedProjectiveConstraint indices="@roi.indices"/>
  </Node>)";
}

}  // namespace

// ---------------------------------------------------------------- EulerImplicitSolver

// §1.1: free particle, one implicit Euler step: v1 = h·g, x1 = x0 + h·v1 (exactly: A = M, one CG step).
TEST(EulerImplicitSolver, FreeParticleFirstStepIsExact) {
  const double h = 0.01, g = -9.81;
  auto s = load(particle(h));
  animate(*s.root);
  const double v1 = h * g;
  EXPECT_EQ(v_of(s), (std::vector<double>{0, v1, 0}));
  EXPECT_EQ(x_of(s), (std::vector<double>{1, 2 + v1 * h, 3}));
  EXPECT_DOUBLE_EQ(s.root->time.value(), h);
}

// §1.1: the second step uses v1: v2 = v1 + h·g, x2 = x1 + h·v2.
TEST(EulerImplicitSolver, FreeParticleTwoSteps) {
  const double h = 0.01, g = -9.81;
  auto s = load(particle(h));
  animate(*s.root);
  animate(*s.root);
  const double v1 = h * g, y1 = 2 + v1 * h;
  const double v2 = v1 + h * g, y2 = y1 + v2 * h;
  EXPECT_DOUBLE_EQ(v_of(s)[1], v2);
  EXPECT_DOUBLE_EQ(x_of(s)[1], y2);
  EXPECT_EQ(x_of(s)[0], 1.0);
  EXPECT_EQ(x_of(s)[2], 3.0);
}

// §1.1: with rayleighMass rM, (1 + h·rM)·M·Δv = h·(f − rM·M·v); from rest: v1 = h·g / (1 + h·rM).
TEST(EulerImplicitSolver, RayleighMassDampsTheFirstStep) {
  const double h = 0.1, g = -9.81, rM = 0.5;
  auto s = load(particle(h, R"(rayleighMass="0.5")"));
  animate(*s.root);
  const double v1 = h * g / (1 + h * rM);
  EXPECT_NEAR(v_of(s)[1], v1, 1e-15);
  EXPECT_NEAR(x_of(s)[1], 2 + h * v1, 1e-15);
}

// §1.1: second step with rM: Δv = h·(g − rM·v1) / (1 + h·rM).
TEST(EulerImplicitSolver, RayleighMassSecondStep) {
  const double h = 0.1, g = -9.81, rM = 0.5;
  auto s = load(particle(h, R"(rayleighMass="0.5")"));
  animate(*s.root);
  animate(*s.root);
  const double v1 = h * g / (1 + h * rM);
  const double v2 = v1 + h * (g - rM * v1) / (1 + h * rM);
  EXPECT_NEAR(v_of(s)[1], v2, 1e-14);
}

// §1.1 step 9: vdamping multiplies the new velocity by exp(−h·vdamping), after the position update.
TEST(EulerImplicitSolver, VelocityDampingAfterThePositionUpdate) {
  const double h = 0.01, g = -9.81;
  auto s = load(particle(h, R"(vdamping="2")"));
  animate(*s.root);
  const double v1 = h * g;
  EXPECT_DOUBLE_EQ(v_of(s)[1], v1 * std::exp(-h * 2));
  EXPECT_DOUBLE_EQ(x_of(s)[1], 2 + v1 * h);
}

// §1.1 first order: v = Δv (not v + Δv); with A = M and b = f: v = g·m/m... = g, x += h·g.
TEST(EulerImplicitSolver, FirstOrderVelocityIsTheSolution) {
  const double h = 0.01, g = -9.81;
  auto s = load(particle(h, R"(firstOrder="1")"));
  animate(*s.root);
  EXPECT_DOUBLE_EQ(v_of(s)[1], g);
  EXPECT_DOUBLE_EQ(x_of(s)[1], 2 + h * g);
}

// §4 / framework §6.5: a fixed particle never moves.
TEST(EulerImplicitSolver, FixedParticleDoesNotMove) {
  const double h = 0.01;
  auto s = load(R"(<Node dt="0.01">
    <EulerImplicitSolver/>
    <CGLinearSolver iterations="25" tolerance="1e-9" threshold="1e-20"/>
    <MechanicalObject name="dofs" position="0 0 0  1 0 0"/>
    <UniformMass vertexMass="1"/>
    <FixedProjectiveConstraint indices="0"/>
  </Node>)");
  for (int i = 0; i < 5; ++i) animate(*s.root);
  const auto& x = x_of(s);
  const auto& v = v_of(s);
  EXPECT_EQ(x[0], 0.0);
  EXPECT_EQ(x[1], 0.0);
  EXPECT_EQ(x[2], 0.0);
  EXPECT_EQ(v[0], 0.0);
  EXPECT_EQ(v[1], 0.0);
  EXPECT_EQ(v[2], 0.0);
  EXPECT_LT(x[4], -1e-3);  // the free particle fell
  EXPECT_DOUBLE_EQ(s.root->time.value(), 5 * h);
}

// framework §4.1: no animation loop in the root → a DefaultAnimationLoop is added in front (T16).
TEST(EulerImplicitSolver, MissingAnimationLoopIsAdded) {
  auto s = load(R"(<Node>
    <EulerImplicitSolver/>
    <CGLinearSolver iterations="25" tolerance="1e-9" threshold="1e-20"/>
    <MechanicalObject name="dofs" position="0 0 0"/>
    <UniformMass vertexMass="1"/>
  </Node>)");
  ASSERT_NE(s.root->animation_loop, nullptr);
  EXPECT_EQ(s.root->objects()[0].get(), s.root->animation_loop);
  animate(*s.root);
  EXPECT_DOUBLE_EQ(v_of(s)[1], 0.01 * -9.81);
}

// T4: states outside every solver's subtree are never integrated.
TEST(EulerImplicitSolver, StatesWithoutSolverStayPut) {
  auto s = load(R"(<Node>
    <MechanicalObject name="dofs" position="0 0 0"/>
    <UniformMass vertexMass="1"/>
  </Node>)");
  animate(*s.root);
  EXPECT_EQ(x_of(s), (std::vector<double>{0, 0, 0}));
}

// ---------------------------------------------------------------- CGLinearSolver

// §3.1: A = M·const converges in one iteration; the next iteration sees r = 0 and stops.
TEST(CGLinearSolver, DiagonalSystemTakesOneIteration) {
  auto s = load(particle(0.01));
  animate(*s.root);
  EXPECT_EQ(cg_of(s).last_iterations(), 1);
  EXPECT_EQ(cg_of(s).last_error(), 0.0);
}

// §3.1 step 3b: at the very first solve, reaching the tolerance at k = 1 does not stop
// (warning); at later solves it stops at once with x = 0 (no velocity change).
TEST(CGLinearSolver, FirstSolveNeverStopsAtTheFirstIterationOnTolerance) {
  const double h = 0.01, g = -9.81;
  auto s = load(particle(h, "", R"(iterations="25" tolerance="10" threshold="1e-20")"));
  animate(*s.root);
  EXPECT_EQ(cg_of(s).last_iterations(), 1);
  EXPECT_EQ(v_of(s)[1], h * g);
  EXPECT_TRUE(any_contains(messages(s.root->diagnostics(), Severity::warning), "tolerance reached"));
  const double y1 = x_of(s)[1];

  animate(*s.root);
  EXPECT_EQ(cg_of(s).last_iterations(), 0);
  EXPECT_EQ(v_of(s)[1], h * g);  // Δv = 0
  EXPECT_EQ(x_of(s)[1], y1 + h * (h * g));
}

// §3.1 step 3f: same for the denominator threshold; later solves stop before updating x.
TEST(CGLinearSolver, FirstSolveNeverStopsAtTheFirstIterationOnThreshold) {
  const double h = 0.01, g = -9.81;
  auto s = load(particle(h, "", R"(iterations="25" tolerance="1e-9" threshold="1e10")"));
  animate(*s.root);
  EXPECT_EQ(v_of(s)[1], h * g);
  EXPECT_TRUE(any_contains(messages(s.root->diagnostics(), Severity::warning), "denominator threshold"));
  animate(*s.root);
  EXPECT_EQ(v_of(s)[1], h * g);  // stopped before the update: Δv = 0
}

// §3.1: with b = 0 nothing is solved (x stays 0).
TEST(CGLinearSolver, ZeroRightHandSideDoesNothing) {
  auto s = load(R"(<Node gravity="0 0 0">
    <EulerImplicitSolver/>
    <CGLinearSolver name="cg" iterations="25" tolerance="1e-9" threshold="1e-9"/>
    <MechanicalObject name="dofs" position="0 0 0"/>
    <UniformMass vertexMass="1"/>
  </Node>)");
  animate(*s.root);
  EXPECT_EQ(cg_of(s).last_iterations(), 0);
  EXPECT_EQ(x_of(s), (std::vector<double>{0, 0, 0}));
}

// §3.1: `iterations` bounds the loop.
TEST(CGLinearSolver, StopsAtTheIterationLimit) {
  auto s = load(fem_block(R"(iterations="3" tolerance="1e-12" threshold="1e-30")"));
  animate(*s.root);
  EXPECT_EQ(cg_of(s).last_iterations(), 3);
  EXPECT_GT(cg_of(s).last_error(), 1e-12);
}

// §3.1 step 3b: stops at the first iteration where ‖r‖/‖b‖ ≤ tolerance (not squared).
TEST(CGLinearSolver, StopsWhenTheRelativeResidualReachesTheTolerance) {
  auto s = load(fem_block(R"(iterations="1000" tolerance="1e-6" threshold="1e-30")"));
  animate(*s.root);
  const int n = cg_of(s).last_iterations();
  EXPECT_GT(n, 1);
  EXPECT_LT(n, 1000);
  EXPECT_LE(cg_of(s).last_error(), 1e-6);

  // Capped at n iterations, the loop runs to the limit: the residual at iteration n was
  // still above the tolerance, so the first run stopped as early as it could.
  auto capped = load(fem_block("iterations=\"" + std::to_string(n) + R"(" tolerance="1e-6" threshold="1e-30")"));
  animate(*capped.root);
  EXPECT_EQ(cg_of(capped).last_iterations(), n);
  EXPECT_GT(cg_of(capped).last_error(), 1e-6);
}

// §3.1: the three "required" fields warn when absent, and the defaults are 25 / 1e-5 / 1e-5.
TEST(CGLinearSolver, MissingRequiredFieldsWarn) {
  auto s = load(R"(<Node>
    <EulerImplicitSolver/>
    <CGLinearSolver name="cg"/>
    <MechanicalObject position="0 0 0"/>
    <UniformMass vertexMass="1"/>
  </Node>)");
  auto& cg = cg_of(s);
  EXPECT_EQ(cg.iterations.value(), 25u);
  EXPECT_EQ(cg.tolerance.value(), 1e-5);
  EXPECT_EQ(cg.threshold.value(), 1e-5);
  const auto w = messages(s.root->diagnostics(), Severity::warning);
  EXPECT_TRUE(any_contains(w, "'iterations'"));
  EXPECT_TRUE(any_contains(w, "'tolerance'"));
  EXPECT_TRUE(any_contains(w, "'threshold'"));
}

// ---------------------------------------------------------------- through runner::Session

// The same free-fall through a scene file and runner::Session.
TEST(Session, RunsAFreeFallFromAFile) {
  sinew::test::TempDir dir;
  const std::string path = dir.write("fall.scn", particle(0.01));
  runner::Session session(path, {});
  ASSERT_TRUE(session.ok());
  ASSERT_TRUE(session.step());
  ASSERT_TRUE(session.step());
  EXPECT_EQ(session.steps_done(), 2);
  auto* mo = get<MechanicalObject>(session.root(), "dofs");
  ASSERT_NE(mo, nullptr);
  const double h = 0.01, g = -9.81;
  const double v1 = h * g, y1 = 2 + v1 * h, v2 = v1 + h * g;
  EXPECT_DOUBLE_EQ(mo->velocity.get().data[1], v2);
  EXPECT_DOUBLE_EQ(mo->position.get().data[1], y1 + v2 * h);
}

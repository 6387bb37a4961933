// LCPForceFeedback: the step's contact problem re-solved at the device's pose
// (spec/interaction.md §6.2). A rigid tool rests on a static floor through one
// point contact; the tests compare the haptic force with the step's own
// constraint force, with the analytic change when the device goes deeper, with
// zero when it leaves the floor, and check the torque of an off-centre contact,
// the isolation of the snapshot, the timeout and a servo thread racing the steps.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <sstream>
#include <thread>

#include "constraint/solver/lcp_constraint_solver.h"
#include "haptics/lcp_force_feedback.h"
#include "test_scene.h"

using namespace sinew;
using namespace sinew::haptics;

namespace {

// A Rigid3d tool whose contact point sits at `offset` from its centre, falling
// on the floor y = 0 (contact distance 0.01).
std::string tool_scene(double offset_x, const std::string& ff_attrs) {
  std::ostringstream x;
  x << R"(<Node name="root" dt="0.01" gravity="0 -9.81 0">
    <FreeMotionAnimationLoop/>
    <LCPConstraintSolver name="lcp" tolerance="1e-9" maxIt="1000" mu="0.5"/>
    <CollisionPipeline/><BruteForceBroadPhase/><BVHNarrowPhase/>
    <MinProximityIntersection alarmDistance="0.1" contactDistance="0.01"/>
    <CollisionResponse response="FrictionContactConstraint" responseParams="mu=0.5"/>
    <Node name="floor">
      <MechanicalObject position="-5 0 -5  5 0 -5  5 0 5  -5 0 5"/>
      <MeshTopology triangles="0 2 1  0 3 2"/>
      <TriangleCollisionModel simulated="0" moving="0"/>
    </Node>
    <Node name="tool">
      <EulerImplicitSolver/>
      <CGLinearSolver iterations="25" tolerance="1e-12" threshold="1e-12"/>
      <MechanicalObject name="x" template="Rigid3d" position="0.3 0.03 0.2 0 0 0 1"/>
      <UniformMass totalMass="1"/>
      <LCPForceFeedback name="ff" )"
    << ff_attrs << R"(/>
      <UncoupledConstraintCorrection/>
      <Node name="tip"><MechanicalObject position=")"
    << offset_x << R"( 0 0"/><PointCollisionModel/><RigidMapping/></Node>
    </Node>
  </Node>)";
  return x.str();
}

struct Tool {
  scene::LoadedScene scene;
  LCPForceFeedback* ff = nullptr;
  LCPConstraintSolver* lcp = nullptr;
  MechanicalState* state = nullptr;
};

// Loads the scene and steps until the tool rests on the floor.
Tool settled_tool(double offset_x, const std::string& ff_attrs = "activate=\"1\" forceCoef=\"0.5\"") {
  Tool t;
  t.scene = test::load(tool_scene(offset_x, ff_attrs));
  if (!t.scene.root) return t;
  Node& tool = *t.scene.root->find_child_named("tool");
  t.ff = test::get<LCPForceFeedback>(tool, "ff");
  t.lcp = test::get<LCPConstraintSolver>(*t.scene.root, "lcp");
  t.state = tool.get_mechanical_state();
  // The tool falls 0.02 onto the floor (about 7 steps), then rests on it.
  for (int i = 0; i < 30; ++i) animate(*t.scene.root);
  return t;
}

// coef · Jᵀλ of the step on the tool's DoF 0 (force, torque).
void step_wrench(const Tool& t, double coef, Vec3& force, Vec3& torque) {
  force = torque = Vec3::Zero();
  const ConstraintMatrix& J = t.state->constraint_jacobian();
  const auto& f = t.lcp->problem().f;
  for (const auto& r : J.rows())
    for (int k = r.begin; k < r.end; ++k) {
      const double* v = J.value(k);
      for (int c = 0; c < 3; ++c) force[c] += coef * v[c] * f[static_cast<std::size_t>(r.id)];
      for (int c = 0; c < 3; ++c) torque[c] += coef * v[3 + c] * f[static_cast<std::size_t>(r.id)];
    }
}

Vec3 free_centre(const Tool& t) {
  const auto& xf = t.state->read(kFreePosition);
  return Vec3(xf[0], xf[1], xf[2]);
}

}  // namespace

TEST(LCPForceFeedback, ReSolvesTheStepsContactAtTheDevicePose) {
  Tool t = settled_tool(0.0);
  ASSERT_TRUE(t.ff && t.lcp && t.state);
  ASSERT_EQ(t.lcp->problem().n, 3) << "one friction contact";
  EXPECT_EQ(t.ff->state(), ComponentState::valid);
  EXPECT_GE(t.ff->snapshots(), 1u);
  const double coef = 0.5;
  Vec3 F_step, T_step;
  step_wrench(t, coef, F_step, T_step);
  ASSERT_GT(F_step[1], 0.0) << "the floor pushes the tool up";

  // At the free position: the step's problem unchanged, so the step's force.
  const Vec3 xf = free_centre(t);
  const Vec3 F0 = t.ff->compute_force(xf, Quat{});
  EXPECT_NEAR(F0[1], F_step[1], 1e-9 * F_step.norm());
  EXPECT_NEAR(F0[0], F_step[0], 1e-9 * F_step.norm());
  EXPECT_NEAR(F0[2], F_step[2], 1e-9 * F_step.norm());

  // Deeper by δ: the normal force grows by δ / W_nn (translational compliance only:
  // W is diagonal, the tangential rows do not move), times forceCoef.
  const double W_nn = t.lcp->problem().w(0, 0);
  for (double delta : {1e-3, 4e-3}) {
    const Vec3 F = t.ff->compute_force(xf - Vec3(0, delta, 0), Quat{});
    EXPECT_NEAR(F[1] - F_step[1], coef * delta / W_nn, 1e-7 * coef * delta / W_nn) << delta;
    EXPECT_NEAR(F[0], F_step[0], 1e-9 * F.norm());
  }
  // Sideways by 1e-3 with the friction cone wide enough to stick: the tangential force
  // opposes the motion, |Ft| = coef·1e-3 / W_tt, and the normal force stays.
  const double W_tt = t.lcp->problem().w(1, 1);
  const Vec3 Fs = t.ff->compute_force(xf + Vec3(1e-4, 0, 0), Quat{});
  EXPECT_LT(Fs[0], 0.0);
  EXPECT_NEAR(std::hypot(Fs[0] - F_step[0], Fs[2] - F_step[2]), coef * 1e-4 / W_tt, 1e-6 * coef * 1e-4 / W_tt);
  EXPECT_NEAR(Fs[1], F_step[1], 1e-9 * F_step.norm());
  // Lifted well above the contact distance: the contact separates, no force.
  const Vec3 Fl = t.ff->compute_force(xf + Vec3(0, 0.5, 0), Quat{});
  EXPECT_EQ(Fl, Vec3::Zero());
  // Back at the free position: the same force again (dfree was restored; only the
  // warm start changed).
  const Vec3 F0b = t.ff->compute_force(xf, Quat{});
  EXPECT_NEAR((F0b - F0).norm(), 0.0, 1e-7 * F0.norm());
  // The solver's own problem was never touched by the haptic solves.
  EXPECT_EQ(t.lcp->problem().n, 3);
  EXPECT_GE(t.ff->solves(), 6u);
}

TEST(LCPForceFeedback, TorqueOfAnOffCentreContactIsTheLeverArmCrossTheForce) {
  Tool t = settled_tool(0.5);
  ASSERT_TRUE(t.ff && t.lcp && t.state);
  ASSERT_EQ(t.lcp->problem().n, 3);
  const auto& xf = t.state->read(kFreePosition);
  const Vec3 c(xf[0], xf[1], xf[2]);
  const Quat q = Quat::from(&xf[3]);
  Vec3 F, T;
  t.ff->compute_wrench(c - Vec3(0, 1e-3, 0), q, Vec3::Zero(), Vec3::Zero(), F, T);
  ASSERT_GT(F[1], 0.0);
  // The contact point: the tip (mapped) at the last mapping of the step.
  const auto& tip = t.scene.root->find_child_named("tool")->children()[0]->get_mechanical_state()->read(kPosition);
  const auto& x = t.state->read(kPosition);
  const Vec3 r = Vec3(tip[0], tip[1], tip[2]) - Vec3(x[0], x[1], x[2]);
  EXPECT_NEAR(r.norm(), 0.5, 1e-9);
  const Vec3 expected = r.cross(F);
  // J was built at the start of the step, r is read at its end: the tool turned a little
  // in between (0.3% here), hence 1%.
  EXPECT_NEAR((T - expected).norm(), 0.0, 1e-2 * expected.norm()) << T.transpose() << " vs " << expected.transpose();
  EXPECT_GT(std::abs(T[2]), 0.1 * F.norm() * 0.5) << "a lever arm of 0.5 along x, a force along y: torque about z";
  // compute_force (SOFA's computeForce(x, y, z, ...)) gives the same force at the identity orientation
  // (the rotation is not part of the violation without derivRotations).
  const Vec3 F2 = t.ff->compute_force(c - Vec3(0, 1e-3, 0), Quat{});
  EXPECT_NEAR((F2 - F).norm(), 0.0, 1e-7 * F.norm());
}

TEST(LCPForceFeedback, InactiveTimedOutAndWrongSolver) {
  Tool off = settled_tool(0.0, "activate=\"0\" forceCoef=\"0.5\"");
  ASSERT_TRUE(off.ff);
  ASSERT_EQ(off.lcp->problem().n, 3);
  EXPECT_EQ(off.ff->compute_force(free_centre(off) - Vec3(0, 1e-3, 0), Quat{}), Vec3::Zero());
  EXPECT_EQ(off.ff->solves(), 0u);

  // A zero time budget stops after the first contact update of the first sweep.
  Tool timed = settled_tool(0.0, "activate=\"1\" solverTimeout=\"0\"");
  ASSERT_EQ(timed.lcp->problem().n, 3);
  timed.ff->compute_force(free_centre(timed) - Vec3(0, 1e-3, 0), Quat{});
  EXPECT_EQ(timed.ff->timeouts(), 1u);

  // Another constraint solver: a clear error, the component stops.
  auto bad = test::build(R"(<Node name="root"><FreeMotionAnimationLoop/>
    <BlockGaussSeidelConstraintSolver/>
    <Node name="tool"><MechanicalObject template="Rigid3d" position="0 0 0 0 0 0 1"/>
    <LCPForceFeedback name="ff" activate="1"/></Node></Node>)");
  ASSERT_TRUE(bad.root);
  init_root(*bad.root);
  EXPECT_TRUE(test::any_contains(test::messages(bad.root->diagnostics(), Severity::error), "not an LCPConstraintSolver"));
}

// A servo thread computing forces while the simulation steps: it never waits on
// the steps and always reads a whole snapshot (finite, upward forces).
TEST(LCPForceFeedback, ServoThreadRacesTheSimulationSafely) {
  Tool t = settled_tool(0.0);
  ASSERT_TRUE(t.ff);
  const Vec3 xf = free_centre(t);
  std::atomic<bool> stop{false};
  std::atomic<long> calls{0}, bad{0};
  std::thread servo([&] {
    while (!stop.load()) {
      const Vec3 F = t.ff->compute_force(xf - Vec3(0, 1e-3, 0), Quat{});
      if (!std::isfinite(F.norm()) || F[1] <= 0) bad.fetch_add(1);
      calls.fetch_add(1);
    }
  });
  while (calls.load() == 0) std::this_thread::yield();  // the servo runs before the steps start
  const auto before = t.ff->snapshots();
  const long calls_before = calls.load();
  for (int i = 0; i < 300; ++i) animate(*t.scene.root);
  // The servo keeps going after the steps (nothing they did holds it). On a loaded machine it
  // may not have been scheduled during the 300 short steps: it is given up to 10 s.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (calls.load() == calls_before && std::chrono::steady_clock::now() < deadline) std::this_thread::yield();
  stop.store(true);
  servo.join();
  EXPECT_EQ(t.ff->snapshots() - before, 300u);
  EXPECT_GT(calls.load(), calls_before);
  EXPECT_EQ(bad.load(), 0);
}

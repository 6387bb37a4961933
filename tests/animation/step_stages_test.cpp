// The step as declared stages: their order (seen by observers and events),
// the per-simulation profile, and the seam where outside code acts.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "test_scene.h"
#include "animation/default_animation_loop.h"
#include "animation/free_motion_animation_loop.h"
#include "core/simulation.h"

namespace sinew {
namespace {

const char* kFallingPoint = R"(<Node name="root" dt="0.01" gravity="0 -10 0">
  <DefaultAnimationLoop/>
  <EulerExplicitSolver name="ode"/>
  <MechanicalObject name="dofs" position="0 0 0"/>
  <UniformMass name="mass" totalMass="1"/>
</Node>)";

// Writes "before <stage>" / "after <stage>" into a shared log.
struct StageLog final : StepObserver {
  std::vector<std::string>* log;
  explicit StageLog(std::vector<std::string>* l) : log(l) {}
  void before_stage(Stage s, Node&) override { log->push_back(std::string("before ") + stage_name(s)); }
  void after_stage(Stage s, Node&) override { log->push_back(std::string("after ") + stage_name(s)); }
};

// A component that logs the events it receives (with the time it sees).
class EventLog final : public Component {
 public:
  std::vector<std::string>* log = nullptr;
  bool wants_events() const override { return true; }
  void handle_event(Event& e) override {
    log->push_back(e.kind == Event::Kind::animate_begin ? "AnimateBeginEvent"
                   : e.kind == Event::Kind::animate_end ? "AnimateEndEvent"
                                                        : "other event");
  }
};

TEST(StepStages, RunInTheDeclaredOrderWithEventsInsideTheirStages) {
  auto s = test::build(kFallingPoint);
  std::vector<std::string> log;
  auto ev = std::make_unique<EventLog>();
  ev->log = &log;
  s.root->add_object(std::move(ev));
  init_root(*s.root);
  log.clear();  // SimulationInitDone
  StageLog observer(&log);
  add_step_observer(*s.root, &observer);
  animate(*s.root);

  std::vector<std::string> expected;
  for (Stage st : DefaultAnimationLoop::kStages) {
    expected.push_back(std::string("before ") + stage_name(st));
    if (st == Stage::begin_events) expected.push_back("AnimateBeginEvent");
    if (st == Stage::end_events) expected.push_back("AnimateEndEvent");
    expected.push_back(std::string("after ") + stage_name(st));
  }
  EXPECT_EQ(log, expected);
  // Every stage but the free motion (FreeMotionAnimationLoop's) exactly once, in the enum's order.
  std::vector<Stage> all;
  for (int i = 0; i < kStageCount; ++i)
    if (static_cast<Stage>(i) != Stage::free_motion) all.push_back(static_cast<Stage>(i));
  EXPECT_EQ(std::vector<Stage>(std::begin(DefaultAnimationLoop::kStages), std::end(DefaultAnimationLoop::kStages)),
            all);
  // The free-motion loop: free motion before collision, constraints before end integration (SOFA's order).
  const std::vector<Stage> free(std::begin(FreeMotionAnimationLoop::kStages), std::end(FreeMotionAnimationLoop::kStages));
  EXPECT_EQ(free, (std::vector<Stage>{Stage::begin_events, Stage::free_motion, Stage::collision,
                                      Stage::constraint_correction, Stage::end_integration,
                                      Stage::project_and_propagate, Stage::check_state, Stage::advance_time,
                                      Stage::end_events}));

  remove_step_observer(*s.root, &observer);
  log.clear();
  animate(*s.root);
  EXPECT_EQ(log, (std::vector<std::string>{"AnimateBeginEvent", "AnimateEndEvent"}));
}

// The seam: an observer sets the state before the solve and reads the result after it.
TEST(StepStages, ObserverAppliesInputsBeforeTheSolveAndReadsAfterIt) {
  auto s = test::load(kFallingPoint);
  auto* dofs = s.root->get_mechanical_state();
  struct Device final : StepObserver {
    MechanicalState* dofs;
    double seen_y = 0;
    void before_stage(Stage st, Node&) override {
      if (st == Stage::collision) dofs->write(kVelocity)[0] = 2.0;  // a device pushes the point along x
    }
    void after_stage(Stage st, Node&) override {
      if (st == Stage::end_integration) seen_y = dofs->read(kVelocity)[1];
    }
  } device;
  device.dofs = dofs;
  add_step_observer(*s.root, &device);
  animate(*s.root);
  // Symplectic Euler: v = v0 + h·g, x = h·v.
  EXPECT_DOUBLE_EQ(dofs->read(kVelocity)[0], 2.0);
  EXPECT_DOUBLE_EQ(dofs->read(kPosition)[0], 0.02);
  EXPECT_DOUBLE_EQ(device.seen_y, -0.1);
}

TEST(StepProfile, FilledPerSimulationAndKeptApart) {
  auto a = test::load(kFallingPoint);
  auto b = test::load(kFallingPoint);
  a.root->profile().set_enabled(true);
  for (int i = 0; i < 5; ++i) animate(*a.root);
  for (int i = 0; i < 3; ++i) animate(*b.root);
  EXPECT_EQ(a.root->profile().steps(), 5);
  EXPECT_EQ(b.root->profile().steps(), 0);  // not enabled there
  EXPECT_GT(a.root->profile().step_seconds(), 0.0);
  EXPECT_GT(a.root->profile().stage_seconds(Stage::solve), 0.0);
  double sum = 0;
  for (int i = 0; i < kStageCount; ++i) sum += a.root->profile().stage_seconds(static_cast<Stage>(i));
  EXPECT_LE(sum, a.root->profile().step_seconds());

  b.root->profile().set_enabled(true);
  for (int i = 0; i < 2; ++i) animate(*b.root);
  EXPECT_EQ(b.root->profile().steps(), 2);
  EXPECT_EQ(a.root->profile().steps(), 5);
  a.root->profile().reset();
  EXPECT_EQ(a.root->profile().steps(), 0);
  EXPECT_EQ(a.root->profile().stage_seconds(Stage::solve), 0.0);
}

// Implicit solver scopes ("solve/forces", ...) land in the simulation's own profile.
TEST(StepProfile, SolverScopesGoToTheirSimulation) {
  const char* xml = R"(<Node name="root" dt="0.01" gravity="0 -10 0">
  <EulerImplicitSolver/>
  <CGLinearSolver iterations="10" tolerance="1e-12" threshold="1e-20"/>
  <MechanicalObject position="0 0 0  1 0 0"/>
  <UniformMass totalMass="1"/>
  <SpringForceField spring="0 1 100 0 1"/>
</Node>)";
  auto a = test::load(xml);
  auto b = test::load(xml);
  a.root->profile().set_enabled(true);
  animate(*a.root);
  animate(*b.root);
  bool forces = false;
  for (const auto& e : a.root->profile().scopes()) forces |= e.name == "solve/forces" && e.count == 1;
  EXPECT_TRUE(forces);
  EXPECT_TRUE(b.root->profile().scopes().empty());
}

}  // namespace
}  // namespace sinew

namespace sinew {
namespace {

// A mapping that writes NaN into its output: a divergence that starts in a mapping.
class NanMapping final : public Mapping {
 public:
  MechanicalState* in = nullptr;
  MechanicalState* out = nullptr;
  std::vector<MechanicalState*> inputs() const override { return {in}; }
  MechanicalState* output() const override { return out; }
  void apply(int x) override {
    std::vector<double>& o = out->write(x);
    o.assign(o.size(), 0.0);
    if (node()->root()->time.value() > 0.015) o[4] = std::nan("");
  }
  void apply_j(int, int) override {}
  void apply_jt(int, int) override {}
};

const char* kFallingBodyWithMappedChild = R"(<Node name="root" dt="0.01" gravity="0 -10 0">
  <EulerExplicitSolver name="ode"/>
  <MechanicalObject name="dofs" position="0 0 0"/>
  <UniformMass name="mass" totalMass="1"/>
  <Node name="child">
    <MechanicalObject name="tip" position="0 0 0  0 0 0"/>
  </Node>
</Node>)";

// The check stage covers mapped states: it names the state, the point and the mapping, once.
TEST(CheckStage, NonFiniteMappedStateStopsItsSolverOnce) {
  auto s = test::build(kFallingBodyWithMappedChild);
  Node* child = s.root->find_child_named("child");
  auto m = std::make_unique<NanMapping>();
  m->name.set("nan");
  m->set_type("NanMapping", "");
  m->in = s.root->mechanical_state;
  m->out = child->mechanical_state;
  child->add_object(std::move(m));
  init_root(*s.root);
  animate(*s.root);  // t = 0.01: finite
  EXPECT_FALSE(s.root->diagnostics().has_errors());
  animate(*s.root);  // the mapping writes NaN when t reaches 0.02
  animate(*s.root);
  const auto errors = test::messages(s.root->diagnostics(), Severity::error);
  ASSERT_EQ(errors.size(), 1u) << ::testing::PrintToString(errors);
  EXPECT_TRUE(test::any_contains(errors, "component 'ode' (EulerExplicitSolver)"));
  EXPECT_TRUE(test::any_contains(errors, "diverged at step"));
  EXPECT_TRUE(test::any_contains(errors, "non-finite position of point 1 in component 'tip' (MechanicalObject)"));
  EXPECT_TRUE(test::any_contains(errors, "(mapped by component 'nan' (NanMapping))"));
  EXPECT_EQ(s.root->solvers[0]->state(), ComponentState::invalid);
}

}  // namespace
}  // namespace sinew

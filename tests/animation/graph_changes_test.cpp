// A graph that changes between steps: objects and nodes added and removed,
// edits refused during a step, scopes rebuilt, links into removed parts cut,
// element lists followed by version; and state reads that leave versions alone.
#include <gtest/gtest.h>

#include <string>

#include "test_scene.h"
#include "core/mechanical_ops.h"
#include "core/simulation.h"
#include "topology/mesh_topology.h"

namespace sinew {
namespace {

// One free point of mass 1, no gravity, symplectic explicit Euler with h = 0.1.
const char* kPoint = R"(<Node name="root" dt="0.1" gravity="0 0 0">
  <DefaultAnimationLoop/>
  <EulerExplicitSolver name="ode"/>
  <MechanicalObject name="dofs" position="0 0 0"/>
  <UniformMass name="mass" totalMass="1"/>
</Node>)";

// Takes the object `name` out of a scene built from `xml` (a component made as the loader makes it;
// a state in the donor scene gives it its template).
std::unique_ptr<Component> make(const std::string& xml, const std::string& name) {
  auto donor = test::build("<Node><MechanicalObject/>" + xml + "</Node>");
  return donor.root->remove_object(donor.root->find_object_named(name));
}

double vx(Node& root) { return root.get_mechanical_state()->read(kVelocity)[0]; }

TEST(GraphChanges, ForceFieldAddedThenRemovedBetweenSteps) {
  auto s = test::load(kPoint);
  Node& root = *s.root;
  animate(root);
  EXPECT_EQ(vx(root), 0.0);

  const auto v0 = root.structure_version();
  Component* cf = root.add_object(make(R"(<ConstantForceField name="push" force="2 0 0"/>)", "push"));
  ASSERT_NE(cf, nullptr);
  EXPECT_GT(root.structure_version(), v0);
  animate(root);  // initialised by the step, then used: v += h·F/m
  EXPECT_TRUE(cf->initialised());
  EXPECT_DOUBLE_EQ(vx(root), 0.2);
  animate(root);
  EXPECT_DOUBLE_EQ(vx(root), 0.4);

  auto taken = root.remove_object(cf);
  ASSERT_EQ(taken.get(), cf);
  EXPECT_EQ(cf->node(), nullptr);
  EXPECT_TRUE(root.force_fields.empty() || root.force_fields.back() != cf);
  animate(root);
  EXPECT_DOUBLE_EQ(vx(root), 0.4);  // no force any more
  EXPECT_FALSE(root.diagnostics().has_errors());
}

TEST(GraphChanges, MassReplacedBetweenSteps) {
  auto s = test::load(kPoint);
  Node& root = *s.root;
  root.add_object(make(R"(<ConstantForceField name="push" force="2 0 0"/>)", "push"));
  animate(root);
  EXPECT_DOUBLE_EQ(vx(root), 0.2);
  ASSERT_NE(root.remove_object(root.find_object_named("mass")), nullptr);
  EXPECT_EQ(root.mass, nullptr);  // the single slot is emptied, as in SOFA
  root.add_object(make(R"(<UniformMass name="heavy" totalMass="4"/>)", "heavy"));
  EXPECT_EQ(root.mass, root.find_object_named("heavy"));
  animate(root);
  EXPECT_DOUBLE_EQ(vx(root), 0.25);  // a = F/4
}

TEST(GraphChanges, WholeChildBodyAddedAndRemoved) {
  auto s = test::load(R"(<Node name="root" dt="0.1" gravity="0 -10 0">
  <DefaultAnimationLoop/>
  <Node name="a">
    <EulerExplicitSolver/>
    <MechanicalObject name="dofs" position="0 0 0"/>
    <UniformMass totalMass="1"/>
  </Node>
</Node>)");
  Node& root = *s.root;
  animate(root);
  auto donor = test::build(R"(<Node><Node name="b">
    <EulerExplicitSolver/>
    <MechanicalObject name="dofs" position="5 0 0"/>
    <UniformMass totalMass="1"/>
    <Node name="mapped">
      <MechanicalObject name="tip" position="0 0 0"/>
      <IdentityMapping/>
    </Node>
  </Node></Node>)");
  Node* b = root.add_child(donor.root->remove_child(donor.root->find_child_named("b")));
  ASSERT_NE(b, nullptr);
  animate(root);
  // The new body fell for one step (its mapped child follows); the old one for two.
  const auto& xb = b->mechanical_state->read(kPosition);
  EXPECT_DOUBLE_EQ(xb[0], 5.0);
  EXPECT_DOUBLE_EQ(xb[1], -0.1);
  EXPECT_DOUBLE_EQ(b->find_child_named("mapped")->mechanical_state->read(kPosition)[1], -0.1);
  Node* a = root.find_child_named("a");
  EXPECT_DOUBLE_EQ(a->mechanical_state->read(kPosition)[1], -0.1 - 0.2);

  auto gone = root.remove_child(b);
  ASSERT_NE(gone, nullptr);
  animate(root);
  EXPECT_DOUBLE_EQ(gone->mechanical_state->read(kPosition)[1], -0.1);  // no longer stepped
  EXPECT_DOUBLE_EQ(a->mechanical_state->read(kPosition)[1], -0.1 - 0.2 - 0.3);
  EXPECT_FALSE(root.diagnostics().has_errors());
}

TEST(GraphChanges, DeactivatedNodeIsSkippedFromTheNextStep) {
  auto s = test::load(R"(<Node name="root" dt="0.1" gravity="0 -10 0">
  <Node name="a"><EulerExplicitSolver/><MechanicalObject position="0 0 0"/><UniformMass totalMass="1"/></Node>
</Node>)");
  Node& root = *s.root;
  Node* a = root.find_child_named("a");
  animate(root);
  a->activated.set(false);
  animate(root);
  EXPECT_DOUBLE_EQ(a->mechanical_state->read(kVelocity)[1], -1.0);
  a->activated.set(true);
  animate(root);
  EXPECT_DOUBLE_EQ(a->mechanical_state->read(kVelocity)[1], -2.0);
}

// Box2D's world->locked: no structural edit while the mechanical stages run.
TEST(GraphChanges, EditsDuringAStepAreRefused) {
  auto s = test::load(kPoint);
  Node& root = *s.root;
  struct Meddler final : StepObserver {
    std::unique_ptr<Component> spare;
    Component* added_in_solve = reinterpret_cast<Component*>(1);
    std::unique_ptr<Component> removed_in_solve;
    Component* added_in_begin = nullptr;
    void before_stage(Stage st, Node& root) override {
      if (st == Stage::solve) {
        added_in_solve = root.add_object(make(R"(<ConstantForceField name="x" force="1 0 0"/>)", "x"));
        removed_in_solve = root.remove_object(root.find_object_named("mass"));
      }
      if (st == Stage::begin_events && spare) added_in_begin = root.add_object(std::move(spare));
    }
  } meddler;
  add_step_observer(root, &meddler);
  animate(root);
  EXPECT_EQ(meddler.added_in_solve, nullptr);
  EXPECT_EQ(meddler.removed_in_solve, nullptr);
  EXPECT_NE(root.find_object_named("mass"), nullptr);
  const auto errors = test::messages(root.diagnostics(), Severity::error);
  EXPECT_TRUE(test::any_contains(errors, "while a step is running")) << ::testing::PrintToString(errors);
  EXPECT_FALSE(root.graph_locked());  // released at the end of the step

  // Event stages are open: a controller may add a force field there, used in the same step.
  remove_step_observer(root, &meddler);
  Meddler opener;
  opener.spare = make(R"(<ConstantForceField name="push" force="3 0 0"/>)", "push");
  struct OnlyBegin final : StepObserver {
    Meddler* m;
    void before_stage(Stage st, Node& r) override {
      if (st == Stage::begin_events) m->before_stage(st, r);
    }
  } only_begin;
  only_begin.m = &opener;
  add_step_observer(root, &only_begin);
  animate(root);
  ASSERT_NE(opener.added_in_begin, nullptr);
  EXPECT_DOUBLE_EQ(vx(root), 0.3);
}

TEST(GraphChanges, RemovingALinkedObjectCutsTheLinks) {
  auto s = test::load(R"(<Node name="root" dt="0.1" gravity="0 -10 0">
  <EulerExplicitSolver/>
  <MechanicalObject name="dofs" position="0 0 0  1 0 0"/>
  <UniformMass name="mass" totalMass="1"/>
  <BoxROI name="box" box="-0.5 -0.5 -0.5  0.5 0.5 0.5"/>
  <FixedProjectiveConstraint name="fix" indices="@box.indices"/>
</Node>)");
  Node& root = *s.root;
  animate(root);
  auto* fix = root.find_object_named("fix");
  // The data link from the constraint to the ROI keeps its last value.
  auto box = root.remove_object(root.find_object_named("box"));
  ASSERT_NE(box, nullptr);
  box.reset();  // destroyed: nothing may point to it any more
  animate(root);
  EXPECT_EQ(fix->state(), ComponentState::valid);
  const auto& x = root.get_mechanical_state()->read(kPosition);
  EXPECT_DOUBLE_EQ(x[1], 0.0);   // point 0 still fixed
  EXPECT_LT(x[4], 0.0);          // point 1 falls

  // An object link: the mass and the constraint act on the removed state; they are disabled, not left dangling.
  auto dofs = root.remove_object(root.find_object_named("dofs"));
  dofs.reset();
  EXPECT_EQ(root.find_object_named("mass")->state(), ComponentState::invalid);
  EXPECT_EQ(fix->state(), ComponentState::invalid);
  animate(root);  // nothing left to integrate; no crash
  EXPECT_TRUE(test::any_contains(test::messages(root.diagnostics(), Severity::warning), "removed from the graph"));
}

// Components that keep per-element data follow the list's version, not its size.
TEST(GraphChanges, SameSizeTopologyChangeIsFollowed) {
  const std::string scene = R"(<Node name="root" dt="0.01" gravity="0 0 0">
  <EulerImplicitSolver/>
  <CGLinearSolver iterations="100" tolerance="1e-14" threshold="1e-20"/>
  <MeshTopology name="topo" position="0 0 0  1 0 0  0 1 0  1 1 0" triangles="TRIS"/>
  <MechanicalObject name="dofs"/>
  <UniformMass totalMass="1"/>
  <TriangularFEMForceField name="fem" youngModulus="1000" poissonRatio="0.3"/>
</Node>)";
  auto with = [&](const std::string& tris) {
    std::string x = scene;
    x.replace(x.find("TRIS"), 4, tris);
    return x;
  };
  auto changed = test::load(with("0 1 2  1 3 2"));
  auto fresh = test::load(with("0 1 2  0 3 2"));
  auto* topo = dynamic_cast<MeshContainer*>(changed.root->find_object_named("topo"));
  ASSERT_NE(topo, nullptr);
  topo->triangles_f.set({{0, 1, 2}, {0, 3, 2}});  // one removed, one added: same size
  for (auto* s : {&changed, &fresh}) {
    auto* dofs = s->root->get_mechanical_state();
    dofs->write(kPosition)[9] = 1.2;  // stretch point 3
    animate(*s->root);
  }
  const auto& a = changed.root->get_mechanical_state()->read(kPosition);
  const auto& b = fresh.root->get_mechanical_state()->read(kPosition);
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i], b[i]) << i;
}

// Reading a state vector is not a change: versions move on writes only.
TEST(StateVersions, ReadsLeaveVersionsAloneWritesMoveThem) {
  auto s = test::load(kPoint);
  Node& root = *s.root;
  MechanicalState* st = root.get_mechanical_state();
  auto* x = st->find_field("position");
  auto* v = st->find_field("velocity");
  ASSERT_TRUE(x && v);
  const auto x0 = x->version(), v0 = v->version();
  st->read(kPosition);
  st->read(kVelocity);
  MechanicalOps ops(root);
  EXPECT_EQ(ops.v_dot(kPosition, kPosition), 0.0);
  EXPECT_TRUE(ops.all_finite(kVelocity));
  EXPECT_EQ(x->version(), x0);
  EXPECT_EQ(v->version(), v0);

  st->write(kVelocity)[0] = 1.0;
  EXPECT_GT(v->version(), v0);
  EXPECT_EQ(x->version(), x0);
  const auto v1 = v->version();
  animate(root);  // the step writes both
  EXPECT_GT(x->version(), x0);
  EXPECT_GT(v->version(), v1);
  EXPECT_DOUBLE_EQ(st->read(kPosition)[0], 0.1);
}

}  // namespace
}  // namespace sinew

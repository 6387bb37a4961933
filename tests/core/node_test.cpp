// Nodes: slots, look-ups, default-name counters, context (spec/framework.md §3.1–§3.3, traps T2, T3, T12).
// Default names built from XML are tested in tests/scene/scene_builder_test.cpp
// (the scene builder is not part of sinew_core).
#include "core/node.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>

#include "core/matrix_sink.h"
#include "core/roles.h"
#include "fake_roles.h"

using namespace sinew;
using sinew::fakes::TestState;
using sinew::fakes::TestSolver;

namespace {

// Minimal implementations of the roles, enough to be filed in slots.

class TestForceField : public ForceField {
 public:
  void add_force(const MechParams&) override {}
  void add_dforce(const MechParams&, double) override {}
};

class TestInteraction final : public TestForceField {
 public:
  bool is_interaction() const override { return true; }
};

class TestMass final : public Mass {
 public:
  void add_force(const MechParams&) override {}
  void add_mdx(const MechParams&, int, int, double) override {}
  void acc_from_f(const MechParams&, int, int) override {}
  void add_gravity_to_v(int, double) override {}
  double total() const override { return 0; }
  bool build_mass(MatrixSink&) override { return false; }
};

class TestTopology final : public MeshTopologyBase {
 public:
  std::size_t nb_points() const override { return 0; }
  bool has_positions() const override { return false; }
  Vec3 point(std::size_t) const override { return Vec3::Zero(); }
  const std::vector<Edge>& edges() const override { return e_; }
  const std::vector<Triangle>& triangles() const override { return t_; }
  const std::vector<Quad>& quads() const override { return q_; }
  const std::vector<Tetra>& tetrahedra() const override { return te_; }
  const std::vector<Hexa>& hexahedra() const override { return h_; }

 private:
  std::vector<Edge> e_;
  std::vector<Triangle> t_;
  std::vector<Quad> q_;
  std::vector<Tetra> te_;
  std::vector<Hexa> h_;
};

class TestLoop final : public AnimationLoop {
 public:
  void step(double) override {}
};

class TestConstraint final : public ProjectiveConstraint {
 public:
  void project_response(int) override {}
  void project_jacobian(ConstraintMatrix&) override {}
  void project_velocity(int, double) override {}
  void project_position(int, double) override {}
};


// Sets gravity of its node to (0, 0, -1) (like SOFA's Gravity component).
class TestGravity final : public ContextObject {
 public:
  void apply(Node& node) override { node.gravity.set(Vec3(0, 0, -1)); }
};

template <class T>
T* add(Node& n, const std::string& name = {}) {
  auto c = std::make_unique<T>();
  c->name.set(name);
  return static_cast<T*>(n.add_object(std::move(c)));
}

Node* child(Node& parent, const std::string& name) { return parent.add_child(std::make_unique<Node>(name)); }

template <class V, class T>
bool contains(const V& v, T* x) {
  return std::find(v.begin(), v.end(), x) != v.end();
}

}  // namespace

// ---------------------------------------------------------------- slots (§3.1)

// §3.1: a single slot holds the last inserted component; the earlier one stays in `objects` and a
// warning is emitted.
TEST(NodeSlots, SecondStateReplacesTheFirstWithAWarning) {
  Node root("root");
  auto* s1 = add<TestState>(root, "s1");
  EXPECT_EQ(root.diagnostics().warning_count(), 0);
  auto* s2 = add<TestState>(root, "s2");
  EXPECT_EQ(root.mechanical_state, s2);
  EXPECT_EQ(root.objects().size(), 2u);
  EXPECT_EQ(root.objects()[0].get(), s1);
  ASSERT_EQ(root.diagnostics().warning_count(), 1);
  EXPECT_NE(root.diagnostics().messages()[0].text.find("only one"), std::string::npos);
}

TEST(NodeSlots, SecondAnimationLoopReplacesTheFirstWithAWarning) {
  Node root("root");
  add<TestLoop>(root);
  auto* l2 = add<TestLoop>(root);
  EXPECT_EQ(root.animation_loop, l2);
  EXPECT_EQ(root.diagnostics().warning_count(), 1);
}

// §3.1 / T12: a mass sits in the mass slot and also in the force-field list (once).
TEST(NodeSlots, MassIsAlsoAForceField) {
  Node root("root");
  auto* ff = add<TestForceField>(root);
  auto* m = add<TestMass>(root);
  EXPECT_EQ(root.mass, m);
  ASSERT_EQ(root.force_fields.size(), 2u);
  EXPECT_EQ(root.force_fields[0], ff);
  EXPECT_EQ(root.force_fields[1], m);
}

// §3.1: interaction force fields are not in the force-field list.
TEST(NodeSlots, InteractionForceFieldsHaveTheirOwnList) {
  Node root("root");
  auto* i = add<TestInteraction>(root);
  EXPECT_TRUE(root.force_fields.empty());
  ASSERT_EQ(root.interaction_force_fields.size(), 1u);
  EXPECT_EQ(root.interaction_force_fields[0], i);
}

// §3.1: the meshTopology slot is the last topology inserted.
TEST(NodeSlots, MeshTopologySlotIsTheLastInserted) {
  Node root("root");
  add<TestTopology>(root, "t1");
  auto* t2 = add<TestTopology>(root, "t2");
  EXPECT_EQ(root.mesh_topology, t2);
}

TEST(NodeSlots, ListsKeepInsertionOrder) {
  Node root("root");
  auto* c1 = add<TestConstraint>(root);
  auto* s1 = add<TestSolver>(root);
  auto* c2 = add<TestConstraint>(root);
  auto* g = add<TestGravity>(root);
  EXPECT_EQ(root.projective_constraints, (std::vector<ProjectiveConstraint*>{c1, c2}));
  EXPECT_EQ(root.solvers, (std::vector<OdeSolver*>{s1}));
  EXPECT_TRUE(contains(root.context_objects, static_cast<ContextObject*>(g)));
}

TEST(NodeSlots, InsertAtFrontPutsTheObjectFirst) {
  Node root("root");
  add<TestState>(root, "s");
  auto* loop = static_cast<TestLoop*>(root.add_object(std::make_unique<TestLoop>(), /*at_front=*/true));
  EXPECT_EQ(root.objects()[0].get(), loop);
  EXPECT_EQ(root.animation_loop, loop);
  EXPECT_EQ(loop->node(), &root);
}

// ---------------------------------------------------------------- look-ups (§3.3)

TEST(NodeLookup, MechanicalStateOfTheNodeItself) {
  Node root("root");
  auto* s = add<TestState>(root);
  Node* c = child(root, "c");
  auto* cs = add<TestState>(*c);
  EXPECT_EQ(root.get_mechanical_state(), s);
  EXPECT_EQ(c->get_mechanical_state(), cs);
}

// §3.3: without a local state, the FIRST state (object order) of the nearest ancestor that has one,
// not that ancestor's slot (which holds the last).
TEST(NodeLookup, MechanicalStateFallsBackToTheFirstStateOfTheNearestAncestor) {
  Node root("root");
  auto* s1 = add<TestState>(root, "s1");
  add<TestState>(root, "s2");
  Node* a = child(root, "a");
  Node* b = child(*a, "b");
  EXPECT_EQ(b->get_mechanical_state(), s1);
  EXPECT_EQ(a->get_mechanical_state(), s1);
}

TEST(NodeLookup, MechanicalStateNearestAncestorWins) {
  Node root("root");
  add<TestState>(root, "top");
  Node* a = child(root, "a");
  auto* mid = add<TestState>(*a, "mid");
  Node* b = child(*a, "b");
  EXPECT_EQ(b->get_mechanical_state(), mid);
  Node lonely("lonely");
  EXPECT_EQ(lonely.get_mechanical_state(), nullptr);
}

// §3.3 / T2: the last topology of the node, else the FIRST one of the nearest ancestor having one.
TEST(NodeLookup, MeshTopologyLinkIsLastLocalElseFirstOfNearestAncestor) {
  Node root("root");
  auto* t1 = add<TestTopology>(root, "t1");
  auto* t2 = add<TestTopology>(root, "t2");
  Node* a = child(root, "a");
  Node* b = child(*a, "b");
  EXPECT_EQ(root.get_mesh_topology_link(), t2);
  EXPECT_EQ(a->get_mesh_topology_link(), t1);
  EXPECT_EQ(b->get_mesh_topology_link(), t1);
  auto* ta = add<TestTopology>(*a, "ta");
  EXPECT_EQ(b->get_mesh_topology_link(), ta);
}

// §3.3: get<T>(Local) is the first in object order (what MechanicalObject uses, T2).
TEST(NodeLookup, FindLocalIsTheFirstInObjectOrder) {
  Node root("root");
  auto* t1 = add<TestTopology>(root, "t1");
  add<TestTopology>(root, "t2");
  EXPECT_EQ(root.find_local<MeshTopologyBase>(), t1);
  Node* a = child(root, "a");
  EXPECT_EQ(a->find_local<MeshTopologyBase>(), nullptr);
  EXPECT_EQ(a->find_up<MeshTopologyBase>(), t1);
}

// §3.3: SearchDown is node objects first, then children depth-first in child order.
TEST(NodeLookup, FindDownAndCollectDownAreDepthFirst) {
  Node root("root");
  Node* a = child(root, "a");
  Node* a1 = child(*a, "a1");
  Node* b = child(root, "b");
  auto* sb = add<TestState>(*b, "sb");
  auto* sa1 = add<TestState>(*a1, "sa1");
  auto* sr = add<TestState>(root, "sr");
  EXPECT_EQ(root.find_down<MechanicalState>(), sr);
  EXPECT_EQ(a->find_down<MechanicalState>(), sa1);
  std::vector<MechanicalState*> all;
  root.collect_down(all);
  EXPECT_EQ(all, (std::vector<MechanicalState*>{sr, sa1, sb}));
}

TEST(NodeLookup, ObjectsAndChildrenByName) {
  Node root("root");
  auto* s = add<TestState>(root, "dofs");
  Node* c = child(root, "Beam");
  EXPECT_EQ(root.find_object_named("dofs"), s);
  EXPECT_EQ(root.find_object_named("Beam"), nullptr);
  EXPECT_EQ(root.find_child_named("Beam"), c);
  EXPECT_EQ(root.find_child_named("dofs"), nullptr);
}

// ---------------------------------------------------------------- structure

TEST(NodeStructure, PathFromTheRoot) {
  Node root("root");
  Node* a = child(root, "a");
  Node* b = child(*a, "b");
  EXPECT_EQ(root.path(), "/");
  EXPECT_EQ(a->path(), "/a");
  EXPECT_EQ(b->path(), "/a/b");
  EXPECT_EQ(b->root(), &root);
  EXPECT_EQ(b->parent(), a);
}

// T17: default-name counters are per node and per class.
TEST(NodeStructure, DefaultNameCountersArePerNodeAndClass) {
  Node root("root");
  Node* c = child(root, "c");
  EXPECT_EQ(root.next_default_index("MechanicalObject"), 1);
  EXPECT_EQ(root.next_default_index("MechanicalObject"), 2);
  EXPECT_EQ(root.next_default_index("UniformMass"), 1);
  EXPECT_EQ(c->next_default_index("MechanicalObject"), 1);
  EXPECT_EQ(root.next_default_index("MechanicalObject"), 3);
}

// The root owns the diagnostics of the whole graph.
TEST(NodeStructure, DiagnosticsAreSharedThroughTheRoot) {
  Node root("root");
  Node* c = child(root, "c");
  c->diagnostics().error({}, "boom");
  EXPECT_TRUE(root.diagnostics().has_errors());
  EXPECT_EQ(&c->diagnostics(), &root.diagnostics());
}

TEST(NodeStructure, ForEachNodeIsPreOrderAndSkipsInactiveSubtrees) {
  Node root("root");
  Node* a = child(root, "a");
  child(*a, "a1");
  Node* b = child(root, "b");
  child(*b, "b1");
  Node* c = child(root, "c");
  b->activated.set(false);
  std::vector<std::string> seen;
  for_each_node(root, [&](Node& n) { seen.push_back(n.name.value()); });
  EXPECT_EQ(seen, (std::vector<std::string>{"root", "a", "a1", "c"}));
  (void)c;
}

// ---------------------------------------------------------------- context (§3.2, T3)

// T3: a child's own dt/gravity are overwritten by its parent's.
TEST(NodeContext, ChildCopiesDtGravityAndTimeFromItsParent) {
  Node root("root");
  root.dt.set(0.04);
  root.gravity.set(Vec3(1, 2, 3));
  root.time.set(0.5);
  Node* c = child(root, "c");
  c->dt.set(99);
  c->gravity.set(Vec3(0, 0, 0));
  c->update_context();
  EXPECT_EQ(c->dt.value(), 0.04);
  EXPECT_EQ(c->gravity.value(), Vec3(1, 2, 3));
  EXPECT_EQ(c->time.value(), 0.5);
}

// §3.2: context objects override the context of their node after the copy.
TEST(NodeContext, ContextObjectsApplyAfterTheCopy) {
  Node root("root");
  Node* c = child(root, "c");
  add<TestGravity>(*c);
  c->update_context();
  EXPECT_EQ(c->gravity.value(), Vec3(0, 0, -1));
  Node* cc = child(*c, "cc");
  cc->update_context();
  EXPECT_EQ(cc->gravity.value(), Vec3(0, 0, -1));
}

TEST(NodeContext, DefaultGravityAndDt) {
  Node root("root");
  EXPECT_EQ(root.gravity.value(), Vec3(0, -9.81, 0));
  EXPECT_EQ(root.dt.value(), 0.01);
}

// ---------------------------------------------------------------- changes between steps

TEST(NodeChanges, RemovedObjectLeavesItsSlotsAndLists) {
  Node root("root");
  auto* s = add<TestState>(root, "s");
  auto* ff = add<TestForceField>(root, "ff");
  auto* m = add<TestMass>(root, "m");
  auto* c = add<TestConstraint>(root, "c");
  auto taken = root.remove_object(m);
  ASSERT_EQ(taken.get(), m);
  EXPECT_EQ(root.mass, nullptr);
  EXPECT_EQ(root.force_fields, (std::vector<ForceField*>{ff}));
  EXPECT_EQ(m->node(), nullptr);
  root.remove_object(c);
  EXPECT_TRUE(root.projective_constraints.empty());
  root.remove_object(s);
  EXPECT_EQ(root.mechanical_state, nullptr);
  EXPECT_EQ(root.objects().size(), 1u);
  // Not an object of this node: nothing happens.
  TestState other;
  EXPECT_EQ(root.remove_object(&other), nullptr);
}

// The single slot empties when its holder leaves, even if an earlier object of the role remains (SOFA).
TEST(NodeChanges, SingleSlotEmptiesWhenItsHolderLeaves) {
  Node root("root");
  add<TestState>(root, "s1");
  auto* s2 = add<TestState>(root, "s2");
  root.remove_object(s2);
  EXPECT_EQ(root.mechanical_state, nullptr);
  EXPECT_EQ(root.objects().size(), 1u);
}

TEST(NodeChanges, EveryStructuralChangeMovesTheVersion) {
  Node root("root");
  Node* a = child(root, "a");
  auto v = root.structure_version();
  auto moved = [&] {
    const bool m = root.structure_version() != v;
    v = root.structure_version();
    return m;
  };
  auto* s = add<TestState>(*a, "s");
  EXPECT_TRUE(moved());
  EXPECT_EQ(a->structure_version(), root.structure_version());  // one counter, owned by the root
  a->activated.set(false);
  EXPECT_TRUE(moved());
  a->sleeping.set(true);
  EXPECT_TRUE(moved());
  s->set_state(ComponentState::invalid);
  EXPECT_TRUE(moved());
  s->set_state(ComponentState::invalid);  // no change, no move
  EXPECT_FALSE(moved());
  (void)a->activated.get();
  EXPECT_FALSE(moved());
  root.remove_object(root.find_object_named("nothing"));
  EXPECT_FALSE(moved());
  EXPECT_NE(root.remove_child(a), nullptr);
  EXPECT_TRUE(moved());
}

TEST(NodeChanges, LockedGraphRefusesEditsWithAnError) {
  Node root("root");
  Node* a = child(root, "a");
  auto* s = add<TestState>(*a, "s");
  root.set_graph_locked(true);
  EXPECT_TRUE(a->graph_locked());
  const auto v = root.structure_version();
  EXPECT_EQ(a->add_object(std::make_unique<TestForceField>()), nullptr);
  EXPECT_EQ(a->remove_object(s), nullptr);
  EXPECT_EQ(root.add_child(std::make_unique<Node>("b")), nullptr);
  EXPECT_EQ(root.remove_child(a), nullptr);
  EXPECT_EQ(root.structure_version(), v);
  EXPECT_EQ(root.diagnostics().error_count(), 4);
  EXPECT_NE(root.diagnostics().messages()[0].text.find("while a step is running"), std::string::npos);
  root.set_graph_locked(false);
  EXPECT_NE(a->remove_object(s), nullptr);
}

// Links from the rest of the graph into a removed subtree are cut; their owners are disabled.
TEST(NodeChanges, LinksIntoARemovedSubtreeAreCut) {
  Node root("root");
  Node* a = child(root, "a");
  auto* s = add<TestState>(*a, "s");
  auto* ff = add<TestForceField>(root, "ff");
  ff->mstate.set(s);
  auto gone = root.remove_child(a);
  EXPECT_EQ(ff->mstate.get(), nullptr);
  EXPECT_EQ(ff->state(), ComponentState::invalid);
  EXPECT_EQ(gone->parent(), nullptr);
  EXPECT_EQ(root.diagnostics().warning_count(), 1);
}

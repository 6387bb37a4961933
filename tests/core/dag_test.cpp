// Nodes with several parents (SOFA's DAG): linking, traversal order, pruning,
// removal and destruction (SOFA's Node::executeVisitorTopDown, DAGNode).
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "core/mechanical_ops.h"
#include "core/node.h"
#include "core/roles.h"
#include "fake_roles.h"

using namespace sinew;
using sinew::fakes::TestState;
using sinew::fakes::TestSolver;

namespace {



Node* child(Node& parent, const std::string& name) { return parent.add_child(std::make_unique<Node>(name)); }

std::vector<std::string> names_in_order(Node& top) {
  std::vector<std::string> seen;
  traverse(top, [&](Node& n, bool) {
    seen.push_back(n.name.value());
    return Visit::descend;
  });
  return seen;
}

using Names = std::vector<std::string>;

// SofaPython3's example-mapping.py: root → {Modelling, Simulation}, Simulation → Modelling.
struct ExampleMappingGraph {
  Node root{"root"};
  Node* modelling = child(root, "Modelling");
  Node* object = child(*modelling, "Object");
  Node* simulation = child(root, "Simulation");
  ExampleMappingGraph() { EXPECT_TRUE(simulation->add_linked_child(modelling)); }
};

}  // namespace

TEST(NodeDag, LinkedChildKeepsItsOwnerAndGainsAParent) {
  ExampleMappingGraph g;
  EXPECT_EQ(g.modelling->parent(), &g.root);
  ASSERT_EQ(g.modelling->parents().size(), 2u);
  EXPECT_EQ(g.modelling->parents()[1], g.simulation);
  EXPECT_TRUE(g.root.owns(g.modelling));
  EXPECT_FALSE(g.simulation->owns(g.modelling));
  ASSERT_EQ(g.simulation->children().size(), 1u);
  EXPECT_EQ(g.simulation->children()[0], g.modelling);
  EXPECT_EQ(g.object->path(), "/Modelling/Object");  // paths follow the owner
  EXPECT_TRUE(graph_has_links(*g.object));
}

// SOFA: a node is visited once, when all of its parents inside the traversal were.
TEST(NodeDag, TraversalVisitsAMultiParentNodeOnceAfterAllItsParents) {
  ExampleMappingGraph g;
  EXPECT_EQ(names_in_order(g.root), (Names{"root", "Simulation", "Modelling", "Object"}));
  // From the solver's node, the owner (outside the traversal) is ignored.
  EXPECT_EQ(names_in_order(*g.simulation), (Names{"Simulation", "Modelling", "Object"}));
  EXPECT_EQ(names_in_order(*g.modelling), (Names{"Modelling", "Object"}));
}

TEST(NodeDag, DiamondIsVisitedOnceInSofaOrder) {
  Node root("root");
  Node* a = child(root, "a");
  Node* b = child(root, "b");
  Node* d = child(*a, "d");
  child(*d, "e");
  ASSERT_TRUE(b->add_linked_child(d));
  child(*b, "f");
  EXPECT_EQ(names_in_order(root), (Names{"root", "a", "b", "d", "e", "f"}));
  std::vector<std::string> up;
  traverse(root, [](Node&, bool) { return Visit::descend; }, [&](Node& n) { up.push_back(n.name.value()); });
  // `up` follows each visit's own recursion: a has no child visited from it.
  EXPECT_EQ(up, (Names{"a", "e", "d", "f", "b", "root"}));
}

// A child is pruned only when all of its parents are: the solver node prunes its
// subtree, yet the owner's branch still reaches the shared node unpruned.
TEST(NodeDag, NodeIsPrunedOnlyWhenAllItsParentsAre) {
  ExampleMappingGraph g;
  std::vector<std::pair<std::string, bool>> seen;
  traverse(g.root, [&](Node& n, bool pruned) {
    seen.emplace_back(n.name.value(), pruned);
    return n.name.value() == "Simulation" ? Visit::prune : Visit::descend;
  });
  EXPECT_EQ(seen, (std::vector<std::pair<std::string, bool>>{
                      {"root", false}, {"Simulation", false}, {"Modelling", false}, {"Object", false}}));
  // Both parents prune: the shared node is pruned, and so is everything below it.
  Node root("root");
  Node* a = child(root, "a");
  Node* b = child(root, "b");
  Node* x = child(*a, "x");
  child(*x, "y");
  ASSERT_TRUE(b->add_linked_child(x));
  for (const bool b_prunes : {false, true}) {
    seen.clear();
    traverse(root, [&](Node& n, bool pruned) {
      seen.emplace_back(n.name.value(), pruned);
      const bool prunes = n.name.value() == "a" || (b_prunes && n.name.value() == "b");
      return prunes ? Visit::prune : Visit::descend;
    });
    EXPECT_EQ(seen, (std::vector<std::pair<std::string, bool>>{
                        {"root", false}, {"a", false}, {"b", false}, {"x", b_prunes}, {"y", b_prunes}}));
  }
}

// SOFA: an inactive parent is pruned and not descended; its multi-parent child still
// runs from the other parent when that one comes last.
TEST(NodeDag, SkippedParentCountsAsPruned) {
  ExampleMappingGraph g;
  g.simulation->activated.set(false);
  std::vector<std::string> seen;
  for_each_node(g.root, [&](Node& n) { seen.push_back(n.name.value()); });
  EXPECT_EQ(seen, (Names{"root"}));  // Modelling waits for Simulation, which never descends
}

// A solver's scope reaches the subtree linked under it; the graph's solver list has it once.
TEST(NodeDag, SolverScopeReachesTheLinkedSubtree) {
  ExampleMappingGraph g;
  auto* s = static_cast<MechanicalState*>(g.object->add_object(std::make_unique<TestState>()));
  g.simulation->add_object(std::make_unique<TestSolver>());
  MechanicalOps ops(*g.simulation);
  ASSERT_EQ(ops.all_states().size(), 1u);
  EXPECT_EQ(ops.all_states()[0], s);
  MechanicalOps whole(g.root);
  EXPECT_EQ(whole.all_states().size(), 1u);  // once, not through both parents
  std::vector<MechanicalState*> states;
  g.root.collect_down(states);
  EXPECT_EQ(states.size(), 1u);
}

TEST(NodeDag, FindUpSearchesEveryParent) {
  ExampleMappingGraph g;
  auto* solver = static_cast<OdeSolver*>(g.simulation->add_object(std::make_unique<TestSolver>()));
  EXPECT_EQ(g.object->find_up<OdeSolver>(), solver);
  auto* s = static_cast<MechanicalState*>(g.simulation->add_object(std::make_unique<TestState>()));
  EXPECT_EQ(g.object->get_mechanical_state(), s);
}

TEST(NodeDag, LinksThatWouldBreakTheGraphAreRefused) {
  ExampleMappingGraph g;
  EXPECT_FALSE(g.simulation->add_linked_child(g.modelling));  // already a child
  EXPECT_FALSE(g.object->add_linked_child(g.modelling));      // cycle
  EXPECT_FALSE(g.modelling->add_linked_child(g.modelling));   // itself
  Node other("other");
  Node* stranger = child(other, "stranger");
  EXPECT_FALSE(g.root.add_linked_child(stranger));  // another graph
  EXPECT_GE(g.root.diagnostics().error_count(), 3);
  EXPECT_EQ(names_in_order(g.root), (Names{"root", "Simulation", "Modelling", "Object"}));
}

TEST(NodeDag, RemovingALinkedChildKeepsTheNode) {
  ExampleMappingGraph g;
  EXPECT_EQ(g.simulation->remove_child(g.modelling), nullptr);
  EXPECT_TRUE(g.simulation->children().empty());
  EXPECT_EQ(g.modelling->parents().size(), 1u);
  EXPECT_FALSE(graph_has_links(g.root));
  EXPECT_EQ(names_in_order(g.root), (Names{"root", "Modelling", "Object", "Simulation"}));
}

TEST(NodeDag, RemovingTheOwnerHandsTheNodeToTheNextParent) {
  ExampleMappingGraph g;
  EXPECT_EQ(g.root.remove_child(g.modelling), nullptr);
  EXPECT_EQ(g.modelling->parent(), g.simulation);
  EXPECT_TRUE(g.simulation->owns(g.modelling));
  EXPECT_EQ(g.object->path(), "/Simulation/Modelling/Object");
  EXPECT_FALSE(graph_has_links(g.root));
  EXPECT_EQ(names_in_order(g.root), (Names{"root", "Simulation", "Modelling", "Object"}));
}

// A subtree that leaves the graph leaves as a tree: parent links across its border are cut.
TEST(NodeDag, RemovedSubtreeLeavesAsATree) {
  Node root("root");
  Node* a = child(root, "a");
  Node* a1 = child(*a, "a1");
  Node* b = child(root, "b");
  ASSERT_TRUE(b->add_linked_child(a1));  // link from outside into the subtree
  ASSERT_TRUE(a1->add_linked_child(b) == false);
  Node* c = child(root, "c");
  ASSERT_TRUE(a->add_linked_child(c));  // link from the subtree to outside
  std::unique_ptr<Node> gone = root.remove_child(a);
  ASSERT_EQ(gone.get(), a);
  EXPECT_EQ(a->parent(), nullptr);
  EXPECT_TRUE(b->children().empty());
  EXPECT_EQ(a1->parents().size(), 1u);
  EXPECT_EQ(c->parents().size(), 1u);
  EXPECT_EQ(a->children().size(), 1u);
  EXPECT_FALSE(graph_has_links(root));
  EXPECT_FALSE(graph_has_links(*a));
  EXPECT_EQ(names_in_order(root), (Names{"root", "b", "c"}));
}

// Destroying a graph whose links go both ways between siblings (owner destroyed
// first, linker destroyed first) touches no freed node (the checking build's ASan
// sees it).
TEST(NodeDag, GraphsWithLinksAreDestroyedCleanly) {
  for (int order = 0; order < 2; ++order) {
    auto top = std::make_unique<Node>("top");
    Node* x = child(*top, "x");
    Node* y = child(*top, "y");
    Node* xs = child(*x, "xs");
    Node* ys = child(*y, "ys");
    ASSERT_TRUE((order ? x : y)->add_linked_child(order ? ys : xs));
    ASSERT_TRUE(top->add_linked_child(xs));
    top.reset();
  }
  // A whole subtree handed out with inner links keeps them and is destroyed cleanly too.
  Node root("root");
  Node* a = child(root, "a");
  Node* a1 = child(*a, "a1");
  Node* a2 = child(*a, "a2");
  ASSERT_TRUE(a2->add_linked_child(a1));
  std::unique_ptr<Node> gone = root.remove_child(a);
  EXPECT_EQ(a1->parents().size(), 2u);
  EXPECT_TRUE(graph_has_links(*a));
  EXPECT_FALSE(graph_has_links(root));
  gone.reset();
  EXPECT_EQ(names_in_order(root), (Names{"root"}));
}

// A refused addition leaves the node or component with the caller (nothing is
// destroyed behind its back: the Python front end gives it back to its handle).
TEST(NodeDag, RefusedAdditionsLeaveOwnershipWithTheCaller) {
  auto top = std::make_unique<Node>("top");
  Node* a = child(*top, "a");
  EXPECT_EQ(a->add_child(std::move(top)), nullptr);  // the root below its own child: a cycle
  ASSERT_NE(top, nullptr);
  EXPECT_TRUE(top->diagnostics().has_errors());
  EXPECT_EQ(a->parent(), top.get());

  top->set_graph_locked(true);
  std::unique_ptr<Component> solver = std::make_unique<TestSolver>();
  auto node = std::make_unique<Node>("late");
  EXPECT_EQ(a->add_object(std::move(solver)), nullptr);
  EXPECT_EQ(a->add_child(std::move(node)), nullptr);
  EXPECT_NE(solver, nullptr);
  EXPECT_NE(node, nullptr);
  top->set_graph_locked(false);
  EXPECT_NE(a->add_object(std::move(solver)), nullptr);
  EXPECT_EQ(solver, nullptr);
}

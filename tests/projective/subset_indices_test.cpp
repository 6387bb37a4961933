// Index lists following point removals (SOFA's TopologySubsetIndices): the
// update rule on hand-made lists, and the projective constraints of a scene
// whose container loses points.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/node.h"
#include "core/simulation.h"
#include "projective/affine_movement_projective_constraint.h"
#include "projective/direction_projective_constraint.h"
#include "projective/fixed_projective_constraint.h"
#include "projective/subset_indices.h"
#include "test_scene.h"
#include "topology/dynamic/point_set_topology_modifier.h"

using namespace sinew;
using sinew::test::get;
using sinew::test::load;

TEST(SubsetIndices, RemovedEntriesLeaveInOrderAndTheLastPointTakesTheSlot) {
  // 6 points; points 4 and 1 removed (decreasing). Point 4: entry 4 erased, the last point 5
  // becomes 4. Point 1: entry 1 erased, the last point (now 4) becomes 1.
  std::vector<unsigned> s = {5, 1, 3, 4, 0, 5};
  follow_point_removal(s, {4, 1}, 6);
  EXPECT_EQ(s, (std::vector<unsigned>{1, 3, 0, 1}));
  // Removing the last point only drops it.
  std::vector<unsigned> t = {2, 0, 1};
  follow_point_removal(t, {2}, 3);
  EXPECT_EQ(t, (std::vector<unsigned>{0, 1}));
  // Removing every point empties the list.
  std::vector<unsigned> u = {0, 1};
  follow_point_removal(u, {1, 0}, 2);
  EXPECT_TRUE(u.empty());
}

TEST(SubsetIndices, ProjectiveConstraintsRenumberTheirIndicesWhenPointsAreRemoved) {
  auto s = load(R"(<Node name="root" dt="0.1" gravity="0 0 0">
    <DefaultAnimationLoop/>
    <MechanicalObject name="dofs" position="0 0 0  1 0 0  2 0 0  3 0 0  4 0 0  5 0 0"/>
    <PointSetTopologyContainer name="topo" position="0 0 0  1 0 0  2 0 0  3 0 0  4 0 0  5 0 0"/>
    <PointSetTopologyModifier name="mod"/>
    <FixedProjectiveConstraint name="fixed" indices="5 1 3"/>
    <AffineMovementProjectiveConstraint name="affine" indices="5 1 3" translation="1 0 0"/>
    <DirectionProjectiveConstraint name="direction" indices="5 1 3" direction="1 0 0"/>
    <LinearMovementProjectiveConstraint name="linear" indices="5 1 3" keyTimes="0 1" movements="0 0 0  1 0 0"/>
    <FixedPlaneProjectiveConstraint name="plane_fixed" indices="5 1 3" direction="0 1 0"/>
    <PointProjectiveConstraint name="point" indices="5 1 3"/>
    <LineProjectiveConstraint name="line" indices="5 1 3" direction="1 0 0"/>
    <PlaneProjectiveConstraint name="plane" indices="5 1 3" normal="0 1 0"/>
  </Node>)");
  ASSERT_TRUE(s.root);
  auto* mod = get<PointSetTopologyModifier>(*s.root, "mod");
  ASSERT_NE(mod, nullptr);
  mod->remove_points({1}, true);  // point 1 leaves, point 5 becomes 1
  const std::vector<unsigned> expected = {1, 3};
  EXPECT_EQ(get<FixedProjectiveConstraint>(*s.root, "fixed")->indices.get(), expected);
  EXPECT_EQ(get<AffineMovementProjectiveConstraint>(*s.root, "affine")->indices.get(), expected);
  EXPECT_EQ(get<DirectionProjectiveConstraint>(*s.root, "direction")->indices.get(), expected);
  for (const char* name : {"linear", "plane_fixed", "point", "line", "plane"}) {
    Component* c = s.root->find_object_named(name);
    ASSERT_NE(c, nullptr) << name;
    EXPECT_EQ(c->find_field("indices")->text(), "1 3") << name;
  }
  EXPECT_EQ(s.root->mechanical_state->size(), 5u);
  animate(*s.root);
}

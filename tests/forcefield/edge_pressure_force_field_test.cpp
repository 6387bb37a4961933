// EdgePressureForceField: each mode SOFA's example scenes use, with forces computed by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "forcefield/load/edge_pressure_force_field.h"
#include "spring_helpers.h"
#include "test_scene.h"
#include "topology/dynamic/edge_set_topology_modifier.h"

using namespace sinew;
using namespace sinew::test;

TEST(EdgePressureForceField, PressureIsHalfOfPressureTimesRestLengthOnEachVertex) {
  auto s = load(R"(<Node gravity="0 0 0">
    <MeshTopology name="topo" position="0 0 0  2 0 0  2 1 0" edges="0 1  1 2"/>
    <MechanicalObject name="dofs"/>
    <EdgePressureForceField name="ff" edges="1 2" pressure="0 0 1"/>
  </Node>)");
  auto* ff = get<EdgePressureForceField>(*s.root, "ff");
  ASSERT_NE(ff, nullptr);
  ASSERT_EQ(ff->state(), ComponentState::valid);
  MechanicalState& st = *s.root->mechanical_state;
  const auto f = force_at(*ff, st, st.write(kPosition));
  EXPECT_DOUBLE_EQ(f[2], 0.0);
  EXPECT_DOUBLE_EQ(f[5], 0.5);
  EXPECT_DOUBLE_EQ(f[8], 0.5);
}

TEST(EdgePressureForceField, PressureWinsOverIntensityAndUsesTheRestLength) {
  // EdgePressureForceField.scn's combination: pressure, normal and p_intensity all given.
  auto s = load(R"(<Node gravity="0 0 0">
    <MeshTopology name="topo" position="0 0 0  3 0 0  3 4 0" edges="0 1  1 2"/>
    <MechanicalObject name="dofs"/>
    <EdgePressureForceField name="ff" edges="@topo.edges" pressure="0 0 -0.1" normal="0 0 1" p_intensity="1"/>
  </Node>)");
  auto* ff = get<EdgePressureForceField>(*s.root, "ff");
  ASSERT_NE(ff, nullptr);
  ASSERT_EQ(ff->state(), ComponentState::valid);
  MechanicalState& st = *s.root->mechanical_state;
  std::vector<double> x = st.write(kPosition);
  x[6] += 5;  // moving a point changes nothing: rest lengths 3 and 4
  force_at(*ff, st, x);
  const auto f = force_at(*ff, st, x);
  EXPECT_NEAR(f[2], -0.15, 1e-15);
  EXPECT_NEAR(f[5], -0.15 - 0.2, 1e-15);
  EXPECT_NEAR(f[8], -0.2, 1e-15);
  EXPECT_DOUBLE_EQ(f[3], 0.0);
}

TEST(EdgePressureForceField, BinormalModeByHand) {
  // The projective-constraint scenes' mode: edgeIndices, binormal, p_intensity. Edge 1 = (1, 2)
  // runs along +y: n = normalize(b × t) = (0,0,1) × (0,1,0) = (−1, 0, 0). SOFA takes the length of
  // the topology's edge i = 0 (rest length 2), not of edge 1 (length 1): F = n · (−10) · 2 =
  // (20, 0, 0), half on each vertex.
  auto s = load(R"(<Node gravity="0 0 0">
    <MeshTopology name="topo" position="0 0 0  2 0 0  2 1 0" edges="0 1  1 2"/>
    <MechanicalObject name="dofs"/>
    <EdgePressureForceField name="ff" edgeIndices="1" binormal="0 0 2" p_intensity="-10"/>
  </Node>)");
  auto* ff = get<EdgePressureForceField>(*s.root, "ff");
  ASSERT_NE(ff, nullptr);
  ASSERT_EQ(ff->state(), ComponentState::valid);
  MechanicalState& st = *s.root->mechanical_state;
  std::vector<double> x = st.write(kPosition);
  auto f = force_at(*ff, st, x);
  EXPECT_DOUBLE_EQ(f[0], 0.0);
  EXPECT_DOUBLE_EQ(f[3], 10.0);
  EXPECT_DOUBLE_EQ(f[6], 10.0);
  EXPECT_DOUBLE_EQ(f[4], 0.0);
  EXPECT_DOUBLE_EQ(f[8], 0.0);

  // Point 2 moves to (3, 1, 0): the force follows the current tangent (1, 1, 0)/√2, one call
  // late as in SOFA (computed after being applied): n = (−1, 1, 0)/√2, F = n · (−10) · 2.
  x[6] = 3;
  f = force_at(*ff, st, x);
  EXPECT_DOUBLE_EQ(f[3], 10.0);
  f = force_at(*ff, st, x);
  const double h = 10 / std::sqrt(2.0);
  EXPECT_NEAR(f[3], h, 1e-13);
  EXPECT_NEAR(f[4], -h, 1e-13);
  EXPECT_NEAR(f[6], h, 1e-13);
  EXPECT_NEAR(f[7], -h, 1e-13);
  EXPECT_DOUBLE_EQ(f[5], 0.0);
}

TEST(EdgePressureForceField, OneIntensityPerEdgeWhenSeveralAreGiven) {
  // Edges (0,1) along +x and (1,2) along +y, binormal z: normals (0,1,0) and (−1,0,0);
  // lengths of edges 0 and 1 (2 and 1); intensities 3 and 5.
  auto s = load(R"(<Node gravity="0 0 0">
    <MeshTopology name="topo" position="0 0 0  2 0 0  2 1 0" edges="0 1  1 2"/>
    <MechanicalObject name="dofs"/>
    <EdgePressureForceField name="ff" edgeIndices="0 1" binormal="0 0 1" p_intensity="3 5"/>
  </Node>)");
  auto* ff = get<EdgePressureForceField>(*s.root, "ff");
  ASSERT_NE(ff, nullptr);
  MechanicalState& st = *s.root->mechanical_state;
  const auto f = force_at(*ff, st, st.write(kPosition));
  EXPECT_DOUBLE_EQ(f[1], 3.0);    // vertex 0: half of (0, 6, 0)
  EXPECT_DOUBLE_EQ(f[3], -2.5);   // vertex 1: half of (−5, 0, 0) ...
  EXPECT_DOUBLE_EQ(f[4], 3.0);    // ... and of (0, 6, 0)
  EXPECT_DOUBLE_EQ(f[6], -2.5);
  EXPECT_DOUBLE_EQ(f[7], 0.0);
}

TEST(EdgePressureForceField, WithoutBinormalABoundaryEdgeIsPushedTowardsItsTriangle) {
  // Edge 0 = (0, 1) lies on one triangle whose third vertex is (0, 1, 0): n = (0,0,1) × (1,0,0) =
  // (0, 1, 0) points towards it; F = n · L · p = (0, 2, 0). Edge 2 = (2, 0)... is a boundary
  // edge too: t = (0,−1,0), (0,0,1) × t = (1, 0, 0), towards vertex 1: F = (1,0,0) · L(edge 1) · 2.
  auto s = load(R"(<Node gravity="0 0 0">
    <MeshTopology name="topo" position="0 0 0  1 0 0  0 1 0" edges="0 1  1 2  2 0" triangles="0 1 2"/>
    <MechanicalObject name="dofs"/>
    <EdgePressureForceField name="ff" edgeIndices="0 2" p_intensity="2"/>
  </Node>)");
  auto* ff = get<EdgePressureForceField>(*s.root, "ff");
  ASSERT_NE(ff, nullptr);
  ASSERT_EQ(ff->state(), ComponentState::valid);
  MechanicalState& st = *s.root->mechanical_state;
  ASSERT_EQ(ff->edge_forces().size(), 2u);
  EXPECT_DOUBLE_EQ(ff->edge_forces()[0][1], 2.0);
  EXPECT_DOUBLE_EQ(ff->edge_forces()[0][0], 0.0);
  EXPECT_NEAR(ff->edge_forces()[1][0], 2 * std::sqrt(2.0), 1e-15);
  EXPECT_DOUBLE_EQ(ff->edge_forces()[1][1], 0.0);
  const auto f = force_at(*ff, st, st.write(kPosition));
  EXPECT_NEAR(f[0], std::sqrt(2.0), 1e-15);
  EXPECT_DOUBLE_EQ(f[1], 1.0);
  EXPECT_DOUBLE_EQ(f[4], 1.0);
  EXPECT_NEAR(f[6], std::sqrt(2.0), 1e-15);
}

TEST(EdgePressureForceField, SelectedEdgesFollowEdgeRemoval) {
  // SOFA's EdgeSubsetData: the removed edge 0 leaves the subset; the last edge (2) moves into
  // slot 0 and its entry is renamed. The force stays on the same vertices (2, 3), rest length 3.
  auto s = load(R"(<Node gravity="0 0 0">
    <MechanicalObject name="dofs" position="0 0 0  1 0 0  1 2 0  1 2 3"/>
    <EdgeSetTopologyContainer name="topo" position="@dofs.position" edges="0 1  1 2  2 3"/>
    <EdgeSetTopologyModifier name="mod"/>
    <EdgePressureForceField name="ff" edgeIndices="0 2" pressure="1 0 0"/>
  </Node>)");
  auto* ff = get<EdgePressureForceField>(*s.root, "ff");
  auto* mod = get<EdgeSetTopologyModifier>(*s.root, "mod");
  ASSERT_NE(ff, nullptr);
  ASSERT_NE(mod, nullptr);
  ASSERT_EQ(ff->state(), ComponentState::valid);
  mod->remove_edges({0}, false);
  EXPECT_EQ(ff->selected_edges(), std::vector<unsigned>{0});
  MechanicalState& st = *s.root->mechanical_state;
  const auto f = force_at(*ff, st, st.write(kPosition));
  EXPECT_DOUBLE_EQ(f[0], 0.0);
  EXPECT_DOUBLE_EQ(f[3], 0.0);
  EXPECT_DOUBLE_EQ(f[6], 1.5);
  EXPECT_DOUBLE_EQ(f[9], 1.5);
}

TEST(EdgePressureForceField, OutOfRangeEdgeIndexIsAnError) {
  auto s = load(R"(<Node gravity="0 0 0">
    <MeshTopology name="topo" position="0 0 0  2 0 0" edges="0 1"/>
    <MechanicalObject name="dofs"/>
    <EdgePressureForceField name="ff" edgeIndices="3" binormal="0 0 1" p_intensity="1"/>
  </Node>)");
  auto* ff = get<EdgePressureForceField>(*s.root, "ff");
  ASSERT_NE(ff, nullptr);
  EXPECT_EQ(ff->state(), ComponentState::invalid);
  bool named = false;
  for (const std::string& m : messages(s.root->diagnostics(), Severity::error))
    named = named || m.find("edge index 3") != std::string::npos;
  EXPECT_TRUE(named);
}

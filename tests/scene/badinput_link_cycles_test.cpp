// Bad-input hardening, link cycles: a ring of data links (two or three
// fields, positions, element lists, grid sizes, scalars) or an engine feeding
// its own input is refused with the chain and the file:line of each member.
#include <gtest/gtest.h>

#include <string>

#include "badinput_helpers.h"

using namespace sinew;
using namespace sinew::test;

namespace {

class BadInputLinkCycles : public ::testing::Test {
 protected:
  TempDir dir;
};

std::string with_root(const std::string& body, const std::string& root_attrs = R"(dt="0.01")") {
  return "<Node name=\"root\" " + root_attrs + ">\n  <DefaultAnimationLoop/>\n" + body + "\n</Node>\n";
}

}  // namespace

TEST_F(BadInputLinkCycles, TwoFieldLinkCycleIsRefusedWithTheChain) {
  const Outcome o = run_xml(dir, with_root(R"(  <MechanicalObject name="dofs" position="0 0 0 1 0 0 2 0 0"/>
  <FixedProjectiveConstraint name="a" indices="@b.indices"/>
  <FixedProjectiveConstraint name="b" indices="@a.indices"/>)"));
  EXPECT_FALSE(o.init_ok);
  EXPECT_TRUE(any_contains_all(o.errors, {"link cycle", "'a' (FixedProjectiveConstraint).indices (", "scene.scn:4)",
                                          "'b' (FixedProjectiveConstraint).indices (", "scene.scn:5)"}))
      << o.all();
}

TEST_F(BadInputLinkCycles, ThreeFieldCyclesOverPositionsAndScalarsAreRefused) {
  const Outcome o = run_xml(dir, with_root(R"(  <EulerImplicitSolver/>
  <CGLinearSolver iterations="25" tolerance="1e-9" threshold="1e-9"/>
  <MechanicalObject name="a" position="@c.position"/>
  <MechanicalObject name="b" position="@a.position"/>
  <MechanicalObject name="c" position="@b.position"/>
  <UniformMass name="m1" totalMass="@m2.totalMass"/>
  <UniformMass name="m2" totalMass="@m1.totalMass"/>)"));
  EXPECT_FALSE(o.init_ok);
  EXPECT_TRUE(any_contains_all(o.errors, {"link cycle", "'a' (MechanicalObject).position", "'b' (MechanicalObject)",
                                          "'c' (MechanicalObject)"}))
      << o.all();
  EXPECT_TRUE(any_contains_all(o.errors, {"link cycle", "'m1' (UniformMass).totalMass", "'m2' (UniformMass)"}))
      << o.all();
}

TEST_F(BadInputLinkCycles, CyclesOverElementListsAndGridSizesAreRefused) {
  const Outcome o = run_xml(dir, with_root(R"(  <MeshTopology name="t1" edges="@t2.edges"/>
  <MeshTopology name="t2" edges="@t1.edges"/>
  <RegularGridTopology name="g1" n="@g2.n"/>
  <RegularGridTopology name="g2" n="@g1.n"/>)"));
  EXPECT_FALSE(o.init_ok);
  EXPECT_TRUE(any_contains_all(o.errors, {"link cycle", "'t1' (MeshTopology).edges"})) << o.all();
  EXPECT_TRUE(any_contains_all(o.errors, {"link cycle", "'g1' (RegularGridTopology).n"})) << o.all();
}

TEST_F(BadInputLinkCycles, EngineFeedingItsOwnInputIsRefused) {
  const Outcome o = run_xml(dir, with_root(R"(  <TransformEngine name="e" input_position="@e.output_position" translation="1 0 0"/>
  <MechanicalObject name="dofs" position="@e.output_position"/>)"));
  EXPECT_FALSE(o.init_ok);
  EXPECT_TRUE(any_contains_all(o.errors, {"link cycle", "'e' (TransformEngine)"})) << o.all();
}

TEST_F(BadInputLinkCycles, LinkChainsWithoutCycleStillLoad) {
  const Outcome o = run_xml(dir, with_root(R"(  <MechanicalObject name="dofs" position="0 0 0 1 0 0 2 0 0"/>
  <FixedProjectiveConstraint name="a" indices="0 1"/>
  <FixedProjectiveConstraint name="b" indices="@a.indices"/>
  <FixedProjectiveConstraint name="c" indices="@b.indices"/>)"));
  EXPECT_TRUE(o.init_ok) << o.all();
  EXPECT_FALSE(any_contains(o.errors, "link cycle"));
}

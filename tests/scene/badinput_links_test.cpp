// Bad-input audit, links and sizes: points outside a barycentric mapping,
// indices beyond the state in constraints, masses, springs and mappings,
// linked fields of mismatched sizes. Each case: a message naming the
// component and the index (or the sizes); no crash, no NaNs without an error.
#include <gtest/gtest.h>

#include "badinput_helpers.h"

using namespace sinew;
using namespace sinew::test;

namespace {

// Six points, two good tetrahedra, a mass and an implicit solver; `extra` goes
// in the same node, `child` in a child node.
std::string base_scene(const std::string& extra, const std::string& child = "",
                  const std::string& mo_extra = "", const std::string& mass = R"(<UniformMass totalMass="1"/>)") {
  return R"(<Node name="root" gravity="0 -9.81 0" dt="0.01">
  <DefaultAnimationLoop/>
  <EulerImplicitSolver/>
  <CGLinearSolver iterations="50" tolerance="1e-9" threshold="1e-12"/>
  <MechanicalObject name="dofs" position="0 0 0  1 0 0  0 1 0  0 0 1  1 1 0  1 1 1" )" +
         mo_extra + R"(/>
  <MeshTopology name="topo" tetrahedra="0 1 2 3  1 4 2 5"/>
  )" + mass + R"(
  <TetrahedronFEMForceField name="fem" youngModulus="1000" poissonRatio="0.3"/>
  )" + extra +
         (child.empty() ? "" : "\n  <Node name=\"child\">\n    " + child + "\n  </Node>") + "\n</Node>";
}

class BadInputLinks : public ::testing::Test {
 protected:
  TempDir dir;
};

}  // namespace

TEST_F(BadInputLinks, ReferenceSceneRuns) {
  const Outcome o = run_xml(dir, base_scene(R"(<FixedProjectiveConstraint name="fix" indices="0 2 3"/>)"), 5);
  EXPECT_TRUE(o.init_ok) << o.all();
  EXPECT_EQ(o.steps, 5);
  EXPECT_TRUE(o.finite);
}

TEST_F(BadInputLinks, BarycentricMappingPointOutsideEveryElementIsReported) {
  const Outcome o = run_xml(dir,
                            base_scene(R"(<FixedProjectiveConstraint name="fix" indices="0 2 3"/>)",
                                  R"(<MechanicalObject name="mapped" position="0.1 0.1 0.1  10 20 30"/>
    <BarycentricMapping name="map" input="@.." output="@mapped"/>)"),
                            5);
  EXPECT_TRUE(any_contains_all(o.problems(), {"component 'map' (BarycentricMapping)", "1"})) << o.all();
  EXPECT_FALSE(any_contains_all(o.problems(), {"component 'map' (BarycentricMapping)", "point 0"})) << o.all();
  expect_no_silent_garbage(o);
}

TEST_F(BadInputLinks, BarycentricMappingOntoFlatTetrahedronIsNotSilent) {
  // The only input element is flat: the mapping cannot locate anything.
  const Outcome o = run_xml(dir, R"(<Node name="root" dt="0.01" gravity="0 -9.81 0">
  <EulerImplicitSolver/><CGLinearSolver iterations="20" tolerance="1e-9" threshold="1e-12"/>
  <MechanicalObject name="dofs" position="0 0 0  1 0 0  0 1 0  1 1 0"/>
  <MeshTopology name="topo" tetrahedra="0 1 2 3"/>
  <UniformMass totalMass="1"/>
  <Node name="child">
    <MechanicalObject name="mapped" position="0.2 0.2 0.5"/>
    <BarycentricMapping name="map" input="@.." output="@mapped"/>
  </Node>
</Node>)",
                            3);
  EXPECT_TRUE(any_contains_all(o.problems(), {"component 'map' (BarycentricMapping)"})) << o.all();
  expect_no_silent_garbage(o);
}

TEST_F(BadInputLinks, FixedConstraintIndexBeyondTheState) {
  const Outcome o = run_xml(dir, base_scene(R"(<FixedProjectiveConstraint name="fix" indices="0 2 99"/>)"), 5);
  EXPECT_TRUE(any_contains_all(o.problems(), {"component 'fix' (FixedProjectiveConstraint)", "99"})) << o.all();
  expect_no_silent_garbage(o);
}

TEST_F(BadInputLinks, PartialFixedConstraintIndexBeyondTheState) {
  const Outcome o = run_xml(
      dir, base_scene(R"(<PartialFixedProjectiveConstraint name="fix" indices="0 99" fixedDirections="1 1 1"/>)"), 5);
  EXPECT_TRUE(any_contains_all(o.problems(), {"component 'fix' (PartialFixedProjectiveConstraint)", "99"}))
      << o.all();
  expect_no_silent_garbage(o);
}

TEST_F(BadInputLinks, LinearVelocityConstraintIndexBeyondTheState) {
  const Outcome o = run_xml(
      dir,
      base_scene(R"(<LinearVelocityProjectiveConstraint name="lv" indices="0 99" keyTimes="0 1" velocities="0 0 0  1 0 0"/>)"),
      5);
  EXPECT_TRUE(any_contains_all(o.problems(), {"component 'lv' (LinearVelocityProjectiveConstraint)", "99"}))
      << o.all();
  expect_no_silent_garbage(o);
}

TEST_F(BadInputLinks, UniformMassIndexBeyondTheState) {
  const Outcome o = run_xml(dir, base_scene("", "", "", R"(<UniformMass name="mass" totalMass="1" indices="0 1 99"/>)"), 5);
  EXPECT_TRUE(any_contains_all(o.problems(), {"component 'mass' (UniformMass)", "99"})) << o.all();
  expect_no_silent_garbage(o);
}

TEST_F(BadInputLinks, DiagonalMassVertexMassOfAnotherSize) {
  const Outcome o =
      run_xml(dir, base_scene("", "", "", R"(<DiagonalMass name="mass" vertexMass="1 1 1"/>)"), 5);
  EXPECT_TRUE(any_contains_all(o.problems(), {"component 'mass' (DiagonalMass)", "vertexMass"})) << o.all();
  expect_no_silent_garbage(o);
}

TEST_F(BadInputLinks, NegativeMassIsReported) {
  const Outcome o = run_xml(dir, base_scene("", "", "", R"(<UniformMass name="mass" totalMass="-1"/>)"), 5);
  EXPECT_TRUE(any_contains_all(o.problems(), {"component 'mass' (UniformMass)", "negative"})) << o.all();
  expect_no_silent_garbage(o);
}

TEST_F(BadInputLinks, SpringIndexBeyondTheState) {
  const Outcome o =
      run_xml(dir, base_scene(R"(<SpringForceField name="springs" spring="0 1 100 1 1  2 99 100 1 1"/>)"), 5);
  EXPECT_TRUE(any_contains_all(o.errors, {"component 'springs' (SpringForceField)", "99"})) << o.all();
  EXPECT_TRUE(any_contains_all(o.errors, {"component 'springs' (SpringForceField)", "spring 1"})) << o.all();
  EXPECT_FALSE(o.init_ok);
}

TEST_F(BadInputLinks, SpringWithNegativeIndexOrGarbage) {
  const Outcome o = run_xml(dir, base_scene(R"(<SpringForceField name="springs" spring="0 -1 100 1 1"/>)"), 5);
  EXPECT_TRUE(any_contains_all(o.problems(), {"springs", "spring"})) << o.all();
  EXPECT_FALSE(o.init_ok);
}

TEST_F(BadInputLinks, RestShapeSpringIndexBeyondTheState) {
  const Outcome o =
      run_xml(dir, base_scene(R"(<RestShapeSpringsForceField name="rss" points="0 99" stiffness="100"/>)"), 5);
  EXPECT_TRUE(any_contains_all(o.errors, {"component 'rss' (RestShapeSpringsForceField)", "99"})) << o.all();
  EXPECT_FALSE(o.init_ok);
}

TEST_F(BadInputLinks, MeshSpringTopologyBeyondTheState) {
  const Outcome o = run_xml(dir, R"(<Node name="root" dt="0.01">
  <EulerImplicitSolver/><CGLinearSolver iterations="20" tolerance="1e-9" threshold="1e-12"/>
  <MechanicalObject name="dofs" position="0 0 0  1 0 0  0 1 0"/>
  <MeshTopology name="topo" edges="0 1  1 2  2 7"/>
  <UniformMass totalMass="1"/>
  <MeshSpringForceField name="springs" stiffness="100"/>
</Node>)",
                            3);
  EXPECT_TRUE(any_contains_all(o.errors, {"component 'springs' (MeshSpringForceField)", "7"})) << o.all();
  EXPECT_FALSE(o.init_ok);
}

TEST_F(BadInputLinks, VelocityOfAnotherSizeThanPosition) {
  const Outcome o = run_xml(dir,
                            base_scene(R"(<FixedProjectiveConstraint name="fix" indices="0 2 3"/>)", "",
                                  R"(velocity="1 0 0  1 0 0")"),
                            5);
  EXPECT_TRUE(any_contains_all(o.problems(), {"component 'dofs' (MechanicalObject)", "velocity"})) << o.all();
  expect_no_silent_garbage(o);
}

TEST_F(BadInputLinks, RestPositionOfAnotherSizeThanPosition) {
  const Outcome o = run_xml(dir,
                            base_scene(R"(<FixedProjectiveConstraint name="fix" indices="0 2 3"/>)", "",
                                  R"(rest_position="0 0 0  1 0 0")"),
                            5);
  EXPECT_TRUE(any_contains_all(o.problems(), {"component 'dofs' (MechanicalObject)", "rest_position"})) << o.all();
  expect_no_silent_garbage(o);
}

TEST_F(BadInputLinks, PositionLinkedToALoaderWithFewerPointsThanTheTopology) {
  dir.write("small.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  dir.write("big.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 2 4 3\n");
  const Outcome o = run_xml(dir, R"(<Node name="root" dt="0.01">
  <EulerImplicitSolver/><CGLinearSolver iterations="20" tolerance="1e-9" threshold="1e-12"/>
  <MeshOBJLoader name="small" filename="small.obj"/>
  <MeshOBJLoader name="big" filename="big.obj"/>
  <MechanicalObject name="dofs" position="@small.position"/>
  <MeshTopology name="topo" src="@big"/>
  <UniformMass totalMass="1"/>
  <TriangularFEMForceField name="fem" youngModulus="1000" poissonRatio="0.3"/>
</Node>)",
                            3);
  EXPECT_TRUE(any_contains_all(o.errors, {"component 'fem' (TriangularFEMForceField)", "3"})) << o.all();
  EXPECT_FALSE(o.init_ok);
}

TEST_F(BadInputLinks, TetraFEMOnALoaderWithFewerPointsThanItsTetrahedra) {
  const Outcome o = run_xml(dir, R"(<Node name="root" dt="0.01">
  <EulerImplicitSolver/><CGLinearSolver iterations="20" tolerance="1e-9" threshold="1e-12"/>
  <MechanicalObject name="dofs" position="0 0 0  1 0 0  0 1 0  0 0 1"/>
  <MeshTopology name="topo" position="0 0 0  1 0 0  0 1 0  0 0 1  1 1 1" tetrahedra="0 1 2 3  1 2 3 4"/>
  <UniformMass totalMass="1"/>
  <TetrahedronFEMForceField name="fem" youngModulus="1000" poissonRatio="0.3"/>
</Node>)",
                            3);
  EXPECT_TRUE(any_contains_all(o.errors, {"component 'fem' (TetrahedronFEMForceField)", "4"})) << o.all();
  EXPECT_FALSE(o.init_ok);
}

TEST_F(BadInputLinks, SubsetMappingIndexBeyondTheInput) {
  const Outcome o = run_xml(dir,
                            base_scene(R"(<FixedProjectiveConstraint name="fix" indices="0 2 3"/>)",
                                  R"(<MechanicalObject name="sub"/>
    <SubsetMapping name="map" input="@.." output="@sub" indices="0 1 42"/>)"),
                            3);
  EXPECT_TRUE(any_contains_all(o.errors, {"component 'map' (SubsetMapping)", "42"})) << o.all();
  EXPECT_FALSE(o.init_ok);
}

TEST_F(BadInputLinks, IdentityMappingBetweenStatesOfDifferentSizes) {
  const Outcome o = run_xml(dir,
                            base_scene(R"(<FixedProjectiveConstraint name="fix" indices="0 2 3"/>)",
                                  R"(<MechanicalObject name="copy" position="0 0 0  1 1 1"/>
    <IdentityMapping name="map" input="@.." output="@copy"/>)"),
                            3);
  EXPECT_TRUE(any_contains_all(o.problems(), {"component 'map' (IdentityMapping)"})) << o.all();
  expect_no_silent_garbage(o);
}

TEST_F(BadInputLinks, RigidMappingIndexBeyondTheRigidState) {
  const Outcome o = run_xml(dir, R"(<Node name="root" dt="0.01">
  <EulerImplicitSolver/><CGLinearSolver iterations="20" tolerance="1e-9" threshold="1e-12"/>
  <MechanicalObject template="Rigid3d" name="rigid" position="0 0 0 0 0 0 1"/>
  <UniformMass totalMass="1"/>
  <Node name="child">
    <MechanicalObject name="pts" position="1 0 0  0 1 0"/>
    <RigidMapping name="map" input="@.." output="@pts" rigidIndexPerPoint="0 5"/>
  </Node>
</Node>)",
                            3);
  EXPECT_TRUE(any_contains_all(o.errors, {"component 'map' (RigidMapping)", "5"})) << o.all();
  EXPECT_FALSE(o.init_ok);
}

TEST_F(BadInputLinks, LinkToAMissingObjectIsReported) {
  const Outcome o = run_xml(dir, base_scene(R"(<FixedProjectiveConstraint name="fix" indices="0 2 3"/>)",
                                       R"(<MechanicalObject name="mapped" position="0.1 0.1 0.1"/>
    <BarycentricMapping name="map" input="@../nothere" output="@mapped"/>)"),
                            3);
  EXPECT_TRUE(any_contains_all(o.errors, {"nothere"})) << o.all();
  EXPECT_TRUE(any_contains_all(o.errors, {"scene.scn:"})) << o.all();
  EXPECT_FALSE(o.init_ok);
}

// ---------------------------------------------------------------- scene text
TEST_F(BadInputLinks, UnknownComponentHasFileLineAndSuggestion) {
  const Outcome o = run_xml(dir, base_scene(R"(<FixedProjectiveConstraint name="fix" indices="0 2 3"/>
  <MechanicalObjekt name="typo"/>)"),
                            1);
  EXPECT_FALSE(o.init_ok);
  EXPECT_TRUE(any_contains_all(o.errors, {"scene.scn:10:", "MechanicalObjekt", "MechanicalObject"})) << o.all();
}

TEST_F(BadInputLinks, UnknownAttributeHasFileLineAndSuggestion) {
  const Outcome o = run_xml(dir, base_scene(R"(<FixedProjectiveConstraint name="fix" indicess="0 2 3"/>)"), 1);
  EXPECT_TRUE(any_contains_all(o.problems(), {"scene.scn:9:", "indicess", "indices"})) << o.all();
}

TEST_F(BadInputLinks, UnparsableIndexIsReported) {
  const Outcome o = run_xml(dir, base_scene(R"(<FixedProjectiveConstraint name="fix" indices="0 two 3"/>)"), 1);
  EXPECT_TRUE(any_contains_all(o.problems(), {"scene.scn:9:", "'fix'", "indices", "two"})) << o.all();
}

TEST_F(BadInputLinks, MalformedXmlHasFileLine) {
  const Outcome o = run_xml(dir, R"(<Node name="root">
  <MechanicalObject name="dofs" position="0 0 0"/>
  <UniformMass totalMass="1"
</Node>)",
                            1);
  EXPECT_FALSE(o.init_ok);
  EXPECT_TRUE(any_contains_all(o.errors, {"scene.scn:"})) << o.all();
}

TEST_F(BadInputLinks, EmptySceneFileIsAnError) {
  const Outcome o = run_xml(dir, "", 1);
  EXPECT_FALSE(o.init_ok);
  EXPECT_TRUE(any_contains_all(o.errors, {"scene.scn"})) << o.all();
}

TEST_F(BadInputLinks, NonFiniteDtIsNotSilent) {
  std::string xml = base_scene(R"(<FixedProjectiveConstraint name="fix" indices="0 2 3"/>)");
  xml.replace(xml.find("dt=\"0.01\""), 9, "dt=\"1e400\"");
  const Outcome o = run_xml(dir, xml, 3);
  expect_no_silent_garbage(o);
}

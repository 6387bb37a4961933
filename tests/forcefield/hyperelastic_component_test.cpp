// TetrahedronHyperelasticityFEMForceField as a component: bad input gives an
// error naming the component (unknown material, wrong number of parameters for
// each material, flat element, index beyond the state), every material runs, and
// an assembled direct solver gives the same motion as matrix-free CG.
#include <gtest/gtest.h>

#include "badinput_helpers.h"

using namespace sinew;
using namespace sinew::test;

namespace {

const char* kPoints = "0 0 0  1 0 0  0 1 0  0 0 1  1 1 0  1 1 1";
const char* kWho = "component 'fem' (TetrahedronHyperelasticityFEMForceField)";

std::string scene(const std::string& tets, const std::string& material, const std::string& solver = "") {
  return R"(<Node name="root" gravity="0 -9.81 0" dt="0.01">
  <DefaultAnimationLoop/>
  <EulerImplicitSolver/>
  )" + (solver.empty() ? std::string(R"(<CGLinearSolver iterations="100" tolerance="1e-12" threshold="1e-14"/>)")
                       : solver) +
         R"(
  <MechanicalObject name="dofs" position=")" + kPoints + R"("/>
  <MeshTopology name="topo" tetrahedra=")" + tets + R"("/>
  <UniformMass totalMass="1"/>
  <FixedProjectiveConstraint indices="0 2 3"/>
  <TetrahedronHyperelasticityFEMForceField name="fem" )" + material + R"(/>
</Node>)";
}

class HyperelasticComponent : public ::testing::Test {
 protected:
  void check_assembled_matches_matrix_free(const std::string& material);
  TempDir dir;
};

TEST_F(HyperelasticComponent, GoodMeshRunsWithoutMessagesForEveryMaterial) {
  for (const char* m : {R"(ParameterSet="3448 31034")", R"(materialName="StVenantKirchhoff" ParameterSet="3448 31034")",
                        R"(materialName="NeoHookean" ParameterSet="3448 31034")",
                        R"(materialName="MooneyRivlin" ParameterSet="5000 7000 10")",
                        R"(materialName="Ogden" ParameterSet="1500 5 5000")",
                        R"(materialName="VerondaWestman" ParameterSet="1000 5 20000")",
                        R"(materialName="Costa" ParameterSet="1000 10000 10 5 8 4 3 6")",
                        R"(materialName="StableNeoHookean" ParameterSet="3448 31034")"}) {
    const Outcome o = run_xml(dir, scene("0 1 2 3  1 2 4 5", m), 5);
    EXPECT_TRUE(o.init_ok) << m << "\n" << o.all();
    EXPECT_EQ(o.steps, 5) << m;
    EXPECT_TRUE(o.finite) << m;
    EXPECT_TRUE(o.errors.empty()) << m << "\n" << o.all();
  }
}

// StandardTetrahedralFEMForceField runs SOFA's example scene's four materials and has no
// StableNeoHookean (SOFA's list of materials for it).
TEST_F(HyperelasticComponent, StandardTetrahedralRunsItsMaterialsAndRefusesStableNeoHookean) {
  auto standard = [](std::string xml) {
    const std::string from = "TetrahedronHyperelasticityFEMForceField";
    xml.replace(xml.find(from), from.size(), "StandardTetrahedralFEMForceField");
    return xml;
  };
  for (const char* m : {R"(ParameterSet="3448 31034")", R"(materialName="StVenantKirchhoff" ParameterSet="3448 31034")",
                        R"(materialName="NeoHookean" ParameterSet="3448 31034")",
                        R"(materialName="MooneyRivlin" ParameterSet="5000 7000 10")"}) {
    const Outcome o = run_xml(dir, standard(scene("0 1 2 3  1 2 4 5", m)), 5);
    EXPECT_TRUE(o.init_ok) << m << "\n" << o.all();
    EXPECT_EQ(o.steps, 5) << m;
    EXPECT_TRUE(o.finite) << m;
    EXPECT_TRUE(o.errors.empty()) << m << "\n" << o.all();
  }
  const Outcome o =
      run_xml(dir, standard(scene("0 1 2 3", R"(materialName="StableNeoHookean" ParameterSet="3448 31034")")), 5);
  EXPECT_TRUE(any_contains_all(o.errors, {"StableNeoHookean", "unknown"})) << o.all();
  EXPECT_FALSE(o.init_ok);
}

TEST_F(HyperelasticComponent, UnknownMaterialIsAnError) {
  const Outcome o = run_xml(dir, scene("0 1 2 3", R"(materialName="Rubber" ParameterSet="1 2")"), 5);
  EXPECT_TRUE(any_contains_all(o.errors, {kWho, "Rubber", "unknown"})) << o.all();
  EXPECT_FALSE(o.init_ok);
}

// Costa takes 8 values; the message lists their meaning.
TEST_F(HyperelasticComponent, CostaWithTooFewParametersIsAnError) {
  const Outcome o = run_xml(dir, scene("0 1 2 3", R"(materialName="Costa" ParameterSet="1 2 3")"), 5);
  EXPECT_TRUE(any_contains_all(o.errors, {kWho, "Costa", "needs 8", "a k0 bff bfs bss bfn bsn bnn", "3 given"}))
      << o.all();
  EXPECT_FALSE(o.init_ok);
}

TEST_F(HyperelasticComponent, WrongNumberOfParametersIsAnError) {
  for (const char* m : {R"(ParameterSet="")", R"(materialName="MooneyRivlin" ParameterSet="1 2")",
                        R"(materialName="NeoHookean" ParameterSet="1 2 3")",
                        R"(materialName="VerondaWestman" ParameterSet="1 2")",
                        R"(materialName="VerondaWestman" ParameterSet="1 2 3 4")",
                        R"(materialName="Costa" ParameterSet="1 2 3 4 5 6 7")",
                        R"(materialName="Costa" ParameterSet="1 2 3 4 5 6 7 8 9")",
                        R"(materialName="StableNeoHookean" ParameterSet="1")",
                        R"(materialName="StableNeoHookean" ParameterSet="1 2 3")"}) {
    const Outcome o = run_xml(dir, scene("0 1 2 3", m), 5);
    EXPECT_TRUE(any_contains_all(o.errors, {kWho, "ParameterSet"})) << m << "\n" << o.all();
    EXPECT_FALSE(o.init_ok) << m;
  }
}

TEST_F(HyperelasticComponent, FlatElementIsAnErrorNamingTheElement) {
  const Outcome o = run_xml(dir, scene("0 1 2 3  1 2 4 0", R"(ParameterSet="3448 31034")"), 5);
  EXPECT_TRUE(any_contains_all(o.errors, {kWho, "tetrahedron 1", "degenerate"})) << o.all();
  EXPECT_FALSE(o.init_ok);
}

TEST_F(HyperelasticComponent, IndexBeyondTheStateIsAnError) {
  const Outcome o = run_xml(dir, scene("0 1 2 3  1 2 4 99", R"(ParameterSet="3448 31034")"), 5);
  EXPECT_TRUE(any_contains_all(o.problems(), {"99"})) << o.all();
  EXPECT_FALSE(o.init_ok);
}

// Same motion with an assembled LDLᵀ solve (build_stiffness) as with CG (add_dforce).
TEST_F(HyperelasticComponent, AssembledSolverMatchesMatrixFree) {
  for (const std::string mat : {R"(materialName="NeoHookean" ParameterSet="3448 31034")",
                                R"(materialName="VerondaWestman" ParameterSet="1000 5 20000")",
                                R"(materialName="Costa" ParameterSet="1000 10000 10 5 8 4 3 6")",
                                R"(materialName="StableNeoHookean" ParameterSet="3448 31034")"}) {
    SCOPED_TRACE(mat);
    check_assembled_matches_matrix_free(mat);
  }
}

void HyperelasticComponent::check_assembled_matches_matrix_free(const std::string& mat) {
  auto run = [&](const std::string& solver) {
    scene::LoadedScene s = load(scene("0 1 2 3  1 2 4 5", mat, solver));
    for (int i = 0; i < 10; ++i) animate(*s.root);
    auto* mo = get<MechanicalState>(*s.root, "dofs");
    return mo ? mo->write(kPosition) : std::vector<double>{};
  };
  const auto a = run("");
  const auto b = run("<SparseLDLSolver/>");
  ASSERT_EQ(a.size(), b.size());
  ASSERT_FALSE(a.empty());
  double moved = 0;
  const std::vector<double> x0 = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 0, 1, 1, 1};
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_NEAR(a[i], b[i], 1e-7) << i;  // CG stops at its tolerance
    moved = std::max(moved, std::fabs(a[i] - x0[i]));
  }
  EXPECT_GT(moved, 1e-4);  // the body did move
}

}  // namespace
